#pragma once
// Where a glTF image's bytes come from, whether they are there at all, and which
// material slots read it: what a user needs to find a missing or broken texture.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <sherpa/scene/scene.h>

namespace sherpa::scene {

// The file an external image URI names (percent escapes decoded, relative to the
// scene file's directory); empty for data URIs, bufferViews and generated images.
std::filesystem::path image_file_path(const Scene& scene, const ImageRecord& image);

// True when the image has no bytes to decode: its file could not be read (tinygltf
// keeps the URI and leaves the bytes empty) or its bufferView was empty.
bool image_is_missing(const ImageRecord& image);

// Why a missing image's file gave no bytes, in words, as the filesystem says now: "not
// found", "is a directory, not a file", "is empty", ...; empty when the image is not
// missing or has no file (a bufferView or data URI).
std::string image_missing_reason(const Scene& scene, const ImageRecord& image);

// "material 'NAME' baseColorTexture, emissiveTexture" for every material that reads
// image `image` (through any texture), in material order. Materials without a name
// are named by index: "material 3".
std::vector<std::string> image_slot_uses(const Scene& scene, std::int32_t image);

// Where the image's bytes come from, for messages: the file path, else "bufferView N"
// or "data URI", else "image N".
std::string image_location(const Scene& scene, std::int32_t image);

} // namespace sherpa::scene
