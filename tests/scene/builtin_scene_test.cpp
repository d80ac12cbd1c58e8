// Built-in scenes: consistent counts, outward winding, the features they exist
// to show (UV seams, mirrored UVs, alpha modes, a normal map, instances).
#include <sherpa/scene/scene_loader.h>
#include <sherpa/scene/usage_report.h>

#include <set>

#include <gtest/gtest.h>

namespace {

using sherpa::scene::Provenance;
using sherpa::scene::VertexAttribute;

TEST(BuiltinDefault, HasEverythingTheDebugViewsNeed) {
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene("builtin:default");
    ASSERT_TRUE(r) << r.error;
    const sherpa::scene::Scene& s = *r.scene;
    std::set<sherpa::scene::AlphaMode> modes;
    bool normal_map = false;
    for (const auto& m : s.materials) {
        modes.insert(m.alpha_mode);
        normal_map |= m.normal.present();
    }
    EXPECT_EQ(modes.size(), 3u) << "opaque, masked and blended objects";
    EXPECT_TRUE(normal_map);
    EXPECT_GE(s.instances.size(), 40u) << "a grid of instances";
    EXPECT_EQ(s.placed_lights.size(), 1u);
    EXPECT_EQ(s.placed_cameras.size(), 1u);
    EXPECT_TRUE(s.bounds.valid());
    EXPECT_EQ(s.counts.primitives, s.meshes.size());
    for (const auto& w : s.warnings) // only the UV sphere's pole triangles are degenerate
        EXPECT_NE(w.find("degenerate_position"), std::string::npos) << w;
    for (const auto& m : s.meshes)
        if (s.materials[m.material_id].normal.present()) {
            EXPECT_EQ(m.provenance_of(VertexAttribute::Tangent), Provenance::Generated) << m.name;
        }
    for (const auto& img : s.images)
        EXPECT_EQ(img.pixels.size(), std::size_t{img.width} * img.height * 4);
}

// Every triangle's geometric normal agrees with its vertex normals: outward,
// counter-clockwise winding on every generated shape.
TEST(BuiltinDefault, ShapesWindCounterClockwiseOutward) {
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene("builtin:default");
    ASSERT_TRUE(r) << r.error;
    for (const auto& m : r.scene->meshes) {
        for (std::size_t t = 0; t < m.indices.size(); t += 3) {
            const auto& a = m.vertices[m.indices[t]];
            const auto& b = m.vertices[m.indices[t + 1]];
            const auto& c = m.vertices[m.indices[t + 2]];
            const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
            if (glm::length(n) < 1e-7f) continue; // pole triangles of the UV sphere
            ASSERT_GT(glm::dot(n, a.normal + b.normal + c.normal), 0.0f)
                << m.name << " triangle " << t / 3;
        }
    }
}

// Mirrored UV islands have opposite signs of the UV-space triangle area.
TEST(BuiltinDefault, TorusAndBoxHaveMirroredUvIslands) {
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene("builtin:default");
    ASSERT_TRUE(r) << r.error;
    for (const auto& m : r.scene->meshes) {
        if (m.name.find("mirrored") == std::string::npos) continue;
        int positive = 0, negative = 0;
        for (std::size_t t = 0; t < m.indices.size(); t += 3) {
            const glm::vec2 a = m.vertices[m.indices[t]].uv0, b = m.vertices[m.indices[t + 1]].uv0,
                            c = m.vertices[m.indices[t + 2]].uv0;
            const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
            if (area > 1e-9f) ++positive;
            if (area < -1e-9f) ++negative;
        }
        EXPECT_GT(positive, 0) << m.name;
        EXPECT_GT(negative, 0) << m.name;
    }
}

TEST(BuiltinGrid, PlacesNInstances) {
    for (std::uint64_t n : {1u, 7u, 10000u}) {
        const sherpa::scene::LoadResult r =
            sherpa::scene::load_scene("builtin:grid?n=" + std::to_string(n));
        ASSERT_TRUE(r) << r.error;
        EXPECT_EQ(r.scene->instances.size(), n);
        for (const auto& inst : r.scene->instances) ASSERT_TRUE(inst.world_bounds.valid());
    }
}

TEST(BuiltinGrid, RejectsBadSpecs) {
    for (const char* spec :
         {"builtin:grid?n=0", "builtin:grid?n=-3", "builtin:grid?n=12x",
          "builtin:grid?n=", "builtin:grid?n=99999999999", "builtin:nothing", "builtin:"}) {
        const sherpa::scene::LoadResult r = sherpa::scene::load_scene(spec);
        EXPECT_FALSE(r) << spec;
        EXPECT_EQ(r.error.rfind(spec, 0), 0u) << r.error;
    }
}

} // namespace
