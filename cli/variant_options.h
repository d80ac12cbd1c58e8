#pragma once
// --variant NAME (render, lab, info): which KHR_materials_variants variant is shown.
#include "cli_common.h"
#include "texture_cli.h" // OptionMatch

#include <string>

#include <nlohmann/json.hpp>

#include <sherpa/scene/scene.h>

namespace sherpa::cli {

// If args[i] is --variant, consumes it and its value (advancing i) into `variant`.
OptionMatch parse_variant_option(Args args, std::size_t& i, std::string& variant,
                                 std::string& error);

// Shows variant `variant` of `scene` (nothing for an empty name). False with `error`
// naming the variants the file has when it has none of that name.
bool apply_variant_option(scene::Scene& scene, const std::string& variant, std::string& error);

// `info`: the variants, and per variant the primitives whose material it changes.
nlohmann::json variants_json(const scene::Scene& scene);
void print_variants_text(const scene::Scene& scene);

} // namespace sherpa::cli
