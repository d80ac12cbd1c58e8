// The lighting family's method list and the path tracer's accumulation series.
#include "lighting_plan.h"

#include <algorithm>

namespace sherpa::lab {
namespace detail {

std::string LightingSetup::environment_key() const {
    return std::string(to_string(environment.irradiance)) + "/" +
           std::to_string(environment.specular_size) + "/" +
           std::to_string(environment.specular_samples);
}

std::string LightingSetup::key() const {
    return environment_key() + "/" + std::to_string(shadow_resolution) + "/" +
           std::to_string(shadows) + "/" + std::to_string(cascades) + "/" + std::to_string(taps) +
           "/" + std::to_string(compensation) + "/" + std::to_string(transmission) + "/" +
           std::to_string(anisotropy) + "/" + std::to_string(spp);
}

std::vector<LightingMethod> lighting_methods(const LightingFamilyOptions& options) {
    std::vector<LightingMethod> out;
    auto add = [&](LightingGroup g, const char* group, std::string name, std::string parameters,
                   std::string description, LightingSetup setup) {
        setup.group = g;
        out.push_back(
            {{std::move(name), std::move(parameters), std::move(description), group}, setup});
    };
    LightingSetup setup;
    setup.environment.irradiance = render::IrradianceMode::Cube;
    add(LightingGroup::Irradiance, "irradiance", "irradiance cube", "32x32 faces, 48 samples",
        "diffuse environment light from the Lambert-prefiltered irradiance cube", setup);
    setup.environment.irradiance = render::IrradianceMode::Sh9;
    add(LightingGroup::Irradiance, "irradiance", "irradiance sh9", "9 coefficients",
        "diffuse environment light from 9 spherical-harmonic coefficients, per pixel", setup);

    add(LightingGroup::Prefilter, "specular prefilter", "prefilter default",
        "size=auto samples=16,32",
        "the default specular cube: a quarter of the source's width, 16 then 32 samples", {});
    for (std::uint32_t size : options.specular_sizes)
        for (std::uint32_t samples : options.specular_samples) {
            LightingSetup p;
            p.environment.specular_size = size;
            p.environment.specular_samples = samples;
            add(LightingGroup::Prefilter, "specular prefilter",
                "prefilter " + std::to_string(size) + "/" + std::to_string(samples),
                "size=" + std::to_string(size) + " samples=" + std::to_string(samples),
                "GGX-prefiltered specular cube of " + std::to_string(size) + "x" +
                    std::to_string(size) + " faces, " + std::to_string(samples) +
                    " samples a texel",
                p);
        }

    for (int on : {1, 0}) {
        LightingSetup c;
        c.compensation = on;
        add(LightingGroup::Compensation, "energy compensation",
            on ? "compensation on" : "compensation off", "",
            on ? "split-sum specular with multiple-scattering energy compensation"
               : "split-sum specular, single scattering only",
            c);
    }

    using render::AnisotropyLighting;
    const std::pair<AnisotropyLighting, const char*> anisotropy[] = {
        {AnisotropyLighting::Isotropic,
         "the isotropic split-sum table read along a bent normal (three.js's form)"},
        {AnisotropyLighting::Albedo, "the anisotropic lobe's own split-sum table, one read"},
        {AnisotropyLighting::Lobe,
         "the anisotropic table, four reads spread along the anisotropy direction"}};
    for (const auto& [mode, description] : anisotropy) {
        LightingSetup a;
        a.anisotropy = int(mode);
        add(LightingGroup::Anisotropy, "anisotropy",
            "anisotropy " + std::string(render::to_string(mode)), "", description, a);
    }

    LightingSetup off;
    off.shadows = false;
    add(LightingGroup::Shadows, "shadows", "shadows off", "", "the sun unshadowed", off);
    for (const LightingShadowSetting& sh : options.shadows) {
        LightingSetup s;
        s.shadow_resolution = sh.resolution;
        s.cascades = sh.cascades;
        s.taps = sh.taps;
        add(LightingGroup::Shadows, "shadows",
            "shadows " + shadow_method_name(sh.resolution, sh.cascades, sh.taps),
            "resolution=" + std::to_string(sh.resolution) +
                " cascades=" + std::to_string(sh.cascades) + " taps=" + std::to_string(sh.taps),
            "cascaded shadow maps of the sun", s);
    }

    for (bool on : {true, false}) {
        LightingSetup t;
        t.transmission = on;
        add(LightingGroup::Transmission, "transmission",
            on ? "transmission on" : "transmission off", "",
            on ? "screen-space refraction of the opaque scene (TransmissionPass)"
               : "KHR_materials_transmission dropped: the surfaces drawn as without it",
            t);
    }

    for (std::uint32_t spp : lighting_convergence_spp(options)) {
        LightingSetup p;
        p.spp = spp;
        add(LightingGroup::PathTracer, "path tracer", "path tracer " + std::to_string(spp) + " spp",
            "spp=" + std::to_string(spp),
            "the path tracer itself at fewer samples (another seed) against the reference", p);
    }
    return out;
}

std::vector<PathImage> path_trace_series(render::Renderer& renderer, render::FrameRequest base,
                                         std::uint32_t seed, const std::vector<std::uint32_t>& spp,
                                         const std::function<bool()>& step) {
    std::vector<PathImage> out;
    base.renderer = render::RendererKind::RayTraced;
    base.view = render::DebugView::Lit;
    base.path.seed = seed;
    std::uint32_t done = 0;
    double ms = 0.0;
    bool first = true;
    for (std::uint32_t target : spp) {
        while (done < target) {
            render::FrameRequest s = base;
            s.path.samples = std::min(kPathLaunch, target - done);
            s.path.restart = first;
            first = false;
            const bool last = done + s.path.samples == target;
            PathImage image;
            const render::FrameStats stats = renderer.render(s, last ? &image.rgba : nullptr);
            ms += stats.gpu_ms;
            done += s.path.samples;
            if (last) {
                image.spp = done;
                image.gpu_ms = ms;
                image.error = render::path_trace_error(renderer);
                out.push_back(std::move(image));
            }
            if (!step()) return out;
        }
    }
    return out;
}

} // namespace detail

std::vector<std::uint32_t> lighting_convergence_spp(const LightingFamilyOptions& options) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t s : options.convergence_spp)
        if (s > 0 && s < options.reference_spp) out.push_back(s);
    if (options.convergence_spp.empty())
        for (std::uint32_t s = 1; s <= options.reference_spp / 4; s *= 4) out.push_back(s);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

} // namespace sherpa::lab
