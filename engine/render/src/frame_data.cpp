// Per-frame constants: camera, lights (scene lights or the default sun), shadow
// cascades, debug view. Decides whether the cached shadow cascades are still valid.
#include "frame_recorder.h"

#include <sherpa/render/gpu_structs.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/shadow_cascades.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sherpa::render {
namespace {

// The bounds shadow cascades are fitted to: the scene's, grown by where its moving
// instances are in this frame's pose (an arm raised above the bind pose still casts).
// A box the pose pushed past the float range is left out: one infinite or NaN corner
// would make every cascade, and so every shadow lookup, NaN.
core::Aabb shadow_bounds(const SceneLights& lights, const FrameContext& frame) {
    core::Aabb b = lights.cameras.bounds;
    if (frame.slot.posed)
        for (const core::Aabb& box : frame.slot.posed_bounds)
            if (!box.valid() || !scene::box_is_invalid(box.min, box.max)) b.expand(box);
    return b;
}

} // namespace

// The first directional light is the main (shadowed) one; with no scene lights at
// all a default sun stands in. Shared with the ray tracer's shadow rays.
MainSun main_sun(const SceneLights& lighting, const FrameRequest& settings) {
    MainSun sun;
    for (std::size_t i = 0; i < lighting.placed_lights.size(); ++i) {
        const scene::PlacedLight& pl = lighting.placed_lights[i];
        if (pl.light >= lighting.lights.size()) continue;
        const scene::Light& l = lighting.lights[pl.light];
        if (l.type != scene::LightType::Directional) continue;
        sun.present = true;
        sun.direction = glm::normalize(pl.direction);
        sun.radiance = l.color * l.intensity;
        sun.placed_light = std::int64_t(i);
        return sun;
    }
    if (lighting.placed_lights.empty() && settings.sun) {
        sun.present = true;
        sun.direction = glm::normalize(settings.sun_direction);
        sun.radiance = glm::vec3(settings.sun_intensity);
    }
    return sun;
}

// Lights, sun, ambient, environment and display transform of a lit frame: what the
// raster's frame constants and the path tracer's share (params.y: the light count).
GPUFrameData lighting_constants(const SceneLights& info, const EnvironmentMap* environment,
                                const FrameRequest& settings) {
    GPUFrameData f{};
    const MainSun sun = main_sun(info, settings);
    f.sun_radiance = glm::vec4(sun.radiance, 0.0f);
    std::uint32_t count = 0;
    for (std::size_t i = 0; i < info.placed_lights.size(); ++i) {
        const scene::PlacedLight& pl = info.placed_lights[i];
        if (pl.light >= info.lights.size() || std::int64_t(i) == sun.placed_light) continue;
        const scene::Light& l = info.lights[pl.light];
        if (count >= kMaxLights) continue; // beyond the fixed array: not lit (documented limit)
        GPULight& g = f.lights[count++];
        g.position_range = glm::vec4(pl.position, l.range);
        g.direction_type =
            glm::vec4(glm::normalize(pl.direction), l.type == scene::LightType::Directional ? 0.0f
                                                    : l.type == scene::LightType::Point     ? 1.0f
                                                                                            : 2.0f);
        g.color_intensity = glm::vec4(l.color, l.intensity);
        g.cone = glm::vec4(std::cos(l.outer_cone), std::cos(l.inner_cone), 0.0f, 0.0f);
    }
    f.params.y = count;
    f.sun_direction = glm::vec4(sun.direction, 0.0f);
    f.ambient = glm::vec4(glm::vec3(settings.ambient), 0.0f);
    // Environment and display transform (ibl.glsl, tonemap.glsl, background.frag).
    if (environment) {
        const EnvironmentStats& env = environment->stats();
        const float turn = glm::radians(settings.environment_rotation);
        f.environment = glm::vec4(settings.environment_intensity, float(env.specular_levels),
                                  std::cos(turn), std::sin(turn));
        if (const auto& sh = environment->irradiance_sh()) {
            for (std::size_t k = 0; k < sh->size(); ++k)
                f.irradiance_sh[k] = glm::vec4((*sh)[k], 0.0f);
            f.irradiance_sh[0].w = 1.0f;
        }
        f.irradiance_sh[1].w = float(settings.anisotropy_lighting); // ibl.glsl
    }
    const float background_level =
        !environment || settings.background == Background::Color ? -1.0f
        : settings.background == Background::Blurred
            ? kBlurredBackgroundRoughness * float(environment->stats().specular_levels - 1)
            : 0.0f;
    f.display = glm::vec4(std::exp2(settings.exposure), float(settings.tone_map),
                          settings.energy_compensation ? 1.0f : 0.0f, background_level);
    return f;
}

void FrameRecorder::write_frame_data(FrameContext& frame) {
    FrameSlot& slot = frame.slot;
    const FrameRequest& settings = frame.settings;
    const SceneLights& info = state.lights;
    slot.camera = resolve_camera(settings.camera, info.cameras, frame.aspect());
    GPUFrameData f = lighting_constants(info, environment.get(), settings);
    const std::uint32_t count = f.params.y;
    f.view = slot.camera.view;
    f.proj = slot.camera.proj;
    f.view_proj = slot.camera.proj * slot.camera.view;
    f.camera_position = glm::vec4(slot.camera.position, 1.0f);
    const MainSun sun = main_sun(info, settings);
    const bool have_sun = sun.present;
    const glm::vec3 sun_dir = sun.direction;

    std::uint32_t cascades = 0;
    frame.cascades = 0;
    slot.cascades = scene::ShadowCascades{};
    if (have_sun && settings.shadows && !settings.floor_only && scene &&
        (settings.view == DebugView::Lit || settings.view == DebugView::Shadow)) {
        // The one cascade fit (scene layer), shared with `sherpa-cli cull`.
        const scene::ShadowCascades c = scene::fit_shadow_cascades(
            cascade_camera(slot.camera), shadow_bounds(info, frame), sun_dir,
            std::min(settings.cascades, kShadowCascades), options.shadow_resolution);
        slot.cascades = c;
        cascades = c.count;
        for (std::uint32_t i = 0; i < c.count; ++i) f.shadow_view_proj[i] = c.view_proj[i];
        f.cascade_splits = c.splits;
        f.cascade_texel = c.texel;
        f.sun_direction.w = c.count > 0 ? 1.0f : 0.0f;
        // A new pose moves the casters: the cached cascades are redrawn.
        const std::uint64_t generation = state.generation ^ (slot.pose_key * 0x9e3779b97f4a7c15ull);
        if (shadows_.needs_render(c, generation, settings.cache_shadows)) frame.cascades = c.count;
    }
    // Every filtered fetch is expensive on a CPU rasterizer: one 2x2 PCF tap there
    // unless the settings ask for more (shadows.glsl reads 1, 4 or 16).
    const std::uint32_t taps = settings.shadow_pcf_taps >= 16  ? 16u
                               : settings.shadow_pcf_taps >= 4 ? 4u
                               : settings.shadow_pcf_taps >= 1 ? 1u
                               : context.info().is_cpu()       ? 1u
                                                               : 4u;
    f.params = glm::uvec4(static_cast<std::uint32_t>(settings.view), count, cascades, taps);
    const core::Aabb& bounds = info.cameras.bounds;
    const float diagonal = bounds.valid() ? glm::length(bounds.extent()) : 1.0f;
    f.overlay = glm::vec4(settings.glyph_length > 0.0f ? settings.glyph_length : 0.02f * diagonal,
                          settings.uv_checker_density,
                          settings.texture_lod >= 0.0f ? settings.texture_lod : -1.0f, 0.0f);
    std::memcpy(resources->get(slot.frame_data).mapped, &f, sizeof(f));
}

} // namespace sherpa::render
