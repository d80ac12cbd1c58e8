#pragma once
// Internal: edits that let tinygltf read what glTF allows but tinygltf refuses, made
// on the JSON the importer parsed once (validate_gltf_document). Each edit is named in
// a SHERPA_ message, so nothing is changed silently:
// - integers written as floats ("count": 3.0) become integers;
// - a buffer tinygltf cannot fill (no uri in a .gltf or beyond a GLB's BIN chunk, a
//   URI with a scheme such as https:, a data URI of another media type or whose length
//   is not byteLength) becomes an empty placeholder: whatever reads it is skipped,
//   the rest of the file loads.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <sherpa/scene/validation.h>

#include <nlohmann/json.hpp>

namespace sherpa::scene::detail {

// Integral floats in integer-valued glTF properties become integers; true when any did.
bool normalize_integers(nlohmann::json& root);

// Replaces buffers tinygltf cannot fill with 1-byte placeholders (see above); adds a
// message per buffer to `report`; true when any was replaced.
bool replace_unreadable_buffers(nlohmann::json& root, bool glb, bool glb_has_bin,
                                ValidationReport& report);

// EXT_mesh_gpu_instancing attribute ids that are not accessor indices tinygltf can hold
// (2^32 reads as 0 through its int, 1.5 as 1): each is removed with a
// SHERPA_VALUE_IGNORED warning at its pointer, so the importer draws the node once (the
// extension's fallback) instead of reading another accessor. True when any was removed.
bool drop_unreadable_instancing_ids(nlohmann::json& root, ValidationReport& report);

// tinygltf drops an animation channel whose target has no "node" (glTF allows it:
// KHR_animation_pointer and other extensions define the target), which would also shift
// the indices of the channels after it. A copy of `root` where such targets carry
// "node": -1 (which tinygltf reads, and the importer treats as no node), or nothing
// when the file has none. Not a change of meaning, so no message.
std::optional<nlohmann::json> with_channel_nodes(const nlohmann::json& root);

// The file's bytes with `root` as its JSON (a .glb keeps its BIN chunk).
std::vector<std::uint8_t> with_json(const nlohmann::json& root, std::span<const std::uint8_t> file,
                                    bool glb);

} // namespace sherpa::scene::detail
