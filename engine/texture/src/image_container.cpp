#include <sherpa/texture/image_container.h>

#include <cstring>

#include <sherpa/texture/basis.h>

namespace sherpa::tex {
namespace {

std::uint32_t u32_at(std::span<const std::uint8_t> b, std::size_t at) {
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
           std::uint32_t(b[at + 3]) << 24;
}

} // namespace

ImageContainer image_container(std::span<const std::uint8_t> b) {
    const auto starts = [&](const char* magic, std::size_t at = 0) {
        const std::size_t n = std::strlen(magic);
        return b.size() >= at + n && std::memcmp(b.data() + at, magic, n) == 0;
    };
    if (is_ktx2(b)) {
        // KTX2 header: vkFormat at byte 12, supercompressionScheme at byte 44.
        if (b.size() < 48) return {"ktx2", "?"};
        const std::uint32_t vk_format = u32_at(b, 12), scheme = u32_at(b, 44);
        // The Basis names come from basis.h; zlib (scheme 3) is KTX2's but not Basis'.
        const std::string super =
            scheme <= 2   ? std::string(supercompression_name(BasisSupercompression(scheme)))
            : scheme == 3 ? "zlib"
                          : "?";
        const auto payload = [](BasisPayload p) { return std::string(basis_payload_name(p)); };
        if (scheme == 1) return {payload(BasisPayload::Etc1s), super};
        if (vk_format == 0 && (scheme == 0 || scheme == 2))
            return {payload(BasisPayload::Uastc), super};
        return {"ktx2", super};
    }
    if (starts("\x89PNG")) return {"png", {}};
    if (starts("\xFF\xD8\xFF")) return {"jpeg", {}};
    if (starts("RIFF") && starts("WEBP", 8)) return {"webp", {}};
    return {b.empty() ? "none" : "other", {}};
}

} // namespace sherpa::tex
