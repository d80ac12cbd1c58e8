#pragma once
// Internal: EXT_meshopt_compression / KHR_meshopt_compression, decoded with Debian's
// meshoptimizer before the importer reads any accessor. A compressed bufferView is
// replaced by a new buffer holding its decoded bytes, so every later stage reads it
// like any other view (KHR_mesh_quantization types included).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <sherpa/scene/scene.h>

namespace tinygltf {
class Model;
}

namespace sherpa::detail {

// What decoding one compressed bufferView did, for inspection.
struct DecodedView {
    std::int32_t view = -1;
    std::string codec; // EXT_meshopt_compression or KHR_meshopt_compression
    std::string mode;  // ATTRIBUTES / TRIANGLES / INDICES, then "/FILTER" if any
    std::uint64_t encoded_bytes = 0, decoded_bytes = 0;
    double decode_ms = 0.0;
};

// Decodes every meshopt-compressed bufferView of `model` in place (see above).
// Throws ImportError naming the view and the problem: truncated or corrupt streams,
// ranges outside their buffer, strides/counts the extension forbids, or a bitstream
// version Debian's meshoptimizer cannot decode.
std::vector<DecodedView> decode_meshopt_views(tinygltf::Model& model);

// Sets PrimitiveInfo::compression of each primitive reading a decoded view.
void attach_meshopt_compression(const tinygltf::Model& model, std::span<const DecodedView> views,
                                Scene& scene);

} // namespace sherpa::detail
