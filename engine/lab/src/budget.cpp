// build_budget: GPU bytes per category, oversized textures over a camera path,
// attributes nothing reads.
#include <sherpa/lab/budget.h>
#include <sherpa/lab/families.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/image_sources.h>
#include <sherpa/scene/usage_report.h>
#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/source_export.h>
#include <sherpa/texture/texture_pipeline.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace sherpa::lab {
namespace {

// Bytes of a full mip chain at `texel_bytes` per texel (RGBA8), or BC blocks.
std::uint64_t chain_bytes(std::uint32_t w, std::uint32_t h, bool block_compressed) {
    std::uint64_t total = 0;
    for (;; w = std::max(1u, w / 2), h = std::max(1u, h / 2)) {
        total += block_compressed ? tex::compressed_size(w, h) : std::uint64_t(w) * h * 4;
        if (w == 1 && h == 1) return total;
    }
}

// Texel density (texels per world unit) of each triangle of an instance in uv set `set`
// of a w x h texture, with the triangle's world area, appended to `out` divided by
// `screen` (pixels per world unit): texels per pixel, area.
void texel_ratios(const scene::Scene& scene, const scene::MeshInstance& inst, std::uint32_t set,
                  std::uint32_t w, std::uint32_t h, double screen,
                  std::vector<std::pair<double, double>>& out) {
    const scene::Mesh& mesh = scene.meshes[inst.mesh_id];
    if (mesh.topology() != scene::Topology::Triangles) return;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::dvec3 p[3];
        glm::dvec2 uv[3];
        for (int k = 0; k < 3; ++k) {
            const scene::Vertex& v = mesh.vertices[mesh.indices[t + std::size_t(k)]];
            p[k] = glm::dvec3(inst.world * glm::vec4(v.position, 1.0f));
            uv[k] = glm::dvec2(set == 1 ? v.uv1 : v.uv0) * glm::dvec2(w, h);
        }
        const double area = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
        const glm::dvec2 a = uv[1] - uv[0], b = uv[2] - uv[0];
        const double uv_area = 0.5 * std::abs(a.x * b.y - a.y * b.x);
        if (!(area > 0.0) || !std::isfinite(uv_area / area)) continue;
        out.emplace_back(std::sqrt(uv_area / area) / screen, area);
    }
}

// The texels per pixel below which only kFineShare of the seen surface lies: level 0
// matters where a pixel covers fewer than 2 texels, and a sliver of degenerate uvs
// should not keep a whole texture at full size.
constexpr double kFineShare = 0.05;
double area_quantile(std::vector<std::pair<double, double>> ratios) {
    std::sort(ratios.begin(), ratios.end());
    double total = 0.0, sum = 0.0;
    for (const auto& r : ratios) total += r.second;
    for (const auto& r : ratios)
        if ((sum += r.second) >= kFineShare * total) return r.first;
    return ratios.empty() ? INFINITY : ratios.back().first;
}

// Screen pixels per world unit at the instance's nearest point, largest over the
// views that see it; 0 when none does.
double max_screen_density(const scene::MeshInstance& inst,
                          const std::vector<scene::CameraSpec>& views,
                          const std::vector<scene::Frustum>& frusta,
                          std::uint32_t viewport_height) {
    double best = 0.0;
    for (std::size_t c = 0; c < views.size(); ++c) {
        if (!inst.world_bounds.valid() || !scene::exact_visible(frusta[c], inst.world_bounds))
            continue;
        const glm::vec3 nearest =
            glm::clamp(views[c].eye, inst.world_bounds.min, inst.world_bounds.max);
        const double d =
            std::max(double(glm::length(nearest - views[c].eye)), double(views[c].near_plane));
        const double half = std::tan(glm::radians(double(views[c].fov_y_degrees)) / 2.0);
        best = std::max(best, double(viewport_height) / (2.0 * d * half));
    }
    return best;
}

// The uv set of the first slot of `m` that samples `image`, or -1.
int uv_set_for(const scene::Scene& scene, const scene::MaterialInstance& m, std::int32_t image) {
    for (const scene::TextureSlot* s :
         {&m.base_color, &m.metallic_roughness, &m.normal, &m.occlusion, &m.emissive})
        if (s->present() && std::size_t(s->texture) < scene.textures.size() &&
            scene.textures[std::size_t(s->texture)].image == image)
            return int(s->tex_coord);
    return -1;
}

// An image's size and how many texels of it a pixel covers at best over the views
// (infinite when no view sees a surface using it); `ok` false when it can't be decoded.
struct ImageMeasure {
    bool ok = false;
    std::uint32_t width = 0, height = 0;
    double texels_per_pixel = 0.0;
};

ImageMeasure measure_image(const scene::Scene& scene, std::int32_t image,
                           const std::vector<scene::CameraSpec>& views,
                           const std::vector<scene::Frustum>& frusta, std::uint32_t viewport_height,
                           std::vector<std::string>& notes) {
    ImageMeasure out;
    tex::RgbaImage decoded;
    std::string error;
    if (scene::image_is_missing(scene.images[std::size_t(image)])) {
        notes.push_back("image " + std::to_string(image) +
                        " not measured: missing: " + scene::image_location(scene, image) +
                        " (the file does not exist or cannot be read)");
        return out;
    }
    if (!tex::decode_image_source(scene.images[std::size_t(image)], decoded, error)) {
        notes.push_back("image " + std::to_string(image) + " not measured: " + error);
        return out;
    }
    out.ok = true;
    out.width = decoded.width;
    out.height = decoded.height;
    std::vector<std::pair<double, double>> ratios;
    for (const scene::MeshInstance& inst : scene.instances) {
        const int set = uv_set_for(scene, scene.materials[inst.material_id], image);
        const double screen = max_screen_density(inst, views, frusta, viewport_height);
        if (set >= 0 && screen > 0.0)
            texel_ratios(scene, inst, std::uint32_t(set), out.width, out.height, screen, ratios);
    }
    out.texels_per_pixel = area_quantile(std::move(ratios));
    if (!std::isfinite(out.texels_per_pixel))
        notes.push_back("image " + std::to_string(image) + ": no view sees a surface using it");
    return out;
}

void add_unread(const scene::Scene& scene, const scene::UsageReport& usage, BudgetReport& out) {
    std::map<std::uint32_t, const scene::PrimitiveUsage*> by_mesh;
    for (const scene::PrimitiveUsage& u : usage.primitives) by_mesh[u.mesh_id] = &u;
    for (const scene::PrimitiveInfo& p : scene.primitives) {
        if (p.engine_mesh < 0) continue;
        const auto it = by_mesh.find(std::uint32_t(p.engine_mesh));
        const bool drawn = it != by_mesh.end() && it->second->instances > 0;
        for (const std::string& name : p.file_attributes) {
            std::string reason;
            if (!drawn)
                reason = "the primitive is not drawn in the displayed scene";
            else if (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0)
                reason = "read by motion evaluation only (info --time); the renderer draws the "
                         "static pose";
            else {
                bool stream = false;
                for (scene::VertexAttribute a : scene::kAllVertexAttributes)
                    if (scene::gltf_name(a) == name) {
                        stream = true;
                        if (!it->second->used[std::size_t(a)])
                            reason = a == scene::VertexAttribute::Tangent
                                         ? "no normal texture reads tangents"
                                         : "the material's shading does not read it";
                    }
                if (!stream && name != "POSITION") reason = "no engine stream holds it";
            }
            if (!reason.empty()) out.unread.push_back({p.mesh, p.primitive, name, reason});
        }
    }
}

} // namespace

BudgetReport build_budget(const scene::Scene& scene, const BudgetOptions& options) {
    BudgetReport out;
    const scene::UsageReport usage = scene::build_usage_report(scene);
    out.categories.push_back(
        {"vertex streams", usage.unified_bytes, usage.used_bytes, usage.used_bytes});
    std::uint64_t index_bytes = 0;
    for (const scene::PrimitiveUsage& u : usage.primitives)
        if (u.instances > 0) index_bytes += 4ull * scene.meshes[u.mesh_id].indices.size();
    out.categories.push_back({"indices", index_bytes, index_bytes, index_bytes});

    std::vector<scene::CameraSpec> views = options.views;
    if (views.empty()) { // the outside orbit of the culling path: the scene framed
        views = camera_path(scene.bounds, 32);
        views.resize(16);
    }
    std::vector<scene::Frustum> frusta;
    for (const scene::CameraSpec& v : views)
        frusta.push_back(scene::frustum_from_view_projection(v.view_projection()));
    out.notes.push_back("views: " + std::to_string(views.size()) + " cameras at " +
                        std::to_string(options.viewport_height) + " px height");
    BudgetCategory textures{"textures", 0, 0, 0};
    // An image in two roles (occlusion and metal-roughness in one file) is stored once
    // per role but decoded and measured once.
    std::map<std::int32_t, ImageMeasure> measured;
    for (const tex::TextureUse& use : tex::collect_texture_uses(scene)) {
        auto [it, fresh] = measured.try_emplace(use.image);
        if (fresh)
            it->second =
                measure_image(scene, use.image, views, frusta, options.viewport_height, out.notes);
        const ImageMeasure& image = it->second;
        if (!image.ok) continue;
        const double texels_per_pixel = image.texels_per_pixel;
        std::uint32_t reduce = 1;
        if (std::isfinite(texels_per_pixel))
            while (reduce * 2 <= texels_per_pixel && image.width / (reduce * 2) >= 1 &&
                   image.height / (reduce * 2) >= 1)
                reduce *= 2;
        const std::uint64_t stored = chain_bytes(image.width, image.height, true);
        textures.unified += chain_bytes(image.width, image.height, false);
        textures.stored += stored;
        textures.needed +=
            reduce > 1 ? chain_bytes(image.width / reduce, image.height / reduce, true) : stored;
        if (reduce > 1)
            out.oversized.push_back({use.image,
                                     scene::image_location(scene, use.image) + " (" +
                                         std::string(tex::role_name(use.role)) + ")",
                                     image.width, image.height, texels_per_pixel, reduce});
    }
    out.categories.push_back(textures);
    const std::uint64_t materials = sizeof(scene::GPUMaterialData) * scene.materials.size();
    out.categories.push_back({"materials", materials, materials, materials});
    const std::uint64_t instances = sizeof(render::GPUInstanceData) * scene.instances.size();
    out.categories.push_back({"instances", instances, instances, instances});
    add_unread(scene, usage, out);
    return out;
}

} // namespace sherpa::lab
