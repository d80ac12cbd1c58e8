// sherpa-cli budget SCENE [--json] [--viewport-height N]
// GPU bytes per category against the 56-byte unified layout and against what the
// materials and views need, oversized textures and unread attributes (lab/budget.h).
#include "cli_common.h"

#include <sherpa/lab/budget.h>
#include <sherpa/lab/family.h>
#include <sherpa/scene/scene_loader.h>

#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

constexpr std::string_view kUsage = "budget"; // main.cpp's usage text

nlohmann::json budget_json(const lab::BudgetReport& b) {
    nlohmann::json categories = nlohmann::json::array(), oversized = nlohmann::json::array(),
                   unread = nlohmann::json::array();
    for (const lab::BudgetCategory& c : b.categories)
        categories.push_back(
            {{"name", c.name}, {"unified", c.unified}, {"stored", c.stored}, {"needed", c.needed}});
    for (const lab::OversizedTexture& t : b.oversized)
        oversized.push_back({{"image", t.image},
                             {"where", t.where},
                             {"size", {t.width, t.height}},
                             {"texels_per_pixel", t.texels_per_pixel},
                             {"reduce", t.reduce}});
    for (const lab::UnreadAttribute& u : b.unread)
        unread.push_back({{"mesh", u.mesh},
                          {"primitive", u.primitive},
                          {"attribute", u.attribute},
                          {"reason", u.reason}});
    return {{"categories", categories},
            {"oversized_textures", oversized},
            {"unread_attributes", unread},
            {"notes", b.notes}};
}

void print_text(const lab::BudgetReport& b) {
    std::printf("%-16s %14s %14s %14s\n", "GPU bytes", "unified", "stored", "needed");
    for (const lab::BudgetCategory& c : b.categories)
        std::printf("%-16s %14llu %14llu %14llu\n", c.name.c_str(), (unsigned long long)c.unified,
                    (unsigned long long)c.stored, (unsigned long long)c.needed);
    for (const lab::OversizedTexture& t : b.oversized)
        std::printf("oversized: image %d %s %ux%u: %.3g texels per pixel at best, 1/%u per side "
                    "would look the same\n",
                    t.image, t.where.c_str(), t.width, t.height, t.texels_per_pixel, t.reduce);
    for (const lab::UnreadAttribute& u : b.unread)
        std::printf("unread: mesh %u primitive %u %s: %s\n", u.mesh, u.primitive,
                    u.attribute.c_str(), u.reason.c_str());
    for (const std::string& n : b.notes) std::printf("note: %s\n", n.c_str());
}

} // namespace

int run_budget(Args args) {
    std::string spec;
    bool json = false;
    lab::BudgetOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--json")
            json = true;
        else if (args[i] == "--viewport-height" && i + 1 < args.size()) {
            if (!parse_number(args[++i], options.viewport_height) || options.viewport_height == 0)
                return usage_error("--viewport-height needs a positive integer", kUsage);
        } else if (!args[i].empty() && args[i][0] != '-' && spec.empty())
            spec = std::string(args[i]);
        else
            return usage_error("unexpected argument '" + std::string(args[i]) + "'", kUsage);
    }
    if (spec.empty()) return usage_error("no SCENE given", kUsage);
    scene::LoadResult loaded = scene::load_scene(spec);
    if (!loaded) {
        std::fprintf(stderr, "error: %s\n", loaded.error.c_str());
        return kExitLoadError;
    }
    const lab::BudgetReport b = lab::build_budget(*loaded.scene, options);
    if (json)
        std::cout << budget_json(b).dump(2) << "\n";
    else
        print_text(b);
    return kExitOk;
}

} // namespace sherpa::cli
