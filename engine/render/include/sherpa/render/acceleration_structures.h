#pragma once
// A scene's ray-tracing data: one bottom-level acceleration structure per glTF mesh
// (one geometry per triangle primitive, VK_GEOMETRY_OPAQUE_BIT only for opaque
// materials whose sides need no any-hit, compacted; meshes of single-sided materials
// let the traversal cull back faces), the GPUGeometryInfo array hit shaders read vertices and
// materials through, and the top-level structure with one instance per (node, glTF
// mesh). Built once on scene load, batched under a scratch budget; never per frame
// (the TLAS is refitted or rebuilt on demand when transforms or visibility change).
// Instances of meshes that skin or morph get posed vertex copies and BLAS of their
// own, refitted when the pose changes (update_pose(), PosedStats).
// Needs a Context with DeviceInfo::ray_tracing_enabled (GpuScene's buffers then carry
// the build-input usage).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <sherpa/gpu/acceleration_structure.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/render/acceleration_stats.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/scene/scene.h>

namespace sherpa::render {

struct TlasCandidate; // rt_plan.h

// The frame's pose on the GPU (the Renderer's PosePass writes it, motion.glsl reads it).
struct PoseFrame {
    VkDeviceAddress instances = 0; // GPUInstanceData per GPU instance (GpuScene order)
    VkDeviceAddress pose = 0;      // joint matrices, then floats
    std::uint32_t highlight_base = 0;
    std::span<const glm::mat4> node_world; // per node: world transforms of the pose
};

class PosedGeometry;

class SceneAccelerationStructures {
public:
    // `gpu` is `scene` on the GPU (same meshes, buffers with the build-input usage).
    SceneAccelerationStructures(gpu::ResourceManager& resources, const scene::Scene& scene,
                                const GpuScene& gpu, const AccelerationSettings& settings = {});
    ~SceneAccelerationStructures();
    SceneAccelerationStructures(const SceneAccelerationStructures&) = delete;
    SceneAccelerationStructures& operator=(const SceneAccelerationStructures&) = delete;

    const AccelerationStats& stats() const { return stats_; }
    // Null when no instance has triangles.
    VkAccelerationStructureKHR tlas() const { return tlas_.get(); }
    // The GPUGeometryInfo array (0 when there are no geometries).
    VkDeviceAddress geometry_records() const;
    // After transforms (animation) or visibility changed: the TLAS is refitted when
    // the same instances remain (same BLAS in the same order), else rebuilt. `scene`
    // is the one the structures were built from, with its instances' world
    // transforms updated. Waits for the build; no frame may be using the TLAS.
    void update_instances(const scene::Scene& scene, const std::vector<bool>& hidden_nodes);
    // Visibility changed (per node, subtree rule applied): the TLAS is rebuilt over
    // the same candidates at their loaded transforms (a posed scene is posed again by
    // the caller). Waits; no frame may be using the TLAS.
    void set_hidden_nodes(const std::vector<bool>& hidden_nodes);
    // True when some instance skins or morphs (then update_pose() must run before its
    // instances are in the TLAS).
    bool posed() const { return posed_ != nullptr; }
    // Applies a pose: the moving meshes' vertices are posed and their BLAS refitted
    // (or rebuilt), then the TLAS refitted with the pose's node transforms (hidden
    // nodes as last given). Waits; no frame may be using the structures.
    void update_pose(const PoseFrame& frame);

    // What follow_materials() changed.
    struct MaterialFollow {
        std::uint32_t records = 0;       // geometry records whose material word was rewritten
        std::uint64_t gpu_bytes = 0;     // uploaded: those material words
        std::uint32_t forced_blas = 0;   // BLAS built opaque that now need any-hit
        std::uint32_t unculled_blas = 0; // BLAS built to cull back faces that now must not
        bool tlas_rebuilt = false;       // at the loaded transforms: the caller poses it again
    };
    // After meshes took other materials (KHR_materials_variants): each geometry
    // record's material word follows its mesh's in `gpu`, so hit shaders shade the new
    // material; no BLAS is rebuilt. Where a BLAS built to cull back faces now has a
    // material that must not (double-sided, or bounding a volume), its instances stop
    // culling (VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR). A geometry
    // built with VK_GEOMETRY_OPAQUE_BIT whose new material is masked or blended, or
    // single-sided where its instances do not cull, needs any-hit: the TLAS instances
    // of its BLAS get VK_GEOMETRY_INSTANCE_FORCE_NO_OPAQUE_BIT_KHR (the other
    // geometries of those instances then run an any-hit that accepts them or rejects
    // their back faces) and the TLAS is rebuilt; the flags go when no geometry needs
    // them. Waits; no frame may be using the structures.
    MaterialFollow follow_materials(const GpuScene& gpu);

private:
    void build_blas(const scene::Scene& scene, const GpuScene& gpu, const AccelerationSettings& s);
    // The TLAS over candidates_ (hidden_ excluded) at `node_world` (empty: as loaded).
    void build_tlas(std::span<const glm::mat4> node_world);
    VkDeviceAddress blas_address(std::uint32_t blas) const;
    std::uint32_t first_geometry(std::uint32_t blas) const;
    std::uint32_t plan_of(std::uint32_t blas) const; // its index in stats_.blas
    // Whether the TLAS instances of `blas` let the traversal cull back faces.
    bool instances_cull(std::uint32_t blas) const;

    gpu::ResourceManager& resources_;
    gpu::RayTracingFunctions fn_;
    std::vector<gpu::AccelerationStructure> blas_; // by stats_.blas
    std::vector<std::int32_t> blas_of_mesh_;       // per glTF mesh: index into blas_, -1 none
    std::unique_ptr<PosedGeometry> posed_;         // BLAS blas_.size() + i: posed_'s i-th
    std::vector<TlasCandidate> candidates_;        // what the TLAS may instance
    std::vector<bool> hidden_;
    gpu::AccelerationStructure tlas_;
    std::vector<std::uint32_t> tlas_blas_; // BLAS per TLAS instance, as last built
    // Per geometry record: its engine mesh, whether it was built opaque, its material now.
    std::vector<std::uint32_t> record_mesh_, record_material_;
    std::vector<bool> record_opaque_;
    std::vector<bool> material_culls_; // per material: rt_plan.h's culls_back_faces()
    // Per BLAS (static, then posed), from follow_materials(): its instances force
    // any-hit, or no longer cull back faces (a material of it is now double-sided).
    std::vector<bool> force_no_opaque_, cull_disabled_;
    gpu::BufferHandle records_, instances_;
    AccelerationStats stats_;
};

} // namespace sherpa::render
