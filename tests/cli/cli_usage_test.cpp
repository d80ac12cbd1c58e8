// sherpa-cli's usage texts and the messages a new user meets first: `COMMAND --help`
// prints that command's usage and exits 0, a usage error is one line and a pointer,
// the top-level help lists every Lab family, every command takes one camera syntax,
// and the warnings say each thing once and only when it applies.
#include "cli/cli_run.h"
#include "test_support.h"

#include <sherpa/lab/family.h>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace {

namespace test = sherpa::test;
using test::CliRun;
using test::run_cli;

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// The commands the top-level help names ("sherpa-cli NAME ..." lines), in order.
std::vector<std::string> command_names() {
    std::vector<std::string> names;
    for (const std::string& line : lines_of(run_cli("--help").out)) {
        if (line.rfind("sherpa-cli ", 0) != 0) continue;
        const std::string name = line.substr(11, line.find(' ', 11) - 11);
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    return names;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

} // namespace

TEST(CliUsage, EveryCommandPrintsItsUsageWithHelpAndExitsZero) {
    const std::vector<std::string> names = command_names();
    for (const char* expected :
         {"info", "cull", "tangents", "textures", "render", "rt", "lab", "compare", "budget"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
    for (const std::string& name : names) {
        for (const char* flag : {"--help", "-h"}) {
            const CliRun r = run_cli(name + " " + flag, "2>&1");
            EXPECT_EQ(r.exit_code, 0) << name << " " << flag << "\n" << r.out;
            EXPECT_EQ(r.out.rfind("usage: sherpa-cli " + name + " ", 0), 0u) << r.out;
        }
        // After other arguments too, and `help COMMAND` says the same.
        const CliRun late = run_cli(name + " Box.gltf --json --help", "2>&1");
        EXPECT_EQ(late.exit_code, 0) << late.out;
        EXPECT_EQ(late.out, run_cli("help " + name).out);
    }
}

TEST(CliUsage, AUsageErrorIsOneLineAndAPointerToHelp) {
    const struct {
        std::string args, message;
    } cases[] = {
        {"info '" + test::gltf_asset("Box") + "' --bogus", "error: unknown option '--bogus'"},
        {"render", "error: no SCENE given"},
        {"cull", "error: no SCENE given"},
        {"rt '" + test::gltf_asset("Box") + "' --rt maybe", "error: --rt needs on or off"},
        {"lab x --family nope", "error: unknown family 'nope'"},
        {"budget", "error: no SCENE given"},
        {"compare one", "error: give two files"},
        {"tangents", "error: no SCENE given"},
        {"textures", "error: no SCENE given"},
    };
    for (const auto& c : cases) {
        const CliRun r = run_cli(c.args, "2>&1 >/dev/null");
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.out;
        const std::vector<std::string> lines = lines_of(r.out);
        ASSERT_EQ(lines.size(), 2u) << c.args << "\n" << r.out;
        EXPECT_EQ(lines[0], c.message) << c.args;
        const std::string command = c.args.substr(0, c.args.find(' '));
        EXPECT_EQ(lines[1], "run 'sherpa-cli " + command + " --help' for usage") << c.args;
    }
    const CliRun unknown = run_cli("frobnicate", "2>&1 >/dev/null");
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_EQ(lines_of(unknown.out).size(), 2u) << unknown.out;
}

TEST(CliUsage, TopLevelHelpListsEveryLabFamily) {
    const CliRun r = run_cli("--help", "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0);
    std::string families;
    for (std::string_view name : sherpa::lab::family_names())
        families += (families.empty() ? "" : "|") + std::string(name);
    EXPECT_NE(r.out.find("--family " + families + " "), std::string::npos) << r.out;
    EXPECT_NE(families.find("shadows"), std::string::npos);
}

// `cull` parses cameras with the renderer's parser: auto, gltf:N and explicit ones.
TEST(CliUsage, CullTakesTheCameraSyntaxRenderTakes) {
    const std::string box = test::gltf_asset("Box");
    const CliRun framed = run_cli("cull '" + box + "' --camera auto --json", "2>/dev/null");
    ASSERT_EQ(framed.exit_code, 0) << framed.out;
    const auto j = nlohmann::json::parse(framed.out);
    EXPECT_EQ(j["passes"][0]["visible"].size(), 1u) << "auto frames the box: it is in view";
    // The default is auto, as for render.
    const auto by_default =
        nlohmann::json::parse(run_cli("cull '" + box + "' --json", "2>/dev/null").out);
    EXPECT_EQ(by_default["passes"][0]["cull_view_projection"],
              j["passes"][0]["cull_view_projection"]);
    const CliRun placed = run_cli("cull '" + test::gltf_asset("Cameras") + "' --camera gltf:0");
    EXPECT_EQ(placed.exit_code, 0) << placed.out;
    const CliRun missing = run_cli("cull '" + box + "' --camera gltf:3");
    EXPECT_EQ(missing.exit_code, 1) << missing.out;
    EXPECT_NE(missing.out.find("camera gltf:3: the scene places 0 camera(s)"), std::string::npos)
        << missing.out;
    const CliRun bad = run_cli("cull '" + box + "' --camera gltf:x", "2>&1 >/dev/null");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.out.find("gltf:N needs a camera index"), std::string::npos) << bad.out;
}

// The default-pose warning appears only where no pose was asked for, and not from the
// importer (which the editor shares: it has a timeline).
TEST(CliUsage, DefaultPoseWarningOnlyWithoutAPose) {
    const std::string rigged = test::gltf_asset("RiggedSimple");
    const CliRun plain = run_cli("cull '" + rigged + "' --json", "2>&1 >/dev/null");
    EXPECT_EQ(count(plain.out, "draw the default pose unless given"), 1u) << plain.out;
    for (const char* pose : {"--time 0.5", "--animation 0 --time 2", "--pose bind"}) {
        const CliRun posed = run_cli("cull '" + rigged + "' --json " + pose, "2>&1 >/dev/null");
        EXPECT_EQ(posed.exit_code, 0) << posed.out;
        EXPECT_EQ(posed.out.find("default pose"), std::string::npos) << pose << "\n" << posed.out;
    }
    const CliRun info = run_cli("info '" + rigged + "'");
    EXPECT_EQ(info.out.find("default pose unless"), std::string::npos) << info.out;
}

// A missing image is reported once, by the texture layer, with its path; tinygltf's raw
// "File not found" line is not repeated.
TEST(CliUsage, MissingImageIsReportedOnce) {
    const std::string file = (test::data_dir() / "missing_texture.gltf").string();
    const CliRun r = run_cli("info '" + file + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_EQ(count(r.out, "does_not_exist.png"), 1u) << r.out;
    EXPECT_EQ(r.out.find("File not found"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("name = ["), std::string::npos) << r.out;
}

// `budget` says an image is missing (with its path), not that it lacks bytes.
TEST(CliUsage, BudgetSaysAMissingImageIsMissing) {
    const std::string file = (test::data_dir() / "missing_texture.gltf").string();
    const CliRun r = run_cli("budget '" + file + "'", "2>&1");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_EQ(r.out.find("neither encoded bytes"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("missing: " + (test::data_dir() / "does_not_exist.png").string()),
              std::string::npos)
        << r.out;
}

// The start-up cost: `info` on a file without images to decode loads no OpenImageIO
// (its closure is ~250 libraries), nor does one whose PNGs are probed in process. The
// dynamic loader's own account (LD_DEBUG=libs) lists every object it loads.
TEST(CliUsage, InfoLoadsNoOpenImageIO) {
    for (const char* model : {"Box", "BoxTextured", "Duck"}) {
        const std::string cmd = "LD_DEBUG=libs " + std::string(SHERPA_CLI_PATH) + " info '" +
                                test::gltf_asset(model) + "' 2>&1 >/dev/null";
        FILE* p = popen(cmd.c_str(), "r");
        ASSERT_NE(p, nullptr);
        std::string log;
        char buf[4096];
        for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) log.append(buf, n);
        EXPECT_EQ(pclose(p), 0);
        // The method sees what is loaded: libc is.
        EXPECT_NE(log.find("libc.so"), std::string::npos) << log.substr(0, 2000);
        EXPECT_EQ(log.find("libOpenImageIO"), std::string::npos) << model;
        EXPECT_EQ(log.find("libsherpa_oiio"), std::string::npos) << model;
    }
}

// rt on a skinned model shows what is built: the posed BLAS and their instances in
// the TLAS, no -1 build times; the opaque column is explained.
TEST(CliUsage, RtOnASkinnedModelShowsWhatIsBuilt) {
    const std::string rigged = test::gltf_asset("RiggedSimple");
    const CliRun text = run_cli("rt '" + rigged + "' --validation");
    ASSERT_EQ(text.exit_code, 0) << text.out;
    EXPECT_EQ(text.out.find("-1.000"), std::string::npos) << text.out;
    EXPECT_EQ(text.out.find("TLAS: 0 instances"), std::string::npos) << text.out;
    EXPECT_EQ(text.out.find("0.00 M triangles/s"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("not built: every instance skins or morphs"), std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("no-AH: geometries built with VK_GEOMETRY_OPAQUE_BIT"),
              std::string::npos)
        << text.out;
    const CliRun json = run_cli("rt '" + rigged + "' --json", "2>/dev/null");
    ASSERT_EQ(json.exit_code, 0) << json.out;
    const auto j = nlohmann::json::parse(json.out);
    EXPECT_GE(j["posed"]["blas"].get<int>(), 1);
    EXPECT_EQ(j["tlas"]["instances"], j["posed"]["blas"]) << j.dump(1);
    EXPECT_GE(j["posed"]["updates"].get<int>(), 1);
}

namespace {

std::string base64(const std::vector<unsigned char>& in) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const unsigned v = (in[i] << 16) | ((i + 1 < in.size() ? in[i + 1] : 0) << 8) |
                           (i + 2 < in.size() ? in[i + 2] : 0);
        out += k[(v >> 18) & 63];
        out += k[(v >> 12) & 63];
        out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
        out += i + 2 < in.size() ? k[v & 63] : '=';
    }
    return out;
}

} // namespace

// Non-unit normals (quantized ones are non-unit by design) make one summary line per
// file, with the count and the worst length, not a line per primitive.
TEST(CliUsage, RenormalisedNormalsAreSummarisedOncePerFile) {
    const float data[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0, 0, 2.0f, 0, 0, 0.9f};
    std::vector<unsigned char> bytes(sizeof data);
    std::memcpy(bytes.data(), data, sizeof data);
    const nlohmann::json gltf = {
        {"asset", {{"version", "2.0"}}},
        {"buffers",
         {{{"byteLength", 72}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
          {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 36}}}},
        {"accessors",
         {{{"bufferView", 0},
           {"componentType", 5126},
           {"count", 3},
           {"type", "VEC3"},
           {"min", {0, 0, 0}},
           {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}},
             {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}}}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"scene", 0}};
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / "sherpa_non_unit_normals.gltf";
    std::ofstream(file) << gltf.dump();
    const CliRun r = run_cli("info '" + file.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_EQ(count(r.out, "renormalised"), 1u) << r.out;
    EXPECT_NE(r.out.find("6 non-unit normals renormalised in 2 primitive(s); worst length 2 ("),
              std::string::npos)
        << r.out;
    std::filesystem::remove(file);
}
