// Posing for the GPU: what the vertex stage of moving meshes reads (motion.glsl) and
// the bounds culling uses while things move. Written per frame into the frame slot's
// host-visible pose buffer, laid out as the shaders read it:
//   [GPUInstanceData x instances][mat4 x joints][float x (weights + joints)]
// push constants: instances -> the first part, pose -> the joint matrices, whose
// vec4 array continues with the floats (inst.weight_base, highlight_base index them).
#include "instance_data.h"
#include "passes.h"
#include "skeleton_lines.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sherpa::render {

namespace {

constexpr std::uint32_t kNoJoints = 0xffffffffu; // NO_JOINTS in motion.glsl

GPUInstanceData instance_data(const glm::mat4& world, std::uint32_t material, std::uint32_t mesh) {
    GPUInstanceData g = make_instance_data(world, material, mesh);
    g.joint_base = kNoJoints;
    return g;
}

// FNV-1a over bytes: the shadow cache's key of the pose drawn.
std::uint64_t fnv(std::uint64_t h, const void* data, std::size_t bytes) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

} // namespace

void PosePass::reset() {
    active_ = false;
    scene_ = scene::Scene{};
    default_ = scene::Pose{};
    instances_.clear();
    skin_base_.clear();
    skin_slots_.clear();
    joints_ = weights_ = 0;
}

void PosePass::build(const scene::Scene& scene, const GpuScene& gpu) {
    reset();
    active_ = !scene.motions.empty() || !scene.animations.empty();
    if (!active_ && scene.skins.empty()) return;
    scene_.nodes = scene.nodes;
    scene_.skins = scene.skins;
    if (!active_) { // a skeleton that moves nothing: the overlay draws it as loaded
        default_ = scene::evaluate_pose(scene_, -1, 0.0);
        return;
    }
    ++generation_;
    scene_.primitives = scene.primitives;
    // culling_bounds() reads the per-joint boxes and the target count, not the
    // per-vertex arrays (the largest of the scene, already uploaded): no copy of those.
    scene_.motions.reserve(scene.motions.size());
    for (const scene::PrimitiveMotion& m : scene.motions) {
        scene::PrimitiveMotion& c = scene_.motions.emplace_back();
        c.mesh = m.mesh;
        c.primitive = m.primitive;
        c.influences = m.influences;
        c.max_joint = m.max_joint;
        c.targets.resize(m.targets.size());
        c.target_attributes = m.target_attributes;
        c.boxes = m.boxes;
    }
    default_ = scene::evaluate_pose(scene_, -1, 0.0);
    std::vector<std::int32_t> primitive_of_mesh(scene.meshes.size(), -1);
    for (std::size_t p = 0; p < scene.primitives.size(); ++p)
        if (scene.primitives[p].engine_mesh >= 0 && scene.primitives[p].motion >= 0)
            primitive_of_mesh[static_cast<std::size_t>(scene.primitives[p].engine_mesh)] =
                static_cast<std::int32_t>(p);
    // Matrices per skin: its joints, or more where a primitive weights a joint index
    // past them (never read as garbage).
    skin_slots_.assign(scene.skins.size(), 0);
    for (std::size_t s = 0; s < scene.skins.size(); ++s)
        skin_slots_[s] = static_cast<std::uint32_t>(scene.skins[s].joints.size());
    instances_.resize(gpu.scene_instances().size());
    for (const DrawGroup& g : gpu.groups())
        for (std::uint32_t k = 0; k < g.instance_count; ++k) {
            const std::uint32_t i = g.first_instance + k;
            const scene::MeshInstance& mi = scene.instances[gpu.scene_instances()[i]];
            Instance& out = instances_[i];
            out.node = mi.node_id;
            out.mesh = g.mesh;
            out.material = g.material;
            out.world = mi.world;
            out.row = scene::instance_transform(scene, mi);
            out.local = scene.meshes[g.mesh].local_bounds;
            out.bounds = gpu.instance_bounds()[i];
            out.primitive = primitive_of_mesh[g.mesh];
            if (out.primitive < 0) continue;
            const scene::PrimitiveMotion& m =
                scene.motions[static_cast<std::size_t>(scene.primitives[out.primitive].motion)];
            out.targets = static_cast<std::uint32_t>(m.targets.size());
            weights_ += out.targets;
            const std::int32_t skin = scene.nodes[out.node].skin;
            if (m.skinned() && skin >= 0) {
                out.skin = skin;
                auto& slots = skin_slots_[static_cast<std::size_t>(skin)];
                slots = std::max(slots, m.max_joint + 1);
            }
        }
    skin_base_.assign(scene.skins.size(), 0);
    for (std::size_t s = 0; s < skin_slots_.size(); ++s) {
        skin_base_[s] = joints_;
        joints_ += skin_slots_[s];
    }
}

const scene::Pose& PosePass::pose_of(const FrameRequest& settings) const {
    // A pose of another scene (node or skin counts differ) is not applied.
    const scene::Pose* p = settings.pose.get();
    const std::size_t nodes = scene_.nodes.size();
    if (p && p->world.size() == nodes && p->weights.size() == nodes &&
        p->joint_matrices.size() == scene_.skins.size())
        return *p;
    return default_;
}

void PosePass::append_skeleton_lines(std::vector<GPULineVertex>& out, const FrameRequest& settings,
                                     float joint_size) const {
    if (scene_.skins.empty()) return;
    append_skeleton(out, scene_.skins, scene_.nodes, pose_of(settings).world,
                    settings.selected_joint, joint_size);
}

void PosePass::record(FrameSlot& slot, const FrameRequest& settings, bool scene_loaded) {
    if (!active_ || !scene_loaded) {
        slot.posed = false;
        slot.pose_key = 0;
        slot.pose_generation = 0;
        return;
    }
    // The same pose as this slot's last frame (a paused timeline, the default pose):
    // its buffer, bounds and key stand.
    if (slot.pose_generation == generation_ && slot.pose_written == settings.pose &&
        slot.joint_written == settings.selected_joint)
        return;
    write(slot, settings, pose_of(settings));
    slot.pose_written = settings.pose;
    slot.joint_written = settings.selected_joint;
    slot.pose_generation = generation_;
}

void PosePass::write(FrameSlot& slot, const FrameRequest& settings, const scene::Pose& pose) {
    const std::size_t n = instances_.size();
    const VkDeviceSize instance_bytes = std::max<std::size_t>(n, 1) * sizeof(GPUInstanceData);
    const std::uint32_t floats = (weights_ + joints_ + 3) & ~3u;
    const VkDeviceSize bytes =
        instance_bytes + VkDeviceSize{joints_} * 64 + VkDeviceSize{floats} * 4 + 16;
    if (bytes > slot.pose_capacity) {
        resources_.destroy(slot.pose); // frames still reading it keep it: destruction is deferred
        slot.pose_capacity = bytes;
        slot.pose = resources_.create_buffer(
            {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
             gpu::MemoryUsage::Upload, "pose"});
    }
    const gpu::Buffer& buf = resources_.get(slot.pose);
    auto* base = static_cast<std::uint8_t*>(buf.mapped);
    auto* instances = reinterpret_cast<GPUInstanceData*>(base);
    auto* joints = reinterpret_cast<glm::mat4*>(base + instance_bytes);
    auto* values = reinterpret_cast<float*>(base + instance_bytes + VkDeviceSize{joints_} * 64);
    const std::uint32_t float_base = joints_ * 16; // float index of values[0] from `pose`
    const std::uint32_t highlight = weights_;      // values[highlight + j]: joint j selected

    std::uint64_t key = 0xcbf29ce484222325ull;
    for (std::size_t s = 0; s < skin_slots_.size(); ++s) {
        const auto& m = pose.joint_matrices[s];
        const auto& nodes = scene_.skins[s].joints;
        for (std::uint32_t j = 0; j < skin_slots_[s]; ++j) {
            const std::uint32_t at = skin_base_[s] + j;
            joints[at] = j < m.size() ? m[j] : glm::mat4(1.0f);
            values[highlight + at] =
                settings.selected_joint && j < nodes.size() && nodes[j] == *settings.selected_joint
                    ? 1.0f
                    : 0.0f;
        }
        key = fnv(key, m.data(), m.size() * sizeof(glm::mat4));
    }
    slot.posed_bounds.resize(n);
    std::uint32_t weight_at = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Instance& in = instances_[i];
        const glm::mat4 world = pose.world[in.node] * in.row;
        GPUInstanceData g = instance_data(world, in.material, in.mesh);
        key = fnv(key, &world, sizeof(world));
        if (in.primitive >= 0) {
            if (in.skin >= 0) g.joint_base = skin_base_[static_cast<std::size_t>(in.skin)];
            g.weight_base = float_base + weight_at;
            const auto& w = pose.weights[in.node];
            for (std::uint32_t k = 0; k < in.targets; ++k)
                values[weight_at + k] = k < w.size() && std::isfinite(w[k]) ? w[k] : 0.0f;
            key = fnv(key, w.data(), w.size() * sizeof(float));
            weight_at += in.targets;
            slot.posed_bounds[i] = scene::culling_bounds(
                scene_, pose, in.node, scene_.primitives[static_cast<std::size_t>(in.primitive)],
                in.row);
        } else {
            slot.posed_bounds[i] = world == in.world ? in.bounds : in.local.transformed(world);
        }
        instances[i] = g;
    }
    slot.posed = true;
    slot.pose_key = key;
    slot.posed_instances = buf.address;
    slot.pose_address = buf.address + instance_bytes;
    slot.highlight_base = float_base + highlight;
}

} // namespace sherpa::render
