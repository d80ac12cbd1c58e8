#pragma once
// The shadow and ray-traced lighting options of `render`: cascade count, map
// resolution and PCF taps of the rasterizer's cascaded shadow maps; shadow rays, sun
// disc and ambient-occlusion rays of the ray tracer (docs/raytracing/README.md); samples
// per pixel, bounces and seed of the path tracer (docs/path_tracer.md).
#include "cli_common.h"
#include "texture_cli.h" // OptionMatch

#include <cstdint>
#include <string>

#include <sherpa/render/frame_request.h>

namespace sherpa::cli {

inline constexpr const char* kShadowOptionsSynopsis =
    "[--cascades 1-3] [--shadow-resolution N] [--pcf-taps 1|4|16] [--shadow-rays N]\n"
    "    [--sun-angular-radius RAD] [--ao-rays N] [--ao-radius R] [--spp N] [--max-bounces N]\n"
    "    [--seed N]";

// If args[i] is a shadow option, consumes it and its value (advancing i) into
// `settings` (--shadow-resolution into `resolution`, a renderer option); Bad sets
// `error`.
OptionMatch parse_shadow_option(Args args, std::size_t& i, render::FrameRequest& settings,
                                std::uint32_t& resolution, std::string& error);

} // namespace sherpa::cli
