// compare_files: counts, materials, textures and byte sizes; geometry in
// compare_geometry.cpp.
#include <sherpa/lab/compare.h>
#include <sherpa/scene/image_sources.h>
#include <sherpa/texture/quality.h>
#include <sherpa/texture/source_export.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "compare_detail.h"

namespace sherpa::lab {
namespace {

std::string text(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", double(v));
    return buf;
}
template <int N> std::string text(const glm::vec<N, float>& v) {
    std::string s = "(";
    for (int i = 0; i < N; ++i) s += (i ? ", " : "") + text(v[i]);
    return s + ")";
}
std::string text(bool v) {
    return v ? "true" : "false";
}

std::string slot_text(const scene::TextureSlot& s) {
    if (!s.present()) return "none";
    std::string t = "texture " + std::to_string(s.texture) + " uv" + std::to_string(s.tex_coord);
    if (s.transform.present)
        t += " offset " + text(s.transform.offset) + " scale " + text(s.transform.scale) +
             " rotation " + text(s.transform.rotation);
    return t;
}

// Every compared field of a material as text, by name: one list for both sides.
std::vector<std::pair<std::string, std::string>> material_fields(const scene::MaterialInstance& m) {
    return {{"name", m.name},
            {"base_color_factor", text(m.base_color_factor)},
            {"emissive_factor", text(m.emissive_factor)},
            {"emissive_strength", text(m.emissive_strength)},
            {"metallic_factor", text(m.metallic_factor)},
            {"roughness_factor", text(m.roughness_factor)},
            {"normal_scale", text(m.normal_scale)},
            {"occlusion_strength", text(m.occlusion_strength)},
            {"alpha_mode", std::string(to_string(m.alpha_mode))},
            {"alpha_cutoff", text(m.alpha_cutoff)},
            {"double_sided", text(m.double_sided)},
            {"unlit", text(m.unlit)},
            {"specular_glossiness", text(m.specular_glossiness.has_value())},
            {"base_color_texture", slot_text(m.base_color)},
            {"metallic_roughness_texture", slot_text(m.metallic_roughness)},
            {"normal_texture", slot_text(m.normal)},
            {"occlusion_texture", slot_text(m.occlusion)},
            {"emissive_texture", slot_text(m.emissive)}};
}

std::vector<CountDiff> counts(const scene::Scene& a, const scene::Scene& b) {
    const scene::SourceCounts &x = a.counts, &y = b.counts;
    return {{"scenes", x.scenes, y.scenes},
            {"nodes", x.nodes, y.nodes},
            {"meshes", x.meshes, y.meshes},
            {"primitives", x.primitives, y.primitives},
            {"materials", x.materials, y.materials},
            {"textures", x.textures, y.textures},
            {"images", x.images, y.images},
            {"samplers", x.samplers, y.samplers},
            {"vertices", x.vertices, y.vertices},
            {"triangles", x.triangles, y.triangles},
            {"instances", a.instances.size(), b.instances.size()}};
}

TextureDiff compare_image(const scene::Scene& a, const scene::Scene& b, std::int32_t i) {
    TextureDiff d;
    d.image = i;
    d.a = scene::image_location(a, i), d.b = scene::image_location(b, i);
    const scene::ImageRecord &ia = a.images[std::size_t(i)], &ib = b.images[std::size_t(i)];
    d.bytes_a = ia.byte_size, d.bytes_b = ib.byte_size;
    tex::RgbaImage xa, xb;
    std::string error;
    if (!tex::decode_image_source(ia, xa, error) || !tex::decode_image_source(ib, xb, error)) {
        d.note = "undecodable: " + error;
        return d;
    }
    d.width_a = xa.width, d.height_a = xa.height, d.width_b = xb.width, d.height_b = xb.height;
    if (xa.width != xb.width || xa.height != xb.height)
        d.note = "sizes differ";
    else
        d.psnr = tex::squared_error(xa.pixels, xb.pixels, tex::kChannelsRgba).psnr();
    return d;
}

std::uint64_t file_bytes(const std::filesystem::path& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    return ec ? 0 : std::uint64_t(size);
}

// The file plus the external buffers and images a .gltf names (percent escapes are
// rare in sample files and left as written: such a file counts 0).
std::uint64_t total_bytes(const scene::Scene& scene) {
    const std::filesystem::path path(scene.source);
    std::uint64_t total = file_bytes(path);
    std::ifstream in(path);
    const nlohmann::json doc =
        path.extension() == ".gltf" ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    if (!doc.is_object()) return total;
    for (const char* array : {"buffers", "images"})
        for (const nlohmann::json& item : doc.value(array, nlohmann::json::array()))
            if (item.is_object() && item.contains("uri") && item["uri"].is_string()) {
                const std::string uri = item["uri"];
                if (uri.rfind("data:", 0) != 0) total += file_bytes(path.parent_path() / uri);
            }
    return total;
}

} // namespace

FileComparison compare_files(const scene::Scene& a, const scene::Scene& b) {
    FileComparison out;
    out.counts = counts(a, b);
    out.primitives = detail::compare_primitives(a, b);
    const std::size_t materials = std::min(a.materials.size(), b.materials.size());
    for (std::size_t m = 0; m < materials; ++m) {
        const auto fa = material_fields(a.materials[m]), fb = material_fields(b.materials[m]);
        MaterialDiff diff;
        diff.material = std::uint32_t(m);
        for (std::size_t f = 0; f < fa.size(); ++f)
            if (fa[f].second != fb[f].second)
                diff.fields.push_back(fa[f].first + ": " + fa[f].second + " -> " + fb[f].second);
        if (!diff.fields.empty()) out.materials.push_back(std::move(diff));
    }
    if (a.materials.size() != b.materials.size())
        out.notes.push_back("material counts differ: the first " + std::to_string(materials) +
                            " compared");
    const std::size_t images = std::min(a.images.size(), b.images.size());
    for (std::size_t i = 0; i < images; ++i)
        out.textures.push_back(compare_image(a, b, std::int32_t(i)));
    if (a.images.size() != b.images.size())
        out.notes.push_back("image counts differ: the first " + std::to_string(images) +
                            " compared");
    out.file_bytes_a = file_bytes(a.source), out.file_bytes_b = file_bytes(b.source);
    out.total_bytes_a = total_bytes(a), out.total_bytes_b = total_bytes(b);
    for (const scene::ImageRecord& i : a.images) out.image_bytes_a += i.byte_size;
    for (const scene::ImageRecord& i : b.images) out.image_bytes_b += i.byte_size;
    return out;
}

} // namespace sherpa::lab
