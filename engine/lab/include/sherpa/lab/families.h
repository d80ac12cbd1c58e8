#pragma once
// The Lab's families with their options (make_family() gives the defaults).
#include <cstdint>
#include <memory>
#include <vector>

#include <sherpa/core/aabb.h>
#include <sherpa/lab/family.h>
#include <sherpa/render/frame_request.h>
#include <sherpa/scene/camera_spec.h>

namespace sherpa::lab {

// Tangents: exact MikkTSpace, welded MikkTSpace, Lengyel on every triangle mesh, from
// the uv set its normal texture samples (uv0 without one). Reference: exact
// MikkTSpace (corners where it falls back are left out); where the file has authored
// tangents, errors against them too (`authored_*`). Errors: angle mean/p99/max in
// degrees, handedness flips, corners differing from the reference (angle above
// kDifferingDegrees or flipped). Failures: fallback corners per primitive and cause,
// primitives without the uv set. Time: CPU ms per million triangles, best of `repeat`.
struct TangentFamilyOptions {
    int repeat = 1;
};
inline constexpr double kDifferingDegrees = 1e-3;
std::unique_ptr<Family> make_tangent_family(const TangentFamilyOptions& options = {});

// Texture compression: BC7 levels on the colour and data textures, BC5 levels on the
// normal maps the displayed scene's materials use. Errors: PSNR over the channels the
// role reads (mean over textures, and pooled), for BC5 the mean normal angle against
// the source's RGB normal. Time: CPU ms per megapixel (one thread). Images larger
// than `sample_texels` are measured on a mosaic of 64x64 tiles spread evenly over
// the image (`sample_texels` texels; 0: whole images), noted in the report.
// Failures: images missing or undecodable.
struct TextureFamilyOptions {
    std::uint64_t sample_texels = 512 * 512;
    int threads = 1;
};
std::unique_ptr<Family> make_texture_family(const TextureFamilyOptions& options = {});

// Culling: sphere, p-vertex and exact on the CPU (best SIMD level), and the GPU
// shader (p-vertex) where a Vulkan device is available, over a camera path.
// Reference: the exact test. Errors: false positives (kept, though exact culls them)
// summed over the path, as a fraction of the objects tested; false negatives (must be
// 0; each is a Failure). Time: ns per object tested (GPU: timestamped dispatch).
struct CullFamilyOptions {
    std::vector<scene::CameraSpec> path; // empty: camera_path(scene.bounds, path_length)
    std::uint32_t path_length = 32;
    bool gpu = true;
    bool gpu_validation = false; // Khronos validation on the GPU method's device (tests)
    int repeat = 3;              // CPU timings: best of
};
std::unique_ptr<Family> make_cull_family(const CullFamilyOptions& options = {});

// Mesh compression: KHR_mesh_quantization presets as gltfpack writes them (positions
// as integers over each primitive's bounds, the dequantization in the node transform;
// normals and tangents signed normalized per component; uvs normalized over their
// range; bits vp/vn/vt from 8/8/8 to 16/16/16, gltfpack's default 14/8/12 among them)
// and the 32-bit float reference, each alone (group KHR_mesh_quantization) and through
// meshoptimizer's vertex and index codecs (group "meshopt codec"), where 14/8/12 and
// 16/16/16 also come with octahedral normals and tangents through meshopt's OCTAHEDRAL
// filter ("quantized+meshopt-oct": what gltfpack -cc writes).
// Errors against the float geometry: position RMS (the chart error) and max in world
// units, the grid step, normal and tangent angle mean/max (degrees), uv RMS/max (uv
// units, and in texels of the base colour texture where its size is readable); bytes
// of the vertex streams (4-byte aligned elements) and indices, the chart's x. Time: CPU ms per
// million vertices to encode and decode, best of `repeat`. Failures: primitives without finite
// positions, normals or tangents quantized to zero, tangent frames whose bitangent flips, codec
// round trips.
struct MeshCompressionFamilyOptions {
    int repeat = 3;
};
std::unique_ptr<Family>
make_mesh_compression_family(const MeshCompressionFamilyOptions& options = {});
// Shadows: cascaded shadow map settings (map resolution x PCF taps x cascade count)
// against ray-traced hard shadows (one shadow ray per pixel, the reference). Per
// camera (`cameras` orbiting the scene, alternately at the framing distance and close
// up at 40% of it) the renderer's
// shadow-error view classifies each pixel (render::count_shadow_error). Errors: % of the
// pixels the rays find lit that the maps get wrong either way (the chart error), split
// into false shadow and false light, summed over the cameras. Time: GPU ms of the
// rasterized lit frame with its shadow pass (cascades redrawn every frame), median of
// `frames` frames, mean over the cameras. Needs a device that ray traces: without,
// every method has ran false and says why. Failures: cameras with no lit pixel,
// validation messages, frames the renderer refused.
struct ShadowFamilyOptions {
    std::vector<std::uint32_t> resolutions{1024, 2048, 4096};
    std::vector<std::uint32_t> pcf_taps{1, 4, 16};
    std::vector<std::uint32_t> cascades{1, 2, 3};
    std::uint32_t cameras = 4;
    std::uint32_t width = 160, height = 120;
    std::uint32_t frames = 3;
    std::uint32_t supersample = 4; // the compared raster image's samples per pixel side
    bool ray_tracing = true;       // false: as on a device without it (tests)
    bool validation = false;       // Khronos validation on the family's device (tests)
    // The lit frames' environment and display settings (the main view's): none by default.
    render::Lighting lighting;
};
std::unique_ptr<Family> make_shadow_family(const ShadowFamilyOptions& options = {});

// Lighting: the raster's lighting approximations, each against the converged path-traced
// image of the scene (same framed camera, environment, sun, tone mapping), at a small
// size so that the reference is affordable on a CPU device. Groups (one approximation
// varied at a time from the main view's settings): irradiance cube vs 9 SH coefficients;
// specular prefilter face size x GGX samples (and the default); energy compensation on
// vs off; shadow maps (off, and resolution x cascades x PCF taps); transmission on vs
// off (off: KHR_materials_transmission dropped, what a viewer without it shows); and the
// path tracer itself at `convergence_spp` samples (another seed) against the reference.
// Errors: mean |difference| in 8-bit display steps over the image (the chart error) and
// per material (`material_<i>_mean_diff`, from a material-id image of primary rays),
// PSNR. The raster image compared is drawn at `supersample` times the size and
// box-filtered down in linear values, as the path tracer filters its jittered samples
// (else texture minification and edges, not lighting, dominate the difference). Time:
// GPU ms of the raster frame at the lab's size (cascades redrawn), median of `frames`;
// for the path tracer, of its accumulation. A group the scene cannot show (no environment, no
// transmissive material, no shadow-casting sun) is not run, with the cause in its note;
// so is everything on a device that does not ray trace. Failures: validation messages,
// frames the renderer refused.
struct LightingShadowSetting {
    std::uint32_t resolution = 2048, cascades = 3, taps = 4;
};
struct LightingFamilyOptions {
    std::uint32_t width = 160, height = 120;
    std::uint32_t reference_spp = 256; // the path tracer's converged image
    std::uint32_t max_bounces = 8;
    // The path tracer's own convergence; empty: 1, 4, 16, ... up to reference_spp / 4.
    std::vector<std::uint32_t> convergence_spp;
    std::vector<std::uint32_t> specular_sizes{32, 64, 128, 256};
    std::vector<std::uint32_t> specular_samples{4, 16, 64};
    std::vector<LightingShadowSetting> shadows{{1024, 1, 1}, {2048, 3, 4}, {4096, 3, 16}};
    std::uint32_t frames = 3;
    std::uint32_t supersample = 4; // the compared raster image's samples per pixel side
    bool ray_tracing = true;       // false: as on a device without it (tests)
    bool validation = false;       // Khronos validation on the family's device (tests)
    // The environment and display settings (the main view's): none by default.
    render::Lighting lighting;
};
std::unique_ptr<Family> make_lighting_family(const LightingFamilyOptions& options = {});
// The convergence checkpoints of `options` (convergence_spp, or the default series).
std::vector<std::uint32_t> lighting_convergence_spp(const LightingFamilyOptions& options);

// Whether family `name` draws lit frames (and so takes a render::Lighting): "shadows",
// "lighting".
bool family_draws_lit_frames(std::string_view name);
// make_family() with the lit frames lit by `lighting` (the main view's).
std::unique_ptr<Family> make_family(std::string_view name, const render::Lighting& lighting);
// A method's name and its settings, both ways: "2048x3 pcf4" is 2048 texels, 3
// cascades, 4 PCF taps. Parsing fails (false) on anything else.
std::string shadow_method_name(std::uint32_t resolution, std::uint32_t cascades,
                               std::uint32_t taps);
bool parse_shadow_method(std::string_view name, std::uint32_t& resolution, std::uint32_t& cascades,
                         std::uint32_t& taps);

// The culling family's default path around `bounds`: half the cameras orbit outside
// at the framing distance looking at the centre (everything in view), half stand
// inside at half the radius looking outward (about half culled); 60 degrees, 16:9.
std::vector<scene::CameraSpec> camera_path(const core::Aabb& bounds, std::uint32_t count);

} // namespace sherpa::lab
