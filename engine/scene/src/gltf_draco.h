#pragma once
// Internal: KHR_draco_mesh_compression, decoded with Debian's Draco library before the
// importer reads any accessor. Each compressed primitive's attributes (mapped by the
// extension's unique ids) and indices are decoded, dequantized by Draco, checked
// against the uncompressed accessors' declared count, type and min/max, and written
// to a new buffer the accessors are pointed at, in the component type each accessor
// declares (draco_attributes.h); indices as UNSIGNED_INT.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <sherpa/scene/scene.h>

namespace tinygltf {
class Model;
}

namespace sherpa::scene::detail {

struct DecodedDracoPrimitive {
    std::uint32_t mesh = 0, primitive = 0;
    PrimitiveCompression stats;
    // Accessors whose min/max decode_draco_primitives checked with Draco's
    // quantization slack (the importer's exact check would flag its rounding).
    std::vector<int> range_checked;
    // What the file contradicts but can still be drawn (a mode other than TRIANGLES,
    // missing indices over out-of-order faces): warnings naming the JSON path.
    std::vector<std::string> warnings;
    // Why the primitive could not be decoded (it is skipped), or empty.
    std::string failed;
};

// Decodes every Draco-compressed primitive of `model` in place. A primitive that
// cannot be decoded has `failed` set, naming the primitive's extension path and the
// problem: a stream that does not decode (truncated, corrupt) or declares more than
// its accessors or the documented limits allow, an attribute id the stream lacks, or
// an accessor whose count, type or min/max disagrees with what Draco produced. The
// importer skips it and loads the rest.
std::vector<DecodedDracoPrimitive> decode_draco_primitives(tinygltf::Model& model);

// Sets PrimitiveInfo::compression of each decoded primitive.
void attach_draco_compression(std::span<const DecodedDracoPrimitive> decoded, Scene& scene);

} // namespace sherpa::scene::detail
