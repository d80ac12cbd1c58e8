#pragma once
// The source images exactly as the engine decodes them (level 0, RGBA8,
// unassociated alpha), written as PNGs so users and tests can see what was read:
// `sherpa-cli textures SCENE --export-source DIR`.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <sherpa/scene/scene.h>
#include <sherpa/texture/image.h>

namespace sherpa::tex {

// A file name whose extension picks the decoder for the image's bytes ("image.png"
// from the MIME type, else the URI's file name); decoders name the image by it.
std::string image_decoder_hint(const scene::ImageRecord& image);

// Decodes one glTF image the way the texture pipeline does: KTX2 (Basis Universal)
// by its identifier, level 0; PNG/JPEG/WebP through OpenImageIO with unassociated
// alpha; generated images as stored. False with `error` set on failure.
bool decode_image_source(const scene::ImageRecord& image, RgbaImage& out, std::string& error);

// One PNG file name per image of `scene`, in image order, unique within the list
// (compared case-insensitively, so the names also work on case-folding file
// systems). External files keep their stem (`WaterBottle_baseColor.ktx2` ->
// `WaterBottle_baseColor.png`); embedded images (bufferView, data URI) are named
// after the image's `name` when it has one, else `imageN_bufferViewV` /
// `imageN_datauri`; generated ones `imageN_generated`. Characters a file name
// cannot hold become '_', bidirectional-text controls (U+202E ...) are dropped, and
// a name over 160 bytes keeps its first 120 and gets a hash of the whole name
// (`<start>_<16 hex digits>`), so no name exceeds NAME_MAX. A later image whose
// name is taken gets `_imageN`.
std::vector<std::string> source_export_names(const scene::Scene& scene);

struct SourceExport {
    std::int32_t image = -1;
    std::filesystem::path file; // where the PNG went (or would have gone)
    std::uint32_t width = 0, height = 0;
    std::string error; // empty: written
};

// Decodes and writes every image of `scene` into `dir` (created if needed) under
// source_export_names(). An image that cannot be decoded or written keeps its
// error (naming the image's location) and the others are still written.
std::vector<SourceExport> export_sources(const scene::Scene& scene,
                                         const std::filesystem::path& dir);

} // namespace sherpa::tex
