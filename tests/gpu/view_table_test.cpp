// The debug-view/overlay table (sherpa/render/debug_views.h) is the one source of the
// views: the generated GLSL header must agree with it, the forward shader must
// handle every view in it (a view added to the table but not to the shader's switch
// falls through to lit shading: ForwardShaderHasACaseForEveryViewButLit fails), and
// the CLI must list every name in it.
#include "cli/cli_run.h"
#include "gpu_test_support.h"

#include <sherpa/render/debug_views.h>
#include <sherpa/render/frame_request.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace sherpa::test {
namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in) << path;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string glsl_name(std::string_view name) {
    std::string out;
    for (char c : name) out += c == '-' ? '_' : static_cast<char>(std::toupper(c));
    return out;
}

// `const uint PREFIX_NAME = VALUE[u];` declarations of a GLSL file.
std::map<std::string, std::uint32_t> glsl_constants(const std::string& text,
                                                    const std::string& prefix) {
    std::map<std::string, std::uint32_t> out;
    const std::regex decl("const uint " + prefix + "(\\w+) = (\\d+)u?;");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), decl);
         it != std::sregex_iterator(); ++it)
        out[(*it)[1]] = static_cast<std::uint32_t>(std::stoul((*it)[2]));
    return out;
}

TEST(DebugViewTable, GeneratedGlslHeaderAgreesWithTheTable) {
    const std::string dir = SHERPA_GLSL_GENERATED_DIR;
    std::map<std::string, std::uint32_t> views, overlays;
    for (const render::DebugViewInfo& v : render::kDebugViews)
        views[glsl_name(v.name)] = static_cast<std::uint32_t>(v.id);
    for (const render::OverlayEntry& o : render::kOverlays) overlays[glsl_name(o.name)] = o.bit;
    EXPECT_EQ(glsl_constants(read_text(dir + "/sherpa_views.glsl"), "VIEW_"), views);
    EXPECT_EQ(glsl_constants(read_text(dir + "/sherpa_overlays.glsl"), "OVERLAY_"), overlays);
}

std::set<std::string> view_cases(const std::string& shader) {
    const std::string text = read_text(std::string(SHERPA_SHADER_DIR) + "/" + shader);
    std::set<std::string> cases;
    const std::regex case_re("case VIEW_(\\w+):");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), case_re);
         it != std::sregex_iterator(); ++it)
        cases.insert((*it)[1]);
    return cases;
}

// The forward shader's own cases plus the surface-data views it shares with the ray
// tracer (include/surface_views.glsl); those are exactly the ray-traced views.
TEST(DebugViewTable, ForwardShaderHasACaseForEveryViewButLit) {
    std::set<std::string> cases = view_cases("forward.frag");
    const std::set<std::string> surface = view_cases("include/surface_views.glsl");
    cases.insert(surface.begin(), surface.end());
    std::set<std::string> expected, ray_traced;
    for (const render::DebugViewInfo& v : render::kDebugViews) {
        // lit: `default:`; ao and shadow-error: rays only.
        if (v.id != render::DebugView::Lit && render::raster_view(v.id))
            expected.insert(glsl_name(v.name));
        // The lighting views are traced by rt.rgen (lit: path traced by pt.rgen), not
        // looked up in surface_views.glsl.
        const bool lighting = v.id == render::DebugView::Lit || v.id == render::DebugView::Shadow ||
                              v.id == render::DebugView::AmbientOcclusion ||
                              v.id == render::DebugView::ShadowError;
        if (render::ray_traced_view(v.id) && !lighting) ray_traced.insert(glsl_name(v.name));
    }
    EXPECT_EQ(cases, expected);
    EXPECT_EQ(surface, ray_traced);
}

TEST(DebugViewTable, NamesAndLabelsAreUniqueAndComplete) {
    std::set<std::string_view> names;
    for (const render::DebugViewInfo& v : render::kDebugViews) {
        EXPECT_TRUE(names.insert(v.name).second) << v.name;
        EXPECT_TRUE(v.label && *v.label) << v.name;
    }
    std::uint32_t bits = 0;
    for (const render::OverlayEntry& o : render::kOverlays) {
        EXPECT_TRUE(names.insert(o.name).second) << o.name;
        EXPECT_EQ(bits & o.bit, 0u) << o.name;
        bits |= o.bit;
    }
}

// The CLI's usage text (render --help) lists every view and overlay of the table, and
// an unknown view's error names every view.
TEST(DebugViewTable, CliListsEveryName) {
    const CliRun r = run_cli("render builtin:default -o /dev/null --view nonsense");
    EXPECT_NE(r.exit_code, 0);
    const CliRun help = run_cli("render --help");
    EXPECT_EQ(help.exit_code, 0);
    for (const render::DebugViewInfo& v : render::kDebugViews) {
        EXPECT_NE(r.out.find(std::string(v.name)), std::string::npos) << v.name << "\n" << r.out;
        EXPECT_NE(help.out.find(std::string(v.name)), std::string::npos) << v.name;
    }
    for (const render::OverlayEntry& o : render::kOverlays)
        EXPECT_NE(help.out.find(std::string(o.name)), std::string::npos) << o.name << "\n"
                                                                         << help.out;
}

class DebugViewRenderTest : public GpuTest {};

// Each view of the table renders validation-clean and shows something other than the
// lit image.
TEST_F(DebugViewRenderTest, EveryViewRendersAndDiffersFromLit) {
    auto scene = load(gltf_asset("NormalTangentMirrorTest"));
    ASSERT_TRUE(scene);
    renderer().load(*scene, streams_setup(render::StreamPolicy::AllPresent));
    render::FrameRequest s;
    s.width = 64;
    s.height = 64;
    // Only the lit view draws shadows: compare shading, not shadows.
    s.shadows = false;
    std::vector<std::uint8_t> lit;
    renderer().render(s, &lit);
    ASSERT_EQ(lit.size(), 64u * 64u * 4u);
    for (const render::DebugViewInfo& v : render::kDebugViews) {
        if (v.id == render::DebugView::Lit || !render::raster_view(v.id)) continue;
        s.view = v.id;
        std::vector<std::uint8_t> rgba;
        renderer().render(s, &rgba);
        ASSERT_EQ(rgba.size(), lit.size()) << v.name;
        EXPECT_GT(differing_pixels(rgba, lit, 2), 100u) << v.name << " renders as lit";
    }
    renderer().unload();
}

} // namespace
} // namespace sherpa::test
