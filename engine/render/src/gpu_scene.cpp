#include "instance_data.h"
#include "motion_streams.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/material_extensions.h>
#include <sherpa/scene/usage_report.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <tuple>

namespace sherpa::render {

namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                        VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_DST_BIT;

std::uint32_t provenance_bits(scene::Provenance p) {
    switch (p) {
    case scene::Provenance::Authored:
        return 0;
    case scene::Provenance::Generated:
        return 1;
    case scene::Provenance::Defaulted:
        return 2;
    }
    return 2;
}

// One attribute of the interleaved CPU vertex as a tightly packed stream.
void append_stream(std::vector<std::uint8_t>& out, const scene::Mesh& mesh,
                   scene::VertexAttribute a) {
    const std::size_t at = out.size();
    const std::uint32_t stride = stream_stride(a);
    out.resize(at + std::size_t(stride) * mesh.vertices.size());
    std::uint8_t* dst = out.data() + at;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i, dst += stride) {
        const scene::Vertex& v = mesh.vertices[i];
        const void* src = nullptr;
        switch (a) {
        case scene::VertexAttribute::Position:
            src = &v.position;
            break;
        case scene::VertexAttribute::Normal:
            src = &v.normal;
            break;
        case scene::VertexAttribute::Tangent:
            src = &v.tangent;
            break;
        case scene::VertexAttribute::TexCoord0:
            src = &v.uv0;
            break;
        case scene::VertexAttribute::TexCoord1:
            src = &v.uv1;
            break;
        case scene::VertexAttribute::Color0:
            src = &mesh.colors[i];
            break;
        }
        std::memcpy(dst, src, stride);
    }
}

} // namespace

GpuScene::GpuScene(gpu::ResourceManager& resources, gpu::BindlessTable& table,
                   const scene::Scene& scene,
                   std::shared_ptr<const tex::PreparedTextureSet> textures, StreamPolicy policy,
                   MissingTextures missing)
    : resources_(resources), table_(table), policy_(policy) {
    upload(scene, std::move(textures), missing);
}

GpuScene::GpuScene(gpu::ResourceManager& resources, gpu::BindlessTable& table,
                   const scene::Scene& scene, const TextureSettings& texture_settings,
                   StreamPolicy policy, MissingTextures missing)
    : resources_(resources), table_(table), policy_(policy) {
    auto prepared = std::const_pointer_cast<tex::PreparedTextureSet>(tex::prepare_scene_textures(
        scene, texture_target(resources.context().info(), texture_settings),
        texture_pipeline_options(texture_settings)));
    upload(scene, prepared, missing);
    // Nobody else holds this set: the levels are on the GPU now, keep the records only.
    for (tex::PreparedTexture& t : prepared->textures) decltype(t.levels)().swap(t.levels);
}

void GpuScene::upload(const scene::Scene& scene,
                      std::shared_ptr<const tex::PreparedTextureSet> textures,
                      MissingTextures missing) {
    try {
        materials_ =
            std::make_unique<GpuMaterials>(resources_, table_, scene, std::move(textures), missing);
        memory_.textures = materials_->textures().gpu_bytes();
        memory_.materials = materials_->bytes();
        memory_.material_extensions = materials_->extensions().bytes();
        upload_geometry(scene);
        upload_instances(scene);
    } catch (...) {
        release();
        throw;
    }
}

GpuScene::~GpuScene() {
    release();
}

void GpuScene::release() {
    for (gpu::BufferHandle* b :
         {&vertices_, &indices_, &instances_, &motion_streams_, &motion_meshes_})
        resources_.destroy(*b);
}

GpuMaterials::GpuMaterials(gpu::ResourceManager& resources, gpu::BindlessTable& table,
                           const scene::Scene& scene,
                           std::shared_ptr<const tex::PreparedTextureSet> textures,
                           MissingTextures missing)
    : resources_(resources), textures_(std::make_unique<SceneTextures>(
                                 resources, table, scene, std::move(textures), missing)) {
    try {
        upload(scene);
    } catch (...) {
        resources_.destroy(materials_);
        resources_.destroy(extras_);
        throw;
    }
}

void GpuScene::upload_geometry(const scene::Scene& scene) {
    std::vector<bool> instanced(scene.meshes.size(), false);
    for (const scene::MeshInstance& inst : scene.instances)
        if (inst.mesh_id < scene.meshes.size()) instanced[inst.mesh_id] = true;

    std::vector<std::uint8_t> streams;
    std::vector<std::uint32_t> indices;
    std::vector<std::array<VkDeviceSize, scene::kVertexAttributeCount>> offsets(
        scene.meshes.size());
    meshes_.resize(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const scene::Mesh& mesh = scene.meshes[m];
        GpuMesh& g = meshes_[m];
        g.material = mesh.material_id;
        g.flags = provenance_bits(mesh.provenance_of(scene::VertexAttribute::Tangent))
                      << kTangentProvenanceShift |
                  provenance_bits(mesh.provenance_of(scene::VertexAttribute::Normal))
                      << kNormalProvenanceShift;
        if (mesh.topology() == scene::Topology::Lines) g.flags |= kMeshLinesBit;
        if (mesh.topology() == scene::Topology::Points) g.flags |= kMeshPointsBit;
        if (!instanced[m] || mesh.vertices.empty() || mesh.indices.empty()) continue;
        if (mesh.material_id >= scene.materials.size())
            throw gpu::GpuError("mesh " + std::to_string(m) + " names material " +
                                std::to_string(mesh.material_id) + " of " +
                                std::to_string(scene.materials.size()));

        // What shading reads; debug views add every authored or generated stream.
        std::array<bool, scene::kVertexAttributeCount> upload =
            scene::mesh_attributes_used(scene, static_cast<std::uint32_t>(m));
        if (policy_ == StreamPolicy::AllPresent)
            for (scene::VertexAttribute a : scene::kAllVertexAttributes)
                if (mesh.provenance_of(a) != scene::Provenance::Defaulted)
                    upload[std::size_t(a)] = true;
        upload[std::size_t(scene::VertexAttribute::Position)] = true; // every pass reads positions
        if (mesh.colors.size() != mesh.vertices.size())
            upload[std::size_t(scene::VertexAttribute::Color0)] = false;

        for (scene::VertexAttribute a : scene::kAllVertexAttributes) {
            const std::size_t ai = std::size_t(a);
            offsets[m][ai] = ~VkDeviceSize(0);
            if (!upload[ai]) continue;
            streams.resize((streams.size() + 15) & ~std::size_t(15)); // 16-byte aligned streams
            offsets[m][ai] = streams.size();
            append_stream(streams, mesh, a);
            g.flags |= 1u << ai;
        }
        g.first_index = static_cast<std::uint32_t>(indices.size());
        g.index_count = static_cast<std::uint32_t>(mesh.indices.size());
        g.vertex_count = static_cast<std::uint32_t>(mesh.vertices.size());
        for (std::uint32_t i : mesh.indices)
            if (i >= mesh.vertices.size())
                throw gpu::GpuError("mesh " + std::to_string(m) + " has index " +
                                    std::to_string(i) + " past its " +
                                    std::to_string(mesh.vertices.size()) + " vertices");
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
        memory_.unified_vertex_bytes +=
            std::uint64_t(sizeof(scene::Vertex)) * mesh.vertices.size() +
            (mesh.colors.empty() ? 0 : 16ull * mesh.colors.size());
    }

    // Ray tracing builds from positions and indices and reads every stream in hit
    // shaders by device address; without it the buffers carry none of that usage.
    const bool rt = resources_.context().info().ray_tracing_enabled;
    const VkBufferUsageFlags as_input =
        rt ? VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR : 0;
    const VkBufferUsageFlags vertex_usage = kStorage | as_input;
    const VkBufferUsageFlags index_usage = VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
                                           VK_BUFFER_USAGE_TRANSFER_DST_BIT | as_input |
                                           (rt ? VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT : 0);
    gpu::UploadBatch batch(resources_);
    if (!streams.empty()) {
        vertices_ = resources_.create_buffer(
            {streams.size(), vertex_usage, gpu::MemoryUsage::DeviceLocal, "vertex streams"});
        memory_.geometry_usage |= vertex_usage;
        batch.upload_buffer(vertices_, 0, streams.data(), streams.size());
        const VkDeviceAddress base = resources_.get(vertices_).address;
        for (std::size_t m = 0; m < meshes_.size(); ++m)
            for (std::size_t a = 0; a < scene::kVertexAttributeCount; ++a)
                if (meshes_[m].flags & (1u << a)) meshes_[m].stream[a] = base + offsets[m][a];
    }
    if (!indices.empty()) {
        const VkDeviceSize bytes = indices.size() * sizeof(std::uint32_t);
        indices_ = resources_.create_buffer(
            {bytes, index_usage, gpu::MemoryUsage::DeviceLocal, "indices"});
        memory_.geometry_usage |= index_usage;
        batch.upload_buffer(indices_, 0, indices.data(), bytes);
    }
    upload_motion(scene, instanced, batch);
    batch.submit_and_wait();
    memory_.vertex_streams = streams.size();
    memory_.indices = indices.size() * sizeof(std::uint32_t);
}

// Skinning and morph streams, only for the meshes that move: a static scene makes
// no buffer and reports 0 motion bytes.
void GpuScene::upload_motion(const scene::Scene& scene, const std::vector<bool>& instanced,
                             gpu::UploadBatch& batch) {
    MotionStreams motion = build_motion_streams(scene, instanced);
    if (motion.records.empty()) return;
    VkDeviceAddress base = 0;
    if (!motion.bytes.empty()) {
        motion_streams_ = resources_.create_buffer(
            {motion.bytes.size(), kStorage, gpu::MemoryUsage::DeviceLocal, "motion streams"});
        batch.upload_buffer(motion_streams_, 0, motion.bytes.data(), motion.bytes.size());
        base = resources_.get(motion_streams_).address;
    }
    for (GPUMotionMesh& r : motion.records) { // offsets of the streams present -> addresses
        const std::pair<VkDeviceAddress*, std::uint32_t> streams[] = {
            {&r.joints, kMotionSkin},
            {&r.weights, kMotionSkin},
            {&r.morph_positions, kMotionMorphPositions},
            {&r.morph_normals, kMotionMorphNormals},
            {&r.morph_tangents, kMotionMorphTangents}};
        for (auto [address, bit] : streams)
            if (r.flags & bit) *address += base;
    }
    const VkDeviceSize bytes = motion.records.size() * sizeof(GPUMotionMesh);
    motion_meshes_ =
        resources_.create_buffer({bytes, kStorage, gpu::MemoryUsage::DeviceLocal, "motion meshes"});
    batch.upload_buffer(motion_meshes_, 0, motion.records.data(), bytes);
    const VkDeviceAddress records = resources_.get(motion_meshes_).address;
    for (std::size_t m = 0; m < meshes_.size(); ++m)
        if (const std::int32_t r = motion.record_of_mesh[m]; r >= 0) {
            meshes_[m].motion = records + VkDeviceSize(r) * sizeof(GPUMotionMesh);
            meshes_[m].flags |= kMeshMotionBit;
        }
    memory_.motion = motion.bytes.size() + bytes;
}

std::uint64_t update_scene_materials(GpuScene& scene,
                                     std::span<const scene::MaterialInstance> materials) {
    return scene.materials_->update(materials);
}

void GpuScene::upload_instances(const scene::Scene& scene) {
    for (const scene::MaterialInstance& m : scene.materials)
        material_modes_.emplace_back(m.alpha_mode, m.double_sided);
    struct Keyed {
        std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, bool, bool>
            key; // mesh, alpha, material, ds, mirror
        std::uint32_t instance;
    };
    std::vector<Keyed> order;
    for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::MeshInstance& inst = scene.instances[i];
        if (inst.mesh_id >= meshes_.size() || meshes_[inst.mesh_id].index_count == 0) continue;
        const std::uint32_t material = scene.meshes[inst.mesh_id].material_id;
        const scene::MaterialInstance& m = scene.materials[material];
        const bool mirrored = glm::determinant(glm::mat3(inst.world)) < 0.0f;
        order.push_back(
            {{inst.mesh_id, std::uint32_t(m.alpha_mode), material, m.double_sided, mirrored}, i});
    }
    std::stable_sort(order.begin(), order.end(),
                     [](const Keyed& a, const Keyed& b) { return a.key < b.key; });

    std::vector<GPUInstanceData> data;
    for (const Keyed& k : order) {
        const scene::MeshInstance& inst = scene.instances[k.instance];
        const GPUInstanceData g = make_instance_data(inst.world, std::get<2>(k.key), inst.mesh_id);
        if (groups_.empty() ||
            std::make_tuple(groups_.back().mesh, std::uint32_t(groups_.back().alpha),
                            groups_.back().material, groups_.back().double_sided,
                            groups_.back().mirrored) != k.key) {
            DrawGroup grp;
            grp.mesh = inst.mesh_id;
            grp.alpha = scene::AlphaMode(std::get<1>(k.key));
            grp.material = std::get<2>(k.key);
            grp.double_sided = std::get<3>(k.key);
            grp.mirrored = std::get<4>(k.key);
            grp.first_instance = static_cast<std::uint32_t>(data.size());
            groups_.push_back(grp);
        }
        ++groups_.back().instance_count;
        data.push_back(g);
        instance_bounds_.push_back(inst.world_bounds);
        scene_instances_.push_back(k.instance);
        bounds_.expand(inst.world_bounds);
        triangles_ += meshes_[inst.mesh_id].index_count / 3;
    }
    if (data.empty()) data.push_back(GPUInstanceData{}); // valid address even for empty scenes
    const VkDeviceSize bytes = data.size() * sizeof(GPUInstanceData);
    instances_ =
        resources_.create_buffer({bytes, kStorage, gpu::MemoryUsage::DeviceLocal, "instances"});
    gpu::UploadBatch batch(resources_);
    batch.upload_buffer(instances_, 0, data.data(), bytes);
    batch.submit_and_wait();
    memory_.instances = bytes;
}

MaterialSwitch
switch_mesh_materials(GpuScene& scene,
                      std::span<const std::pair<std::uint32_t, std::uint32_t>> meshes) {
    MaterialSwitch out;
    std::vector<std::uint32_t> material_of(scene.meshes_.size(), ~0u); // ~0: unchanged
    for (auto [mesh, material] : meshes) {
        if (mesh >= scene.meshes_.size() || material >= scene.material_modes_.size())
            throw gpu::GpuError("material switch: mesh " + std::to_string(mesh) + " or material " +
                                std::to_string(material) + " out of range");
        if (scene.meshes_[mesh].material == material) continue;
        scene.meshes_[mesh].material = material;
        material_of[mesh] = material;
        ++out.meshes;
    }
    if (out.meshes == 0) return out;
    constexpr VkDeviceSize kWord = offsetof(GPUInstanceData, material);
    gpu::UploadBatch batch(scene.resources_);
    for (DrawGroup& g : scene.groups_) {
        const std::uint32_t material = material_of[g.mesh];
        if (material == ~0u || g.material == material) continue;
        const auto [alpha, double_sided] = scene.material_modes_[material];
        out.modes_changed |= alpha != g.alpha || double_sided != g.double_sided;
        g.material = material;
        g.alpha = alpha;
        g.double_sided = double_sided;
        ++out.groups;
        for (std::uint32_t k = 0; k < g.instance_count; ++k) {
            const VkDeviceSize at = VkDeviceSize(g.first_instance + k) * sizeof(GPUInstanceData);
            batch.upload_buffer(scene.instances_, at + kWord, &material, sizeof material);
            out.gpu_bytes += sizeof material;
        }
        out.instances += g.instance_count;
    }
    batch.submit_and_wait();
    return out;
}

} // namespace sherpa::render
