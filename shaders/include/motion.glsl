// Skinning and morphing in the vertex stage, through vertex pulling. Only pipelines
// built with MOTION (for meshes with MESH_MOTION) run any of it: a static mesh's
// pipeline folds the constant and carries no motion code or loads.
//
// The pose buffer (pc.pose, written per frame by the PosePass) is one vec4 array:
// joint matrices (world(joint) x inverseBind, 4 vec4 each) from index 0, then
// floats (4 per vec4): each instance's morph weights from inst.weight_base, and per
// joint matrix its joint-influence highlight (1 for FrameRequest::selected_joint)
// from pc.highlight_base.
#ifndef SHERPA_MOTION_GLSL
#define SHERPA_MOTION_GLSL

layout(constant_id = 1) const bool MOTION = false;

// An instance drawn without a skin (its node has none) holds this joint_base.
const uint NO_JOINTS = 0xffffffffu;

float pose_float(uint f) { return pc.pose.v[f >> 2][f & 3u]; }

mat4 joint_matrix(uint j) {
    uint at = 4u * j;
    return mat4(pc.pose.v[at], pc.pose.v[at + 1u], pc.pose.v[at + 2u], pc.pose.v[at + 3u]);
}

// World position, normal (not normalised) and tangent of vertex i, and the weight of
// the highlighted joint in it. `frame`: deform normals and tangents too (the depth
// passes need positions only; the position math is the same either way).
struct Deformed {
    vec3 position;
    vec3 normal;
    vec4 tangent;
    float highlight;
};

Deformed deform(uint i, GPUInstanceData inst, bool frame) {
    Deformed d;
    vec3 p = pc.positions.v[i];
    vec3 n = frame ? fetch_normal(i) : vec3(0.0, 0.0, 1.0);
    vec4 t = frame ? fetch_tangent(i) : vec4(1.0, 0.0, 0.0, 1.0);
    d.highlight = 0.0;
    bool skinned = false;
    mat4 skin = mat4(0.0);
    if (MOTION) {
        GPUMotionMesh m = pc.motion.m;
        uint flags = m.flags;
        uint vc = m.vertex_count;
        // Morph targets first, in the mesh's space (glTF: morph, then skin).
        for (uint k = 0u; k < m.target_count; ++k) {
            float w = pose_float(inst.weight_base + k);
            if (w == 0.0) continue;
            uint at = k * vc + i;
            if ((flags & MOTION_MORPH_POSITIONS) != 0u) p += w * m.morph_positions.v[at];
            if (frame && (flags & MOTION_MORPH_NORMALS) != 0u) n += w * m.morph_normals.v[at];
            if (frame && (flags & MOTION_MORPH_TANGENTS) != 0u) t.xyz += w * m.morph_tangents.v[at];
        }
        skinned = (flags & MOTION_SKIN) != 0u && inst.joint_base != NO_JOINTS;
        if (skinned) {
            uint sets = m.influence_sets;
            for (uint s = 0u; s < sets; ++s) {
                uvec2 packed = m.joints.v[i * sets + s];
                vec4 w = m.weights.v[i * sets + s];
                uvec4 j = inst.joint_base +
                          uvec4(packed.x & 0xffffu, packed.x >> 16, packed.y & 0xffffu, packed.y >> 16);
                skin += w.x * joint_matrix(j.x) + w.y * joint_matrix(j.y) +
                        w.z * joint_matrix(j.z) + w.w * joint_matrix(j.w);
                if (frame)
                    d.highlight += w.x * pose_float(pc.highlight_base + j.x) +
                               w.y * pose_float(pc.highlight_base + j.y) +
                               w.z * pose_float(pc.highlight_base + j.z) +
                               w.w * pose_float(pc.highlight_base + j.w);
            }
        }
    }
    if (skinned) {
        // The skinned mesh's node transform does not apply (glTF); normals and
        // tangents go through the blended matrix, as three.js's skinning does.
        d.position = (skin * vec4(p, 1.0)).xyz;
        mat3 s3 = mat3(skin);
        d.normal = s3 * n;
        d.tangent = vec4(s3 * t.xyz, t.w);
    } else {
        d.position = (inst.model * vec4(p, 1.0)).xyz;
        d.normal = normal_matrix(inst) * n;
        // Tangents are directions on the surface: they transform with the model matrix.
        d.tangent = vec4(mat3(inst.model) * t.xyz, t.w);
    }
    return d;
}
#endif
