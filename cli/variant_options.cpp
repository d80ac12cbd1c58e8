#include "variant_options.h"

#include <cstdio>

namespace sherpa::cli {
namespace {

std::string material_name(const scene::Scene& scene, std::uint32_t m) {
    std::string out = "materials[" + std::to_string(m) + "]";
    if (m < scene.materials.size() && !scene.materials[m].name.empty())
        out += " \"" + scene.materials[m].name + "\"";
    return out;
}

} // namespace

OptionMatch parse_variant_option(Args args, std::size_t& i, std::string& variant,
                                 std::string& error) {
    if (args[i] != "--variant") return OptionMatch::NotMine;
    if (i + 1 >= args.size() || args[i + 1].empty()) {
        error = "--variant needs the name of a KHR_materials_variants variant";
        return OptionMatch::Bad;
    }
    variant = std::string(args[++i]);
    return OptionMatch::Taken;
}

bool apply_variant_option(scene::Scene& scene, const std::string& variant, std::string& error) {
    if (variant.empty()) return true;
    const std::int32_t v = scene::find_variant(scene, variant);
    if (v < 0) {
        error = "--variant " + variant + ": " + scene.source + " has ";
        if (scene.variants.names.empty()) error += "no material variants";
        for (std::size_t i = 0; i < scene.variants.names.size(); ++i)
            error += (i ? ", \"" : "the variants \"") + scene.variants.names[i] + "\"";
        return false;
    }
    scene::apply_material_variant(scene, v);
    return true;
}

nlohmann::json variants_json(const scene::Scene& scene) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t v = 0; v < scene.variants.names.size(); ++v) {
        nlohmann::json changes = nlohmann::json::array();
        for (const scene::VariantChange& c :
             scene::variant_changes(scene, static_cast<std::int32_t>(v)))
            changes.push_back({{"mesh", c.gltf_mesh},
                               {"primitive", c.primitive},
                               {"from_material", c.from},
                               {"to_material", c.to}});
        out.push_back({{"index", v},
                       {"name", scene.variants.names[v]},
                       {"active", scene.variants.active == static_cast<std::int32_t>(v)},
                       {"changes", changes}});
    }
    return out;
}

void print_variants_text(const scene::Scene& scene) {
    const auto& names = scene.variants.names;
    for (std::size_t v = 0; v < names.size(); ++v) {
        const auto changes = scene::variant_changes(scene, static_cast<std::int32_t>(v));
        std::printf("  variant %zu \"%s\"%s: %zu primitive(s) change material\n", v,
                    names[v].c_str(),
                    scene.variants.active == static_cast<std::int32_t>(v) ? " (shown)" : "",
                    changes.size());
        for (const scene::VariantChange& c : changes)
            std::printf("    mesh %u primitive %u: %s -> %s\n", c.gltf_mesh, c.primitive,
                        material_name(scene, c.from).c_str(), material_name(scene, c.to).c_str());
    }
}

} // namespace sherpa::cli
