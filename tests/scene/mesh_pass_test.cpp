// MeshPass bookkeeping: incremental updates equal a full rebuild, batches group by
// (pipeline, mesh), multi-batches by pipeline, moves only dirty their object.
#include <sherpa/scene/mesh_pass.h>
#include <sherpa/scene/scene_loader.h>

#include <random>

#include <gtest/gtest.h>

namespace {

using namespace sherpa;

// Sorted (key, instance) pairs of a pass: what the GPU would draw, in order.
std::vector<std::pair<std::uint64_t, std::uint32_t>> draw_list(const scene::MeshPass& p) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> out;
    for (const scene::FlatBatch& b : p.flat_batches())
        out.emplace_back(b.sort_key, p.objects()[b.object].instance);
    return out;
}

void expect_consistent(const scene::MeshPass& p) {
    const auto flat = p.flat_batches();
    ASSERT_EQ(flat.size(), p.live_count());
    for (std::size_t i = 1; i < flat.size(); ++i) ASSERT_LE(flat[i - 1].sort_key, flat[i].sort_key);
    std::uint32_t covered = 0;
    for (const scene::IndirectBatch& b : p.batches()) {
        ASSERT_EQ(b.first, covered);
        for (std::uint32_t k = b.first; k < b.first + b.count; ++k)
            ASSERT_EQ(flat[k].sort_key, (std::uint64_t{b.pipeline} << 32) | b.mesh_id);
        covered += b.count;
    }
    ASSERT_EQ(covered, flat.size());
    std::uint32_t batches = 0;
    for (const scene::MultiBatch& m : p.multi_batches()) {
        ASSERT_EQ(m.first, batches);
        for (std::uint32_t k = m.first; k < m.first + m.count; ++k)
            ASSERT_EQ(p.batches()[k].pipeline, p.batches()[m.first].pipeline);
        batches += m.count;
    }
    ASSERT_EQ(batches, p.batches().size());
}

TEST(MeshPass, IncrementalUpdatesMatchAFullRebuild) {
    std::mt19937 rng(3);
    scene::MeshPass incremental(scene::MeshPassKind::Forward);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> live; // (handle, instance)
    std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>>
        objects; // instance -> mesh, pipeline
    std::uint32_t next_instance = 0;
    for (int round = 0; round < 50; ++round) {
        for (int k = 0; k < 20; ++k) {
            const std::uint32_t mesh = rng() % 7, pipe = rng() % 4;
            objects.emplace_back(next_instance, mesh, pipe);
            live.emplace_back(incremental.add(next_instance, mesh, pipe), next_instance);
            ++next_instance;
        }
        for (int k = 0; k < 12 && !live.empty(); ++k) {
            const std::size_t at = rng() % live.size();
            ASSERT_TRUE(incremental.remove(live[at].first));
            ASSERT_FALSE(incremental.remove(live[at].first)) << "a second removal is reported";
            live.erase(live.begin() + static_cast<std::ptrdiff_t>(at));
        }
        incremental.update();
        expect_consistent(incremental);
        scene::MeshPass full(scene::MeshPassKind::Forward);
        for (const auto& [h, inst] : live) {
            (void)h;
            const auto& [i, mesh, pipe] = objects[inst];
            full.add(i, mesh, pipe);
        }
        full.update();
        auto a = draw_list(incremental), b = draw_list(full);
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        ASSERT_EQ(a, b) << "round " << round;
        ASSERT_EQ(incremental.batches().size(), full.batches().size());
    }
    EXPECT_FALSE(incremental.remove(100000)) << "unknown handles are reported";
}

TEST(MeshPass, MovesOnlyDirtyTheMovedObject) {
    scene::MeshPass p(scene::MeshPassKind::Forward);
    const std::uint32_t a = p.add(0, 1, 0), b = p.add(1, 1, 0);
    p.update();
    EXPECT_EQ(p.dirty().size(), 2u) << "new objects need an upload";
    p.clear_dirty();
    p.mark_dirty(b);
    p.mark_dirty(b);
    ASSERT_EQ(p.dirty().size(), 1u);
    EXPECT_EQ(p.dirty()[0], b);
    p.clear_dirty();
    p.mark_dirty(a);
    EXPECT_EQ(p.dirty().size(), 1u) << "flags reset after clear";
    EXPECT_EQ(p.batches().size(), 1u);
    EXPECT_EQ(p.batches()[0].count, 2u);
}

TEST(MeshPass, ScenePassesSplitByAlphaMode) {
    const scene::LoadResult r = scene::load_scene("builtin:default");
    ASSERT_TRUE(r) << r.error;
    const scene::ScenePasses passes = scene::build_mesh_passes(*r.scene);
    EXPECT_EQ(passes.forward.live_count() + passes.transparent.live_count(),
              r.scene->instances.size());
    EXPECT_EQ(passes.shadow.live_count(), passes.forward.live_count());
    EXPECT_EQ(passes.transparent.live_count(), 1u);
    expect_consistent(passes.forward);
    EXPECT_LT(passes.forward.batches().size(), passes.forward.live_count())
        << "instances share batches";
    EXPECT_LE(passes.forward.multi_batches().size(), 8u) << "one multi-batch per pipeline state";
    for (const auto& mb : passes.forward.multi_batches()) {
        const scene::PipelineState st =
            scene::pipeline_state(passes.forward.batches()[mb.first].pipeline);
        EXPECT_NE(st.alpha_mode, scene::AlphaMode::Blend);
    }
    for (scene::AlphaMode a :
         {scene::AlphaMode::Opaque, scene::AlphaMode::Mask, scene::AlphaMode::Blend})
        for (bool ds : {false, true})
            for (bool mir : {false, true}) {
                const scene::PipelineState st =
                    scene::pipeline_state(scene::pipeline_key(a, ds, mir));
                EXPECT_EQ(st.alpha_mode, a);
                EXPECT_EQ(st.double_sided, ds);
                EXPECT_EQ(st.mirrored, mir);
            }
}

} // namespace
