#pragma once
// Internal: the few edits a compressed glTF needs before tinygltf can parse it.
// - EXT/KHR_meshopt_compression fallback buffers have no data (no uri), which
//   tinygltf refuses in a .gltf and, in a .glb, fills from the BIN chunk (failing
//   when that is shorter): each gets a 1-byte data URI (never read: every view on it
//   is replaced by its decoded stream).
// - A KHR_draco_mesh_compression primitive's index accessor has no bufferView (its
//   data is in the Draco stream), which tinygltf refuses ("accessor[N] invalid
//   bufferView"): the primitive's `indices` moves into the extension object as
//   kDracoIndicesKey, and decode_draco_primitives puts it back.
#include <cstdint>
#include <span>
#include <vector>

namespace sherpa::scene::detail {

inline constexpr const char* kDracoIndicesKey = "sherpa_indices";

// The file's bytes with the edits above, or an empty vector when none is needed.
// `bytes` passed validate_gltf_bytes.
std::vector<std::uint8_t> prepared_for_tinygltf(std::span<const std::uint8_t> bytes);

} // namespace sherpa::scene::detail
