// Per-corner tangent generation on small hand-built meshes: conventions, welding,
// seams, and every kind of degenerate input.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <sherpa/scene/tangents.h>

namespace sherpa {
namespace {

// A mesh under construction: indexed vertices.
struct TestMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;

    std::uint32_t vertex(glm::vec3 p, glm::vec2 uv, glm::vec3 n = {0, 0, 1}) {
        positions.push_back(p);
        normals.push_back(n);
        uvs.push_back(uv);
        return static_cast<std::uint32_t>(positions.size() - 1);
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        indices.insert(indices.end(), {a, b, c});
    }
    scene::TangentInput input() const { return {positions, normals, uvs, indices}; }
};

struct Result {
    std::vector<glm::vec4> tangents;
    std::vector<scene::TangentFallback> fallbacks;
    scene::TangentStats stats;
};

Result run(const TestMesh& m, scene::TangentMethod method = scene::TangentMethod::MikkTSpace) {
    Result r;
    r.tangents.resize(m.indices.size());
    r.fallbacks.resize(m.indices.size());
    r.stats = scene::generate_corner_tangents(m.input(), method, r.tangents, r.fallbacks);
    return r;
}

// Unit square in the XY plane facing +Z; glTF uv: u along +x, v down the image, i.e.
// along -y. Tangent +x, bitangent (towards decreasing v) +y = cross(+z, +x): w = +1.
TestMesh square(float scale = 1.0f, bool mirror_u = false) {
    TestMesh m;
    auto uv = [&](float x, float y) { return glm::vec2(mirror_u ? 1.0f - x : x, 1.0f - y); };
    const auto a = m.vertex({0, 0, 0}, uv(0, 0)), b = m.vertex({scale, 0, 0}, uv(1, 0));
    const auto c = m.vertex({scale, scale, 0}, uv(1, 1)), d = m.vertex({0, scale, 0}, uv(0, 1));
    m.triangle(a, b, c);
    m.triangle(a, c, d);
    return m;
}

void expect_tangent(const glm::vec4& t, glm::vec3 xyz, float w, float tolerance = 1e-5f) {
    EXPECT_NEAR(t.x, xyz.x, tolerance);
    EXPECT_NEAR(t.y, xyz.y, tolerance);
    EXPECT_NEAR(t.z, xyz.z, tolerance);
    EXPECT_EQ(t.w, w);
}

void expect_finite_unit_orthogonal(const Result& r, const TestMesh& m) {
    for (std::size_t c = 0; c < r.tangents.size(); ++c) {
        const glm::vec4 t = r.tangents[c];
        ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z))
            << "corner " << c;
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f) << "corner " << c;
        EXPECT_TRUE(t.w == 1.0f || t.w == -1.0f);
        const glm::vec3 n = m.normals[m.indices[c]];
        if (std::isfinite(n.x) && glm::length(n) > 0.0f) {
            EXPECT_NEAR(glm::dot(glm::normalize(n), glm::vec3(t)), 0.0f, 1e-5f) << "corner " << c;
        }
    }
}

TEST(Tangents, MethodNamesRoundTrip) {
    for (scene::TangentMethod m : scene::kAllTangentMethods) {
        scene::TangentMethod parsed{};
        ASSERT_TRUE(scene::parse_tangent_method(to_string(m), parsed));
        EXPECT_EQ(parsed, m);
    }
    scene::TangentMethod unused{};
    EXPECT_FALSE(scene::parse_tangent_method("mikk", unused));
}

TEST(Tangents, EmptyInputIsFine) {
    const TestMesh m;
    const Result r = run(m);
    EXPECT_TRUE(r.tangents.empty());
    EXPECT_EQ(r.stats.fallbacks(), 0u);
}

TEST(Tangents, BrokenContractsThrow) {
    TestMesh m = square();
    std::vector<glm::vec4> out(m.indices.size());
    m.indices.push_back(0);
    std::vector<glm::vec4> wrong(m.indices.size());
    EXPECT_THROW(
        scene::generate_corner_tangents(m.input(), scene::TangentMethod::MikkTSpace, wrong),
        std::invalid_argument);
    m.indices.pop_back();
    m.indices[0] = 17;
    EXPECT_THROW(scene::generate_corner_tangents(m.input(), scene::TangentMethod::MikkTSpace, out),
                 std::invalid_argument);
    m.indices[0] = 0;
    m.uvs.pop_back();
    EXPECT_THROW(scene::generate_corner_tangents(m.input(), scene::TangentMethod::MikkTSpace, out),
                 std::invalid_argument);
    m.uvs.push_back({});
    std::vector<glm::vec4> short_out(2);
    EXPECT_THROW(
        scene::generate_corner_tangents(m.input(), scene::TangentMethod::MikkTSpace, short_out),
        std::invalid_argument);
}

TEST(Tangents, GltfHandednessOnAPlainSquare) {
    for (scene::TangentMethod method : scene::kAllTangentMethods) {
        const TestMesh m = square();
        const Result r = run(m, method);
        for (const glm::vec4& t : r.tangents) expect_tangent(t, {1, 0, 0}, 1.0f);
        EXPECT_EQ(r.stats.fallbacks(), 0u) << to_string(method);
    }
}

TEST(Tangents, MirroredUvsFlipTangentAndHandedness) {
    for (scene::TangentMethod method : scene::kAllTangentMethods) {
        const TestMesh m = square(1.0f, true);
        const Result r = run(m, method);
        for (const glm::vec4& t : r.tangents) expect_tangent(t, {-1, 0, 0}, -1.0f);
    }
}

// Two squares sharing an edge whose uvs mirror across it: the shared vertices are one
// welded vertex with corners of both orientations, so MikkTSpace keeps two tangent spaces.
TEST(Tangents, MirrorSeamKeepsBothSidesExact) {
    TestMesh m;
    const auto a = m.vertex({-1, 0, 0}, {1, 1}), b = m.vertex({0, 0, 0}, {0, 1});
    const auto c = m.vertex({0, 1, 0}, {0, 0}), d = m.vertex({-1, 1, 0}, {1, 0});
    const auto e = m.vertex({1, 0, 0}, {1, 1}), f = m.vertex({1, 1, 0}, {1, 0});
    m.triangle(a, b, c);
    m.triangle(a, c, d); // left: u grows towards -x (mirrored)
    m.triangle(b, e, f);
    m.triangle(b, f, c); // right: u grows towards +x
    const Result r = run(m);
    for (std::size_t k = 0; k < 6; ++k) expect_tangent(r.tangents[k], {-1, 0, 0}, -1.0f);
    for (std::size_t k = 6; k < 12; ++k) expect_tangent(r.tangents[k], {1, 0, 0}, 1.0f);
    // Without splitting, the shared vertices b and c take whichever side wrote last.
    const Result welded = run(m, scene::TangentMethod::MikkTSpaceWelded);
    EXPECT_EQ(welded.tangents[1], welded.tangents[6]);
}

// Welding is by value: duplicated vertices with equal attributes act as one vertex,
// so an indexed and an unindexed copy of a mesh give the same tangents.
TEST(Tangents, WeldingIsByValueNotByIndex) {
    TestMesh indexed;
    const auto a = indexed.vertex({0, 0, 0}, {0, 1}), b = indexed.vertex({1, 0, 0.5f}, {1, 1});
    const auto c = indexed.vertex({1, 1, 0}, {1, 0}), d = indexed.vertex({0, 1, -0.5f}, {0, 0});
    for (auto& n : indexed.normals) n = glm::normalize(glm::vec3(0.1f, 0.2f, 1.0f));
    indexed.triangle(a, b, c);
    indexed.triangle(a, c, d);
    TestMesh flat;
    for (std::uint32_t i : indexed.indices)
        flat.indices.push_back(
            flat.vertex(indexed.positions[i], indexed.uvs[i], indexed.normals[i]));
    const Result r1 = run(indexed), r2 = run(flat);
    EXPECT_EQ(r1.tangents, r2.tangents);
}

TEST(Tangents, ZeroAreaUvTriangleFallsBackOrthogonal) {
    TestMesh m;
    const auto a = m.vertex({0, 0, 0}, {0.5f, 0.5f}), b = m.vertex({1, 0, 0}, {0.5f, 0.5f});
    const auto c = m.vertex({0, 1, 0}, {0.5f, 0.5f});
    m.triangle(a, b, c);
    for (scene::TangentMethod method : scene::kAllTangentMethods) {
        const Result r = run(m, method);
        expect_finite_unit_orthogonal(r, m);
        EXPECT_EQ(r.stats.count(scene::TangentFallback::DegenerateUv), 3u) << to_string(method);
    }
    // The textbook Lengyel formula divides by the uv area: that is counted.
    EXPECT_EQ(run(m, scene::TangentMethod::Lengyel).stats.nonfinite_before_guard, 3u);
}

TEST(Tangents, CollinearAndCoincidentCornersFallBack) {
    TestMesh m;
    const auto a = m.vertex({0, 0, 0}, {0, 0}), b = m.vertex({1, 0, 0}, {1, 0});
    const auto c = m.vertex({2, 0, 0}, {0, 1});
    m.triangle(a, b, c); // collinear
    const auto d = m.vertex({5, 5, 5}, {0, 0});
    m.triangle(d, d, m.vertex({6, 5, 5}, {1, 0})); // repeated vertex
    const auto e = m.vertex({3, 3, 3}, {0, 0}), f = m.vertex({3, 3, 3}, {1, 0});
    m.triangle(e, f, m.vertex({3, 3, 3}, {0, 1})); // coincident, distinct uvs
    // MikkTSpace: corners whose tangent would come only from zero-area triangles fall
    // back (the reference would still return dP/du along the collinear line). Lengyel,
    // as textbooks write it, keeps the collinear triangle's dP/du.
    const std::size_t expected[] = {9, 9, 6};
    for (scene::TangentMethod method : scene::kAllTangentMethods) {
        const Result r = run(m, method);
        expect_finite_unit_orthogonal(r, m);
        EXPECT_EQ(r.stats.count(scene::TangentFallback::DegeneratePosition),
                  expected[static_cast<std::size_t>(method)])
            << to_string(method);
        EXPECT_EQ(r.stats.fallbacks(), r.stats.count(scene::TangentFallback::DegeneratePosition));
    }
    expect_tangent(run(m, scene::TangentMethod::Lengyel).tangents[1], {1, 0, 0}, -1.0f);
}

// A degenerate triangle attached to a good one takes the good one's tangent at shared
// vertices, as the reference does.
TEST(Tangents, DegenerateTriangleBorrowsFromItsWeldedNeighbour) {
    TestMesh m = square();
    m.triangle(0, 1, 1);
    const Result r = run(m);
    expect_tangent(r.tangents[6], {1, 0, 0}, 1.0f);
    EXPECT_EQ(r.fallbacks[6], scene::TangentFallback::None);
}

TEST(Tangents, NanAndZeroNormalsNeverYieldNan) {
    TestMesh m = square();
    m.normals[0] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    m.normals[2] = glm::vec3(0.0f);
    for (scene::TangentMethod method : scene::kAllTangentMethods) {
        const Result r = run(m, method);
        expect_finite_unit_orthogonal(r, m);
        EXPECT_EQ(r.stats.count(scene::TangentFallback::NonFiniteInput), 2u) << to_string(method);
        EXPECT_EQ(r.stats.count(scene::TangentFallback::InvalidNormal), 2u) << to_string(method);
    }
}

TEST(Tangents, NonFinitePositionsAndUvsNeverYieldNan) {
    TestMesh m = square();
    m.positions[1].x = std::numeric_limits<float>::infinity();
    m.uvs[3].y = std::numeric_limits<float>::quiet_NaN();
    for (scene::TangentMethod method : scene::kAllTangentMethods) {
        const Result r = run(m, method);
        expect_finite_unit_orthogonal(r, m);
        EXPECT_EQ(r.stats.count(scene::TangentFallback::NonFiniteInput), 6u) << to_string(method);
    }
}

TEST(Tangents, NonUnitNormalsAreRescaledBeforeProjection) {
    TestMesh m = square();
    for (auto& n : m.normals) n = glm::vec3(0.0f, 0.6f, 3.0f); // tilted and long
    const Result r = run(m);
    EXPECT_EQ(r.stats.rescaled_normals, 4u); // once per distinct vertex
    expect_finite_unit_orthogonal(r, m);
    EXPECT_EQ(r.stats.fallbacks(), 0u);
}

TEST(Tangents, HugeAndTinyCoordinatesKeepTheirTangent) {
    for (float scale : {1e-30f, 1e-20f, 1e-6f, 1e6f, 1e20f, 1e30f}) {
        for (scene::TangentMethod method :
             {scene::TangentMethod::MikkTSpace, scene::TangentMethod::MikkTSpaceWelded}) {
            const TestMesh m = square(scale);
            const Result r = run(m, method);
            for (const glm::vec4& t : r.tangents) expect_tangent(t, {1, 0, 0}, 1.0f);
            EXPECT_EQ(r.stats.fallbacks(), 0u) << scale;
        }
    }
}

// Three triangles on one edge (a "butterfly"): pairing must not crash or lose corners.
TEST(Tangents, NonManifoldEdgesAreHandled) {
    TestMesh m;
    const auto a = m.vertex({0, 0, 0}, {0, 1}), b = m.vertex({1, 0, 0}, {1, 1});
    m.triangle(a, b, m.vertex({0.5f, 1, 0}, {0.5f, 0}));
    m.triangle(b, a, m.vertex({0.5f, -1, 0}, {0.5f, 2}));
    m.triangle(b, a, m.vertex({0.5f, -0.5f, 0}, {0.5f, 1.5f}));
    const Result r = run(m);
    expect_finite_unit_orthogonal(r, m);
    EXPECT_EQ(r.stats.fallbacks(), 0u);
}

// On a curved surface (a cylinder strip), MikkTSpace and Lengyel agree closely, and the
// welded variant equals MikkTSpace because no vertex has conflicting corners.
TEST(Tangents, MethodsAgreeOnSmoothSurfaces) {
    TestMesh m;
    const int segments = 16;
    for (int i = 0; i <= segments; ++i) {
        const float angle = 1.5f * static_cast<float>(i) / segments;
        const glm::vec3 n(std::cos(angle), std::sin(angle), 0.0f);
        m.vertex(glm::vec3(n.x, n.y, 0), {i / float(segments), 1.0f}, n);
        m.vertex(glm::vec3(n.x, n.y, 1), {i / float(segments), 0.0f}, n);
    }
    for (std::uint32_t i = 0; i < segments; ++i) {
        m.triangle(2 * i, 2 * i + 2, 2 * i + 3);
        m.triangle(2 * i, 2 * i + 3, 2 * i + 1);
    }
    const Result mikk = run(m), welded = run(m, scene::TangentMethod::MikkTSpaceWelded),
                 lengyel = run(m, scene::TangentMethod::Lengyel);
    EXPECT_EQ(mikk.tangents, welded.tangents);
    for (std::size_t c = 0; c < mikk.tangents.size(); ++c) {
        EXPECT_GT(glm::dot(glm::vec3(mikk.tangents[c]), glm::vec3(lengyel.tangents[c])), 0.999f);
        EXPECT_EQ(mikk.tangents[c].w, lengyel.tangents[c].w);
    }
}

} // namespace
} // namespace sherpa

namespace sherpa {
namespace {

// A workspace carries memory, never results: reusing one across meshes of different
// sizes and methods gives what fresh calls give.
TEST(Tangents, WorkspaceReuseNeverChangesResults) {
    TestMesh small = square(), large;
    for (int i = 0; i < 40; ++i) {
        const float x = float(i);
        const auto a = large.vertex({x, 0, 0}, {x, 1}), b = large.vertex({x + 1, 0, 0}, {x + 1, 1});
        const auto c = large.vertex({x + 1, 1, 0.5f}, {x + 1, 0}),
                   d = large.vertex({x, 1, 0.5f}, {x, 0});
        large.triangle(a, b, c);
        large.triangle(a, c, d);
        large.triangle(a, a, c); // dropped (repeated vertex)
    }
    scene::TangentWorkspace workspace;
    for (int round = 0; round < 2; ++round)
        for (const TestMesh* m : {&large, &small, &large})
            for (scene::TangentMethod method : scene::kAllTangentMethods) {
                const Result fresh = run(*m, method);
                std::vector<glm::vec4> reused(m->indices.size());
                std::vector<scene::TangentFallback> fallbacks(m->indices.size());
                const scene::TangentStats stats = scene::generate_corner_tangents(
                    m->input(), method, reused, fallbacks, &workspace);
                EXPECT_EQ(reused, fresh.tangents) << to_string(method);
                EXPECT_EQ(fallbacks, fresh.fallbacks) << to_string(method);
                EXPECT_EQ(stats.corners, fresh.stats.corners) << to_string(method);
            }
}

TEST(Tangents, StatsAddUp) {
    scene::TangentStats a, b;
    a.corners[0] = 3;
    a.corners[static_cast<std::size_t>(scene::TangentFallback::DegenerateUv)] = 2;
    b.corners[static_cast<std::size_t>(scene::TangentFallback::ZeroResult)] = 1;
    b.nonfinite_before_guard = 4;
    b.rescaled_normals = 5;
    a += b;
    EXPECT_EQ(a.fallbacks(), 3u);
    EXPECT_EQ(a.count(scene::TangentFallback::None), 3u);
    EXPECT_EQ(a.nonfinite_before_guard, 4u);
    EXPECT_EQ(a.rescaled_normals, 5u);
    for (std::size_t c = 0; c < scene::kTangentFallbackCauses; ++c)
        EXPECT_NE(to_string(scene::TangentFallback(c)), "unknown");
}

} // namespace
} // namespace sherpa
