// sherpa-cli SUBCOMMAND ...: headless access to the engine.
#include "cli_common.h"

#include <sherpa/core/heap_tuning.h>

#include <cstdio>
#include <vector>

namespace {

struct Subcommand {
    std::string_view name;
    int (*run)(sherpa::cli::Args);
    std::string_view usage;
};

constexpr Subcommand kSubcommands[] = {
    {"info", sherpa::cli::run_info,
     "info SCENE [--json] [--scene N] [--animation N --time T | --pose bind]   report on a scene "
     "(path or builtin:...)"},
    {"cull", sherpa::cli::run_cull,
     "cull SCENE --camera eye=x,y,z:target=x,y,z[:...] [--method sphere|pvertex|exact] [--json]"},
    {"tangents", sherpa::cli::run_tangents,
     "tangents SCENE --dump FILE.csv [--method NAME] [--regenerate]   per-corner tangents\n"
     "  tangents SCENE --compare [--method NAME] [--json]   authored vs regenerated"},
    {"textures", sherpa::cli::run_textures,
     "textures SCENE [--cache-dir DIR] [--cache-cap-mb N] [--quality N] [--no-cache] [--no-bc]\n"
     "           [--json]   texture pipeline and cache report"},
    {"render", sherpa::cli::run_render,
     "render SCENE -o OUT.png [--width W --height H] [--view NAME] [--overlay NAME ...]\n"
     "         [--camera auto|gltf:N|eye=x,y,z:target=x,y,z] [--frames N] [--report FILE.json]\n"
     "         [--cache-dir DIR] [--no-cache] [--quality N] [--no-bc]\n"
     "         [--compare split|difference [--compare-with FILE] [--compare-renderer raster|rt]\n"
     "          [--compare-view NAME] [--divider F] [--threshold T] [--json] ...]\n"
     "                                     render offscreen (Vulkan) to a PNG; with --compare\n"
     "                                     side A against side B, split or difference"},
    {"rt", sherpa::cli::run_rt,
     "rt SCENE [--json] [--validation] [--scratch-budget BYTES] [--no-compact] [--rt on|off]\n"
     "                                     acceleration structures: BLAS/TLAS statistics"},
    {"lab", sherpa::cli::run_lab,
     "lab SCENE --family tangents|textures|culling|mesh-compression\n"
     "      [--json|--csv] [--chart OUT.svg] [--repeat N] [--sample-texels N] [--cameras N] "
     "[--no-gpu]   methods: time vs error"},
    {"compare", sherpa::cli::run_compare,
     "compare A B [--json] [--image OUT.png]   structural diff of two glTF files"},
    {"validate", sherpa::cli::run_validate,
     "validate FILE|DIR [--json] [--max-severity error|warning|info|hint] [--jobs N]\n"
     "                                     Khronos glTF-Validator codes and JSON pointers;\n"
     "                                     exit 2 on errors, 1 on warnings, 0 otherwise"},
    {"budget", sherpa::cli::run_budget,
     "budget SCENE [--json] [--viewport-height N]   GPU bytes against what the scene needs"},
};

int usage(std::FILE* out) {
    std::fprintf(out, "usage: sherpa-cli SUBCOMMAND ...\n\nsubcommands:\n");
    for (const auto& s : kSubcommands)
        std::fprintf(out, "  %.*s\n", static_cast<int>(s.usage.size()), s.usage.data());
    std::fprintf(out, "\nSCENE is a .gltf/.glb path, builtin:default or builtin:grid?n=N\n");
    return out == stdout ? sherpa::cli::kExitOk : sherpa::cli::kExitUsage;
}

} // namespace

int main(int argc, char** argv) {
    // A CPU Vulkan device frees and reallocates large blocks every frame: keep them mapped
    // (see heap_tuning.h for the measurements).
    sherpa::keep_freed_memory_mapped();
    std::vector<std::string_view> args(argv + 1, argv + argc);
    if (args.empty()) return usage(stderr);
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") return usage(stdout);
    for (const auto& s : kSubcommands)
        if (s.name == args[0]) return s.run(sherpa::cli::Args(args).subspan(1));
    std::fprintf(stderr, "error: unknown subcommand '%.*s'\n", static_cast<int>(args[0].size()),
                 args[0].data());
    return usage(stderr);
}
