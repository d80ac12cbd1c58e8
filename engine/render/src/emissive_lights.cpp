#include <sherpa/render/emissive_lights.h>

#include <sherpa/scene/image_sources.h>
#include <sherpa/texture/source_export.h>
#include <sherpa/texture/texture_pipeline.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace sherpa::render {

namespace {

// A texture coordinate wrapped into [0, 1] as the sampler's address mode does.
float wrap(float u, scene::AddressMode mode) {
    if (!std::isfinite(u)) return 0.0f;
    switch (mode) {
    case scene::AddressMode::ClampToEdge:
        return std::clamp(u, 0.0f, 1.0f);
    case scene::AddressMode::MirroredRepeat: {
        const float m = u - 2.0f * std::floor(0.5f * u); // [0, 2)
        return m > 1.0f ? 2.0f - m : m;
    }
    case scene::AddressMode::Repeat:
        break;
    }
    return u - std::floor(u);
}

float nearest(const LuminanceGrid& g, glm::vec2 uv, scene::AddressMode wrap_u,
              scene::AddressMode wrap_v) {
    const float u = wrap(uv.x, wrap_u), v = wrap(uv.y, wrap_v);
    const std::uint32_t x = std::min(std::uint32_t(u * float(g.width)), g.width - 1);
    const std::uint32_t y = std::min(std::uint32_t(v * float(g.height)), g.height - 1);
    return g.texels[std::size_t(y) * g.width + x];
}

// What the user reads: the file, the JSON pointer (where one applies) and the problem.
std::string warning(const scene::Scene& scene, const std::string& pointer,
                    const std::string& problem) {
    return "path tracer lights: " + scene.source + ": " + (pointer.empty() ? "" : pointer + ": ") +
           problem;
}

std::string material_pointer(const scene::Scene& scene, std::size_t material) {
    // The default material the importer adds is not in the file.
    return material < scene.counts.materials ? "/materials/" + std::to_string(material) : "";
}

std::string quoted_name(const scene::MaterialInstance& m) {
    return m.name.empty() ? "" : " '" + m.name + "'";
}

// Why a scene that animates gets no list: its animations, else its first skinned or
// morphed primitive.
std::string animation_warning(const scene::Scene& scene) {
    const std::string what = "its emissive triangles move, so they are found by BSDF sampling "
                             "only (no light list)";
    if (!scene.animations.empty())
        return warning(scene, "/animations",
                       "the scene animates (" + std::to_string(scene.animations.size()) +
                           (scene.animations.size() == 1 ? " animation): " : " animations): ") +
                           what);
    const scene::PrimitiveMotion& m = scene.motions.front();
    return warning(
        scene, "/meshes/" + std::to_string(m.mesh) + "/primitives/" + std::to_string(m.primitive),
        std::string("the scene animates (this primitive is ") +
            (m.skinned() ? "skinned" : "morphed") + "): " + what);
}

// The first variant mapping that changes an emitter's luminance, as a warning; empty
// when every variant keeps every emitter's.
std::string variant_warning(const scene::Scene& scene, const std::vector<float>& luminance) {
    for (const scene::VariantMeshMapping& v : scene.variants.meshes)
        for (std::size_t k = 0; k < v.materials.size(); ++k) {
            const std::int32_t m = v.materials[k];
            if (m < 0 || std::size_t(m) >= luminance.size() ||
                v.default_material >= luminance.size() ||
                luminance[std::size_t(m)] == luminance[v.default_material])
                continue;
            std::string pointer;
            for (const scene::PrimitiveInfo& p : scene.primitives)
                if (p.engine_mesh == std::int32_t(v.mesh))
                    pointer = "/meshes/" + std::to_string(p.mesh) + "/primitives/" +
                              std::to_string(p.primitive) + "/extensions/KHR_materials_variants";
            const std::string name =
                k < scene.variants.names.size() ? " '" + scene.variants.names[k] + "'" : "";
            return warning(
                scene, pointer,
                "material variant " + std::to_string(k) + name +
                    " changes which surfaces emit (material " + std::to_string(m) +
                    quoted_name(scene.materials[std::size_t(m)]) + " emits luminance " +
                    std::to_string(luminance[std::size_t(m)]) + ", the default material " +
                    std::to_string(v.default_material) +
                    quoted_name(scene.materials[v.default_material]) + " " +
                    std::to_string(luminance[v.default_material]) +
                    "): its emissive triangles are found by BSDF sampling only (no light list)");
        }
    return {};
}

// The prepared texture of `image`, or null.
const tex::PreparedTexture* prepared_image(const tex::PreparedTextureSet* set, std::int32_t image) {
    if (!set) return nullptr;
    for (const tex::PreparedTexture& t : set->textures)
        if (t.image == image) return &t;
    return nullptr;
}

// The luminance grid of emissive image `image`, read by material `material`: the
// texture pipeline's when it made one, else decoded here; empty (sampled as if white,
// with a warning) when the image cannot be read.
LuminanceGrid image_grid_of(const scene::Scene& scene, std::int32_t image, std::size_t material,
                            const tex::PreparedTextureSet* textures, EmissiveLights& out) {
    const tex::PreparedTexture* prepared = prepared_image(textures, image);
    if (prepared && prepared->luminance) {
        ++out.textures_reused;
        return *prepared->luminance;
    }
    std::string error;
    if (prepared && prepared->failed) {
        error = prepared->note; // the pipeline tried already: "undecodable: ...", "missing: ..."
    } else {
        tex::RgbaImage decoded;
        if (tex::decode_image_source(scene.images[std::size_t(image)], decoded, error)) {
            ++out.textures_read;
            return luminance_grid(decoded.width, decoded.height, decoded.pixels);
        }
    }
    const std::string pointer = material_pointer(scene, material);
    out.warnings.push_back(
        warning(scene, pointer.empty() ? "" : pointer + "/emissiveTexture",
                "its image (/images/" + std::to_string(image) + ", " +
                    scene::image_location(scene, image) + ") cannot be read (" + error +
                    "): its emissive triangles are weighted as if it were white"));
    return {};
}

} // namespace

double mean_over_triangle(const LuminanceGrid& grid, const glm::vec2 uv[3],
                          scene::AddressMode wrap_u, scene::AddressMode wrap_v) {
    if (grid.texels.empty()) return 0.0;
    constexpr int n = 8; // 64 sub-triangles of equal area, each sampled at its centroid
    const glm::vec2 d1 = uv[1] - uv[0], d2 = uv[2] - uv[0];
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
            sum += nearest(grid,
                           uv[0] + ((float(i) + 1.0f / 3.0f) / n) * d1 +
                               ((float(j) + 1.0f / 3.0f) / n) * d2,
                           wrap_u, wrap_v);
            if (i + j < n - 1)
                sum += nearest(grid,
                               uv[0] + ((float(i) + 2.0f / 3.0f) / n) * d1 +
                                   ((float(j) + 2.0f / 3.0f) / n) * d2,
                               wrap_u, wrap_v);
        }
    return sum / double(n * n);
}

float emitted_luminance(const scene::MaterialInstance& m) {
    if (m.unlit) return 0.0f;
    const glm::vec3 e = m.emissive_factor * m.emissive_strength;
    const float lum = 0.2126f * e.r + 0.7152f * e.g + 0.0722f * e.b;
    return std::isfinite(lum) && lum > 0.0f ? lum : 0.0f;
}

EmissiveLights emissive_lights(const scene::Scene& scene, std::size_t max_triangles,
                               const tex::PreparedTextureSet* textures) {
    EmissiveLights out;
    std::vector<float> luminance(scene.materials.size(), 0.0f);
    bool any = false;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::MaterialInstance& m = scene.materials[i];
        const float lum = emitted_luminance(m);
        if (lum > kMaxEmissiveLuminance) {
            out.warnings.push_back(warning(scene, material_pointer(scene, i),
                                           "material" + quoted_name(m) + ": emitted luminance " +
                                               std::to_string(lum) +
                                               " is beyond 1e20; not sampled as a light (its "
                                               "samples are capped at 1e20)"));
            continue;
        }
        luminance[i] = lum;
        any = any || lum > 0.0f;
    }
    if (!any) return out;
    if (!scene.animations.empty() || !scene.motions.empty()) {
        out.warnings.push_back(animation_warning(scene));
        return out;
    }
    // A material variant switched after loading may change what emits: a list of the
    // loaded variant would bias the others, so BSDF sampling alone finds them.
    if (std::string w = variant_warning(scene, luminance); !w.empty()) {
        out.warnings.push_back(std::move(w));
        return out;
    }
    // Per emitting material with an emissive texture: its image's luminance grid (decoded
    // once per image, shared by the materials that use it) and its sampler's wrap modes.
    struct EmissiveTexture {
        const LuminanceGrid* grid = nullptr;
        scene::AddressMode wrap_u = scene::AddressMode::Repeat, wrap_v = scene::AddressMode::Repeat;
    };
    std::vector<EmissiveTexture> grids(scene.materials.size());
    std::vector<std::optional<LuminanceGrid>> image_grids(scene.images.size());
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::TextureSlot& slot = scene.materials[i].emissive;
        if (!(luminance[i] > 0.0f) || !slot.present() || slot.tex_coord > 1 ||
            std::size_t(slot.texture) >= scene.textures.size())
            continue;
        const scene::TextureRecord& texture = scene.textures[std::size_t(slot.texture)];
        if (texture.image < 0 || std::size_t(texture.image) >= scene.images.size()) continue;
        std::optional<LuminanceGrid>& image_grid = image_grids[std::size_t(texture.image)];
        // Sampled as if white when it cannot be read: unbiased, only less apt.
        if (!image_grid) image_grid = image_grid_of(scene, texture.image, i, textures, out);
        if (image_grid->texels.empty()) continue;
        const scene::SamplerDesc sampler = scene.sampler_of(texture);
        grids[i] = {&*image_grid, sampler.wrap_u, sampler.wrap_v};
    }
    std::vector<double> power, sampled;
    for (const scene::MeshInstance& inst : scene.instances) {
        if (inst.mesh_id >= scene.meshes.size() || inst.material_id >= luminance.size()) continue;
        const float lum = luminance[inst.material_id];
        const scene::Mesh& mesh = scene.meshes[inst.mesh_id];
        if (!(lum > 0.0f) || mesh.topology() != scene::Topology::Triangles) continue;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            glm::vec3 p[3];
            glm::vec2 uv[3];
            bool valid = true;
            const EmissiveTexture& grid = grids[inst.material_id];
            const scene::TextureSlot& slot = scene.materials[inst.material_id].emissive;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = mesh.indices[t + std::size_t(k)];
                if (v >= mesh.vertices.size()) {
                    valid = false;
                    break;
                }
                const scene::Vertex& vertex = mesh.vertices[v];
                p[k] = glm::vec3(inst.world * glm::vec4(vertex.position, 1.0f));
                uv[k] = slot.tex_coord == 1 ? vertex.uv1 : vertex.uv0;
                if (slot.transform.present)
                    uv[k] = glm::vec2(slot.transform.matrix() * glm::vec3(uv[k], 1.0f));
            }
            if (!valid || !core::is_finite(p[0]) || !core::is_finite(p[1]) ||
                !core::is_finite(p[2]))
                continue;
            const glm::vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
            const double area = 0.5 * double(glm::length(glm::cross(e1, e2)));
            if (!(area > 0.0) || !std::isfinite(area)) continue; // degenerate: never hit
            if (out.triangles.size() == max_triangles) {
                out.warnings.push_back(warning(scene, "",
                                               "more than " + std::to_string(max_triangles) +
                                                   " emissive triangles: none sampled as lights"));
                return EmissiveLights{{}, 0.0f, 0.0, 0.0, 0, 0, std::move(out.warnings)};
            }
            // The texture's mean over the triangle, with a floor (kEmissiveTextureFloor);
            // 1 without a texture. A black texture emits nothing anywhere.
            const double mean = grid.grid
                                    ? mean_over_triangle(*grid.grid, uv, grid.wrap_u, grid.wrap_v) +
                                          kEmissiveTextureFloor * grid.grid->mean
                                    : 1.0;
            if (!(mean > 0.0)) continue;
            out.triangles.push_back({glm::vec4(p[0], 0.0f), glm::vec4(e1, 0.0f),
                                     glm::vec4(e2, 0.0f),
                                     glm::vec4(lum, float(double(lum) * mean), 0.0f, 0.0f)});
            power.push_back(double(lum) * area);
            sampled.push_back(double(lum) * mean * area);
        }
    }
    double total = 0.0, sampled_total = 0.0;
    for (double w : power) total += w;
    for (double w : sampled) sampled_total += w;
    const auto representable = [](double w) {
        return w > 0.0 && std::isfinite(w) && std::isfinite(float(1.0 / w)) &&
               float(1.0 / w) != 0.0f;
    };
    if (out.triangles.empty() || !representable(total) || !representable(sampled_total)) {
        if (!out.triangles.empty())
            out.warnings.push_back(warning(scene, "",
                                           "the emissive triangles' total power is not "
                                           "representable; none sampled as lights"));
        return EmissiveLights{{}, 0.0f, 0.0, 0.0, 0, 0, std::move(out.warnings)};
    }
    double running = 0.0;
    for (std::size_t i = 0; i < out.triangles.size(); ++i) {
        running += sampled[i];
        EmissiveTriangle& tri = out.triangles[i];
        tri.p0_cdf.w = i + 1 == out.triangles.size() ? 1.0f : float(running / sampled_total);
        // The share of the triangle over its area: the triangle's share / its area.
        tri.e1_density.w = float(double(tri.emission.y) / sampled_total);
    }
    out.power = total;
    out.sampled_power = sampled_total;
    out.inv_power = float(1.0 / total);
    return out;
}

} // namespace sherpa::render
