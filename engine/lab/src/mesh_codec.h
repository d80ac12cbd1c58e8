#pragma once
// One primitive's vertex streams through a quantization preset (quantize.h) and,
// optionally, meshoptimizer's vertex and index codecs: the decoded streams, the bytes
// they take and what went wrong. The mesh-compression family measures this.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sherpa::lab::detail {

// Bits per attribute; 0 keeps 32-bit floats. Tangents use the normal bits. `meshopt`:
// the streams through meshoptimizer's codecs; `octahedral` (with meshopt only, as
// EXT_meshopt_compression's OCTAHEDRAL filter carries it): normals and tangents
// through meshopt_encodeFilterOct instead of per-component snorm.
struct QuantizationPreset {
    int position = 0, normal = 0, uv = 0;
    bool meshopt = false, octahedral = false;
};

// A primitive's attributes (empty where the file has none) and its index list.
struct MeshStreams {
    std::vector<glm::vec3> position, normal;
    std::vector<glm::vec4> tangent;
    std::vector<glm::vec2> uv0, uv1;
    std::vector<std::uint32_t> indices;
    bool triangles = true;
};

struct EncodedMesh {
    MeshStreams decoded; // indices not copied
    std::uint64_t vertex_bytes = 0, index_bytes = 0;
    double position_step = 0.0;         // the grid's step (0 for floats or one point)
    std::uint64_t zero_normals = 0;     // normals or tangents quantized to the zero vector
    std::uint64_t nonfinite_values = 0; // coded as 0
    std::string codec_error;            // meshopt: an encoder or round trip failure
};

// Quantizes and dequantizes every stream of `in`; with `preset.meshopt`, encodes each packed
// stream (as KHR_mesh_quantization lays it out, one buffer per attribute as gltfpack
// writes them) with meshopt_encodeVertexBuffer and the indices with
// meshopt_encodeIndexBuffer (triangles) or meshopt_encodeIndexSequence, decodes them
// and checks the round trip. Bytes: stride x vertices per stream (quantize.h's
// stream_stride), indices as 16-bit below 65536 vertices else 32-bit, each buffer
// padded to 4 bytes; with meshopt the encoded sizes. `in.position` must hold a finite
// value (position_grid succeeds).
EncodedMesh encode_mesh(const MeshStreams& in, const QuantizationPreset& preset);

} // namespace sherpa::lab::detail
