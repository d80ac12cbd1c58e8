// Declarations of the ray-tracing stages (rt.rgen, rt.rmiss, rt.rchit, rt.rahit) and
// the hit interpolation: a hit's vertices are read through its GPUGeometryInfo
// record (gl_InstanceCustomIndexEXT + gl_GeometryIndexEXT) and interpolated with
// the hit's barycentrics, as the rasterizer interpolates mesh.vert's outputs.
// C++ twin of the push constants: GPURayPushConstants (gpu_structs.h).
#ifndef SHERPA_RT_HIT_GLSL
#define SHERPA_RT_HIT_GLSL
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#include "material.glsl"
#include "material_extra.glsl"
#include "rt_geometry.glsl"
#include "stream_refs.glsl"
#include "sherpa_mesh_flags.glsl"
#include "sherpa_views.glsl"

layout(set = 0, binding = 0) uniform sampler2D textures[];
layout(set = 1, binding = 0) uniform accelerationStructureEXT tlas;
layout(set = 1, binding = 1, rgba8) uniform writeonly image2D out_image;
layout(set = 1, binding = 2, std430) readonly buffer MaterialBlock {
    GPUMaterialData materials[];
};
layout(set = 1, binding = 3, std430) readonly buffer MaterialExtraBlock {
    GPUMaterialExtra material_extras[];
};

#ifdef SHERPA_PATH_TRACE
// The path tracer's (pt.*; C++ twin GPUPathPushConstants): the same offsets for the
// fields the hit interpolation and texture sampling read.
layout(push_constant, scalar) uniform PathPush {
    mat4 inv_view_proj;       // 0: NDC -> world, reverse Z
    GeometryInfos geometries; // 64
    uint first_sample;        // 72: index of this launch's first sample in each pixel
    float texture_lod;        // 76: mip level every texture is sampled at (< 0: 0)
    vec4 clear_color;         // 80: linear, the background where it is a colour
    uint samples;             // 96: samples per pixel this launch (PATH_SAMPLE_COUNT), flags
    uint max_bounces;         // 100: surface interactions after the camera ray's hit
    uint seed;                // 104
    float light_inv_power;    // 108: 1 / the emissive triangles' power (0: no light list)
    uvec2 env_size;           // 112: columns, rows of the environment distribution (0: none)
    float sun_cos_radius;     // 120: cosine of the sun's angular radius
    float max_radiance;       // 124: larger sample radiance is counted non-finite (0)
} pc;
const uint PATH_SAMPLE_COUNT = 0xffffu;    // pc.samples: the count
const uint PATH_ALL_LIGHTS = 0x10000u;     // pc.samples: one shadow ray per light (reference)
#else
layout(push_constant, scalar) uniform RayPush {
    mat4 inv_view_proj;       // 0: NDC -> world, reverse Z
    GeometryInfos geometries; // 64
    uint view;                // 72: VIEW_*
    float texture_lod;        // 76: mip level every texture is sampled at (< 0: 0)
    vec4 clear_color;         // 80: linear, what a miss shows
    vec4 sun;                 // 96: xyz unit direction toward the sun, w angular radius
    uint shadow_rays;         // 112: per pixel; 0: the sun casts no shadow
    uint ao_rays;             // 116
    float ao_radius;          // 120: world units
    uint reserved;            // 124
} pc;
#endif

// What a ray is for: any-hit culls by it (rt.rahit), raygen traces each kind.
const uint RAY_PRIMARY = 0u;
const uint RAY_SHADOW = 1u;
const uint RAY_AO = 2u;

struct RayPayload {
    vec4 color;     // rgb; a: 1 linear colour, 0 data (the surface views)
    vec3 position;  // world hit point
    uint kind;      // RAY_*, set by the tracer
    vec3 geometric; // unit face normal on the ray's side
    uint hit;       // 1 hit, 0 miss (rt.rmiss clears it)
    vec3 normal;    // interpolated normal of the side seen (flipped on double-sided backs)
};

// Rays have no derivatives: textures are read at an explicit level, 0 unless
// render --texture-lod names one.
vec4 sample_transformed(GPUTextureTransform t, uint tex, vec2 uv0, vec2 uv1) {
    return textureLod(textures[nonuniformEXT(tex)], transform_uv(t, uv0, uv1), max(pc.texture_lod, 0.0));
}

vec4 sample_slot(GPUMaterialExtra extra, uint slot, uint tex, vec2 uv0, vec2 uv1) {
    return sample_transformed(extra.uv[slot], tex, uv0, uv1);
}

#ifndef SHERPA_RT_RAYGEN
struct SurfaceHit {
    vec3 normal;  // world space, not normalised (as mesh.vert's output)
    vec4 tangent; // world xyz, w handedness
    vec2 uv0, uv1;
    vec4 color;
    uint material, flags;
    bool front; // counter-clockwise seen from the ray, in object space (see below)
    vec3 position;  // world, from the barycentrics (not origin + t * direction)
    vec3 geometric; // world face normal (counter-clockwise side), not normalised
};

// The hit with barycentrics (b1, b2). Absent streams read glTF's defaults, as
// common.glsl's fetch_*. The front face is decided from the triangle's winding in
// object space against the object-space ray: glTF's rule that a negative-determinant
// instance swaps the winding is then implicit (the rasterizer flips its front face
// per mirrored instance instead, draw.cpp).
SurfaceHit interpolate_hit(vec2 bary) {
    GeometryInfo g = pc.geometries.g[gl_InstanceCustomIndexEXT + gl_GeometryIndexEXT];
    IndexRef indices = IndexRef(g.indices);
    const uint p = 3u * uint(gl_PrimitiveID);
    const uvec3 i = uvec3(indices.v[p], indices.v[p + 1u], indices.v[p + 2u]);
    const vec3 w = vec3(1.0 - bary.x - bary.y, bary.x, bary.y);
    SurfaceHit h;
    h.material = g.material;
    h.flags = g.flags;
    Vec3Ref pos = Vec3Ref(g.stream[0]);
    const vec3 p0 = pos.v[i.x], p1 = pos.v[i.y], p2 = pos.v[i.z];
    const vec3 face = cross(p1 - p0, p2 - p0);
    h.front = dot(face, gl_ObjectRayDirectionEXT) < 0.0;
    h.position = gl_ObjectToWorldEXT * vec4(w.x * p0 + w.y * p1 + w.z * p2, 1.0);
    h.geometric = vec4(face * gl_WorldToObjectEXT).xyz;
    vec3 n = vec3(0.0, 0.0, 1.0);
    if ((g.flags & HAS_NORMAL) != 0u) {
        Vec3Ref s = Vec3Ref(g.stream[1]);
        n = w.x * s.v[i.x] + w.y * s.v[i.y] + w.z * s.v[i.z];
    }
    // Normals by the inverse transpose: n * W = transpose(W) n, W = world-to-object.
    h.normal = vec4(n * gl_WorldToObjectEXT).xyz;
    vec4 t = vec4(1.0, 0.0, 0.0, 1.0);
    if ((g.flags & HAS_TANGENT) != 0u) {
        Vec4Ref s = Vec4Ref(g.stream[2]);
        t = w.x * s.v[i.x] + w.y * s.v[i.y] + w.z * s.v[i.z];
    }
    // Tangents are directions on the surface: they transform with the model matrix.
    h.tangent = vec4(mat3(gl_ObjectToWorldEXT) * t.xyz, t.w);
    h.uv0 = vec2(0.0);
    if ((g.flags & HAS_UV0) != 0u) {
        Vec2Ref s = Vec2Ref(g.stream[3]);
        h.uv0 = w.x * s.v[i.x] + w.y * s.v[i.y] + w.z * s.v[i.z];
    }
    h.uv1 = vec2(0.0);
    if ((g.flags & HAS_UV1) != 0u) {
        Vec2Ref s = Vec2Ref(g.stream[4]);
        h.uv1 = w.x * s.v[i.x] + w.y * s.v[i.y] + w.z * s.v[i.z];
    }
    h.color = vec4(1.0);
    if ((g.flags & HAS_COLOR) != 0u) {
        Vec4Ref s = Vec4Ref(g.stream[5]);
        h.color = w.x * s.v[i.x] + w.y * s.v[i.y] + w.z * s.v[i.z];
    }
    return h;
}
#endif
#endif
