// sherpa-cli COMMAND ...: headless access to the engine. Every command is one entry
// of kCommands: its name, its entry point and its one usage text (usage.h).
#include "cli_common.h"
#include "usage.h"

#include <sherpa/core/heap_tuning.h>

#include <cstdio>
#include <vector>

namespace sherpa::cli {
namespace {

constexpr Command kCommands[] = {
    {"info", run_info,
     "sherpa-cli info SCENE [--json] [--scene N] [--animation N --time T | --pose bind]\n"
     "    [--variant NAME]\n"
     "\n"
     "Reports on a scene: counts, bounds, vertex streams the materials read, images\n"
     "that cannot become textures, cameras, motion, material variants. --time T adds\n"
     "the pose at T seconds; --variant NAME shows that KHR_materials_variants variant.\n"},
    {"cull", run_cull,
     "sherpa-cli cull SCENE [--camera CAMERA] [--method sphere|pvertex|exact|gpu] [--json]\n"
     "    [--animation N --time T | --pose bind]\n"
     "\n"
     "The camera pass and one pass per shadow cascade: visible instances and statistics.\n"
     "{camera-help}"},
    {"tangents", run_tangents,
     "sherpa-cli tangents SCENE --dump FILE.csv [--method NAME] [--regenerate]\n"
     "sherpa-cli tangents SCENE --compare [--method NAME] [--json]\n"
     "\n"
     "Per-corner tangents, or authored against regenerated ones.\n"
     "methods: mikktspace (default), mikktspace-welded, lengyel\n"},
    {"textures", run_textures,
     "sherpa-cli textures SCENE [--json] [--export-source DIR]\n"
     "    {texture-options}\n"
     "\n"
     "The texture pipeline and cache report, per image and role.\n"
     "{texture-help}"
     "  --export-source DIR  write every image of the file as decoded (level 0,\n"
     "                     RGBA8 PNG, unassociated alpha), named after its file\n"},
    {"render", run_render,
     "sherpa-cli render SCENE -o OUT.png [--width W --height H] [--view NAME] [--overlay NAME "
     "...]\n"
     "    [--camera CAMERA] [--frames N] [--report FILE.json] [--validation] [--no-shadows]\n"
     "    [--prepass|--no-prepass] [--glyph-length L] [--floor] [--rt on|off]\n"
     "    [--renderer raster|rt] [--texture-lod N] [--animation N --time T | --pose bind]\n"
     "    [--hide-node N ...] [--cull none|cpu|gpu] [--cull-method sphere|pvertex|exact]\n"
     "    [--cull-check] [--freeze-cull CAMERA] [--variant NAME]\n"
     "    {texture-options}\n"
     "    {shadow-options}\n"
     "    {environment-options}\n"
     "    {compare-options}\n"
     "\n"
     "Renders offscreen (Vulkan) to a PNG; with --compare, side A against side B.\n"
     "{camera-help}"
     "  --view NAME        {views}\n"
     "  --overlay NAME     {overlays}\n"
     "  --renderer rt --view lit  path traced (docs/path_tracer.md): --spp N samples per\n"
     "                     pixel (default 64), --max-bounces N (default 8), --seed N; the\n"
     "                     estimated error is printed\n"
     "{texture-help}{compare-help}"},
    {"rt", run_rt,
     "sherpa-cli rt SCENE [--json] [--validation] [--scratch-budget BYTES] [--no-compact] [--rt "
     "on|off]\n"
     "\n"
     "Builds the scene's acceleration structures and reports them (BLAS, TLAS, totals).\n"},
    {"lab", run_lab,
     "sherpa-cli lab SCENE --family {families} [--json|--csv]\n"
     "    [--chart OUT.svg] [--repeat N] [--sample-texels N] [--cameras N] [--no-gpu]\n"
     "    [--variant NAME] [--width N] [--height N] [--reference-spp N] [--max-bounces N]\n"
     "    {environment-options}\n"
     "\n"
     "Every method of one family measured on the scene: time against error.\n"
     "  shadows: --cameras N around the scene, --repeat N timed frames (median), lit\n"
     "           as render lights its frame (the environment options)\n"
     "  lighting: the raster's lighting against the path tracer at --reference-spp N\n"
     "           (default 256) and --max-bounces N (default 8), --width N x --height N\n"
     "           (default 160x120), --repeat N timed frames (median), lit as render\n"
     "           lights its frame\n"},
    {"compare", run_compare,
     "sherpa-cli compare A B [--json] [--image OUT.png]\n"
     "    {environment-options}\n"
     "\n"
     "Structural diff of two glTF files; --image draws where they differ, both lit as\n"
     "render lights its frame (the environment options).\n"},
    {"validate", run_validate,
     "sherpa-cli validate FILE|DIR [--json] [--max-severity error|warning|info|hint] [--jobs N]\n"
     "\n"
     "Khronos glTF-Validator codes and JSON pointers, per file or for every glTF in DIR.\n"
     "Exit status: 2 when a reported message is an error, 1 a warning, 0 otherwise.\n"},
    {"budget", run_budget,
     "sherpa-cli budget SCENE [--json] [--viewport-height N]\n"
     "\n"
     "GPU bytes per category against what the scene needs.\n"},
};

} // namespace

std::span<const Command> commands() {
    return kCommands;
}

} // namespace sherpa::cli

int main(int argc, char** argv) {
    using namespace sherpa::cli;
    // A CPU Vulkan device frees and reallocates large blocks every frame: keep them mapped
    // (see heap_tuning.h for the measurements).
    sherpa::core::keep_freed_memory_mapped();
    std::vector<std::string_view> args(argv + 1, argv + argc);
    if (args.empty()) {
        std::fprintf(stderr, "error: no command given\nrun 'sherpa-cli --help' for usage\n");
        return kExitUsage;
    }
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        if (args.size() > 1 && !usage_text(args[1]).empty()) {
            std::fputs(usage_text(args[1]).c_str(), stdout);
            return kExitOk;
        }
        std::fputs(overview_text().c_str(), stdout);
        return kExitOk;
    }
    for (const Command& c : commands()) {
        if (c.name != args[0]) continue;
        for (std::size_t i = 1; i < args.size(); ++i)
            if (args[i] == "--help" || args[i] == "-h") {
                std::fputs(usage_text(c.name).c_str(), stdout);
                return kExitOk;
            }
        return c.run(Args(args).subspan(1));
    }
    std::fprintf(stderr, "error: unknown command '%.*s'\nrun 'sherpa-cli --help' for usage\n",
                 static_cast<int>(args[0].size()), args[0].data());
    return kExitUsage;
}
