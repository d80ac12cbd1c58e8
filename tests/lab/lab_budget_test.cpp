// The budget report on a synthetic scene with known answers.
#include "lab/lab_scenes.h"

#include <sherpa/lab/budget.h>
#include <sherpa/texture/block_codecs.h>

#include <gtest/gtest.h>

namespace {

using namespace sherpa;

// A unit quad in z = 0 (uv = xy), 4 vertices with authored tangents, its material's
// base colour a 1024x1024 texture; the file also names JOINTS_0 and TEXCOORD_2.
scene::Scene budget_scene() {
    scene::Mesh quad;
    for (int k = 0; k < 4; ++k) {
        scene::Vertex v;
        v.position = {float(k & 1), float(k >> 1), 0.0f};
        v.uv0 = {v.position.x, v.position.y};
        quad.vertices.push_back(v);
        quad.local_bounds.expand(v.position);
    }
    quad.indices = {0, 1, 3, 0, 3, 2};
    quad.provenance[std::size_t(scene::VertexAttribute::TexCoord1)] = scene::Provenance::Defaulted;
    quad.provenance[std::size_t(scene::VertexAttribute::Color0)] = scene::Provenance::Defaulted;
    scene::Scene s = test::scene_of({quad});
    scene::ImageRecord img;
    img.width = img.height = 1024;
    img.pixels.assign(std::size_t(1024) * 1024 * 4, 200);
    s.images.push_back(img);
    s.textures.push_back(scene::TextureRecord{"", 0, -1, scene::kRoleColor});
    s.materials[0].base_color.texture = 0;
    scene::PrimitiveInfo p;
    p.engine_mesh = 0;
    p.file_attributes = {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "JOINTS_0", "TEXCOORD_2"};
    s.primitives.push_back(p);
    return s;
}

TEST(LabBudget, BytesOversizedTexturesAndUnreadAttributes) {
    lab::BudgetOptions o;
    scene::CameraSpec view; // 90 degrees, 5 units in front of the quad's centre
    view.eye = {0.5f, 0.5f, 5.0f}, view.target = {0.5f, 0.5f, 0.0f};
    view.fov_y_degrees = 90.0f;
    o.views = {view};
    o.viewport_height = 200; // 200 / (2 * 5 * tan 45) = 20 pixels per unit
    const lab::BudgetReport b = lab::build_budget(budget_scene(), o);
    ASSERT_EQ(b.categories.size(), 5u);
    EXPECT_EQ(b.categories[0].name, "vertex streams");
    EXPECT_EQ(b.categories[0].unified, 4u * 56u);
    EXPECT_EQ(b.categories[0].stored, 4u * (12u + 12u + 8u)) << "position, normal, uv0";
    EXPECT_EQ(b.categories[1].stored, 6u * 4u) << "32-bit indices";
    // 1024 texels per unit against 20 pixels per unit: 51.2 texels per pixel, so 1/32.
    ASSERT_EQ(b.oversized.size(), 1u);
    EXPECT_NEAR(b.oversized[0].texels_per_pixel, 51.2, 1e-3);
    EXPECT_EQ(b.oversized[0].reduce, 32u);
    const lab::BudgetCategory& t = b.categories[2];
    std::uint64_t bc_1024 = 0, bc_32 = 0;
    for (std::uint32_t s = 1024; s >= 1; s /= 2) bc_1024 += tex::compressed_size(s, s);
    for (std::uint32_t s = 32; s >= 1; s /= 2) bc_32 += tex::compressed_size(s, s);
    EXPECT_EQ(t.stored, bc_1024);
    EXPECT_EQ(t.needed, bc_32);
    EXPECT_GT(t.unified, 4 * t.stored - 1024) << "RGBA8 against 1 byte per texel";
    ASSERT_EQ(b.unread.size(), 3u);
    EXPECT_EQ(b.unread[0].attribute, "TANGENT");
    EXPECT_EQ(b.unread[1].attribute, "JOINTS_0");
    EXPECT_EQ(b.unread[2].attribute, "TEXCOORD_2");
    EXPECT_EQ(b.unread[2].reason, "no engine stream holds it");
}

TEST(LabBudget, ANearViewNeedsTheFullTexture) {
    lab::BudgetOptions o;
    scene::CameraSpec view;
    view.eye = {0.5f, 0.5f, 0.2f}, view.target = {0.5f, 0.5f, 0.0f};
    o.views = {view};
    const lab::BudgetReport b = lab::build_budget(budget_scene(), o);
    EXPECT_TRUE(b.oversized.empty());
    EXPECT_EQ(b.categories[2].needed, b.categories[2].stored);
}

} // namespace
