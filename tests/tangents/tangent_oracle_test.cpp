// Exact MikkTSpace against the oracle: the npm `mikktspace` package (a WebAssembly build
// of the reference), run through Node.js on every triangle primitive with normals and uvs
// of every sample model. Every corner must match to 0.01° with the same handedness,
// except corners we report as fallbacks, which the oracle must itself leave degenerate
// (zero, NaN, or its default tangent on a degenerate triangle).
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <sherpa/scene/tangent_compare.h>
#include <sherpa/scene/tangents.h>

#include "gltf_primitives.h"
#include "oracle_runner.h"

namespace sherpa::tools {
namespace {

struct OracleCase {
    std::string model;
    GltfPrimitive primitive;
    scene::TangentInput input() const {
        return {primitive.positions, primitive.normals, primitive.uvs, primitive.indices};
    }
};

TEST(TangentOracle, ExactMikkTSpaceMatchesTheReferenceOnEverySampleModel) {
    std::vector<OracleCase> cases;
    for (const std::string& model : sample_models(SHERPA_ASSETS_DIR))
        for (GltfPrimitive& p : read_gltf_primitives(sample_model_path(SHERPA_ASSETS_DIR, model)))
            if (!p.normals.empty() && !p.uvs.empty() && !p.indices.empty())
                cases.push_back({model, std::move(p)});
    ASSERT_GE(cases.size(), 10u) << "sample models missing under " << SHERPA_ASSETS_DIR;
    std::vector<scene::TangentInput> inputs;
    for (const OracleCase& c : cases) inputs.push_back(c.input());
    const OracleResult oracle =
        run_oracle({SHERPA_NODE, SHERPA_ORACLE_SCRIPT, SHERPA_ORACLE_CACHE, "."}, inputs);

    std::size_t compared = 0, skipped = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const OracleCase& c = cases[i];
        const GltfPrimitive& p = c.primitive;
        const std::vector<glm::vec4>& reference = oracle.tangents[i];
        std::vector<glm::vec4> ours(p.indices.size());
        std::vector<scene::TangentFallback> fallback(p.indices.size());
        scene::generate_corner_tangents(c.input(), scene::TangentMethod::MikkTSpace, ours,
                                        fallback);
        std::vector<std::uint8_t> skip(ours.size(), 0);
        for (std::size_t k = 0; k < ours.size(); ++k) {
            if (fallback[k] == scene::TangentFallback::None) {
                // An angle against a zero vector would read as 0°: rule it out first.
                EXPECT_FALSE(oracle_unusable(reference[k]))
                    << c.model << " corner " << k << ": a tangent where the oracle has none";
                continue;
            }
            EXPECT_TRUE(oracle_agrees_with_fallback(reference[k], fallback[k]))
                << c.model << " mesh " << p.mesh << " prim " << p.primitive << " corner " << k
                << ": fallback (" << to_string(fallback[k]) << ") where the oracle has a tangent";
            skip[k] = 1;
            ++skipped;
        }
        const scene::TangentComparison stats = scene::compare_tangents(ours, reference, skip);
        compared += stats.corners;
        const std::string where =
            c.model + " mesh " + std::to_string(p.mesh) + " prim " + std::to_string(p.primitive);
        EXPECT_EQ(stats.nonfinite, 0u) << where;
        EXPECT_LE(stats.max, 0.01) << where;
        EXPECT_EQ(stats.flips, 0u) << where;
        std::printf("%-40s %7llu corners, max %.2e deg, p99 %.2e deg, %llu flips\n", where.c_str(),
                    (unsigned long long)stats.corners, stats.max, stats.p99,
                    (unsigned long long)stats.flips);
    }
    std::printf("compared %zu corners, %zu fallback corners skipped\n", compared, skipped);
}

// The reference reproduces NormalTangentMirrorTest's authored tangents to 0.002° (p99);
// exact MikkTSpace must too.
TEST(TangentOracle, ReproducesAuthoredMirrorTestTangents) {
    const auto prims =
        read_gltf_primitives(sample_model_path(SHERPA_ASSETS_DIR, "NormalTangentMirrorTest"));
    ASSERT_FALSE(prims.empty());
    for (const GltfPrimitive& p : prims) {
        ASSERT_FALSE(p.tangents.empty());
        std::vector<glm::vec4> ours(p.indices.size());
        scene::generate_corner_tangents({p.positions, p.normals, p.uvs, p.indices},
                                        scene::TangentMethod::MikkTSpace, ours);
        std::vector<glm::vec4> authored;
        for (std::uint32_t i : p.indices) authored.push_back(p.tangents[i]);
        const scene::TangentComparison stats = scene::compare_tangents(ours, authored);
        EXPECT_LE(stats.p99, 0.005);
        EXPECT_EQ(stats.flips, 0u);
        std::printf("NormalTangentMirrorTest vs authored: p99 %.2e deg, max %.2e deg\n", stats.p99,
                    stats.max);
    }
}

} // namespace
} // namespace sherpa::tools
