#include "shadow_options.h"

#include <cmath>

#include <sherpa/render/gpu_structs.h>

namespace sherpa::cli {
OptionMatch parse_shadow_option(Args args, std::size_t& i, render::FrameRequest& settings,
                                std::uint32_t& resolution, std::string& error) {
    const std::string_view a = args[i];
    const bool integer = a == "--cascades" || a == "--shadow-resolution" || a == "--pcf-taps" ||
                         a == "--shadow-rays" || a == "--ao-rays" || a == "--spp" ||
                         a == "--max-bounces" || a == "--seed";
    const bool real = a == "--sun-angular-radius" || a == "--ao-radius";
    if (!integer && !real) return OptionMatch::NotMine;
    if (i + 1 >= args.size()) {
        error = std::string(a) + " needs a value";
        return OptionMatch::Bad;
    }
    const std::string_view v = args[++i];
    std::uint32_t n = 0;
    float x = 0.0f;
    if (integer && !parse_number(v, n)) {
        error = std::string(a) + " needs a non-negative integer, not '" + std::string(v) + "'";
        return OptionMatch::Bad;
    }
    if (real && (!parse_number(v, x) || !std::isfinite(x) || x < 0.0f)) {
        error = std::string(a) + " needs a finite number >= 0, not '" + std::string(v) + "'";
        return OptionMatch::Bad;
    }
    if (a == "--cascades") {
        if (n < 1 || n > render::kShadowCascades) {
            error = "--cascades needs 1 to " + std::to_string(render::kShadowCascades);
            return OptionMatch::Bad;
        }
        settings.cascades = n;
    } else if (a == "--shadow-resolution") {
        if (n < 64 || n > 8192) {
            error = "--shadow-resolution needs 64 to 8192 texels";
            return OptionMatch::Bad;
        }
        resolution = n;
    } else if (a == "--pcf-taps") {
        if (n != 1 && n != 4 && n != 16) {
            error = "--pcf-taps needs 1, 4 or 16";
            return OptionMatch::Bad;
        }
        settings.shadow_pcf_taps = n;
    } else if (a == "--shadow-rays" || a == "--ao-rays") {
        if (n < 1 || n > 1024) {
            error = std::string(a) + " needs 1 to 1024 rays";
            return OptionMatch::Bad;
        }
        (a == "--shadow-rays" ? settings.shadow_rays : settings.ao_rays) = n;
    } else if (a == "--spp") {
        if (n < 1 || n > 1u << 20) {
            error = "--spp needs 1 to 1048576 samples per pixel";
            return OptionMatch::Bad;
        }
        settings.path.samples = n;
    } else if (a == "--max-bounces") {
        if (n > 64) {
            error = "--max-bounces needs 0 to 64";
            return OptionMatch::Bad;
        }
        settings.path.max_bounces = n;
    } else if (a == "--seed") {
        settings.path.seed = n;
    } else if (a == "--sun-angular-radius") {
        if (x > 0.5f) {
            error = "--sun-angular-radius needs radians from 0 to 0.5";
            return OptionMatch::Bad;
        }
        settings.sun_angular_radius = x;
    } else {
        settings.ao_radius = x; // 0: 5% of the scene's diagonal
    }
    return OptionMatch::Taken;
}

} // namespace sherpa::cli
