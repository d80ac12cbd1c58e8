#include "render_report.h"
#include "scene_json.h"
#include "texture_cli.h"

#include <sherpa/render/gpu_scene.h>

#include <algorithm>
#include <map>

namespace sherpa::cli {

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string device_type(VkPhysicalDeviceType t) {
    switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "cpu";
    default:
        return "other";
    }
}

// Per prepared texture its record with the GPU side (bindless slot, mip levels,
// device bytes), and counts by cache state and by format.
nlohmann::json textures_json(const render::SceneTextures& textures,
                             const std::optional<std::filesystem::path>& cache_dir) {
    using nlohmann::json;
    json list = json::array();
    std::map<std::string, int> by_state, by_format;
    for (std::size_t i = 0; i < textures.records().size(); ++i) {
        const tex::PreparedTexture& t = textures.records()[i];
        const render::GpuTexture& g = textures.gpu()[i];
        json j = texture_json(t);
        j["mips"] = g.mip_levels;
        j["bindless_slot"] = g.slot == scene::kTextureSentinel ? json(nullptr) : json(g.slot);
        j["bytes"] = g.bytes; // device memory of the image
        list.push_back(j);
        ++by_state[std::string(tex::to_string(t.state))];
        ++by_format[std::string(tex::vk_format_name(t.format))];
    }
    return {{"cache_dir",
             cache_dir ? json(std::filesystem::absolute(*cache_dir).string()) : json(nullptr)},
            {"count", list.size()},
            {"by_state", by_state},
            {"by_format", by_format},
            {"gpu_bytes", textures.gpu_bytes()},
            {"textures", list}};
}

} // namespace

nlohmann::json render_report_json(render::Renderer& renderer, const RenderRun& run) {
    using nlohmann::json;
    const gpu::DeviceInfo& dev = renderer.context().info();
    json j;
    j["device"] = {{"name", dev.name},
                   {"type", device_type(dev.type)},
                   {"api_version", std::to_string(VK_API_VERSION_MAJOR(dev.api_version)) + "." +
                                       std::to_string(VK_API_VERSION_MINOR(dev.api_version)) + "." +
                                       std::to_string(VK_API_VERSION_PATCH(dev.api_version))},
                   {"ray_tracing", dev.ray_tracing},
                   {"ray_query", dev.ray_query},
                   {"ray_tracing_enabled", dev.ray_tracing_enabled},
                   {"ray_query_enabled", dev.ray_query_enabled}};
    j["scene"] = run.scene;
    j["width"] = run.settings.width;
    j["height"] = run.settings.height;
    j["view"] = std::string(to_string(run.settings.view));
    j["renderer"] = std::string(to_string(run.settings.renderer));
    j["camera"] = run.camera_text;
    j["frames"] = run.frames.size();

    // The environment lighting the lit view (absent: none, no GPU bytes) and the display
    // transform.
    const render::EnvironmentStats env = renderer.resident().environment;
    j["tone_map"] = std::string(to_string(run.settings.tone_map));
    j["exposure"] = run.settings.exposure;
    if (env.present)
        j["environment"] = {
            {"name", env.name},
            {"source", {env.source_width, env.source_height}},
            {"cube_size", env.cube_size},
            {"specular_levels", env.specular_levels},
            {"irradiance", std::string(to_string(env.irradiance))},
            {"irradiance_size", env.irradiance_size},
            {"sheen_size", env.sheen_size},
            {"sheen_levels", env.sheen_levels},
            {"lut_size", env.lut_size},
            {"anisotropy_lut_bytes", env.anisotropy_lut_bytes},
            {"bytes", env.bytes},
            {"prefilter_ms", env.prefilter_ms},
            {"prefilter_gpu_ms", env.gpu_ms},
            {"rotation_degrees", run.settings.environment_rotation},
            {"intensity", run.settings.environment_intensity},
            {"background", std::string(to_string(run.settings.background))},
            {"energy_compensation", run.settings.energy_compensation},
            {"anisotropy_lighting", std::string(to_string(run.settings.anisotropy_lighting))}};
    else
        j["environment"] = nullptr;
    if (env.present) {
        json passes;
        const char* names[] = {"radiance_cube", "specular", "irradiance", "sheen", "lut"};
        for (std::size_t i = 0; i < std::size(names); ++i) passes[names[i]] = env.pass_ms[i];
        passes["anisotropy_lut"] = env.anisotropy_lut_gpu_ms;
        j["environment"]["pass_gpu_ms"] = passes;
    }
    const render::GpuScene* scene = renderer.scene();
    if (scene) {
        const render::GpuMemoryReport& m = scene->memory();
        j["gpu_memory_bytes"] = {
            {"vertex_streams", m.vertex_streams},
            {"indices", m.indices},
            {"textures", m.textures},
            {"materials", m.materials},
            // Blocks of the materials that use an extension (0: none).
            {"material_extensions", m.material_extensions},
            {"instances", m.instances},
            // Skinning and morph streams: 0 for a static scene.
            {"motion", m.motion},
            {"total", m.total()},
            {"render_targets", renderer.resident().render_target_bytes},
            // KHR_materials_transmission's background (in render_targets):
            // 0 without a transmissive material.
            {"transmission_target", renderer.resident().transmission_target_bytes},
            {"environment", renderer.resident().environment.bytes}};
        // What the geometry buffers were made for: acceleration-structure build input
        // and index device addresses only with ray tracing enabled (`--rt`).
        j["geometry_buffers"] = {
            {"usage_flags", m.geometry_usage},
            {"acceleration_structure_input",
             (m.geometry_usage &
              VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR) != 0}};
        j["vertex_layout"] = {
            {"used_streams_bytes", m.vertex_streams},
            {"unified_56_byte_bytes", m.unified_vertex_bytes},
            {"saved_percent",
             m.unified_vertex_bytes
                 ? 100.0 * (1.0 - double(m.vertex_streams) / double(m.unified_vertex_bytes))
                 : 0.0}};
        j["triangles"] = scene->triangle_count();
        j["draw_groups"] = scene->groups().size();
        j["warnings"] = scene->materials().textures().warnings();
        // What needs no action (how textures were stored for this device).
        j["notices"] = scene->materials().textures().prepared().notices;
        j["textures"] = textures_json(scene->materials().textures(), run.cache_dir);
        if (renderer.resident().acceleration) {
            // The path tracer's emissive light list (ray tracing on): what it samples, the
            // emissive images decoded for it (0 when the texture pipeline gave their
            // luminance), and why emitters are not sampled.
            const render::EmissiveLightStats& e = renderer.resident().emissive;
            j["emissive_lights"] = {{"triangles", e.triangles},
                                    {"images_decoded", e.images_decoded},
                                    {"images_from_textures", e.images_reused},
                                    {"build_ms", e.build_ms},
                                    {"warnings", e.warnings}};
        }
    }
    j["load_ms"] = {{"scene_load", run.timing.scene_load_ms},
                    {"texture_prepare", run.timing.texture_prepare_ms},
                    {"gpu_upload", run.timing.gpu_upload_ms},
                    {"load_and_first_frame", run.timing.load_and_first_frame_ms},
                    {"scope", "wall clock, one run; device creation not included"}};

    // Per pass: median over frames (the first frame also builds pipelines and
    // shadow maps; medians keep the steady state).
    std::map<std::string, std::vector<double>> per_pass;
    std::vector<double> gpu_ms;
    for (const render::FrameStats& f : run.frames) {
        for (const render::PassTiming& p : f.passes) per_pass[p.name].push_back(p.ms);
        gpu_ms.push_back(f.gpu_ms);
    }
    json passes = json::object();
    for (auto& [name, v] : per_pass) passes[name] = median(v);
    j["gpu_time_ms"] = {{"passes_median", passes},
                        {"frame_median", median(gpu_ms)},
                        {"first_frame", run.frames.empty() ? 0.0 : run.frames.front().gpu_ms}};
    j["cpu_frame_ms_median"] = median(run.cpu_frame_ms);
    if (!run.frames.empty()) {
        const render::FrameStats& last = run.frames.back();
        j["pipeline_statistics"] = {
            {"input_assembly_primitives", last.input_primitives},
            {"vertex_shader_invocations", last.vertex_invocations},
            {"clipping_invocations", last.clipping_invocations},
            {"clipping_primitives", last.clipping_primitives},
            {"fragment_shader_invocations", last.fragment_invocations},
            {"scope", "camera passes of the last frame (not shadow cascades)"}};
        j["draw_calls"] = last.draw_calls;
        // Per culled pass of the last frame (cascades: of the last frame that rendered
        // them); times are medians over the frames that ran the pass.
        json culling = json::array();
        for (const scene::CullStats& c : last.culling) {
            std::vector<double> cpu, gpu;
            for (const render::FrameStats& f : run.frames)
                if (const scene::CullStats* same = f.pass(c.pass);
                    same && (c.pass == "camera" || f.shadows_rendered)) {
                    cpu.push_back(same->cpu_ms);
                    if (same->gpu_ms >= 0.0) gpu.push_back(same->gpu_ms);
                }
            json pass = cull_stats_json(c);
            pass["name"] = c.pass;
            pass["path"] = std::string(to_string(run.settings.cull));
            pass["cpu_ms_median"] = median(cpu);
            pass["gpu_ms_median"] = gpu.empty() ? -1.0 : median(gpu);
            culling.push_back(std::move(pass));
        }
        j["culling"] = culling;
        j["culling_scope"] =
            "camera: the shading draws (opaque, mask, blend) once; cascadeN: the shadow draws "
            "into cascade N; depth_prepass: the prepass's repeat of the camera's opaque and "
            "mask draws";
        j["depth_prepass"] = {{"draw_calls", last.prepass.draw_calls},
                              {"triangles", last.prepass.triangles}};
    }
    if (renderer.context().validation().enabled())
        j["validation_messages"] = renderer.context().validation().count();
    return j;
}

} // namespace sherpa::cli
