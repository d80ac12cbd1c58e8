#version 460
// GPU-driven culling (vkguide's design): one invocation per pass object tests the
// object's world AABB against the frustum with the same method as the CPU path,
// and appends visible objects to their batch: atomically bumping the batch's
// indirect instanceCount (once per subgroup where the subgroup's objects share a
// batch, once per object otherwise) and writing the object's GPU instance index
// into the compacted instance-id array at firstInstance + slot. The indirect
// commands were reset from a clear copy before this dispatch.
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_vote : require

#include "cull_structs.glsl"

// 256 invocations a workgroup: lavapipe runs each workgroup as one call of the
// compiled shader, so fewer, larger workgroups spend less on dispatch.
layout(local_size_x = 256) in;

// Uniform for the whole dispatch: a CPU device (lavapipe) loads it once instead of
// gathering it per lane, as it does for device-address reads.
layout(set = 0, binding = 0, scalar) uniform CullParamsBlock { CullParams P; };

layout(push_constant, scalar) uniform CullPush {
    CullObjectRef objects;
    DrawCommandRef draws;
    UintRef instance_ids;
    UintRef visible;
} pc;

// Straight-line tests (no early exit): on a SIMD CPU every lane runs every plane
// anyway, and a GPU loses nothing over six planes.
bool visible_box(vec3 bmin, vec3 bmax) {
    if (P.empty != 0u) return false;
    bool outside = false;
    if (P.method == CULL_SPHERE) {
        const vec3 c = 0.5 * (bmin + bmax);
        const float r = 0.5 * length(bmax - bmin);
        for (uint i = 0u; i < P.plane_count; ++i)
            outside = outside || dot(P.planes[i].xyz, c) + P.planes[i].w < -r;
        return !outside;
    }
    // The same arithmetic as the CPU path (p- and n-vertex per plane), so the two agree
    // bit for bit.
    bool wholly_inside = true;
    for (uint i = 0u; i < P.plane_count; ++i) {
        const vec4 p = P.planes[i];
        const bvec3 positive = greaterThanEqual(p.xyz, vec3(0.0));
        outside = outside || dot(p.xyz, mix(bmin, bmax, positive)) + p.w < 0.0;
        wholly_inside = wholly_inside && dot(p.xyz, mix(bmax, bmin, positive)) + p.w >= 0.0;
    }
    if (outside) return false;
    if (P.method == CULL_PVERTEX || wholly_inside) return true;
    // Exact: the remaining separating axes, frustum intervals precomputed on the CPU.
    const vec3 c = 0.5 * (bmin + bmax), e = 0.5 * (bmax - bmin);
    for (uint k = 0u; k < P.sat_count; ++k) {
        const vec3 axis = P.sat_axis[k].xyz;
        const float r = dot(abs(axis), e), m = dot(c, axis);
        outside = outside || m + r < P.sat_range[k].x || m - r > P.sat_range[k].y;
    }
    return !outside;
}

void main() {
    const uint i = gl_GlobalInvocationID.x;
    const bool in_range = i < P.object_count;
    CullObject o = CullObject(vec3(0.0), 0u, vec3(0.0), 0u); // lanes past the end read nothing
    if (in_range) o = pc.objects.v[i];
    const bool invalid = in_range && (o.batch & CULL_INVALID_BIT) != 0u; // kept, as on the CPU
    const bool keep = in_range && (invalid || visible_box(o.bmin, o.bmax));
    if (in_range) pc.visible.v[i] = keep ? 1u : 0u;
    const uint batch = o.batch & ~CULL_INVALID_BIT;
    // Objects of a batch are contiguous, so a subgroup usually feeds one batch: then
    // one atomic per subgroup reserves all its slots, in object order.
    const uint first_batch = subgroupBroadcastFirst(in_range ? batch : ~0u);
    if (subgroupAll(!in_range || batch == first_batch)) {
        const uvec4 ballot = subgroupBallot(keep);
        const uint count = subgroupBallotBitCount(ballot);
        if (count == 0u) return;
        uint base = 0u;
        if (subgroupElect()) base = atomicAdd(pc.draws.v[first_batch].instance_count, count);
        base = subgroupBroadcastFirst(base);
        if (keep)
            pc.instance_ids.v[pc.draws.v[batch].first_instance + base +
                              subgroupBallotExclusiveBitCount(ballot)] = o.instance;
        return;
    }
    if (!keep) return;
    const uint slot = atomicAdd(pc.draws.v[batch].instance_count, 1u);
    pc.instance_ids.v[pc.draws.v[batch].first_instance + slot] = o.instance;
}
