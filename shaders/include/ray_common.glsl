// Helpers of every ray-generation shader (rt.rgen, pt.rgen): secondary-ray origins and
// an orthonormal basis about a direction.
#ifndef SHERPA_RAY_COMMON_GLSL
#define SHERPA_RAY_COMMON_GLSL

// Wächter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection"
// (Ray Tracing Gems, ch. 6): the origin moved off the surface along its face normal
// by a few units in the last place of its coordinates (a fixed distance near 0), so
// a secondary ray neither re-hits its own triangle nor skips a nearby occluder.
vec3 offset_ray(vec3 p, vec3 n) {
    const ivec3 of = ivec3(256.0 * n);
    const vec3 pi = vec3(intBitsToFloat(floatBitsToInt(p.x) + (p.x < 0.0 ? -of.x : of.x)),
                         intBitsToFloat(floatBitsToInt(p.y) + (p.y < 0.0 ? -of.y : of.y)),
                         intBitsToFloat(floatBitsToInt(p.z) + (p.z < 0.0 ? -of.z : of.z)));
    return mix(pi, p + (1.0 / 65536.0) * n, lessThan(abs(p), vec3(1.0 / 32.0)));
}

// What an sRGB colour target stores for a linear colour (the storage images of the
// ray tracers are RGBA8 UNORM holding sRGB-encoded bytes).
vec3 linear_to_srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

// The camera ray through `ndc` (the viewport is flipped: the top row is NDC y = +1) for
// the rasterizer's reverse-Z matrices: from the near plane (depth 1, where the raster
// clips too) toward the far plane (depth 0). The direction is the homogeneous
// difference far.xyz - origin * far.w, exact at an infinite far plane (far.w = 0):
// unprojecting a second point near the camera (depth 0.5, 2 x near away) and
// subtracting loses the direction to cancellation (4.8e-6 rad, about 1e-3 pixel at
// 320x240, enough to put a pixel centre 1.2e-4 pixel outside a triangle's edge on
// the other side; docs/raytracing/README.md, "One rule for blended surfaces"). The
// point at depth 0.5 only orients it (far.w's sign).
void camera_ray(mat4 inv_view_proj, vec2 ndc, out vec3 origin, out vec3 dir) {
    const vec4 near_point = inv_view_proj * vec4(ndc, 1.0, 1.0);
    const vec4 far_point = inv_view_proj * vec4(ndc, 0.0, 1.0);
    const vec4 mid_point = inv_view_proj * vec4(ndc, 0.5, 1.0);
    origin = near_point.xyz / near_point.w;
    dir = normalize(far_point.xyz - origin * far_point.w);
    if (dot(dir, mid_point.xyz / mid_point.w - origin) < 0.0) dir = -dir;
}

void basis(vec3 n, out vec3 t, out vec3 b) {
    t = normalize(abs(n.x) > 0.9 ? cross(n, vec3(0.0, 1.0, 0.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
    b = cross(n, t);
}
#endif
