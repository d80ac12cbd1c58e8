// The usage report: which streams each primitive's material reads, and bytes.
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>
#include <sherpa/scene/usage_report.h>

#include <gtest/gtest.h>

namespace {

using sherpa::scene::VertexAttribute;
constexpr auto idx(VertexAttribute a) {
    return static_cast<std::size_t>(a);
}

sherpa::scene::UsageReport report_for(const std::string& name,
                                      std::unique_ptr<sherpa::scene::Scene>* keep = nullptr) {
    sherpa::scene::LoadResult r = sherpa::scene::load_scene(sherpa::test::gltf_asset(name));
    EXPECT_TRUE(r) << r.error;
    auto rep = sherpa::scene::build_usage_report(*r.scene);
    if (keep) *keep = std::move(r.scene);
    return rep;
}

TEST(UsageReport, UntexturedBoxNeedsPositionAndNormalOnly) {
    const auto rep = report_for("Box");
    ASSERT_EQ(rep.primitives.size(), 1u);
    const auto& u = rep.primitives[0];
    EXPECT_TRUE(u.used[idx(VertexAttribute::Position)]);
    EXPECT_TRUE(u.used[idx(VertexAttribute::Normal)]);
    EXPECT_FALSE(u.used[idx(VertexAttribute::TexCoord0)]);
    EXPECT_FALSE(u.used[idx(VertexAttribute::Tangent)]);
    EXPECT_EQ(u.used_bytes, 24u * 24u);
    EXPECT_EQ(u.unified_bytes, 24u * 56u);
}

TEST(UsageReport, NormalMapNeedsTangentsEvenWhenNotAuthored) {
    std::unique_ptr<sherpa::scene::Scene> scene;
    const auto rep = report_for("DamagedHelmet", &scene);
    const auto& u = rep.primitives.at(0);
    // Not authored, so the loader generated them (MikkTSpace): present as Generated.
    EXPECT_TRUE(u.present[idx(VertexAttribute::Tangent)]);
    EXPECT_EQ(scene->meshes.at(0).provenance_of(VertexAttribute::Tangent),
              sherpa::scene::Provenance::Generated);
    EXPECT_TRUE(u.used[idx(VertexAttribute::Tangent)]);
    EXPECT_TRUE(u.used[idx(VertexAttribute::TexCoord0)]);
    EXPECT_FALSE(u.used[idx(VertexAttribute::TexCoord1)]);
}

TEST(UsageReport, SecondUvSetOnlyWhenATextureReadsIt) {
    std::unique_ptr<sherpa::scene::Scene> scene;
    const auto rep = report_for("MultiUVTest", &scene);
    EXPECT_TRUE(rep.primitives.at(0).used[idx(VertexAttribute::TexCoord1)]);
    const auto box = report_for("BoxTextured");
    EXPECT_FALSE(box.primitives.at(0).used[idx(VertexAttribute::TexCoord1)]);
    EXPECT_TRUE(box.primitives.at(0).used[idx(VertexAttribute::TexCoord0)]);
}

TEST(UsageReport, UnlitMaterialsNeedNoNormals) {
    const auto rep = report_for("UnlitTest");
    for (const auto& u : rep.primitives) EXPECT_FALSE(u.used[idx(VertexAttribute::Normal)]);
}

TEST(UsageReport, VertexColorsAreUsedWhenPresent) {
    const auto rep = report_for("BoxVertexColors");
    EXPECT_TRUE(rep.primitives.at(0).used[idx(VertexAttribute::Color0)]);
    EXPECT_LT(rep.used_bytes, rep.unified_bytes);
}

} // namespace
