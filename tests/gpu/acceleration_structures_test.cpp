// Acceleration structures on the device (lavapipe: CPU builds) under the validation
// layer: RT off allocates and flags nothing, one BLAS per glTF mesh with the opaque
// flag per material, the TLAS's dedup/hidden/mirrored/non-finite handling, and
// hostile geometry (degenerate triangles, empty meshes). The planning functions are
// checked without a device.
#include "gpu_test_support.h"
#include "rt_plan.h"

#include <sherpa/gpu/acceleration_structure.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/texture/texture_pipeline.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

namespace sherpa::test {
namespace {

constexpr VkBufferUsageFlags kAsInput =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;

std::shared_ptr<const tex::PreparedTextureSet> no_textures() {
    return std::make_shared<const tex::PreparedTextureSet>();
}

class AccelerationTest : public GpuTest {
protected:
    // Builds `scene` on the shared device; `check` sees the statistics.
    render::AccelerationStats build(const scene::Scene& scene,
                                    const render::AccelerationSettings& s = {}) {
        gpu::ResourceManager& rm = renderer().resources();
        gpu::BindlessTable table(rm);
        render::AccelerationStats stats;
        {
            render::GpuScene gpu_scene(rm, table, scene, no_textures());
            render::SceneAccelerationStructures as(rm, scene, gpu_scene, s);
            stats = as.stats();
            EXPECT_EQ(as.tlas() != VK_NULL_HANDLE, stats.tlas.instances > 0);
            EXPECT_EQ(as.geometry_records() != 0, stats.geometry_records > 0);
        }
        rm.flush();
        return stats;
    }
    bool has_rt() { return context().info().ray_tracing_enabled; }
};

TEST_F(AccelerationTest, RtOffEnablesNothingAndBuffersCarryNoBuildInputUsage) {
    auto scene = load("builtin:default");
    auto usage_of = [&](gpu::Context& ctx, VkDeviceAddress& index_address) {
        gpu::ResourceManager rm(ctx);
        gpu::BindlessTable table(rm);
        render::GpuScene g(rm, table, *scene, no_textures());
        index_address = g.index_address();
        return g.memory().geometry_usage;
    };
    gpu::ContextOptions off_options;
    off_options.validation = true;
    off_options.ray_tracing = false;
    gpu::Context off(off_options);
    EXPECT_FALSE(off.info().ray_tracing_enabled);
    EXPECT_FALSE(off.info().ray_query_enabled);
    EXPECT_EQ(off.info().as_scratch_alignment, 0u);
    EXPECT_THROW(gpu::RayTracingFunctions::load(off), gpu::GpuError);
    VkDeviceAddress off_index = 1, on_index = 0;
    const std::uint32_t off_usage = usage_of(off, off_index);
    EXPECT_EQ(off_usage & kAsInput, 0u);
    EXPECT_EQ(off_index, 0u); // the index buffer has no device address
    EXPECT_EQ(off.validation().count(), 0u);

    const std::uint32_t on_usage = usage_of(context(), on_index);
    if (!context().info().ray_tracing) GTEST_SKIP() << "device without ray tracing";
    EXPECT_TRUE(context().info().ray_tracing_enabled);
    EXPECT_NE(on_usage & kAsInput, 0u);
    EXPECT_NE(on_index, 0u);
    // Nothing else changes: the same streams are uploaded either way.
    EXPECT_EQ(on_usage & ~(kAsInput | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT),
              off_usage & ~(kAsInput | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT));
}

TEST_F(AccelerationTest, OneBlasPerGltfMeshOpaqueOnlyForOpaqueMaterials) {
    if (!has_rt()) GTEST_SKIP() << "device without ray tracing";
    auto scene = load("builtin:default");
    const render::AccelerationStats s = build(*scene);
    // Per glTF mesh: whether all its materials are single-sided (the traversal then
    // culls its back faces), and its opaque materials' sidedness.
    std::map<std::uint32_t, bool> single_sided;
    std::uint64_t triangles = 0;
    for (const scene::Mesh& m : scene->meshes) {
        triangles += m.indices.size() / 3;
        const bool ss = !scene->materials[m.material_id].double_sided;
        single_sided[m.group_id] =
            single_sided.contains(m.group_id) ? single_sided[m.group_id] && ss : ss;
    }
    std::uint64_t opaque = 0;
    for (const scene::Mesh& m : scene->meshes) {
        const scene::MaterialInstance& material = scene->materials[m.material_id];
        opaque += material.alpha_mode == scene::AlphaMode::Opaque &&
                  (material.double_sided || single_sided[m.group_id]);
    }
    ASSERT_EQ(s.blas.size(), single_sided.size());
    EXPECT_EQ(s.blas_triangles(), triangles);
    std::uint64_t opaque_geometries = 0, culling = 0;
    for (const render::BlasStats& b : s.blas) {
        opaque_geometries += b.opaque_geometries;
        EXPECT_EQ(b.culls_back_faces, single_sided[b.mesh]) << b.name;
        culling += b.culls_back_faces ? 1 : 0;
        EXPECT_GT(b.scratch_bytes, 0u);
        EXPECT_LE(b.compacted_bytes, b.build_bytes);
    }
    EXPECT_GT(culling, 0u);
    EXPECT_EQ(opaque_geometries, opaque);
    EXPECT_LT(opaque_geometries, s.geometry_records); // glass and perforated box
    EXPECT_EQ(s.geometry_record_bytes, s.geometry_records * sizeof(render::GPUGeometryInfo));
    EXPECT_EQ(s.tlas.instances, scene->instances.size()); // one primitive per mesh here
    EXPECT_EQ(s.tlas.deduplicated + s.tlas.hidden + s.tlas.non_finite, 0u);
}

TEST_F(AccelerationTest, TlasDeduplicatesHidesMirrorsAndDropsNonFiniteTransforms) {
    if (!has_rt()) GTEST_SKIP() << "device without ray tracing";
    auto scene = load("builtin:default");
    const std::size_t base = scene->instances.size();
    // New nodes placing instance 0's mesh: once at the same transform (a duplicate),
    // once mirrored, once with a NaN transform.
    auto place = [&](const glm::mat4& world) {
        scene::MeshInstance inst = scene->instances[0];
        inst.node_id = static_cast<std::uint32_t>(scene->nodes.size());
        inst.world = world;
        scene->nodes.push_back(scene::Node{});
        scene->nodes.back().name = "added";
        scene->instances.push_back(inst);
    };
    const glm::mat4 w = scene->instances[0].world;
    place(w);
    place(glm::scale(w, glm::vec3(-1.0f, 1.0f, 1.0f)));
    glm::mat4 nan = w;
    nan[3][1] = std::numeric_limits<float>::quiet_NaN();
    place(nan);
    render::AccelerationSettings settings;
    settings.hidden_nodes.assign(scene->nodes.size(), false);
    settings.hidden_nodes[scene->instances[1].node_id] = true;
    const render::AccelerationStats s = build(*scene, settings);
    EXPECT_EQ(s.tlas.node_mesh_pairs, base + 3);
    EXPECT_EQ(s.tlas.deduplicated, 1u);
    EXPECT_EQ(s.tlas.mirrored, 1u);
    EXPECT_EQ(s.tlas.non_finite, 1u);
    EXPECT_EQ(s.tlas.hidden, 1u);
    EXPECT_EQ(s.tlas.instances, base + 3 - 3);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("not finite"), std::string::npos) << s.warnings[0];
}

TEST_F(AccelerationTest, DegenerateTrianglesAndEmptyMeshesBuildCleanly) {
    if (!has_rt()) GTEST_SKIP() << "device without ray tracing";
    auto scene = load("builtin:default");
    // Mesh 0: every triangle collapsed to a point or a line; mesh 1: no triangles.
    scene::Mesh& degenerate = scene->meshes[0];
    for (std::size_t t = 0; t + 2 < degenerate.indices.size(); t += 3) {
        const std::uint32_t a = degenerate.indices[t];
        if ((t / 3) % 2 == 0) degenerate.indices[t + 1] = a; // a point
        degenerate.indices[t + 2] = a;                       // else a line
    }
    scene->meshes[1].indices.clear();
    const render::AccelerationStats s = build(*scene);
    std::set<std::uint32_t> groups;
    for (const scene::Mesh& m : scene->meshes) groups.insert(m.group_id);
    EXPECT_EQ(s.blas.size(), groups.size() - 1); // the empty mesh has no BLAS
    for (const render::BlasStats& b : s.blas) EXPECT_NE(b.mesh, scene->meshes[1].group_id);
}

TEST_F(AccelerationTest, MovedInstancesRefitAndVisibilityChangesRebuild) {
    if (!has_rt()) GTEST_SKIP() << "device without ray tracing";
    auto scene = load("builtin:default");
    gpu::ResourceManager& rm = renderer().resources();
    {
        gpu::BindlessTable table(rm);
        render::GpuScene gpu_scene(rm, table, *scene, no_textures());
        render::SceneAccelerationStructures as(rm, *scene, gpu_scene);
        EXPECT_EQ(as.stats().tlas.builds, 1u);
        EXPECT_EQ(as.stats().tlas.refits, 0u);
        // Animation: every instance moves, the set stays: a refit.
        for (scene::MeshInstance& inst : scene->instances)
            inst.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f)) * inst.world;
        as.update_instances(*scene, {});
        EXPECT_EQ(as.stats().tlas.builds, 1u);
        EXPECT_EQ(as.stats().tlas.refits, 1u);
        EXPECT_EQ(as.stats().tlas.instances, scene->instances.size());
        // A node hidden: fewer instances, a rebuild.
        std::vector<bool> hidden(scene->nodes.size(), false);
        hidden[scene->instances[0].node_id] = true;
        as.update_instances(*scene, hidden);
        EXPECT_EQ(as.stats().tlas.builds, 2u);
        EXPECT_EQ(as.stats().tlas.hidden, 1u);
        EXPECT_EQ(as.stats().tlas.instances, scene->instances.size() - 1);
        EXPECT_NE(as.tlas(), VK_NULL_HANDLE);
        // Everything hidden: no TLAS at all.
        hidden.assign(hidden.size(), true);
        as.update_instances(*scene, hidden);
        EXPECT_EQ(as.tlas(), VK_NULL_HANDLE);
        EXPECT_EQ(as.stats().tlas.instances, 0u);
        // Shown again: built anew.
        as.update_instances(*scene, {});
        EXPECT_NE(as.tlas(), VK_NULL_HANDLE);
        EXPECT_EQ(as.stats().tlas.builds, 3u);
    }
    rm.flush();
}

TEST(RtPlan, BatchesStayUnderTheScratchBudget) {
    const std::vector<std::uint64_t> scratch = {100, 30, 70, 500, 1, 1};
    const auto batches = render::batch_by_scratch(scratch, 128, 8);
    // Rounded: 104, 32, 72, 504, 8, 8.
    ASSERT_EQ(batches.size(), 4u);
    EXPECT_EQ(batches[0], (std::vector<std::uint32_t>{0}));
    EXPECT_EQ(batches[1], (std::vector<std::uint32_t>{1, 2}));
    EXPECT_EQ(batches[2], (std::vector<std::uint32_t>{3})); // alone over the budget
    EXPECT_EQ(batches[3], (std::vector<std::uint32_t>{4, 5}));
    EXPECT_TRUE(render::batch_by_scratch({}, 128, 8).empty());
}

TEST(RtPlan, GeometriesFollowPrimitivesOfEachGltfMesh) {
    scene::Scene scene;
    scene.materials.resize(2);
    scene.materials[1].alpha_mode = scene::AlphaMode::Mask;
    std::vector<render::GpuMesh> meshes(4);
    for (std::uint32_t i = 0; i < 4; ++i) {
        scene::Mesh m;
        m.group_id = i < 2 ? 0 : i - 1; // mesh 0: primitives 0, 1; mesh 1: 2; mesh 2: 3
        m.material_id = i == 1 ? 1 : 0;
        m.name = "m" + std::to_string(m.group_id) + "#" + std::to_string(i);
        scene.meshes.push_back(m);
        meshes[i].index_count = 6;
    }
    meshes[2].flags = render::kMeshLinesBit; // lines: no geometry, so mesh 1 has no BLAS
    meshes[3].index_count = 0;               // empty: no geometry, no BLAS
    const auto plans = render::plan_blas(scene, meshes);
    ASSERT_EQ(plans.size(), 1u);
    EXPECT_EQ(plans[0].group, 0u);
    EXPECT_EQ(plans[0].name, "m0");
    ASSERT_EQ(plans[0].geometries.size(), 2u);
    EXPECT_TRUE(plans[0].cull_back_faces);       // all single-sided
    EXPECT_TRUE(plans[0].geometries[0].opaque);  // single-sided: the traversal culls
    EXPECT_FALSE(plans[0].geometries[1].opaque); // masked: reaches any-hit
    EXPECT_EQ(plans[0].triangles, 4u);
}

// Back faces are culled by the traversal only in a mesh whose every material is
// single-sided and bounds no volume; elsewhere single-sided opaque geometries reach
// any-hit, which rejects their back faces per material.
TEST(RtPlan, TheTraversalCullsBackFacesOnlyOfMeshesWhollySingleSided) {
    scene::Scene scene;
    scene.materials.resize(3);
    scene.materials[1].double_sided = true;
    std::vector<render::GpuMesh> meshes(2);
    for (std::uint32_t i = 0; i < 2; ++i) {
        scene::Mesh m;
        m.group_id = 0;
        m.material_id = i; // 0 single-sided, then 1 double-sided
        scene.meshes.push_back(m);
        meshes[i].index_count = 3;
    }
    auto plans = render::plan_blas(scene, meshes);
    ASSERT_EQ(plans.size(), 1u);
    EXPECT_FALSE(plans[0].cull_back_faces);
    EXPECT_FALSE(plans[0].geometries[0].opaque); // single-sided, not culled: any-hit
    EXPECT_TRUE(plans[0].geometries[1].opaque);  // double-sided
    scene.meshes[1].material_id = 2;             // both single-sided
    plans = render::plan_blas(scene, meshes);
    EXPECT_TRUE(plans[0].cull_back_faces);
    EXPECT_TRUE(plans[0].geometries[0].opaque && plans[0].geometries[1].opaque);
    // A volume's back faces bound it: never culled, so any-hit takes the sides.
    scene.materials[2].volume.emplace();
    EXPECT_TRUE(render::plan_blas(scene, meshes)[0].cull_back_faces); // no transmission
    scene.materials[2].transmission.emplace();
    plans = render::plan_blas(scene, meshes);
    EXPECT_FALSE(plans[0].cull_back_faces);
    EXPECT_FALSE(plans[0].geometries[0].opaque || plans[0].geometries[1].opaque);
    scene.materials[2].transmission.reset();
    scene.materials[2].diffuse_transmission.emplace();
    EXPECT_FALSE(render::plan_blas(scene, meshes)[0].cull_back_faces);
    // A mesh without a material (index past the list) is never culled.
    scene.meshes[1].material_id = 7;
    plans = render::plan_blas(scene, meshes);
    EXPECT_FALSE(plans[0].cull_back_faces);
    EXPECT_FALSE(plans[0].geometries[1].opaque);
    EXPECT_TRUE(render::culls_back_faces(scene.materials[0]));
    EXPECT_FALSE(render::culls_back_faces(scene.materials[1]));
}

// Posed BLAS: one per (node, glTF mesh) instance with a moving primitive; skinned
// instances in world space (every geometry copied, the static one too), the others in
// the mesh's space (only the moving geometry copied); the TLAS puts world-space
// instances at the identity and the rest at the pose's node transforms.
TEST(RtPlan, PosedBlasPerMovingInstanceWorldSpaceOnlyWhenSkinned) {
    scene::Scene scene;
    scene.materials.resize(1);
    scene.skins.resize(1);
    scene.nodes.resize(3);
    scene.nodes[0].skin = 0; // node 1 draws the skinned mesh without its skin
    std::vector<render::GpuMesh> meshes(3);
    for (std::uint32_t i = 0; i < 3; ++i) {
        scene::Mesh m;
        m.group_id = i < 2 ? 0 : 1; // glTF mesh 0: engine meshes 0 (skinned) and 1 (static)
        scene.meshes.push_back(m);
        meshes[i].index_count = 6;
        scene::PrimitiveInfo p;
        p.engine_mesh = static_cast<std::int32_t>(i);
        p.motion = i == 0 ? 0 : i == 2 ? 1 : -1;
        scene.primitives.push_back(p);
    }
    meshes[0].motion = 0x100;
    meshes[2].motion = 0x200; // glTF mesh 1: morphed
    scene.motions.resize(2);
    scene.motions[0].influences = 4;
    scene.motions[1].targets.resize(1);
    const std::pair<std::uint32_t, std::uint32_t> placed[] = {
        {0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 2}};
    for (auto [node, mesh] : placed) {
        scene::MeshInstance inst;
        inst.node_id = node;
        inst.mesh_id = mesh;
        inst.world = glm::translate(glm::mat4(1.0f), glm::vec3(float(node), 0.0f, 0.0f));
        scene.instances.push_back(inst);
    }
    const std::vector<std::uint32_t> gpu_order = {4, 3, 2, 1, 0}; // GPU instance -> scene's
    const auto plans = render::plan_blas(scene, meshes);
    ASSERT_EQ(plans.size(), 2u);
    const auto posed = render::plan_posed_blas(scene, meshes, gpu_order, plans);
    ASSERT_EQ(posed.size(), 3u);
    EXPECT_EQ(posed[0].node, 0u);
    EXPECT_TRUE(posed[0].world_space);
    ASSERT_EQ(posed[0].geometries.size(), 2u);
    EXPECT_TRUE(posed[0].geometries[0].moves && posed[0].geometries[0].posed);
    EXPECT_TRUE(!posed[0].geometries[1].moves && posed[0].geometries[1].posed);
    EXPECT_EQ(posed[0].geometries[0].gpu_instance, 4u);
    EXPECT_EQ(posed[0].geometries[1].gpu_instance, 3u);
    EXPECT_FALSE(posed[1].world_space); // node 1 has no skin
    EXPECT_FALSE(posed[1].geometries[1].posed);
    EXPECT_EQ(posed[2].group, 1u);
    EXPECT_FALSE(posed[2].world_space);
    EXPECT_EQ(posed[2].geometries[0].gpu_instance, 0u);
    // Static meshes: nothing posed.
    for (render::GpuMesh& m : meshes) m.motion = 0;
    EXPECT_TRUE(render::plan_posed_blas(scene, meshes, gpu_order, plans).empty());

    std::vector<render::TlasCandidate> candidates =
        render::tlas_candidates(scene, std::vector{0, 1});
    ASSERT_EQ(candidates.size(), 3u); // (0, 0), (1, 0), (2, 1)
    candidates[0].blas = 2;
    candidates[0].world_space = true;
    const std::vector<glm::mat4> pose(3, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)));
    const render::TlasPlan tlas = render::plan_tlas(candidates, {}, pose);
    ASSERT_EQ(tlas.instances.size(), 3u);
    EXPECT_EQ(tlas.instances[0].blas, 2u);
    EXPECT_EQ(tlas.instances[0].world, glm::mat4(1.0f));
    EXPECT_EQ(tlas.instances[1].world, pose[1]);
    EXPECT_EQ(render::plan_tlas(candidates, {}).instances[1].world, scene.instances[2].world);
}

// EXT_mesh_gpu_instancing: one TLAS candidate per (node, row, glTF mesh), placed at
// the pose's node transform times the row's T * R * S.
TEST(RtPlan, EveryInstancingRowIsATlasInstanceAtNodeWorldTimesRow) {
    scene::Scene scene;
    scene.materials.resize(1);
    scene.nodes.resize(1);
    scene::NodeInstancing rows;
    for (int r = 0; r < 3; ++r) {
        scene::InstanceRow row;
        row.translation = glm::vec3(float(r), 0.0f, 0.0f);
        row.scale = glm::vec3(float(r + 1));
        rows.rows.push_back(row);
    }
    scene.nodes[0].instancing = rows;
    for (std::uint32_t i = 0; i < 2; ++i) { // glTF mesh 0: two primitives
        scene::Mesh m;
        m.group_id = 0;
        scene.meshes.push_back(m);
    }
    for (std::int32_t r = 0; r < 3; ++r)
        for (std::uint32_t mesh = 0; mesh < 2; ++mesh) {
            scene::MeshInstance inst;
            inst.mesh_id = mesh;
            inst.row = r;
            inst.world = rows.rows[std::size_t(r)].matrix();
            scene.instances.push_back(inst);
        }
    const auto candidates = render::tlas_candidates(scene, std::vector{0});
    ASSERT_EQ(candidates.size(), 3u) << "one per row, not one per node";
    const std::vector<glm::mat4> pose(1, glm::translate(glm::mat4(1.0f), glm::vec3(0, 5, 0)));
    const render::TlasPlan tlas = render::plan_tlas(candidates, {}, pose);
    ASSERT_EQ(tlas.instances.size(), 3u);
    for (std::size_t r = 0; r < 3; ++r)
        EXPECT_EQ(tlas.instances[r].world, pose[0] * rows.rows[r].matrix()) << r;
    EXPECT_EQ(render::plan_tlas(candidates, {}).instances[2].world, rows.rows[2].matrix());
}

} // namespace
} // namespace sherpa::test
