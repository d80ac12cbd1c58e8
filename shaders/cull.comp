#version 460
// GPU-driven culling (vkguide's design): one invocation per pass object tests the
// object's world AABB against the frustum with the same method as the CPU path,
// and appends visible objects to their batch: atomically bumping the batch's
// indirect instanceCount and writing the object's GPU instance index into the
// compacted instance-id array at firstInstance + slot. The indirect commands were
// reset from a clear copy before this dispatch.
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "cull_structs.glsl"

layout(local_size_x = 64) in;

layout(push_constant, scalar) uniform CullPush {
    CullParamsRef params;
    CullObjectRef objects;
    DrawCommandRef draws;
    UintRef instance_ids;
    UintRef visible;
} pc;

bool outside_plane(vec4 p, vec3 bmin, vec3 bmax, out bool n_inside) {
    const vec3 pv = mix(bmin, bmax, greaterThanEqual(p.xyz, vec3(0.0)));
    const vec3 nv = mix(bmax, bmin, greaterThanEqual(p.xyz, vec3(0.0)));
    n_inside = dot(p.xyz, nv) + p.w >= 0.0;
    return dot(p.xyz, pv) + p.w < 0.0;
}

bool visible_box(vec3 bmin, vec3 bmax) {
    const CullParams P = pc.params.p;
    if (P.empty != 0u) return false;
    if (P.method == CULL_SPHERE) {
        const vec3 c = 0.5 * (bmin + bmax);
        const float r = 0.5 * length(bmax - bmin);
        for (uint i = 0u; i < P.plane_count; ++i)
            if (dot(P.planes[i].xyz, c) + P.planes[i].w < -r) return false;
        return true;
    }
    bool wholly_inside = true;
    for (uint i = 0u; i < P.plane_count; ++i) {
        bool n_inside;
        if (outside_plane(P.planes[i], bmin, bmax, n_inside)) return false;
        wholly_inside = wholly_inside && n_inside;
    }
    if (P.method == CULL_PVERTEX || wholly_inside) return true;
    // Exact: the remaining separating axes, frustum intervals precomputed on the CPU.
    const vec3 c = 0.5 * (bmin + bmax), e = 0.5 * (bmax - bmin);
    for (uint k = 0u; k < P.sat_count; ++k) {
        const vec3 axis = P.sat_axis[k].xyz;
        const float r = dot(abs(axis), e), m = dot(c, axis);
        if (m + r < P.sat_range[k].x || m - r > P.sat_range[k].y) return false;
    }
    return true;
}

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= pc.params.p.object_count) return;
    const CullObject o = pc.objects.v[i];
    const bool invalid = (o.batch & CULL_INVALID_BIT) != 0u; // kept, as on the CPU
    const bool keep = invalid || visible_box(o.bmin, o.bmax);
    pc.visible.v[i] = keep ? 1u : 0u;
    if (!keep) return;
    const uint batch = o.batch & ~CULL_INVALID_BIT;
    const uint slot = atomicAdd(pc.draws.v[batch].instance_count, 1u);
    pc.instance_ids.v[pc.draws.v[batch].first_instance + slot] = o.instance;
}
