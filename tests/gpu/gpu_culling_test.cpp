// GPU-driven culling: the compute shader's visible set equals the CPU path's for
// the same method, and its indirect batches hold exactly the visible objects.
#include "gpu_test_support.h"

#include <sherpa/render/gpu_culling.h>
#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/culling_passes.h>

#include <algorithm>
#include <set>

namespace sherpa::test {
namespace {

class GpuCullingTest : public GpuTest {
protected:
    // Index ranges as a GpuScene would lay them out; identity GPU instance ids.
    static std::vector<render::GpuMesh> mesh_ranges(const scene::Scene& s) {
        std::vector<render::GpuMesh> out(s.meshes.size());
        std::uint32_t first = 0;
        for (std::size_t m = 0; m < s.meshes.size(); ++m) {
            out[m].first_index = first;
            out[m].index_count = static_cast<std::uint32_t>(s.meshes[m].indices.size());
            first += out[m].index_count;
        }
        return out;
    }
    static std::vector<core::Aabb> bounds(const scene::Scene& s) {
        std::vector<core::Aabb> b;
        for (const auto& i : s.instances) b.push_back(i.world_bounds);
        return b;
    }
    static std::vector<std::uint32_t> identity(std::size_t n) {
        std::vector<std::uint32_t> v(n);
        for (std::uint32_t i = 0; i < n; ++i) v[i] = i;
        return v;
    }
    // Each batch's compacted instance ids are exactly its objects flagged visible
    // (as multisets: the order within a batch is the GPU's). Returns the ids kept.
    static std::uint32_t expect_batches_hold_visible(const render::GpuCuller& culler,
                                                     const scene::MeshPass& pass,
                                                     const render::GpuCullReadback& r,
                                                     const std::string& what) {
        const auto batches = pass.batches();
        EXPECT_EQ(r.instance_counts.size(), batches.size()) << what;
        std::uint32_t kept = 0;
        for (std::uint32_t bi = 0; bi < batches.size() && bi < r.instance_counts.size(); ++bi) {
            std::multiset<std::uint32_t> want, got;
            for (std::uint32_t k = batches[bi].first; k < batches[bi].first + batches[bi].count;
                 ++k)
                if (r.visible[k]) want.insert(culler.object_instances()[k]);
            for (std::uint32_t s = 0; s < r.instance_counts[bi]; ++s)
                got.insert(r.instance_ids[batches[bi].first + s]);
            EXPECT_EQ(want, got) << what << ", batch " << bi;
            kept += r.instance_counts[bi];
        }
        return kept;
    }
};

TEST_F(GpuCullingTest, AgreesWithTheCpuPathForEveryMethod) {
    auto scene = load("builtin:grid?n=10000");
    ASSERT_TRUE(scene);
    scene::ScenePasses passes = scene::build_mesh_passes(*scene);
    render::GpuCuller culler(context(), renderer().resources());
    culler.build(passes.forward, *scene);
    ASSERT_EQ(culler.object_count(), scene->instances.size());
    const scene::CullInput input = scene::prepare_cull_input(*scene);
    for (const char* cam :
         {"eye=0,8,0:target=1,7.8,0.35:fov=50", "eye=-80,40,-80:target=0,0,0",
          "eye=0,0.5,0:target=0,0.5,-1:fov=120:far=30", "eye=10,200,10:target=0,0,0:fov=20"}) {
        scene::CameraSpec c;
        std::string error;
        ASSERT_TRUE(parse_camera_spec(cam, c, error)) << error;
        const scene::Frustum f = scene::frustum_from_view_projection(c.view_projection());
        for (scene::CullMethod m :
             {scene::CullMethod::Sphere, scene::CullMethod::PVertex, scene::CullMethod::Exact}) {
            std::vector<std::uint8_t> cpu(input.boxes.size());
            const scene::CullCounts counts =
                scene::cull_boxes(f, input.boxes, m, core::SimdLevel::Avx512, cpu);
            const render::GpuCullReadback gpu_result = culler.run(f, m);
            std::size_t differences = 0, gpu_visible = 0;
            for (std::size_t k = 0; k < gpu_result.visible.size(); ++k) {
                const std::uint32_t inst = culler.object_instances()[k];
                differences += gpu_result.visible[k] != cpu[inst] ? 1 : 0;
                gpu_visible += gpu_result.visible[k];
            }
            EXPECT_EQ(differences, 0u) << cam << " " << to_string(m);
            EXPECT_EQ(gpu_visible, counts.visible);
            std::uint64_t drawn = 0;
            for (std::uint32_t n : gpu_result.instance_counts) drawn += n;
            EXPECT_EQ(drawn, gpu_visible) << "every visible object is appended once";
        }
    }
}

TEST_F(GpuCullingTest, BatchesHoldExactlyTheirVisibleObjects) {
    auto scene = load("builtin:default");
    ASSERT_TRUE(scene);
    scene::ScenePasses passes = scene::build_mesh_passes(*scene);
    render::GpuCuller culler(context(), renderer().resources());
    culler.build(passes.forward, *scene);
    scene::CameraSpec c;
    std::string error;
    ASSERT_TRUE(parse_camera_spec("eye=0,3,9:target=0,1,0", c, error)) << error;
    const render::GpuCullReadback r = culler.run(
        scene::frustum_from_view_projection(c.view_projection()), scene::CullMethod::Exact);
    expect_batches_hold_visible(culler, passes.forward, r, "builtin:default");
    if (context().info().timestamps) {
        EXPECT_GE(r.gpu_ms, 0.0);
    }
}

// The grid's three batches are hundreds of objects long and meet inside a subgroup:
// both the one-atomic-per-subgroup path (a subgroup within one batch) and the
// per-object fallback (a subgroup across two batches) must fill every batch with
// exactly its visible objects, for every method.
TEST_F(GpuCullingTest, LongBatchesMeetingInsideASubgroupHoldExactlyTheirVisibleObjects) {
    auto scene = load("builtin:grid?n=1000");
    ASSERT_TRUE(scene);
    scene::ScenePasses passes = scene::build_mesh_passes(*scene);
    render::GpuCuller culler(context(), renderer().resources());
    culler.build(passes.forward, *scene);
    ASSERT_EQ(passes.forward.batches().size(), 3u);
    for (const char* spec : {"eye=0,6,20:target=0,0,0", "eye=-30,4,-30:target=10,0,5:fov=35"}) {
        scene::CameraSpec c;
        std::string error;
        ASSERT_TRUE(parse_camera_spec(spec, c, error)) << error;
        const scene::Frustum f = scene::frustum_from_view_projection(c.view_projection());
        for (scene::CullMethod m :
             {scene::CullMethod::Sphere, scene::CullMethod::PVertex, scene::CullMethod::Exact}) {
            const std::uint32_t kept = expect_batches_hold_visible(
                culler, passes.forward, culler.run(f, m),
                std::string(spec) + ", method " + std::string(to_string(m)));
            EXPECT_GT(kept, 0u) << spec;
            EXPECT_LT(kept, 1000u) << spec;
        }
    }
}

TEST_F(GpuCullingTest, InvalidBoxesAreKeptLikeOnTheCpu) {
    auto scene = load("builtin:default");
    ASSERT_TRUE(scene);
    scene::ScenePasses passes = scene::build_mesh_passes(*scene);
    auto b = bounds(*scene);
    b[0] = core::Aabb::from_min_max({NAN, 0, 0}, {1, 1, 1});
    b[1] = core::Aabb::from_min_max({5, 5, 5}, {-5, -5, -5});
    render::GpuCuller culler(context(), renderer().resources());
    culler.build(passes.forward, b, identity(b.size()), mesh_ranges(*scene));
    scene::CameraSpec c;
    std::string error;
    ASSERT_TRUE(parse_camera_spec("eye=0,1000,0:target=0,2000,1", c, error)) << error; // looks away
    const render::GpuCullReadback r = culler.run(
        scene::frustum_from_view_projection(c.view_projection()), scene::CullMethod::PVertex);
    for (std::size_t k = 0; k < r.visible.size(); ++k) {
        const std::uint32_t inst = culler.object_instances()[k];
        EXPECT_EQ(r.visible[k], inst <= 1 ? 1 : 0) << "instance " << inst;
    }
}

} // namespace
} // namespace sherpa::test
