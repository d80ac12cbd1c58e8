#pragma once
// What container an encoded image is, from its leading bytes (not its name or MIME
// type): what info --json, the texture dock and error messages call it.
#include <cstdint>
#include <span>
#include <string>

namespace sherpa::tex {

struct ImageContainer {
    // png, jpeg, webp, ktx2-etc1s, ktx2-uastc, ktx2 (another KTX2 payload), other,
    // none (no bytes).
    std::string name;
    // KTX2 only: none, basislz, zstd, zlib; empty for other containers.
    std::string supercompression;
};

// Reads the signature and, for KTX2, the header's vkFormat and
// supercompressionScheme (BasisLZ carries ETC1S; vkFormat UNDEFINED without it is
// UASTC): nothing is decoded.
ImageContainer image_container(std::span<const std::uint8_t> bytes);

} // namespace sherpa::tex
