#pragma once
// Internal: EXT_meshopt_compression / KHR_meshopt_compression, decoded by our own
// decoders (meshopt_codec.h) before the importer reads any accessor. A compressed bufferView is
// replaced by a new buffer holding its decoded bytes, so every later stage reads it
// like any other view (KHR_mesh_quantization types included).
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <sherpa/scene/scene.h>

namespace tinygltf {
class Model;
}

namespace sherpa::scene::detail {

// What decoding one compressed bufferView did, for inspection.
struct DecodedView {
    std::int32_t view = -1;
    std::string codec; // EXT_meshopt_compression or KHR_meshopt_compression
    std::string mode;  // ATTRIBUTES / TRIANGLES / INDICES, then "/FILTER" if any
    std::uint64_t encoded_bytes = 0, decoded_bytes = 0;
    double decode_ms = 0.0;
    // Why the stream did not decode ("bufferViews[N].extensions.CODEC: ..."), empty when
    // it did; fell_back: the view's own uncompressed bytes are read instead.
    std::string failed;
    bool fell_back = false;
};

// Decodes every meshopt-compressed bufferView of `model` in place (see above).
// Throws ImportError naming the view and the problem where the extension object itself
// is wrong: ranges outside their buffer, strides/counts/modes/filters the extension
// forbids. A stream that does not decode (corrupt, truncated, an unknown header or
// bitstream version, shorter than its count needs) is no error for the file: its
// DecodedView says why, and the view keeps its uncompressed fallback bytes where
// `readable` (each buffer's bytes as read from the file; empty where not read) has them,
// else it is emptied so that nothing reads it.
std::vector<DecodedView>
decode_meshopt_views(tinygltf::Model& model,
                     std::span<const std::span<const std::uint8_t>> readable);

// The primitives that read a view whose stream failed without fallback bytes,
// (mesh, primitive) -> the view's reason: the importer skips them by name.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::string>
undecodable_primitives(const tinygltf::Model& model, std::span<const DecodedView> views);

// Sets PrimitiveInfo::compression of each primitive reading a decoded view.
void attach_meshopt_compression(const tinygltf::Model& model, std::span<const DecodedView> views,
                                Scene& scene);

} // namespace sherpa::scene::detail
