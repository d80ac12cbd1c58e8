#include "scene_json.h"

#include "motion_json.h"
#include <sherpa/scene/gltf_extensions.h>
#include <sherpa/texture/basis.h>
#include <sherpa/texture/image_container.h>

#include <chrono>
#include <cstring>

namespace sherpa::cli {

using nlohmann::json;

json aabb_json(const core::Aabb& box) {
    if (!box.valid()) return json{{"min", nullptr}, {"max", nullptr}, {"empty", true}};
    return json{{"min", {box.min.x, box.min.y, box.min.z}},
                {"max", {box.max.x, box.max.y, box.max.z}}};
}

json usage_json(const scene::Scene& scene, const scene::UsageReport& report) {
    json prims = json::array();
    for (const auto& u : report.primitives) {
        json present = json::array(), used = json::array();
        for (scene::VertexAttribute a : scene::kAllVertexAttributes) {
            const auto i = static_cast<std::size_t>(a);
            if (u.present[i]) present.push_back(scene::gltf_name(a));
            if (u.used[i]) used.push_back(scene::gltf_name(a));
        }
        prims.push_back({{"mesh", u.group_id},
                         {"primitive", u.primitive_index},
                         {"material", scene.materials[u.material_id].gltf_index},
                         {"instances", u.instances},
                         {"vertices", u.vertex_count},
                         {"present", present},
                         {"used", used},
                         {"used_bytes", u.used_bytes},
                         {"unified_bytes", u.unified_bytes}});
    }
    const double saved =
        report.unified_bytes ? 1.0 - double(report.used_bytes) / double(report.unified_bytes) : 0.0;
    return json{{"primitives", prims},
                {"used_bytes", report.used_bytes},
                {"unified_bytes", report.unified_bytes},
                {"saved_fraction", saved}};
}

// Each extension the file names, and whether Sherpa reads it.
json extensions_json(const std::vector<std::string>& names) {
    json out = json::array();
    for (const auto& n : names)
        out.push_back({{"name", n}, {"supported", scene::is_supported_gltf_extension(n)}});
    return out;
}

// Per image: its container; KTX2 files have their level 0 transcoded (as the
// texture pipeline does, within the texel budget) to tell ETC1S from UASTC and time it.
json images_json(const scene::Scene& scene) {
    json out = json::array();
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        const scene::ImageRecord& img = scene.images[i];
        json e = {{"image", i}, {"uri", img.uri}, {"bytes", img.byte_size}};
        if (tex::is_ktx2(img.encoded)) {
            tex::BasisTexture t;
            std::string error;
            const auto t0 = std::chrono::steady_clock::now();
            if (tex::transcode_ktx2_basis(img.encoded, t, error, /*base_level_only=*/true)) {
                e["transcode_ms"] =
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                        .count();
                e["container"] = std::string(tex::basis_payload_name(t.payload));
                e["supercompression"] = std::string(tex::supercompression_name(t.supercompression));
            } else {
                e["container"] = "ktx2";
                e["error"] = error;
            }
        } else {
            e["container"] = tex::image_container(img.encoded).name;
        }
        out.push_back(std::move(e));
    }
    return out;
}

json gpu_instancing_json(const scene::Scene& scene) {
    json nodes = json::array();
    std::uint64_t file_rows = 0, drawn_rows = 0, instances = 0;
    for (const scene::MeshInstance& inst : scene.instances) instances += inst.row >= 0 ? 1 : 0;
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const auto& g = scene.nodes[n].instancing;
        if (!g) continue;
        file_rows += g->file_rows;
        drawn_rows += g->rows.size();
        nodes.push_back({{"node", n},
                         {"name", scene.nodes[n].name},
                         {"file_rows", g->file_rows},
                         {"drawn_rows", g->rows.size()},
                         {"translation", g->translation},
                         {"rotation", g->rotation},
                         {"scale", g->scale},
                         {"custom_attributes", g->custom_attributes}});
    }
    return {{"nodes", nodes},
            {"file_rows", file_rows},
            {"drawn_rows", drawn_rows},
            {"instances", instances}};
}

json scene_info_json(const scene::Scene& scene) {
    const scene::SourceCounts& c = scene.counts;
    json j = {{"source", scene.source},
              {"scenes", c.scenes},
              {"displayed_scene", scene.displayed_scene},
              {"nodes", c.nodes},
              {"meshes", c.meshes},
              {"primitives", c.primitives},
              {"materials", c.materials},
              {"textures", c.textures},
              {"images", c.images},
              {"samplers", c.samplers},
              {"lights", c.lights},
              {"cameras", c.cameras},
              {"instances", scene.node_primitive_pairs()},
              {"drawable_instances", scene.instances.size()},
              {"vertices", c.vertices},
              {"triangles", c.triangles},
              {"bounds", aabb_json(scene.bounds)}};
    json detail = json::array();
    for (const auto& p : scene.primitives) {
        json attrs = json::object();
        for (const auto& [name, prov] : scene.attribute_provenance(p))
            attrs[name] = to_string(prov);
        json e = {{"mesh", p.mesh},         {"primitive", p.primitive}, {"mode", to_string(p.mode)},
                  {"vertices", p.vertices}, {"indices", p.indices},     {"triangles", p.triangles},
                  {"material", p.material}, {"attributes", attrs}};
        if (scene::topology_of(p.mode) == scene::Topology::Lines) e["segments"] = p.segments;
        if (scene::topology_of(p.mode) == scene::Topology::Points) e["points"] = p.points;
        if (p.compression)
            e["compression"] = {{"codec", p.compression->codec},
                                {"mode", p.compression->modes},
                                {"encoded_bytes", p.compression->encoded_bytes},
                                {"decoded_bytes", p.compression->decoded_bytes},
                                {"decode_ms", p.compression->decode_ms}};
        if (p.engine_mesh >= 0) {
            const scene::Mesh& m = scene.meshes[static_cast<std::size_t>(p.engine_mesh)];
            e["engine_vertices"] = m.vertices.size();
            e["unwelded"] = m.unwelded;
        } else {
            e["skipped"] = p.skipped_reason;
        }
        if (p.morph_targets) e["morph_targets"] = morph_targets_json(scene, p);
        detail.push_back(std::move(e));
    }
    j["primitives_detail"] = std::move(detail);
    j["skins"] = skins_json(scene);
    j["gpu_instancing"] = gpu_instancing_json(scene);
    j["animations"] = animations_json(scene);
    j["images_detail"] = images_json(scene);
    j["extensions_used"] = extensions_json(scene.extensions_used);
    j["extensions_required"] = extensions_json(scene.extensions_required);
    j["usage"] = usage_json(scene, scene::build_usage_report(scene));
    j["warnings"] = scene.warnings;
    json violations = json::array();
    for (const auto& v : scene.range_violations)
        violations.push_back({{"accessor", v.accessor},
                              {"where", v.where},
                              {"elements", v.elements},
                              {"elements_outside", v.elements_outside},
                              {"declared_min", v.declared_min},
                              {"declared_max", v.declared_max},
                              {"data_min", v.data_min},
                              {"data_max", v.data_max}});
    j["accessor_range_violations"] = std::move(violations);
    j["timings_ms"] = {{"parse", scene.parse_ms},
                       {"process", scene.process_ms},
                       {"validate", scene.validation.ms}};
    j["validation"] = {{"numErrors", scene.validation.count(scene::Severity::Error)},
                       {"numWarnings", scene.validation.count(scene::Severity::Warning)},
                       {"numInfos", scene.validation.count(scene::Severity::Information)},
                       {"numHints", scene.validation.count(scene::Severity::Hint)},
                       {"truncated", scene.validation.truncated}};
    return j;
}

nlohmann::json cull_stats_json(const scene::CullStats& st) {
    nlohmann::json matrix = nlohmann::json::array();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) matrix.push_back(st.view_projection[c][r]);
    return {{"cull_view_projection", matrix},
            {"method", st.gpu ? std::string("gpu (") + std::string(to_string(st.method)) + ")"
                              : std::string(to_string(st.method))},
            {"simd", to_string(st.simd)},
            {"total", st.total},
            {"tested", st.tested},
            {"visible", st.visible},
            {"culled", st.culled},
            {"invalid", st.invalid},
            {"hidden", st.hidden},
            {"false_positives", st.false_positives},
            {"cpu_gpu_differences", st.cpu_gpu_differences},
            {"draw_calls", st.draw_calls},
            {"triangles", st.triangles},
            {"cpu_ms", st.cpu_ms},
            {"gpu_ms", st.gpu_ms}};
}

} // namespace sherpa::cli
