// sherpa-cli tangents SCENE (--dump FILE.csv | --compare) [--method NAME] [--regenerate] [--json]
//
// --dump writes one row per face corner in glTF triangle order (after strip/fan
// conversion): mesh,primitive,triangle,corner,tx,ty,tz,tw. Authored tangents are dumped
// as read unless --regenerate; every other primitive gets generated ones.
// --compare prints, per primitive with authored tangents, the angle error and handedness
// flips of regenerated tangents against the authored ones.
#include "cli_common.h"

#include <sherpa/scene/mesh_tangents.h>
#include <sherpa/scene/scene_loader.h>
#include <sherpa/scene/tangent_compare.h>

#include <cstdio>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

constexpr std::string_view kUsage = "tangents"; // main.cpp's usage text

struct Options {
    std::string spec, dump_path;
    bool compare = false, json = false, regenerate = false;
    scene::TangentMethod method = scene::TangentMethod::MikkTSpace;
};

int usage_error(const std::string& message) {
    return cli::usage_error(message, kUsage);
}

bool authored(const scene::Mesh& mesh) {
    return mesh.provenance_of(scene::VertexAttribute::Tangent) == scene::Provenance::Authored;
}

int dump(scene::Scene& scene, const Options& o) {
    std::ofstream out(o.dump_path);
    if (!out) {
        std::fprintf(stderr, "error: cannot write %s\n", o.dump_path.c_str());
        return kExitLoadError;
    }
    std::uint64_t generated = 0, splits = 0, fallbacks = 0;
    for (scene::Mesh& mesh : scene.meshes) {
        if (o.regenerate || !authored(mesh)) {
            const scene::MeshTangentReport r =
                scene::generate_mesh_tangents(mesh, scene::normal_uv_set(scene, mesh), o.method);
            ++generated;
            splits += r.split_vertices;
            fallbacks += r.stats.fallbacks();
        }
    }
    out << "mesh,primitive,triangle,corner,tx,ty,tz,tw\n";
    char row[256];
    for (const scene::Mesh& mesh : scene.meshes)
        for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
            const glm::vec4 t = mesh.vertices[mesh.indices[c]].tangent;
            std::snprintf(row, sizeof row, "%u,%u,%zu,%zu,%.9g,%.9g,%.9g,%.9g\n", mesh.group_id,
                          mesh.primitive_index, c / 3, c % 3, t.x, t.y, t.z, t.w);
            out << row;
        }
    std::fprintf(
        stderr,
        "%s: %llu primitives generated with %s (%llu vertices split, %llu fallback corners)\n",
        o.dump_path.c_str(), (unsigned long long)generated,
        std::string(to_string(o.method)).c_str(), (unsigned long long)splits,
        (unsigned long long)fallbacks);
    return kExitOk;
}

int compare(const scene::Scene& scene, const Options& o) {
    nlohmann::json rows = nlohmann::json::array();
    if (!o.json)
        std::printf("%-5s %-4s %8s %11s %11s %11s %6s %9s  (%s vs authored, degrees)\n", "mesh",
                    "prim", "corners", "mean", "p99", "max", "flips", "fallback",
                    std::string(to_string(o.method)).c_str());
    for (const scene::Mesh& mesh : scene.meshes) {
        nlohmann::json row = {{"mesh", mesh.group_id},
                              {"primitive", mesh.primitive_index},
                              {"authored", authored(mesh)}};
        if (!authored(mesh)) {
            if (!o.json)
                std::printf("%-5u %-4u   no authored TANGENT\n", mesh.group_id,
                            mesh.primitive_index);
            rows.push_back(row);
            continue;
        }
        const scene::MeshTangentInput input =
            scene::tangent_input_of(mesh, scene::normal_uv_set(scene, mesh));
        std::vector<glm::vec4> regenerated(mesh.indices.size()), read(mesh.indices.size());
        const scene::TangentStats stats =
            scene::generate_corner_tangents(input.view(mesh), o.method, regenerated);
        for (std::size_t c = 0; c < read.size(); ++c)
            read[c] = mesh.vertices[mesh.indices[c]].tangent;
        const scene::TangentComparison cmp = scene::compare_tangents(regenerated, read);
        row.update({{"corners", cmp.corners},
                    {"mean_deg", cmp.mean},
                    {"p99_deg", cmp.p99},
                    {"max_deg", cmp.max},
                    {"handedness_flips", cmp.flips},
                    {"nonfinite_authored", cmp.nonfinite},
                    {"fallback_corners", stats.fallbacks()},
                    {"method", to_string(o.method)}});
        rows.push_back(row);
        if (!o.json)
            std::printf("%-5u %-4u %8llu %11.3e %11.3e %11.3e %6llu %9llu\n", mesh.group_id,
                        mesh.primitive_index, (unsigned long long)cmp.corners, cmp.mean, cmp.p99,
                        cmp.max, (unsigned long long)cmp.flips,
                        (unsigned long long)stats.fallbacks());
    }
    if (o.json)
        std::cout << nlohmann::json{{"source", scene.source}, {"primitives", rows}}.dump(2) << "\n";
    return kExitOk;
}

} // namespace

int run_tangents(Args args) {
    Options o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        if (a == "--dump" && i + 1 < args.size())
            o.dump_path = std::string(args[++i]);
        else if (a == "--method" && i + 1 < args.size()) {
            if (!scene::parse_tangent_method(args[++i], o.method))
                return usage_error("unknown method '" + std::string(args[i]) + "'");
        } else if (a == "--compare")
            o.compare = true;
        else if (a == "--json")
            o.json = true;
        else if (a == "--regenerate")
            o.regenerate = true;
        else if (!a.empty() && a[0] == '-')
            return usage_error("unknown or incomplete option '" + std::string(a) + "'");
        else if (o.spec.empty())
            o.spec = std::string(a);
        else
            return usage_error("more than one SCENE given");
    }
    if (o.spec.empty()) return usage_error("no SCENE given");
    if (o.compare == !o.dump_path.empty())
        return usage_error("give exactly one of --dump FILE and --compare");
    scene::LoadOptions load;
    load.generate_tangents = false; // this command decides what to generate
    scene::LoadResult r = scene::load_scene(o.spec, load);
    if (!r) {
        std::fprintf(stderr, "error: %s\n", r.error.c_str());
        return kExitLoadError;
    }
    return o.compare ? compare(*r.scene, o) : dump(*r.scene, o);
}

} // namespace sherpa::cli
