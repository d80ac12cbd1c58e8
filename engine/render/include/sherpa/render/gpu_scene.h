#pragma once
// A Scene on the GPU: only the vertex streams the materials use (per the usage
// report) as separate tightly packed arrays read by vertex pulling through buffer
// device addresses, one index buffer and the instance array sorted into draw groups
// (GpuScene), and the materials with their textures (GpuMaterials).
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include <sherpa/core/aabb.h>
#include <sherpa/gpu/bindless.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/gpu/upload.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/material_extensions.h>
#include <sherpa/render/scene_textures.h>
#include <sherpa/scene/scene.h>

namespace sherpa::render {

struct GpuMemoryReport {
    std::uint64_t vertex_streams = 0, indices = 0, textures = 0, materials = 0, instances = 0;
    // Skinning and morph streams and their per-mesh records: 0 for static scenes.
    std::uint64_t motion = 0;
    // The material extension buffer (material_extensions.h): 0 where no material uses one.
    std::uint64_t material_extensions = 0;
    // The same vertices in the 56-byte unified layout (+16-byte colour stream where present).
    std::uint64_t unified_vertex_bytes = 0;
    // VkBufferUsageFlags of the vertex-stream and index buffers: acceleration-structure
    // build input (and device addresses of the indices) only where the device has ray
    // tracing enabled.
    std::uint32_t geometry_usage = 0;
    std::uint64_t total() const {
        return vertex_streams + indices + textures + materials + material_extensions + instances +
               motion;
    }
};

struct GpuMesh {
    std::array<VkDeviceAddress, scene::kVertexAttributeCount> stream{}; // 0 = not on the GPU
    std::uint32_t flags = 0;       // mesh_flags for shaders (streams, provenance)
    std::uint32_t first_index = 0; // into the shared index buffer
    std::uint32_t index_count = 0;
    std::uint32_t vertex_count = 0;
    std::uint32_t material = 0;
    VkDeviceAddress motion = 0; // its GPUMotionMesh when it skins or morphs (kMeshMotionBit)
};

// Instances of one mesh that share alpha mode, sidedness and winding: one
// instanced indexed draw.
struct DrawGroup {
    std::uint32_t mesh = 0;
    std::uint32_t material = 0;
    scene::AlphaMode alpha = scene::AlphaMode::Opaque;
    bool double_sided = false;
    bool mirrored = false; // negative determinant: front faces wind clockwise
    std::uint32_t first_instance = 0, instance_count = 0;
};

// The scene's materials: the GPUMaterialData array (one SSBO; texture fields
// resolved to bindless slots, sentinels to the default textures), its
// GPUMaterialExtra twin (KHR_texture_transform, TEXCOORD set, unlit) and the
// textures those slots name.
class GpuMaterials {
public:
    GpuMaterials(gpu::ResourceManager& resources, gpu::BindlessTable& table,
                 const scene::Scene& scene, std::shared_ptr<const tex::PreparedTextureSet> textures,
                 MissingTextures missing);
    ~GpuMaterials();
    GpuMaterials(const GpuMaterials&) = delete;
    GpuMaterials& operator=(const GpuMaterials&) = delete;

    VkBuffer buffer() const { return resources_.get(materials_).buffer.get(); }
    VkBuffer extras_buffer() const { return resources_.get(extras_).buffer.get(); }
    // The material extension buffer; VK_NULL_HANDLE where no material uses one.
    VkBuffer extensions_buffer() const {
        return extension_buffer_.valid() ? resources_.get(extension_buffer_).buffer.get()
                                         : VK_NULL_HANDLE;
    }
    // Where each material's extension blocks are, and the words uploaded.
    const MaterialExtensionBuffer& extensions() const { return extensions_; }
    // Bytes of both arrays.
    std::uint64_t bytes() const { return bytes_; }
    // For inspection: per prepared texture its pipeline record (state, hash, PSNR,
    // timings, bytes), warnings and bindless slot; the editor maps material slots
    // back to them.
    const SceneTextures& textures() const { return *textures_; }
    // New values of the same materials (KHR_animation_pointer: factors, texture
    // transforms; the extensions and textures each uses stay): the records are rebuilt
    // on the CPU and only the 16-byte-aligned records that differ are uploaded. Returns
    // the bytes uploaded. The caller waits for the frames in flight first.
    std::uint64_t update(std::span<const scene::MaterialInstance> materials);

private:
    void upload(const scene::Scene& scene);
    void
    build(std::span<const scene::MaterialInstance> materials); // data_, extras_data_, extensions_

    gpu::ResourceManager& resources_;
    std::unique_ptr<SceneTextures> textures_;
    gpu::BufferHandle materials_, extras_, extension_buffer_;
    MaterialExtensionBuffer extensions_;
    std::vector<scene::GPUMaterialData> data_; // what the buffers hold
    std::vector<GPUMaterialExtra> extras_data_;
    std::uint64_t bytes_ = 0;
};

// What giving meshes other materials changed (KHR_materials_variants).
struct MaterialSwitch {
    std::uint32_t meshes = 0, groups = 0, instances = 0; // that changed material
    std::uint64_t gpu_bytes = 0; // uploaded: the changed instance records' material words
    bool modes_changed = false;  // a group's alpha mode or sidedness changed (culling rebuilds)
};

class GpuScene;
// Gives each (engine mesh, material) of `meshes` that material: its draw groups take
// the material's index, alpha mode and sidedness (pipelines and passes follow them
// from the next frame) and the instance records' material word is rewritten where it
// changed; no other byte moves. The caller waits for the frames in flight first.
MaterialSwitch
switch_mesh_materials(GpuScene& scene,
                      std::span<const std::pair<std::uint32_t, std::uint32_t>> meshes);

// GpuMaterials::update() of `scene`'s materials.
std::uint64_t update_scene_materials(GpuScene& scene,
                                     std::span<const scene::MaterialInstance> materials);

class GpuScene {
public:
    // Uploads textures the caller prepared (tex::prepare_scene_textures(), possibly on
    // another thread) for this scene.
    GpuScene(gpu::ResourceManager& resources, gpu::BindlessTable& table, const scene::Scene& scene,
             std::shared_ptr<const tex::PreparedTextureSet> textures,
             StreamPolicy policy = StreamPolicy::UsedByMaterials,
             MissingTextures missing = MissingTextures::Checker);
    // Prepares the textures itself (on this thread), then uploads; the CPU copies of
    // the texture levels are released after the upload.
    GpuScene(gpu::ResourceManager& resources, gpu::BindlessTable& table, const scene::Scene& scene,
             const TextureSettings& texture_settings,
             StreamPolicy policy = StreamPolicy::UsedByMaterials,
             MissingTextures missing = MissingTextures::Checker);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    StreamPolicy policy() const { return policy_; }
    const std::vector<GpuMesh>& meshes() const { return meshes_; }
    const std::vector<DrawGroup>& groups() const { return groups_; }
    // World bounds per GPU instance (draw-group order) for sorting and overlays.
    const std::vector<core::Aabb>& instance_bounds() const { return instance_bounds_; }
    // Scene instance index per GPU instance (draw-group order).
    const std::vector<std::uint32_t>& scene_instances() const { return scene_instances_; }
    const core::Aabb& bounds() const { return bounds_; }
    // Null when no instanced mesh has triangles (then there are no draw groups).
    VkBuffer index_buffer() const {
        return indices_.valid() ? resources_.get(indices_).buffer.get() : VK_NULL_HANDLE;
    }
    VkDeviceAddress instances_address() const { return resources_.get(instances_).address; }
    // Device address of the shared index buffer: 0 unless ray tracing is enabled (what
    // acceleration-structure builds and hit shaders read) or there are no triangles.
    VkDeviceAddress index_address() const {
        return indices_.valid() ? resources_.get(indices_).address : 0;
    }
    const GpuMemoryReport& memory() const { return memory_; }
    std::uint64_t triangle_count() const { return triangles_; }
    const GpuMaterials& materials() const { return *materials_; }

private:
    friend std::uint64_t update_scene_materials(GpuScene&,
                                                std::span<const scene::MaterialInstance>);
    friend MaterialSwitch
    switch_mesh_materials(GpuScene&, std::span<const std::pair<std::uint32_t, std::uint32_t>>);
    void upload(const scene::Scene& scene, std::shared_ptr<const tex::PreparedTextureSet> textures,
                MissingTextures missing);
    void upload_geometry(const scene::Scene& scene);
    void upload_instances(const scene::Scene& scene);
    void upload_motion(const scene::Scene& scene, const std::vector<bool>& instanced,
                       gpu::UploadBatch& batch);
    void release();

    gpu::ResourceManager& resources_;
    gpu::BindlessTable& table_;
    StreamPolicy policy_;
    std::unique_ptr<GpuMaterials> materials_;
    gpu::BufferHandle vertices_, indices_, instances_, motion_streams_, motion_meshes_;
    std::vector<GpuMesh> meshes_;
    std::vector<DrawGroup> groups_;
    std::vector<std::pair<scene::AlphaMode, bool>>
        material_modes_; // per material: alpha, double-sided
    std::vector<core::Aabb> instance_bounds_;
    std::vector<std::uint32_t> scene_instances_;
    core::Aabb bounds_;
    GpuMemoryReport memory_;
    std::uint64_t triangles_ = 0;
};

} // namespace sherpa::render
