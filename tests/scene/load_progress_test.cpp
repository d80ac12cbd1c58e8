// load_scene's progress reports and cancellation: every stage is reported in
// order with a final done == total, and a cancelled load returns no scene.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>

#include <sherpa/scene/scene_loader.h>

#include "test_support.h"

namespace sherpa::test {
namespace {

struct Report {
    scene::LoadStage stage;
    std::size_t done, total;
};

std::vector<Report> load_with_reports(const std::string& spec, scene::LoadResult& result) {
    std::vector<Report> reports;
    std::mutex m; // tangent progress comes from worker threads
    scene::LoadOptions options;
    options.progress = [&](scene::LoadStage stage, std::size_t done, std::size_t total) {
        std::lock_guard lock(m);
        reports.push_back({stage, done, total});
    };
    result = scene::load_scene(spec, options);
    return reports;
}

void expect_stages(const std::vector<Report>& reports, std::vector<scene::LoadStage> stages,
                   std::size_t meshes) {
    std::vector<scene::LoadStage> seen;
    for (const Report& r : reports)
        if (seen.empty() || seen.back() != r.stage) seen.push_back(r.stage);
    EXPECT_EQ(seen, stages);
    for (scene::LoadStage stage : stages) { // each stage ends complete
        const Report* last = nullptr;
        for (const Report& r : reports)
            if (r.stage == stage) last = &r;
        ASSERT_NE(last, nullptr);
        EXPECT_EQ(last->done, last->total) << to_string(stage);
        if (stage == scene::LoadStage::Tangents) {
            EXPECT_EQ(last->total, meshes);
        }
    }
}

TEST(LoadProgress, GltfReportsParseGeometryTangents) {
    scene::LoadResult r;
    const auto reports = load_with_reports(gltf_asset("DamagedHelmet"), r);
    ASSERT_TRUE(r) << r.error;
    expect_stages(reports,
                  {scene::LoadStage::Parse, scene::LoadStage::Geometry, scene::LoadStage::Tangents},
                  r.scene->meshes.size());
}

TEST(LoadProgress, BuiltinReportsGeometryTangents) {
    scene::LoadResult r;
    const auto reports = load_with_reports("builtin:default", r);
    ASSERT_TRUE(r) << r.error;
    expect_stages(reports, {scene::LoadStage::Geometry, scene::LoadStage::Tangents},
                  r.scene->meshes.size());
}

TEST(LoadProgress, CancelAtEachStageReturnsNoScene) {
    for (scene::LoadStage stop_at :
         {scene::LoadStage::Parse, scene::LoadStage::Geometry, scene::LoadStage::Tangents}) {
        core::CancelToken token;
        scene::LoadOptions options;
        options.cancel = &token;
        std::atomic<int> later{0}; // reports of stages after the cancelled one
        options.progress = [&](scene::LoadStage stage, std::size_t, std::size_t) {
            if (token.cancelled() && stage != stop_at) ++later;
            if (stage == stop_at) token.cancel();
        };
        const scene::LoadResult r = scene::load_scene(gltf_asset("DamagedHelmet"), options);
        EXPECT_FALSE(r) << to_string(stop_at);
        EXPECT_TRUE(r.cancelled) << to_string(stop_at);
        EXPECT_EQ(r.error, "cancelled");
        // The stage that saw the cancel may finish reporting; no later stage starts.
        EXPECT_EQ(later.load(), 0) << to_string(stop_at);
    }
    core::CancelToken before;
    before.cancel();
    scene::LoadOptions options;
    options.cancel = &before;
    EXPECT_TRUE(scene::load_scene("builtin:default", options).cancelled);
}

} // namespace
} // namespace sherpa::test
