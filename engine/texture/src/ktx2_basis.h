#pragma once
// The parts of a Basis Universal KTX2 file the payload decoders need, validated
// against the file: every span lies inside it.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <sherpa/texture/basis.h>

namespace sherpa::tex {

struct Ktx2BasisLevel {
    std::span<const std::uint8_t> bytes; // as stored (possibly supercompressed)
    std::uint64_t uncompressed_length = 0;
    std::uint32_t width = 0, height = 0;
};

struct Ktx2BasisFile {
    BasisPayload payload = BasisPayload::Uastc;
    BasisSupercompression scheme = BasisSupercompression::None;
    bool srgb = false, has_alpha = false;
    std::uint32_t width = 0, height = 0;
    std::vector<Ktx2BasisLevel> levels;
    std::span<const std::uint8_t> global_data; // supercompressionGlobalData
};

// Parses header, level index and DFD. False with `error` on the first problem.
bool parse_ktx2_basis(std::span<const std::uint8_t> in, Ktx2BasisFile& out, std::string& error);

// ETC1S/BasisLZ: decodes the first `level_count` levels of `file` (all by default;
// etc1s.cpp).
bool decode_etc1s_levels(const Ktx2BasisFile& file, std::vector<RgbaImage>& levels,
                         std::string& error, std::size_t level_count = SIZE_MAX);

} // namespace sherpa::tex
