// The path tracer's emitters it cannot sample as lights (render/emissive_lights.h) reach
// the user: `render --renderer rt --view lit` prints each reason once on stderr, naming
// the file and the JSON pointer, and its --report carries them; `lab --family lighting`
// (whose reference is the path tracer) prints and reports them too. A static textured
// emitter has no warning, and its emissive image is decoded once: by the texture
// pipeline, whose luminance grid the light list takes (from the cache on a hit too).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "test_support.h"

#include <filesystem>

namespace sherpa::test {
namespace {

using nlohmann::json;

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

struct Rendered {
    std::string err; // stderr alone
    json report;
};

// A small lit, path-traced frame of `file` under the validation layer.
Rendered render_rt(const std::string& file, const std::string& extra = "") {
    const std::string png = temp_path("emissive_warnings", "frame.png");
    const std::string report = temp_path("emissive_warnings", "report.json");
    const CliRun r = run_cli("render " + quoted(file) + " -o " + quoted(png) +
                                 " --renderer rt --view lit --spp 1 --width 16 --height 12 "
                                 "--validation --report " +
                                 quoted(report) + extra,
                             "2>&1 >/dev/null");
    EXPECT_EQ(r.exit_code, 0) << file << "\n" << r.out;
    Rendered out{r.out, json()};
    if (r.exit_code == 0) out.report = read_json(report);
    std::filesystem::remove(png);
    std::filesystem::remove(report);
    return out;
}

struct Case {
    const char* file;
    const char* pointer_and_problem; // after "FILE: "
};

const Case kCases[] = {
    {"emitter_animated.gltf", "/animations: the scene animates (1 animation): its emissive "
                              "triangles move"},
    {"emitter_variants.gltf", "/meshes/1/primitives/0/extensions/KHR_materials_variants: "
                              "material variant 0 'Dark' changes which surfaces emit"},
    {"emitter_bad_image.gltf", "/materials/1/emissiveTexture: its image (/images/0, "},
};

TEST(CliEmissiveWarnings, RenderRtLitPrintsEachOnceWithFileAndPointer) {
    for (const Case& c : kCases) {
        SCOPED_TRACE(c.file);
        const std::string file = (data_dir() / c.file).string();
        const std::string line =
            "warning: path tracer lights: " + file + ": " + c.pointer_and_problem;
        const Rendered r = render_rt(file);
        EXPECT_EQ(count(r.err, line), 1u) << r.err;
        EXPECT_EQ(count(r.err, "path tracer lights:"), 1u) << r.err;
        ASSERT_TRUE(r.report.contains("emissive_lights")) << r.report.dump(2);
        const json& e = r.report["emissive_lights"];
        // The undecodable image's emitter is still sampled (as if white); the others are not.
        EXPECT_EQ(e["triangles"].get<int>(),
                  std::string(c.file) == "emitter_bad_image.gltf" ? 2 : 0);
        ASSERT_EQ(e["warnings"].size(), 1u);
        EXPECT_EQ(("warning: " + e["warnings"][0].get<std::string>()).rfind(line, 0), 0u);
        // The undecodable image was not decoded a second time: the reason is the texture
        // pipeline's.
        EXPECT_EQ(e["images_decoded"].get<int>(), 0);
        if (std::string(c.file) == "emitter_bad_image.gltf") {
            EXPECT_NE(r.err.find("cannot be read (undecodable: "), std::string::npos) << r.err;
        }
    }
}

// The static textured emitter: sampled as lights, no warning, its image's luminance from
// the texture pipeline (decoded there, or read from the cache entry on a hit).
TEST(CliEmissiveWarnings, StaticEmitterTakesTheTexturePipelinesLuminance) {
    const std::string file = (data_dir() / "textured_emitter.gltf").string();
    const std::string cache = temp_path("emissive_warnings", "cache");
    std::filesystem::remove_all(cache);
    for (const char* pass : {"miss", "hit"}) {
        SCOPED_TRACE(pass);
        const Rendered r = render_rt(file, " --cache-dir " + quoted(cache));
        EXPECT_EQ(r.err.find("path tracer lights"), std::string::npos) << r.err;
        const json& e = r.report["emissive_lights"];
        EXPECT_EQ(e["triangles"].get<int>(), 2);
        EXPECT_EQ(e["images_decoded"].get<int>(), 0);
        EXPECT_EQ(e["images_from_textures"].get<int>(), 1);
        EXPECT_TRUE(e["warnings"].empty());
    }
    std::filesystem::remove_all(cache);
}

// lab --family lighting path-traces its reference: the same warning, once, on stderr and
// in the JSON.
TEST(CliEmissiveWarnings, LabLightingReportsThePathTracersWarning) {
    const std::string file = (data_dir() / "emitter_variants.gltf").string();
    const std::string line = "path tracer lights: " + file + ": " + kCases[1].pointer_and_problem;
    const std::string out = temp_path("emissive_warnings", "lab.json");
    // stderr to the pipe, the JSON to `out`.
    const CliRun r = run_cli("lab " + quoted(file) +
                                 " --family lighting --width 16 --height 12 --reference-spp 2 "
                                 "--repeat 1 --environment none --json",
                             "2>&1 > " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_EQ(count(r.out, "warning: " + line), 1u) << r.out;
    const json j = read_json(out);
    std::filesystem::remove(out);
    ASSERT_EQ(j.at("warnings").size(), 1u) << j.dump(2);
    EXPECT_EQ(j["warnings"][0].get<std::string>().rfind(line, 0), 0u);
}

} // namespace
} // namespace sherpa::test
