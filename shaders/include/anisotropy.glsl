// KHR_materials_anisotropy: the base's GGX specular stretched along a direction in the
// tangent plane, shared by the rasterizer (forward.frag) and the path tracer (pt.rchit).
// As the extension's specification: the strength is anisotropyStrength x
// anisotropyTexture.b, the direction anisotropyTexture.rg (2 rg - 1, normalized; +x of
// the tangent frame without a texture) rotated counter-clockwise by anisotropyRotation;
// alpha along the direction is mix(alpha, 1, strength^2), across it alpha. brdf.glsl
// evaluates that GGX wherever Surface::anisotropy.w > 0 (brdf_times_cos, the
// environment's bent-normal lookup in specular_direction), bsdf_sampling.glsl draws it
// by its visible normals.
//
// Stable functions (with material_ext.glsl included first):
//   GPUAnisotropyBlock anisotropy_block(uint word)
//   vec3 material_anisotropy_tangent(GPUExtensionIndex e, uv0, uv1)
//        xy the direction in the tangent frame, z the strength ((1, 0, 0) without it)
//   vec4 material_anisotropy(GPUExtensionIndex e, t, b, n, uv0, uv1)
//        xyz the direction in the world, perpendicular to the shading normal n; w the
//        strength (0 without the extension: isotropic); for Surface::anisotropy
#ifndef SHERPA_ANISOTROPY_GLSL
#define SHERPA_ANISOTROPY_GLSL

#ifdef SHERPA_MATERIAL_EXT_GLSL
GPUAnisotropyBlock anisotropy_block(uint word) {
    uvec4 t = material_ext[word + 1u];
    return GPUAnisotropyBlock(uintBitsToFloat(material_ext[word]), t.x, t.y, t.z, t.w, transform_words(word + 2u));
}

vec3 material_anisotropy_tangent(GPUExtensionIndex e, vec2 uv0, vec2 uv1) {
    if (e.anisotropy == NO_EXTENSION) return vec3(1.0, 0.0, 0.0);
    GPUAnisotropyBlock k = anisotropy_block(e.anisotropy);
    vec2 direction = vec2(1.0, 0.0);
    float strength = k.factors.x;
    if (k.texture != TEX_WHITE) {
        vec3 texel = sample_transformed(k.uv, k.texture, uv0, uv1).rgb;
        vec2 d = texel.rg * 2.0 - 1.0;
        // A texel of no direction (rg = 0.5) keeps the tangent's.
        if (dot(d, d) > 1e-8) direction = normalize(d);
        strength *= texel.b;
    }
    // Counter-clockwise by the rotation: (cos, sin) stored in factors.yz.
    mat2 rotation = mat2(k.factors.y, k.factors.z, -k.factors.z, k.factors.y);
    return vec3(rotation * direction, strength);
}

vec4 material_anisotropy(GPUExtensionIndex e, vec3 t, vec3 b, vec3 n, vec2 uv0, vec2 uv1) {
    if (e.anisotropy == NO_EXTENSION) return vec4(0.0);
    vec3 a = material_anisotropy_tangent(e, uv0, uv1);
    vec3 d = a.x * t + a.y * b;
    d -= n * dot(n, d);
    // A direction along the normal (a normal map bent 90 degrees) has no tangent part:
    // isotropic there.
    if (dot(d, d) < 1e-12) return vec4(0.0);
    return vec4(normalize(d), a.z);
}
#endif

#endif
