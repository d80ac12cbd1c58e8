// import_gltf(): parse with tinygltf, validate, convert, flatten. Any failure
// discards the partial scene and reports "FILE: what is wrong".
#include "import_context.h"
#include "import_error.h"
#include "load_stages.h"

#include <sherpa/core/file_io.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <filesystem>

#include <tiny_gltf.h>

namespace sherpa {
namespace {

constexpr std::array<std::string_view, 5> kSupportedExtensions{
    "KHR_texture_transform", "KHR_materials_emissive_strength",
    "KHR_lights_punctual",   "KHR_materials_unlit",
    "KHR_mesh_quantization", // every accessor component type is decoded
};

// Keeps images encoded: decoding belongs to the texture pipeline, which hashes the
// encoded bytes for its cache. tinygltf hands us the bytes of external files, data
// URIs and bufferViews alike.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
    image->image.assign(bytes, bytes + size);
    image->width = image->height = -1;
    image->as_is = true;
    return true;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// tinygltf messages can embed whole data URIs; keep messages one readable line.
std::string clean_message(const std::string& s) {
    std::string out = s;
    for (std::size_t at = out.find("base64,"); at != std::string::npos;
         at = out.find("base64,", at + 1)) {
        const std::size_t begin = at + 7;
        std::size_t end = begin;
        while (end < out.size() && (std::isalnum(static_cast<unsigned char>(out[end])) ||
                                    out[end] == '+' || out[end] == '/' || out[end] == '='))
            ++end;
        if (end - begin > 16) out.replace(begin, end - begin, "...");
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    std::replace(out.begin(), out.end(), '\n', ';');
    return out;
}

// Warnings for meshes whose tangents needed fallbacks or could not be generated.

} // namespace

LoadResult import_gltf(const std::string& path, const LoadOptions& options) {
    LoadResult result;
    if (!detail::begin_stage(options, LoadStage::Parse)) return detail::cancelled_result();
    const auto t_parse = std::chrono::steady_clock::now();
    std::vector<std::uint8_t> bytes;
    std::string io_error;
    if (!read_file(path, bytes, io_error)) {
        result.error = io_error;
        return result;
    }
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_encoded_image, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const std::string base_dir = std::filesystem::path(path).parent_path().string();
    const bool is_glb = bytes.size() >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF");
    bool ok = false;
    if (bytes.empty())
        err = "file is empty";
    else if (is_glb)
        ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                         static_cast<unsigned>(bytes.size()), base_dir);
    else
        ok = loader.LoadASCIIFromString(&model, &err, &warn,
                                        reinterpret_cast<const char*>(bytes.data()),
                                        static_cast<unsigned>(bytes.size()), base_dir);
    if (!ok) {
        result.error = path + ": " + (err.empty() ? "not a valid glTF file" : clean_message(err));
        return result;
    }
    auto scene = std::make_unique<Scene>();
    scene->source = path;
    scene->parse_ms = ms_since(t_parse);
    if (!warn.empty()) scene->warnings.push_back("tinygltf: " + clean_message(warn));
    if (!detail::end_stage(options, LoadStage::Parse)) return detail::cancelled_result();

    const auto t_process = std::chrono::steady_clock::now();
    try {
        for (const auto& ext : model.extensionsRequired)
            if (std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), ext) ==
                kSupportedExtensions.end())
                detail::fail("extensionsRequired: \"" + ext + "\" is not supported by Sherpa");
        detail::ImportContext ctx{model, *scene};
        if (!detail::begin_stage(options, LoadStage::Geometry)) return detail::cancelled_result();
        detail::import_samplers_images_textures(ctx);
        detail::import_materials(ctx);
        detail::import_meshes(ctx);
        if (!detail::end_stage(options, LoadStage::Geometry)) return detail::cancelled_result();
        if (!detail::tangent_stage(*scene, options)) return detail::cancelled_result();
        detail::import_lights_cameras(ctx);
        detail::import_nodes_and_scenes(ctx);
        const std::int32_t scene_index =
            options.scene_index >= 0 ? options.scene_index : std::max(model.defaultScene, 0);
        std::string select_error;
        if (!select_scene(*scene, scene_index, select_error)) detail::fail(select_error);
    } catch (const detail::ImportError& e) {
        result.error = path + ": " + e.what();
        return result;
    } catch (const std::exception& e) { // allocation failures on absurd sizes and the like
        result.error = path + ": " + e.what();
        return result;
    }
    scene->process_ms = ms_since(t_process);
    result.scene = std::move(scene);
    return result;
}

} // namespace sherpa
