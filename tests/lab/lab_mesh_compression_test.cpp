// Known answers of the mesh-compression family on synthetic meshes: the half-step
// bound in world space, errors falling with bits, exact byte counts, the meshopt codec's
// round trip, and scenes with nothing to quantize.
#include "lab/lab_scenes.h"

#include <sherpa/lab/families.h>

#include <cmath>
#include <limits>

#include "lab/lab_figures.h"
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace {

using namespace sherpa;
using sherpa::test::failures;
using sherpa::test::figure;

// Bits of a method's parameters "vp=14 vn=8 vt=12" (0 for the float reference).
int bits_of(const lab::MethodResult& m, const char* key) {
    const std::size_t at = m.method.parameters.find(key);
    return at == std::string::npos ? 0 : std::atoi(m.method.parameters.c_str() + at + 3);
}

TEST(LabMeshCompression, KnownBoundsBytesAndMonotonicErrors) {
    const int n = 20; // 400 vertices, 2166 indices
    scene::Scene scene = test::scene_of({test::wavy_grid(n)});
    scene.instances[0].world = glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)); // errors in world
    const lab::FamilyReport r = lab::make_family("mesh-compression")->run(scene, {});
    EXPECT_EQ(r.chart_error, "position_rms");
    EXPECT_EQ(r.chart_x, "bytes");
    ASSERT_EQ(r.methods.size(), 16u);
    const std::uint64_t vertices = 400, index_bytes = 19 * 19 * 6 * 2; // 16-bit indices
    const lab::MethodResult* previous = nullptr;
    for (const lab::MethodResult& m : r.methods) {
        SCOPED_TRACE(m.method.name + " " + m.method.parameters);
        ASSERT_TRUE(m.ran) << m.note;
        EXPECT_TRUE(m.failures.empty());
        EXPECT_GT(m.time, 0.0);
        const int vp = bits_of(m, "vp="), vn = bits_of(m, "vn="), vt = bits_of(m, "vt=");
        // World step: the largest extent (3, x) / (2^bits - 1), times the node's scale 2.
        const double step = vp ? 2.0 * 3.0 / double((1 << vp) - 1) : 0.0;
        EXPECT_NEAR(figure(m, "position_step"), step, 1e-6 * step);
        EXPECT_LE(figure(m, "position_max"), std::sqrt(3.0) * step / 2 * (1 + 1e-5) + 1e-6);
        EXPECT_LE(figure(m, "position_rms"), figure(m, "position_max"));
        if (!vp) {
            for (const char* e : {"position_max", "normal_max_deg", "uv_max"})
                EXPECT_EQ(figure(m, e), 0.0) << e;
        } else {
            EXPECT_GT(figure(m, "position_max"), 0.0);
            // UV step per axis: 2 / (2^vt - 1) on u.
            EXPECT_LE(figure(m, "uv_max"), std::hypot(1.0, 0.5) / double((1 << vt) - 1) + 1e-6);
            // A normal component is off by at most half a step of 1/(2^(vn-1) - 1); on
            // the octahedron, x/y by half a step of 2/(2^(vn-1) - 1).
            const double half = 0.5 / double((1 << (vn - 1)) - 1);
            EXPECT_LE(figure(m, "normal_max_deg"),
                      m.method.name.ends_with("-oct")
                          ? glm::degrees(2.0 * std::asin(1.5 * 2.0 * half))
                          : glm::degrees(2.0 * std::sqrt(3.0) * half));
        }
        const bool meshopt = m.method.group == "meshopt codec";
        if (!meshopt) {
            // 4-byte aligned elements: positions 12 (float), 4 (<= 8 bits) or 8; normals
            // the same; uv 8 (float) or 4.
            const std::uint64_t per_vertex =
                vp == 0 ? 32 : (vp <= 8 ? 4 : 8) + (vn <= 8 ? 4 : 8) + 4;
            EXPECT_EQ(figure(m, "vertex_bytes"), double(per_vertex * vertices));
            EXPECT_EQ(figure(m, "index_bytes"), double(index_bytes));
            EXPECT_EQ(figure(m, "bytes"), double(per_vertex * vertices + index_bytes));
        } else {
            // The same bits without the codec.
            const lab::MethodResult* twin = nullptr;
            for (const lab::MethodResult& t : r.methods)
                if (t.method.group != m.method.group && t.method.parameters == m.method.parameters)
                    twin = &t;
            ASSERT_NE(twin, nullptr);
            for (const char* e : {"position_max", "position_rms", "uv_max"})
                EXPECT_EQ(figure(m, e), figure(*twin, e)) << "the codec is lossless: " << e;
            if (!m.method.name.ends_with("-oct")) {
                EXPECT_EQ(figure(m, "normal_mean_deg"), figure(*twin, "normal_mean_deg"));
            }
            EXPECT_LT(figure(m, "bytes"), figure(*twin, "bytes"));
        }
        const int previous_vp = previous ? bits_of(*previous, "vp=") : 0;
        if (previous_vp != 0 && previous->method.name == m.method.name) {
            for (const char* e : {"position_rms", "position_max", "normal_mean_deg", "uv_rms"}) {
                EXPECT_LE(figure(m, e), figure(*previous, e)) << "falls with bits: " << e;
            }
            if (vp > previous_vp) {
                EXPECT_LT(figure(m, "position_rms"), figure(*previous, "position_rms"));
            }
        }
        previous = &m;
    }
}

TEST(LabMeshCompression, UvErrorInTexelsOfTheBaseColourTexture) {
    scene::Scene scene = test::scene_of({test::wavy_grid(13)}); // no uv on the grid of 2^vt - 1
    lab::FamilyReport r = lab::make_family("mesh-compression")->run(scene, {});
    EXPECT_EQ(r.methods[1].error("uv_max_texels"), nullptr) << "no texture, no texel figure";
    scene::ImageRecord image; // generated in code: the size is in the record
    image.width = 512, image.height = 256;
    image.pixels.resize(512 * 256 * 4);
    scene.images.push_back(image);
    scene.textures.push_back({"base", 0, -1, scene::kRoleColor});
    scene.materials[0].base_color.texture = 0;
    r = lab::make_family("mesh-compression")->run(scene, {});
    for (const lab::MethodResult& m : r.methods) {
        SCOPED_TRACE(m.method.name + " " + m.method.parameters);
        const int vt = bits_of(m, "vt=");
        // Half a step on u (range 2) and v (range 1), in texels of 512 x 256.
        const double half_u = vt ? 1.0 / double((1 << vt) - 1) : 0.0, half_v = half_u / 2;
        // Slack: a float ulp of u near 2 (2.4e-7) in texels.
        EXPECT_LE(figure(m, "uv_max_texels"), std::hypot(512 * half_u, 256 * half_v) + 2e-4);
        EXPECT_LE(figure(m, "uv_max_texels"), figure(m, "uv_max") * 512 + 1e-9);
        EXPECT_GE(figure(m, "uv_max_texels"), figure(m, "uv_max") * 256 - 1e-9);
        EXPECT_EQ(figure(m, "uv_max_texels") > 0.0, vt > 0);
    }
}

TEST(LabMeshCompression, TangentFramesThatCollapseAreFailures) {
    scene::Mesh m = test::mirrored_strip();
    m.provenance[std::size_t(scene::VertexAttribute::Tangent)] = scene::Provenance::Authored;
    // Tangents 0.003 rad off the normal: 8-bit snorm rounds the x component to 0,
    // so the bitangent cross(n, t) vanishes; 12 bits keep it.
    for (scene::Vertex& v : m.vertices)
        v.tangent = glm::vec4(glm::normalize(glm::vec3(0.003f, 0, 1)), 1);
    const lab::FamilyReport r = lab::make_family("mesh-compression")->run(test::scene_of({m}), {});
    const std::string cause = "tangent frame flipped (bitangent reversed)";
    for (const lab::MethodResult& x : r.methods) {
        SCOPED_TRACE(x.method.name + " " + x.method.parameters);
        ASSERT_TRUE(x.ran);
        EXPECT_EQ(failures(x, cause), bits_of(x, "vn=") == 8 ? 6u : 0u);
        EXPECT_GE(figure(x, "tangent_max_deg"), 0.0);
    }
}

TEST(LabMeshCompression, NothingToQuantizeIsSaidNotHidden) {
    for (const scene::Scene& scene : {test::scene_of({}), test::scene_of({scene::Mesh{}})}) {
        const lab::FamilyReport r = lab::make_family("mesh-compression")->run(scene, {});
        ASSERT_EQ(r.methods.size(), 16u);
        for (const lab::MethodResult& m : r.methods) {
            EXPECT_FALSE(m.ran);
            EXPECT_FALSE(m.note.empty());
        }
        EXPECT_FALSE(r.notes.empty());
    }
    scene::Mesh bad = test::wavy_grid(3);
    for (scene::Vertex& v : bad.vertices) v.position.x = std::numeric_limits<float>::quiet_NaN();
    scene::Mesh partly = test::wavy_grid(3);
    partly.vertices[4].position.y = INFINITY;
    scene::Mesh huge = test::wavy_grid(3); // near FLT_MAX, drawn under a scale of 10
    for (scene::Vertex& v : huge.vertices) v.position *= 1e37f;
    const lab::FamilyReport r =
        lab::make_family("mesh-compression")->run(test::scene_of({bad, partly}), {});
    scene::Scene far = test::scene_of({huge});
    far.instances[0].world = glm::scale(glm::mat4(1.0f), glm::vec3(10.0f));
    for (const lab::MethodResult& m : lab::make_family("mesh-compression")->run(far, {}).methods) {
        SCOPED_TRACE(m.method.name + " " + m.method.parameters);
        EXPECT_TRUE(m.failures.empty());
        EXPECT_TRUE(std::isfinite(figure(m, "position_rms")));
        EXPECT_LE(figure(m, "position_max"),
                  std::sqrt(3.0) / 2 * figure(m, "position_step") * (1 + 1e-6));
    }
    for (const lab::MethodResult& m : r.methods) {
        SCOPED_TRACE(m.method.name + " " + m.method.parameters);
        ASSERT_TRUE(m.ran) << "the finite mesh is measured";
        EXPECT_EQ(failures(m, "no finite POSITION"), 9u);
        EXPECT_EQ(failures(m, "non-finite POSITION (left out)"), 1u);
        EXPECT_TRUE(std::isfinite(figure(m, "position_max")));
        EXPECT_EQ(m.note, "9 vertices");
    }
}

} // namespace
