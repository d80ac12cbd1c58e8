// `sherpa-cli info --json --time T` against three.js (the CLI half of the motion oracle
// tests, tests/motion/motion_oracle_test.cpp): needs the three_oracle CTest fixture.
#include "cli/cli_run.h"
#include "motion/three_oracle.h"
#include "test_support.h"

#include <algorithm>
#include <utility>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

namespace {

namespace test = sherpa::test;
using nlohmann::json;

// `info --json --time T` reports as posed_bounds the bounds of the vertices three.js
// poses at T (every primitive of the displayed scene).
TEST(MotionOracle, CliPosedBoundsAreThreeJsVertexBounds) {
    const std::pair<const char*, double> cases[] = {{"RiggedSimple", 0.5},
                                                    {"AnimatedMorphSphere", 1.3},
                                                    {"SimpleMorph", 2.2},
                                                    {"BoxAnimated", 1.7}};
    for (const auto& [model, t] : cases) {
        const std::string file = test::gltf_asset(model);
        const auto r = test::run_cli("info '" + file + "' --json --time " + std::to_string(t));
        ASSERT_EQ(r.exit_code, 0) << r.out;
        const json ours = json::parse(r.out);
        const json oracle = test::run_three_oracle(file, 0, {t});
        ASSERT_TRUE(oracle.contains("frames"));
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const json& p : oracle["frames"][0]["primitives"])
            for (std::size_t i = 0; i + 2 < p["positions"].size(); i += 3)
                for (int c = 0; c < 3; ++c) {
                    lo[c] = std::min(lo[c], p["positions"][i + c].get<double>());
                    hi[c] = std::max(hi[c], p["positions"][i + c].get<double>());
                }
        const double size = glm::length(hi - lo);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(ours["posed_bounds"]["min"][c].get<double>(), lo[c], 1e-4 * size) << model;
            EXPECT_NEAR(ours["posed_bounds"]["max"][c].get<double>(), hi[c], 1e-4 * size) << model;
        }
        EXPECT_EQ(ours["pose"]["culling_contains_posed"], true) << model;
    }
}

} // namespace
