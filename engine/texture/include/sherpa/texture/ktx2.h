#pragma once
// KTX 2.0 container (Khronos KTX File Format Specification 2.0), written and read
// here for the formats Sherpa stores: BC7 (sRGB / linear), BC5 and RGBA8
// (the fallback for devices without BC sampling). No supercompression; 2D
// textures with a mip chain, no layers, faces or depth.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sherpa::tex {

// VkFormat values (Vulkan's enum numbers, so no Vulkan headers are needed here).
enum class VkFormat : std::uint32_t {
    Undefined = 0,
    R8G8B8A8Unorm = 37,
    R8G8B8A8Srgb = 43,
    Bc5UnormBlock = 141,
    Bc7UnormBlock = 145,
    Bc7SrgbBlock = 146,
};
// "VK_FORMAT_BC7_SRGB_BLOCK", ...; "VK_FORMAT_UNDEFINED" for anything else.
std::string_view vk_format_name(VkFormat format);
bool is_block_compressed(VkFormat format);
bool is_srgb(VkFormat format);
// Bytes of one mip level of the given size.
std::size_t level_size(VkFormat format, std::uint32_t width, std::uint32_t height);
// Size of mip level `level` of a texture whose level 0 is `base` (never below 1).
inline std::uint32_t mip_extent(std::uint32_t base, std::uint32_t level) {
    const std::uint32_t v = base >> level;
    return v ? v : 1;
}

// The KTXwriter entry write_ktx2 adds when the metadata has none.
inline constexpr std::string_view kKeyKtxWriter = "KTXwriter";
inline constexpr std::string_view kKtxWriterName = "Sherpa texture pipeline";

struct Ktx2Texture {
    VkFormat format = VkFormat::Undefined;
    std::uint32_t width = 0, height = 0;
    std::vector<std::vector<std::uint8_t>> levels; // [0] is the full-size level
    // Key/value metadata. Values are text (or bytes: the NUL the writer adds after each
    // is the one the reader takes off); they are stored NUL-terminated. The
    // writer adds KTXwriter when absent and sorts keys as the spec requires.
    std::vector<std::pair<std::string, std::string>> metadata;

    // Value of `key`, or nullptr.
    const std::string* find(std::string_view key) const;
};

// Serialises a texture. Throws std::invalid_argument when the format is not one
// of the above, a level has the wrong size, or there are more levels than the
// mip chain of width x height has.
std::vector<std::uint8_t> write_ktx2(const Ktx2Texture& texture);

// Parses and validates a file: identifier, header fields, level index (bounds,
// sizes, alignment), the Data Format Descriptor against the one the format
// requires, and the key/value data. Returns false with `error` on the first problem.
bool read_ktx2(std::span<const std::uint8_t> bytes, Ktx2Texture& out, std::string& error);

} // namespace sherpa::tex
