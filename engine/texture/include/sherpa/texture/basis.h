#pragma once
// Basis Universal textures in KTX2 containers (KTX File Format Specification 2.0,
// KHR_texture_basisu): UASTC payloads, raw or Zstandard-supercompressed, and
// ETC1S/BasisLZ payloads, transcoded here to RGBA8 so that the texture pipeline
// takes them like any decoded image.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <sherpa/texture/image.h>

namespace sherpa::tex {

enum class BasisPayload { Etc1s, Uastc };
enum class BasisSupercompression { None = 0, BasisLZ = 1, Zstandard = 2 };

struct BasisTexture {
    BasisPayload payload = BasisPayload::Uastc;
    BasisSupercompression supercompression = BasisSupercompression::None;
    bool srgb = false;             // the DFD's transfer function is sRGB
    bool has_alpha = false;        // the DFD declares an alpha channel (UASTC RGBA/RRRG, ETC1S AAA)
    std::vector<RgbaImage> levels; // [0] is the full-size level
};

// True when `bytes` starts with the KTX2 identifier.
bool is_ktx2(std::span<const std::uint8_t> bytes);

// "ktx2-uastc", "ktx2-etc1s"; and "none", "basislz", "zstd".
std::string_view basis_payload_name(BasisPayload payload);
std::string_view supercompression_name(BasisSupercompression scheme);

// Transcodes every mip level of a 2D Basis Universal KTX2 file (vkFormat
// UNDEFINED, DFD color model UASTC or ETC1S) to RGBA8. Every offset and length
// is checked against the file before use; any inconsistency (bad level index,
// bad supercompression global data, corrupt Zstandard frame, truncated data,
// reserved UASTC block mode) returns false with `error` describing it, as does a
// size over the texel budget (texel_budget.h), checked before anything is inflated.
// `base_level_only`: transcode level 0 alone (`levels` then holds one image).
bool transcode_ktx2_basis(std::span<const std::uint8_t> ktx2, BasisTexture& out, std::string& error,
                          bool base_level_only = false);

// Checks a Basis Universal KTX2 file's header, data format descriptor, level index
// and global data ranges, and its size against the texel budget, without inflating
// or transcoding anything: what `info` reports. True when they hold.
bool probe_ktx2_basis(std::span<const std::uint8_t> ktx2, std::string& error);

// Same for a file; errors start with the file's path.
bool read_basis_ktx2_file(const std::filesystem::path& path, BasisTexture& out, std::string& error);

// The entry an importer calls for any image source: KTX2 bytes (detected by
// their identifier, not by `name_hint`) are transcoded and their level 0 returned
// (the texture pipeline builds its own mip chain); anything else goes to
// decode_encoded_image. Errors start with `name_hint` for KTX2 input.
bool decode_image_or_ktx2(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                          RgbaImage& out, std::string& error);

} // namespace sherpa::tex
