// sherpa-cli lab SCENE --family NAME [--json|--csv] [--chart OUT.svg] [family options]
// Runs one Lab family (engine/lab) on the scene and prints per method its time, its
// error figures against the family's reference and its failures by cause.
#include "cli_common.h"
#include "environment_options.h"
#include "variant_options.h"

#include <sherpa/core/file_io.h>
#include <sherpa/gpu/context.h>
#include <sherpa/lab/families.h>
#include <sherpa/lab/report_export.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

struct Options {
    std::string spec, family, chart;
    std::string variant; // --variant NAME: KHR_materials_variants
    bool json = false, csv = false, gpu = true;
    int repeat = 0; // 0: the family's default
    long long sample_texels = -1, cameras = -1;
    // The lighting family: image size, the reference's samples and bounces (0: default).
    std::uint32_t width = 0, height = 0, reference_spp = 0, max_bounces = 0;
    bool max_bounces_given = false;
    // The lit frames' environment and display settings (the shadows family), parsed by
    // the options render takes: the room unless --environment says otherwise.
    render::EnvironmentChoice environment;
    render::FrameRequest lighting;
};

// The usage text (main.cpp) lists the engine's families (lab::family_names), the one
// list the editor's dock also reads.
int usage_error(const std::string& message) {
    return cli::usage_error(message, "lab");
}

std::unique_ptr<lab::Family> make(const Options& o) {
    if (o.family == "tangents") {
        lab::TangentFamilyOptions t;
        if (o.repeat > 0) t.repeat = o.repeat;
        return lab::make_tangent_family(t);
    }
    if (o.family == "textures") {
        lab::TextureFamilyOptions t;
        if (o.sample_texels >= 0) t.sample_texels = std::uint64_t(o.sample_texels);
        return lab::make_texture_family(t);
    }
    if (o.family == "culling") {
        lab::CullFamilyOptions c;
        if (o.repeat > 0) c.repeat = o.repeat;
        if (o.cameras > 0) c.path_length = std::uint32_t(o.cameras);
        c.gpu = o.gpu;
        return lab::make_cull_family(c);
    }
    if (o.family == "mesh-compression") {
        lab::MeshCompressionFamilyOptions m;
        if (o.repeat > 0) m.repeat = o.repeat;
        return lab::make_mesh_compression_family(m);
    }
    if (o.family == "shadows") {
        lab::ShadowFamilyOptions sh;
        if (o.repeat > 0) sh.frames = std::uint32_t(o.repeat);
        if (o.cameras > 0) sh.cameras = std::uint32_t(std::min(o.cameras, 64LL));
        sh.lighting = {make_environment_image(o.environment), o.lighting};
        return lab::make_shadow_family(sh);
    }
    if (o.family == "lighting") {
        lab::LightingFamilyOptions l;
        if (o.repeat > 0) l.frames = std::uint32_t(o.repeat);
        if (o.width > 0) l.width = o.width;
        if (o.height > 0) l.height = o.height;
        if (o.reference_spp > 0) l.reference_spp = o.reference_spp;
        if (o.max_bounces_given) l.max_bounces = o.max_bounces;
        // SHERPA_VALIDATION=1: every validation message is a failure of its method.
        l.validation = gpu::ContextOptions::default_validation();
        l.lighting = {make_environment_image(o.environment), o.lighting};
        return lab::make_lighting_family(l);
    }
    return nullptr;
}

nlohmann::json report_json(const scene::Scene& scene, const lab::FamilyReport& r) {
    const std::vector<std::size_t> front = lab::pareto_front(r);
    nlohmann::json methods = nlohmann::json::array();
    for (std::size_t i = 0; i < r.methods.size(); ++i) {
        const lab::MethodResult& m = r.methods[i];
        nlohmann::json errors = nlohmann::json::object(), failures = nlohmann::json::array();
        std::map<std::string, std::uint64_t> by_cause;
        for (const lab::ErrorFigure& e : m.errors) errors[e.name] = e.value;
        for (const lab::Failure& f : m.failures) {
            failures.push_back({{"cause", f.cause}, {"where", f.where}, {"count", f.count}});
            by_cause[f.cause] += f.count;
        }
        methods.push_back({{"name", m.method.name},
                           {"parameters", m.method.parameters},
                           {"group", m.method.group},
                           {"ran", m.ran},
                           {"note", m.note},
                           {"time", m.time},
                           {"time_unit", r.time_unit},
                           {"total_ms", m.total_ms},
                           {"errors", errors},
                           {"failures", failures},
                           {"failures_by_cause", by_cause},
                           {"pareto", std::find(front.begin(), front.end(), i) != front.end()}});
    }
    return {{"source", scene.source},
            {"family", r.family},
            {"reference", r.reference},
            {"time_unit", r.time_unit},
            {"chart_error", r.chart_error},
            {"notes", r.notes},
            {"warnings", r.warnings},
            {"chart_x", lab::chart_x_name(r)},
            {"methods", methods}};
}

void print_text(const lab::FamilyReport& r) {
    std::printf("%s against %s; time in %s\n", r.family.c_str(), r.reference.c_str(),
                r.time_unit.c_str());
    for (const std::string& n : r.notes) std::printf("  note: %s\n", n.c_str());
    const std::vector<std::size_t> front = lab::pareto_front(r);
    for (std::size_t i = 0; i < r.methods.size(); ++i) {
        const lab::MethodResult& m = r.methods[i];
        const std::string name =
            m.method.name + (m.method.parameters.empty() ? "" : " " + m.method.parameters);
        if (!m.ran) {
            std::printf("%-22s not run: %s\n", name.c_str(), m.note.c_str());
        } else {
            const bool pareto = std::find(front.begin(), front.end(), i) != front.end();
            std::printf("%-22s %11.4g %s%s", name.c_str(), m.time, r.time_unit.c_str(),
                        pareto ? " *" : "  ");
            for (const lab::ErrorFigure& e : m.errors)
                std::printf("  %s %.4g", e.name.c_str(), e.value);
            std::printf("\n");
        }
        for (const lab::Failure& f : m.failures)
            std::printf("    failure: %s at %s (%llu)\n", f.cause.c_str(), f.where.c_str(),
                        (unsigned long long)f.count);
    }
    std::printf("* on the Pareto front of %s against %s\n", lab::chart_x_name(r).c_str(),
                r.chart_error.c_str());
}

} // namespace

int run_lab(Args args) {
    Options o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        const bool has_value = i + 1 < args.size();
        std::string option_error;
        const OptionMatch em =
            parse_environment_option(args, i, o.lighting, o.environment, option_error);
        if (em == OptionMatch::Bad) return usage_error(option_error);
        if (em == OptionMatch::Taken) continue;
        const OptionMatch vm = parse_variant_option(args, i, o.variant, option_error);
        if (vm == OptionMatch::Bad) return usage_error(option_error);
        if (vm == OptionMatch::Taken) continue;
        if (a == "--family" && has_value)
            o.family = std::string(args[++i]);
        else if (a == "--chart" && has_value)
            o.chart = std::string(args[++i]);
        else if (a == "--repeat" && has_value)
            o.repeat = std::max(1, std::atoi(std::string(args[++i]).c_str()));
        else if (a == "--sample-texels" && has_value)
            o.sample_texels = std::max(0LL, std::atoll(std::string(args[++i]).c_str()));
        else if (a == "--cameras" && has_value)
            o.cameras = std::max(1LL, std::atoll(std::string(args[++i]).c_str()));
        else if ((a == "--width" || a == "--height" || a == "--reference-spp" ||
                  a == "--max-bounces") &&
                 has_value) {
            const std::string v(args[++i]);
            long long n = 0;
            const long long low = a == "--max-bounces" ? 0 : 1;
            const long long high = a == "--reference-spp" ? 65536
                                   : a == "--max-bounces" ? 64
                                                          : 4096;
            if (!parse_number(v, n) || n < low || n > high)
                return usage_error(std::string(a) + " needs a whole number from " +
                                   std::to_string(low) + " to " + std::to_string(high) + ", not '" +
                                   v + "'");
            (a == "--width"           ? o.width
             : a == "--height"        ? o.height
             : a == "--reference-spp" ? o.reference_spp
                                      : o.max_bounces) = std::uint32_t(n);
            if (a == "--max-bounces") o.max_bounces_given = true;
        } else if (a == "--json")
            o.json = true;
        else if (a == "--csv")
            o.csv = true;
        else if (a == "--no-gpu")
            o.gpu = false;
        else if (!a.empty() && a[0] == '-')
            return usage_error("unknown or incomplete option '" + std::string(a) + "'");
        else if (o.spec.empty())
            o.spec = std::string(a);
        else
            return usage_error("more than one SCENE given");
    }
    if (o.spec.empty()) return usage_error("no SCENE given");
    if (o.json && o.csv) return usage_error("give at most one of --json and --csv");
    std::unique_ptr<lab::Family> family = make(o);
    if (!family) return usage_error("unknown family '" + o.family + "'");
    scene::LoadResult loaded = scene::load_scene(o.spec, lab::lab_load_options());
    if (!loaded) {
        std::fprintf(stderr, "error: %s\n", loaded.error.c_str());
        return kExitLoadError;
    }
    if (std::string error; !apply_variant_option(*loaded.scene, o.variant, error))
        return usage_error(error);
    const lab::FamilyReport report = family->run(*loaded.scene, {});
    // On stderr whatever the format (as render prints its warnings).
    for (const std::string& w : report.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (!o.chart.empty()) {
        const std::string svg = lab::report_svg(report);
        std::string error;
        if (!core::write_file_atomic(
                o.chart, std::span(reinterpret_cast<const std::uint8_t*>(svg.data()), svg.size()),
                error)) {
            std::fprintf(stderr, "error: %s\n", error.c_str());
            return kExitLoadError;
        }
    }
    if (o.json)
        std::cout << report_json(*loaded.scene, report).dump(2) << "\n";
    else if (o.csv)
        std::cout << lab::report_csv(report);
    else
        print_text(report);
    return kExitOk;
}

} // namespace sherpa::cli
