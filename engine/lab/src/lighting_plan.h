#pragma once
// The lighting family's methods and its path-traced reference and convergence series
// (lighting_methods.cpp); lighting_family.cpp runs them.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <sherpa/lab/families.h>
#include <sherpa/render/path_trace.h>
#include <sherpa/render/renderer.h>

namespace sherpa::lab::detail {

enum class LightingGroup {
    Irradiance,
    Prefilter,
    Compensation,
    Anisotropy,
    Shadows,
    Transmission,
    PathTracer
};

// What one method draws: the main view's settings with one approximation changed.
struct LightingSetup {
    LightingGroup group = LightingGroup::Irradiance;
    render::EnvironmentOptions environment;
    std::uint32_t shadow_resolution = scene::kDefaultShadowResolution;
    bool shadows = true;
    std::uint32_t cascades = scene::kDefaultShadowCascades, taps = 0; // 0: the device's default
    int compensation = -1;                                            // -1: the view's; 0 off; 1 on
    bool transmission = true; // false: KHR_materials_transmission dropped from the scene
    int anisotropy = -1;      // -1: the view's; else a render::AnisotropyLighting
    std::uint32_t spp = 0;    // the path tracer's samples (group PathTracer)
    // Everything that changes the raster frame: equal keys draw the same frame.
    std::string key() const;
    // What the environment is made with: equal keys share one EnvironmentMap.
    std::string environment_key() const;
};

struct LightingMethod {
    MethodInfo info;
    LightingSetup setup;
};

std::vector<LightingMethod> lighting_methods(const LightingFamilyOptions& options);

// The path tracer's images at `spp` (each a prefix of one accumulation).
struct PathImage {
    std::uint32_t spp = 0;
    std::vector<std::uint8_t> rgba;
    double gpu_ms = 0.0; // the accumulation up to here
    render::PathTraceError error;
};

// Accumulates with `base` (a path-traced lit frame) and `seed` up to each of `spp`
// (ascending), reading the image at each; `step` is called after every launch (at most
// kPathLaunch samples: about a second of lavapipe for DamagedHelmet at 160x120, so that
// a cancel is seen soon) and returns false to cancel (the images so far are returned).
inline constexpr std::uint32_t kPathLaunch = 4;
std::vector<PathImage> path_trace_series(render::Renderer& renderer, render::FrameRequest base,
                                         std::uint32_t seed, const std::vector<std::uint32_t>& spp,
                                         const std::function<bool()>& step);

} // namespace sherpa::lab::detail
