// The glTF layering of the material extensions, in one place for the rasterizer
// (forward.frag) and the path tracer (pt.rchit, layered_bsdf.glsl): the sheen lies over
// the base (transmission and emission included), the clearcoat over both. `sheen` and
// `coat` are the light the two layers reflect themselves; where a layer is absent
// (sheen black, coat factor 0) it lets everything through and adds nothing.
#ifndef SHERPA_MATERIAL_LAYERS_GLSL
#define SHERPA_MATERIAL_LAYERS_GLSL
#include "clearcoat.glsl"
#include "sheen.glsl"

vec3 layers_over(Clearcoat c, Sheen s, vec3 n, vec3 v, vec3 base, vec3 sheen, vec3 coat) {
    return clearcoat_over(c, v, sheen_over(s, n, v, base, sheen), coat);
}
#endif
