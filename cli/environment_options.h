#pragma once
// The environment-lighting and display options of `render` and `lab`: which
// environment lights the scene, how it is turned and scaled, what shows behind, the
// default sun, energy compensation, tone mapping and exposure (docs/environment.md).
#include "cli_common.h"
#include "texture_cli.h" // OptionMatch

#include <memory>
#include <string>

#include <sherpa/render/environment.h>
#include <sherpa/render/frame_request.h>

namespace sherpa::render {
class Renderer;
} // namespace sherpa::render

namespace sherpa::cli {

inline constexpr const char* kEnvironmentOptionsSynopsis =
    "[--environment room|none|FILE.hdr|FILE.exr] [--environment-rotation DEG]\n"
    "    [--environment-intensity X] [--background environment|blurred|R,G,B]\n"
    "    [--sun on|off] [--energy-compensation on|off] [--tone-map neutral|aces|agx|linear]\n"
    "    [--exposure EV] [--anisotropy-lighting isotropic|albedo|lobe]";

// If args[i] is one of these options, consumes it and its value (advancing i) into
// `settings` (--environment into `environment`); Bad sets `error`.
OptionMatch parse_environment_option(Args args, std::size_t& i, render::FrameRequest& settings,
                                     render::EnvironmentChoice& environment, std::string& error);

// Makes the chosen environment (null: none); its warnings (an unreadable file and the
// fallback used, NaN texels, ...) go to stderr.
std::shared_ptr<const render::EnvironmentImage>
make_environment_image(const render::EnvironmentChoice& environment);

// Makes the chosen environment and gives it to `renderer` (warnings as above).
void apply_environment(render::Renderer& renderer, const render::EnvironmentChoice& environment);

} // namespace sherpa::cli
