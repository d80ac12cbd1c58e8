#pragma once
// A/B comparison of two loaded glTF files (an asset and its optimized version):
// counts, geometry per matched primitive, materials, textures and byte sizes, and a
// rendered difference heat map from one camera. What `sherpa-cli compare` prints.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <sherpa/render/frame_request.h>
#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/scene.h>
#include <sherpa/texture/image.h>

namespace sherpa::lab {

struct CountDiff {
    std::string name; // "nodes", "meshes", "primitives", ...
    std::uint64_t a = 0, b = 0;
};

// Primitives are matched by glTF mesh and primitive index. Geometry is compared in
// world space (each mesh under the node of its first instance: tools such as
// gltfpack move dequantization into node transforms), vertex to nearest vertex in
// both directions (ties in position, as at uv seams, go to the closest normal and
// uv), so vertex order and welding do not count as differences.
struct PrimitiveDiff {
    std::uint32_t mesh = 0, primitive = 0;
    std::uint64_t vertices_a = 0, vertices_b = 0, indices_a = 0, indices_b = 0;
    double position_max = 0.0, position_rms = 0.0; // scene units
    double normal_max_deg = 0.0, normal_mean_deg = 0.0;
    // Only where both files give tangents (authored or generated at load).
    std::optional<double> tangent_max_deg, tangent_mean_deg;
    double uv_max = 0.0, uv_rms = 0.0; // TEXCOORD_0 through the base colour transform
    std::string note;                  // why it was not compared
};

struct MaterialDiff {
    std::uint32_t material = 0;
    std::vector<std::string> fields; // "roughness_factor: 0.5 -> 1"
};

// Images matched by index, both decoded as the texture pipeline decodes them.
struct TextureDiff {
    std::int32_t image = -1;
    std::string a, b; // locations
    std::uint32_t width_a = 0, height_a = 0, width_b = 0, height_b = 0;
    std::uint64_t bytes_a = 0, bytes_b = 0; // encoded
    std::optional<double> psnr;             // RGBA, dB (inf: identical pixels)
    std::string note;                       // why no PSNR
};

struct FileComparison {
    std::vector<CountDiff> counts;
    std::vector<PrimitiveDiff> primitives;
    std::vector<MaterialDiff> materials; // only materials with differing fields
    std::vector<TextureDiff> textures;
    std::uint64_t file_bytes_a = 0, file_bytes_b = 0; // the .gltf/.glb file itself
    // The file and every external file it names (buffers, images): what ships.
    std::uint64_t total_bytes_a = 0, total_bytes_b = 0;
    std::uint64_t image_bytes_a = 0, image_bytes_b = 0; // encoded images, all
    std::vector<std::string> notes;
};

// Both scenes loaded with lab_load_options() (tangents as in the files).
FileComparison compare_files(const scene::Scene& a, const scene::Scene& b);

// Both scenes rendered (lit, no shadows) from `camera` and differenced per pixel:
// the largest RGB channel difference d (0..255) as a heat map (black, blue, red,
// yellow, white from 0 to `scale`, the 99.9th percentile of the differing pixels' d).
// The picture, top to bottom: the heat of every pixel that differs drawn over a
// dimmed grey render of side A (where the difference is, on the model); sides A and
// B at half size, labelled (both sides of a material or texture difference); the
// legend strip with its numbers drawn in (0, half and the scale, mean, max, PSNR, the
// share of pixels over the threshold); then `captions` (one line each).
struct DifferenceImage {
    tex::RgbaImage image;
    std::uint32_t legend_top = 0; // first row of the legend strip
    double mean = 0.0, max = 0.0; // of d
    double scale = 0.0;           // d shown white
    double psnr = 0.0;            // RGB, dB
    double over_threshold_percent = 0.0;
    std::uint32_t threshold = 8;
    std::string error; // set when no image could be rendered
};
struct DifferenceOptions {
    std::uint32_t width = 640, height = 360; // of the difference panel
    std::optional<scene::CameraSpec> camera; // unset: scene a framed automatically
    std::uint32_t threshold = 8;
    bool validation = false;
    render::Lighting lighting;                // both sides lit alike (none by default)
    std::string label_a = "A", label_b = "B"; // drawn over the half-size sides
    std::vector<std::string> captions;        // drawn under the legend, clipped to the width
};
DifferenceImage render_difference(const scene::Scene& a, const scene::Scene& b,
                                  const DifferenceOptions& options);

} // namespace sherpa::lab
