// import_gltf(): parse with tinygltf, validate, convert, flatten. Any failure
// discards the partial scene and reports "FILE: what is wrong".
#include "gltf_draco.h"
#include "gltf_fs.h"
#include "gltf_lenient.h"
#include "gltf_meshopt.h"
#include "gltf_prepare.h"
#include "gltf_validate.h"
#include "import_context.h"
#include "import_error.h"
#include "load_stages.h"
#include "motion_internal.h"
#include "validate_internal.h"

#include <sherpa/scene/gltf_extensions.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <set>

#include <tiny_gltf.h>

namespace sherpa::scene {
namespace {

// The vertex attributes the engine draws with; any other is reported.
constexpr std::array<std::string_view, 6> kDrawnAttributes{"POSITION",   "NORMAL",     "TANGENT",
                                                           "TEXCOORD_0", "TEXCOORD_1", "COLOR_0"};

// Keeps images encoded: decoding belongs to the texture pipeline, which hashes the
// encoded bytes for its cache. tinygltf hands us the bytes of external files and data
// URIs; for a bufferView it passes the view's range unchecked (a view longer than
// its buffer was copied past the end), so those bytes are taken later, range-checked,
// by import_samplers_images_textures.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string* err, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
    if (image->bufferView < 0) {
        if (size < 0) {
            if (err) *err += "image larger than 2 GiB";
            return false;
        }
        image->image.assign(bytes, bytes + size);
    }
    image->width = image->height = -1;
    image->as_is = true;
    return true;
}

// tinygltf's own lines about image files it could not read ("File not found : x.png",
// "Failed to load external 'uri' for image[0] name = []"): the texture layer reports
// every such image once, with its path and the material slots that read it. Images
// are the only files tinygltf loads as optional, so these lines are about images.
std::string without_image_file_lines(const std::string& warn) {
    constexpr std::string_view kImageLines[] = {
        "File not found : ", "File read error : ", "File is empty : ",
        "Failed to load external 'uri' for image["};
    std::string out;
    std::size_t begin = 0;
    while (begin < warn.size()) {
        std::size_t end = warn.find('\n', begin);
        if (end == std::string::npos) end = warn.size();
        const std::string_view line(warn.data() + begin, end - begin);
        bool image_line = false;
        for (std::string_view prefix : kImageLines) image_line |= line.starts_with(prefix);
        if (!image_line && !line.empty()) out.append(line).push_back('\n');
        begin = end + 1;
    }
    return out;
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

// The attributes Sherpa does not draw with (TEXCOORD_2+, ...) are named in a warning,
// so nothing is dropped without a word. Skins, morph targets and animations are drawn
// (the renderer skins and morphs on the GPU); whether a front end draws the default
// pose is that front end's to say (sherpa-cli warns when no --time is given; the
// editor has a timeline).
void warn_unsupported_content(detail::ImportContext& ctx) {
    const auto& model = ctx.model;
    std::set<std::string> unused;
    auto drawn = [](const std::string& name) { // JOINTS_n / WEIGHTS_n: GPU skinning
        return std::find(kDrawnAttributes.begin(), kDrawnAttributes.end(), name) !=
                   kDrawnAttributes.end() ||
               name.starts_with("JOINTS_") || name.starts_with("WEIGHTS_");
    };
    for (const auto& mesh : model.meshes)
        for (const auto& prim : mesh.primitives)
            for (const auto& [name, accessor] : prim.attributes)
                if (!drawn(name)) unused.insert(name);
    if (!unused.empty()) {
        std::string names;
        for (const auto& n : unused) names += (names.empty() ? "" : ", ") + n;
        ctx.warn("attributes " + names + " are not used for drawing");
    }
}

LoadResult import_gltf_unguarded(const std::string& path, const LoadOptions& options) {
    LoadResult result;
    if (!detail::begin_stage(options, LoadStage::Parse)) return detail::cancelled_result();
    const auto t_parse = std::chrono::steady_clock::now();
    std::vector<std::uint8_t> bytes;
    std::string problem;
    if (!detail::read_regular_file(path, bytes, problem)) {
        if (problem.rfind("is a directory", 0) == 0) problem = "is a directory, not a glTF file";
        result.error = path + ": " + problem;
        return result;
    }
    // Refuses what tinygltf would crash on or silently misread (see gltf_validate.h),
    // parsing the JSON once for those checks and the validator.
    nlohmann::json root;
    ValidationReport report;
    auto refuse = [&](const std::string& why) {
        result.error = path + ": " + why;
        detail::add_import_message(report, "SHERPA_LOAD_REFUSED", Severity::Error, why);
        result.validation = std::move(report);
        return std::move(result);
    };
    std::string khronos_code;
    detail::DocumentOrder order;
    if (problem = detail::parse_gltf_document(bytes, root, &khronos_code, &order);
        !problem.empty()) {
        if (!khronos_code.empty()) // the Khronos validator's name for it, too
            report.messages.push_back({khronos_code, problem, "", Severity::Error});
        return refuse(problem);
    }
    const bool is_glb = bytes.size() >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF");
    bool edited = detail::normalize_integers(root); // "count": 3.0 is an integer in glTF
    std::optional<detail::DocumentValidator> validator;
    const std::string base_dir = std::filesystem::path(path).parent_path().string();
    validator.emplace(root, bytes, is_glb, report, base_dir.empty() ? "." : base_dir, &order);
    if (problem = detail::check_gltf_document(root); !problem.empty()) return refuse(problem);
    if (problem = detail::check_gltf_properties(root); !problem.empty()) return refuse(problem);
    edited |= detail::replace_unreadable_buffers(root, is_glb, validator->glb_has_bin(), report);
    edited |= detail::drop_unreadable_instancing_ids(root, report);
    if (edited) bytes = detail::with_json(root, bytes, is_glb);
    if (const auto marked = detail::with_channel_nodes(root)) // KHR_animation_pointer
        bytes = detail::with_json(*marked, bytes, is_glb);
    // Compressed files hold what tinygltf would refuse (see gltf_prepare.h).
    if (auto rewritten = detail::prepared_for_tinygltf(bytes); !rewritten.empty())
        bytes = std::move(rewritten);
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_encoded_image, nullptr);
    loader.SetFsCallbacks(detail::safe_fs_callbacks());
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    try { // tinygltf allocates what the file asks for; keep its failures in this boundary
        if (is_glb)
            ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                             static_cast<unsigned>(bytes.size()), base_dir);
        else
            ok = loader.LoadASCIIFromString(&model, &err, &warn,
                                            reinterpret_cast<const char*>(bytes.data()),
                                            static_cast<unsigned>(bytes.size()), base_dir);
    } catch (const std::bad_alloc&) {
        err = "out of memory while parsing (the file asks for more than this machine has)";
    } catch (const std::exception& e) {
        err = e.what();
    }
    if (!ok) return refuse(err.empty() ? "not a valid glTF file" : clean_message(err));
    std::vector<std::span<const std::uint8_t>> buffers;
    for (const auto& b : model.buffers) buffers.emplace_back(b.data.data(), b.data.size());
    for (const ValidationMessage& m : report.messages) // stand-in bytes are no data
        if (m.code == "SHERPA_BUFFER_NOT_LOADED" && m.pointer.starts_with("/buffers/"))
            if (const auto i = std::strtoull(m.pointer.c_str() + 9, nullptr, 10);
                i < buffers.size())
                buffers[i] = {};
    std::vector<std::span<const std::uint8_t>> images; // encoded bytes from URIs
    for (const auto& image : model.images)
        images.emplace_back(image.image.data(), image.image.size());
    validator->check_data(buffers, images);
    std::vector<std::uint8_t> bounds_hold = validator->take_bounds_hold();
    validator.reset();
    auto scene = std::make_unique<Scene>();
    scene->source = path;
    scene->parse_ms = ms_since(t_parse) - report.ms; // the validator's time is its own
    scene->validation = std::move(report);
    if (const std::string rest = without_image_file_lines(warn); !rest.empty())
        scene->warnings.push_back("tinygltf: " + clean_message(rest));
    if (!detail::end_stage(options, LoadStage::Parse)) return detail::cancelled_result();

    const auto t_process = std::chrono::steady_clock::now();
    try {
        // validate_gltf_bytes refused unsupported required extensions already.
        scene->extensions_used = model.extensionsUsed;
        scene->extensions_required = model.extensionsRequired;
        const auto decoded_views = detail::decode_meshopt_views(model, buffers);
        const auto decoded_draco = detail::decode_draco_primitives(model);
        detail::ImportContext ctx{model, *scene};
        // The validator read the file's bytes; a decoded meshopt view holds others.
        std::vector<bool> decoded(model.bufferViews.size(), false);
        for (const auto& d : decoded_views)
            if (d.view >= 0 && std::size_t(d.view) < decoded.size())
                decoded[std::size_t(d.view)] = true;
        for (std::size_t a = 0; a < model.accessors.size() && a < bounds_hold.size(); ++a) {
            const int view = model.accessors[a].bufferView;
            if (view >= 0 && std::size_t(view) < decoded.size() && decoded[std::size_t(view)])
                bounds_hold[a] = 0;
        }
        ctx.bounds_hold = std::move(bounds_hold);
        ctx.undecodable = detail::undecodable_primitives(model, decoded_views);
        // A view shown from its fallback bytes, or read by no primitive (animation
        // data: the channels reading it are skipped by the accessor reader), is said
        // here; a primitive's skip message carries the reason otherwise.
        std::set<std::string> skipping;
        for (const auto& [key, why] : ctx.undecodable) skipping.insert(why);
        for (const auto& d : decoded_views)
            if (!d.failed.empty() && (d.fell_back || !skipping.contains(d.failed)))
                ctx.warn(d.failed);
        for (const auto& d : decoded_draco) {
            if (!d.failed.empty())
                ctx.undecodable.emplace(std::pair{d.mesh, d.primitive}, d.failed);
            ctx.range_checked.insert(d.range_checked.begin(), d.range_checked.end());
            for (const std::string& w : d.warnings) ctx.warn(w);
        }
        if (!detail::begin_stage(options, LoadStage::Geometry)) return detail::cancelled_result();
        detail::import_samplers_images_textures(ctx);
        detail::import_materials(ctx);
        detail::import_meshes(ctx);
        detail::import_material_variants(ctx);
        detail::attach_meshopt_compression(model, decoded_views, *scene);
        detail::attach_draco_compression(decoded_draco, *scene);
        if (!detail::end_stage(options, LoadStage::Geometry)) return detail::cancelled_result();
        if (!detail::tangent_stage(*scene, options)) return detail::cancelled_result();
        detail::import_lights_cameras(ctx);
        detail::import_nodes_and_scenes(ctx);
        detail::import_skins(ctx);
        detail::import_gpu_instancing(ctx);
        detail::import_default_weights(ctx);
        detail::import_animations(ctx);
        warn_unsupported_content(ctx);
        // What is not drawn, said loudly (gltf_extensions.h).
        for (std::string& w : unsupported_extension_warnings(*scene)) ctx.warn(std::move(w));
        for (ValidationMessage& m : unsupported_extension_messages(*scene))
            scene->validation.messages.push_back(std::move(m));
        std::int32_t scene_index =
            options.scene_index >= 0 ? options.scene_index : std::max(model.defaultScene, 0);
        // An unresolved default scene (the validator's UNRESOLVED_REFERENCE at /scene)
        // shows the first scene rather than nothing; a scene the caller asks for is exact.
        if (options.scene_index < 0 && !scene->scenes.empty() &&
            static_cast<std::size_t>(scene_index) >= scene->scenes.size()) {
            ctx.warn("default scene index " + std::to_string(scene_index) + " out of range (" +
                     std::to_string(scene->scenes.size()) + " scenes); scene 0 is shown");
            scene_index = 0;
        }
        std::string select_error;
        if (!select_scene(*scene, scene_index, select_error)) detail::fail(select_error);
    } catch (const detail::ImportError& e) {
        report = std::move(scene->validation);
        return refuse(e.what());
    } catch (const std::bad_alloc&) {
        report = std::move(scene->validation);
        return refuse("out of memory while importing");
    } catch (const std::exception& e) { // library failures on odd input
        report = std::move(scene->validation);
        return refuse(e.what());
    }
    scene->process_ms = ms_since(t_process);
    // The importer's own warnings, as SHERPA_ messages with the pointer they name.
    std::set<std::string> said; // skipped parts are messages already
    for (const auto& m : scene->validation.messages)
        if (m.code.rfind("SHERPA_", 0) == 0) said.insert(m.message);
    for (const std::string& w : scene->warnings)
        if (!said.contains(w))
            detail::add_import_message(scene->validation, "SHERPA_IMPORT_NOTE",
                                       Severity::Information, w);
    result.scene = std::move(scene);
    return result;
}

} // namespace

// The error boundary: whatever throws while one file is read, checked, parsed or
// converted (allocation included) ends as "FILE: what went wrong", never an abort.
LoadResult import_gltf(const std::string& path, const LoadOptions& options) {
    LoadResult failed;
    try {
        return import_gltf_unguarded(path, options);
    } catch (const std::bad_alloc&) {
        failed.error = path + ": out of memory while loading";
    } catch (const std::exception& e) {
        failed.error = path + ": " + e.what();
    }
    return failed;
}

} // namespace sherpa::scene
