// The material extension buffer in the path tracer's hit shaders (pt.rchit, pt.rahit):
// set 1 binding 9 of its set (PathTracePass; partially bound, nothing there without
// extensions), textures read at the rays' explicit level, then material_ext.glsl and
// transmission.glsl as the raster reads them. Needs rt_hit.glsl.
#ifndef SHERPA_PT_MATERIAL_EXT_GLSL
#define SHERPA_PT_MATERIAL_EXT_GLSL
#define SHERPA_MATERIAL_EXT_DECLARED
layout(set = 1, binding = 9, std430) readonly buffer MaterialExtensionBlock {
    uvec4 material_ext[];
};

#include "sherpa_default_textures.glsl"
#include "material_ext.glsl"
#include "transmission.glsl"
#endif
