// Vertex streams by buffer device address: the rasterizer's push constants
// (common.glsl) and the ray tracer's geometry records (rt_hit.glsl) read the same arrays.
#ifndef SHERPA_STREAM_REFS_GLSL
#define SHERPA_STREAM_REFS_GLSL
layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer Vec2Ref { vec2 v[]; };
layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer Vec3Ref { vec3 v[]; };
layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer Vec4Ref { vec4 v[]; };
layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer IndexRef { uint v[]; };
#endif
