#include "environment_options.h"

#include <cmath>
#include <cstdio>

#include <sherpa/render/renderer.h>

namespace sherpa::cli {

OptionMatch parse_environment_option(Args args, std::size_t& i, render::FrameRequest& settings,
                                     render::EnvironmentChoice& environment, std::string& error) {
    const std::string_view a = args[i];
    if (a != "--environment" && a != "--environment-rotation" && a != "--environment-intensity" &&
        a != "--background" && a != "--tone-map" && a != "--exposure" && a != "--sun" &&
        a != "--energy-compensation" && a != "--anisotropy-lighting")
        return OptionMatch::NotMine;
    if (i + 1 >= args.size()) {
        error = std::string(a) + " needs a value";
        return OptionMatch::Bad;
    }
    const std::string_view v = args[++i];
    const auto on_off = [&](bool& out) {
        if (v != "on" && v != "off") {
            error = std::string(a) + " needs on or off, not '" + std::string(v) + "'";
            return OptionMatch::Bad;
        }
        out = v == "on";
        return OptionMatch::Taken;
    };
    float x = 0.0f;
    if (a == "--environment") {
        if (v.empty()) {
            error = "--environment needs room, none or a file";
            return OptionMatch::Bad;
        }
        environment = render::parse_environment_choice(v);
    } else if (a == "--environment-rotation" || a == "--environment-intensity" ||
               a == "--exposure") {
        if (!parse_number(v, x) || !std::isfinite(x)) {
            error = std::string(a) + " needs a finite number, not '" + std::string(v) + "'";
            return OptionMatch::Bad;
        }
        if (a == "--environment-intensity" && x < 0.0f) {
            error = "--environment-intensity needs a number >= 0";
            return OptionMatch::Bad;
        }
        if (a == "--exposure" && std::abs(x) > 32.0f) {
            error = "--exposure needs stops from -32 to 32";
            return OptionMatch::Bad;
        }
        (a == "--environment-rotation"    ? settings.environment_rotation
         : a == "--environment-intensity" ? settings.environment_intensity
                                          : settings.exposure) = x;
    } else if (a == "--background") {
        glm::vec3 color{};
        const auto b = render::parse_background(v, color);
        if (!b) {
            error = "--background needs environment, blurred or R,G,B (linear, 0 to 1), not '" +
                    std::string(v) + "'";
            return OptionMatch::Bad;
        }
        settings.background = *b;
        if (*b == render::Background::Color) settings.clear_color = glm::vec4(color, 1.0f);
    } else if (a == "--tone-map") {
        const auto t = render::parse_tone_map(v);
        if (!t) {
            error = "--tone-map needs neutral, aces, agx or linear, not '" + std::string(v) + "'";
            return OptionMatch::Bad;
        }
        settings.tone_map = *t;
    } else if (a == "--anisotropy-lighting") {
        const auto m = render::parse_anisotropy_lighting(v);
        if (!m) {
            error = "--anisotropy-lighting needs isotropic, albedo or lobe, not '" +
                    std::string(v) + "'";
            return OptionMatch::Bad;
        }
        settings.anisotropy_lighting = *m;
    } else if (a == "--sun") {
        return on_off(settings.sun);
    } else {
        return on_off(settings.energy_compensation);
    }
    return OptionMatch::Taken;
}

std::shared_ptr<const render::EnvironmentImage>
make_environment_image(const render::EnvironmentChoice& environment) {
    std::vector<std::string> warnings;
    auto image = render::make_environment(environment, warnings);
    for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (!image) return nullptr;
    return std::make_shared<const render::EnvironmentImage>(std::move(*image));
}

void apply_environment(render::Renderer& renderer, const render::EnvironmentChoice& environment) {
    renderer.set_environment(make_environment_image(environment).get());
}

} // namespace sherpa::cli
