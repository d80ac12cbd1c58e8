// Loud about what is not drawn: `info` lists extensions used/required, each marked
// supported or not, and warns about each unsupported one; `render` warns on stderr.
#include "cli/cli_run.h"
#include "test_support.h"

#include <filesystem>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

using sherpa::test::CliRun;
using sherpa::test::run_cli;

std::string glass() {
    return (sherpa::test::data_dir() / "unsupported_material_extensions.gltf").string();
}

TEST(CliUnsupportedExtensions, InfoTextMarksEachExtensionAndWarns) {
    const CliRun r = run_cli("info '" + glass() + "'", "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("extensions used: KHR_materials_emissive_strength (supported), "
                         "ADOBE_materials_thin_transparency (NOT supported: not drawn), "
                         "KHR_materials_clearcoat (NOT supported: not drawn)"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("warning: extensionsUsed[1] ADOBE_materials_thin_transparency is not "
                         "implemented by Sherpa: materials[0] \"Glass\" is drawn without it"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("warning: extensionsUsed[2] KHR_materials_clearcoat"), std::string::npos);
    // Required extensions get their own line (a supported one here).
    const CliRun required = run_cli(
        "info '" + (sherpa::test::data_dir() / "unsupported_used_extension.gltf").string() + "'");
    EXPECT_NE(required.out.find("extensions required: KHR_texture_transform (supported)"),
              std::string::npos)
        << required.out;
}

TEST(CliUnsupportedExtensions, RenderWarnsOnStderr) {
    const std::string png = (std::filesystem::temp_directory_path() /
                             ("sherpa_unsupported_ext_" + std::to_string(::getpid()) + ".png"))
                                .string();
    // stdout discarded: what is left is stderr.
    const CliRun r = run_cli("render '" + glass() + "' -o '" + png +
                                 "' --width 32 --height 32 --no-cache 2>&1 >/dev/null",
                             "");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("warning: extensionsUsed[1] ADOBE_materials_thin_transparency"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("warning: extensionsUsed[2] KHR_materials_clearcoat"), std::string::npos)
        << r.out;
    std::filesystem::remove(png);
}

} // namespace
