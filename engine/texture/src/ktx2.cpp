// KTX 2.0 writer and reader. Layout (spec section 3): identifier, header, index,
// level index, DFD, key/value data, then the mip levels, smallest first, each
// aligned to lcm(texel block size, 4).
#include <sherpa/texture/ktx2.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <sherpa/texture/block_codecs.h>

#include "ktx2_dfd.h"

namespace sherpa::tex {

namespace {
constexpr std::uint8_t kIdentifier[12] = {0xAB, 'K',  'T',  'X',  ' ',  '2',
                                          '0',  0xBB, '\r', '\n', 0x1A, '\n'};
constexpr std::size_t kHeaderEnd = 80;       // identifier + header + index
constexpr std::size_t kLevelIndexEntry = 24; // byteOffset, byteLength, uncompressedByteLength

void put32(std::vector<std::uint8_t>& out, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void put64(std::vector<std::uint8_t>& out, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) out[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}
std::uint32_t get32(std::span<const std::uint8_t> in, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t{in[at + i]} << (8 * i);
    return v;
}
std::uint64_t get64(std::span<const std::uint8_t> in, std::size_t at) {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t{in[at + i]} << (8 * i);
    return v;
}
std::size_t align_up(std::size_t v, std::size_t a) {
    return (v + a - 1) / a * a;
}

std::size_t level_alignment(VkFormat format) {
    return is_block_compressed(format) ? 16 : 4;
}

std::uint32_t max_levels(std::uint32_t w, std::uint32_t h) {
    std::uint32_t n = 1;
    for (std::uint32_t s = std::max(w, h); s > 1; s >>= 1) ++n;
    return n;
}

std::vector<std::uint8_t> key_value_data(std::vector<std::pair<std::string, std::string>> kv) {
    if (std::none_of(kv.begin(), kv.end(), [](const auto& e) { return e.first == kKeyKtxWriter; }))
        kv.emplace_back(kKeyKtxWriter, kKtxWriterName);
    // Sorted by key as raw bytes (the spec's "sorted by codepoint").
    std::sort(kv.begin(), kv.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::uint8_t> out;
    for (const auto& [key, value] : kv) {
        const std::uint32_t length = static_cast<std::uint32_t>(key.size() + 1 + value.size() + 1);
        const std::size_t at = out.size();
        out.resize(at + 4);
        put32(out, at, length);
        out.insert(out.end(), key.begin(), key.end());
        out.push_back(0);
        out.insert(out.end(), value.begin(), value.end());
        out.push_back(0);
        out.resize(align_up(out.size(), 4), 0); // valuePadding
    }
    return out;
}
} // namespace

std::string_view vk_format_name(VkFormat format) {
    switch (format) {
    case VkFormat::R8G8B8A8Unorm:
        return "VK_FORMAT_R8G8B8A8_UNORM";
    case VkFormat::R8G8B8A8Srgb:
        return "VK_FORMAT_R8G8B8A8_SRGB";
    case VkFormat::Bc5UnormBlock:
        return "VK_FORMAT_BC5_UNORM_BLOCK";
    case VkFormat::Bc7UnormBlock:
        return "VK_FORMAT_BC7_UNORM_BLOCK";
    case VkFormat::Bc7SrgbBlock:
        return "VK_FORMAT_BC7_SRGB_BLOCK";
    case VkFormat::Undefined:
        break;
    }
    return "VK_FORMAT_UNDEFINED";
}

bool is_block_compressed(VkFormat f) {
    return f == VkFormat::Bc5UnormBlock || f == VkFormat::Bc7UnormBlock ||
           f == VkFormat::Bc7SrgbBlock;
}
bool is_srgb(VkFormat f) {
    return f == VkFormat::Bc7SrgbBlock || f == VkFormat::R8G8B8A8Srgb;
}

std::size_t level_size(VkFormat format, std::uint32_t width, std::uint32_t height) {
    return is_block_compressed(format) ? compressed_size(width, height)
                                       : std::size_t{width} * height * 4;
}

const std::string* Ktx2Texture::find(std::string_view key) const {
    for (const auto& [k, v] : metadata)
        if (k == key) return &v;
    return nullptr;
}

std::vector<std::uint8_t> write_ktx2(const Ktx2Texture& t) {
    const std::vector<std::uint8_t> dfd = data_format_descriptor(t.format);
    if (dfd.empty()) throw std::invalid_argument("write_ktx2: unsupported format");
    if (t.width == 0 || t.height == 0 || t.levels.empty() ||
        t.levels.size() > max_levels(t.width, t.height))
        throw std::invalid_argument("write_ktx2: bad size or level count");
    for (std::size_t l = 0; l < t.levels.size(); ++l) {
        const auto lw = mip_extent(t.width, std::uint32_t(l)),
                   lh = mip_extent(t.height, std::uint32_t(l));
        if (t.levels[l].size() != level_size(t.format, lw, lh))
            throw std::invalid_argument("write_ktx2: level " + std::to_string(l) + " has " +
                                        std::to_string(t.levels[l].size()) + " bytes, expected " +
                                        std::to_string(level_size(t.format, lw, lh)));
    }
    const auto levels = static_cast<std::uint32_t>(t.levels.size());
    const std::vector<std::uint8_t> kvd = key_value_data(t.metadata);
    const std::size_t dfd_offset = kHeaderEnd + kLevelIndexEntry * levels;
    const std::size_t kvd_offset = dfd_offset + dfd.size();
    std::size_t cursor = kvd_offset + kvd.size();

    // Levels go smallest first; remember where each one lands.
    std::vector<std::size_t> offsets(levels);
    for (std::uint32_t l = levels; l-- > 0;) {
        cursor = align_up(cursor, level_alignment(t.format));
        offsets[l] = cursor;
        cursor += t.levels[l].size();
    }
    std::vector<std::uint8_t> out(cursor, 0);
    std::memcpy(out.data(), kIdentifier, sizeof kIdentifier);
    put32(out, 12, static_cast<std::uint32_t>(t.format));
    put32(out, 16, 1); // typeSize: 1 for block-compressed and 8-bit formats
    put32(out, 20, t.width);
    put32(out, 24, t.height);
    put32(out, 28, 0); // pixelDepth
    put32(out, 32, 0); // layerCount
    put32(out, 36, 1); // faceCount
    put32(out, 40, levels);
    put32(out, 44, 0); // supercompressionScheme: none
    put32(out, 48, static_cast<std::uint32_t>(dfd_offset));
    put32(out, 52, static_cast<std::uint32_t>(dfd.size()));
    put32(out, 56, static_cast<std::uint32_t>(kvd_offset));
    put32(out, 60, static_cast<std::uint32_t>(kvd.size()));
    put64(out, 64, 0); // sgdByteOffset
    put64(out, 72, 0); // sgdByteLength
    for (std::uint32_t l = 0; l < levels; ++l) {
        const std::size_t at = kHeaderEnd + kLevelIndexEntry * l;
        put64(out, at, offsets[l]);
        put64(out, at + 8, t.levels[l].size());
        put64(out, at + 16, t.levels[l].size());
        std::memcpy(out.data() + offsets[l], t.levels[l].data(), t.levels[l].size());
    }
    std::memcpy(out.data() + dfd_offset, dfd.data(), dfd.size());
    std::memcpy(out.data() + kvd_offset, kvd.data(), kvd.size());
    return out;
}

namespace {
bool parse_key_values(std::span<const std::uint8_t> kvd, Ktx2Texture& out, std::string& error) {
    std::size_t at = 0;
    while (at < kvd.size()) {
        if (at + 4 > kvd.size()) return error = "key/value data: truncated length", false;
        const std::uint32_t length = get32(kvd, at);
        if (length == 0 || at + 4 + length > kvd.size())
            return error = "key/value data: entry overruns", false;
        const auto entry = kvd.subspan(at + 4, length);
        const auto nul = std::find(entry.begin(), entry.end(), std::uint8_t{0});
        if (nul == entry.end()) return error = "key/value data: key without NUL", false;
        std::string key(entry.begin(), nul);
        std::string value(nul + 1, entry.end());
        if (!value.empty() && value.back() == '\0') value.pop_back();
        out.metadata.emplace_back(std::move(key), std::move(value));
        at = align_up(at + 4 + length, 4);
    }
    return true;
}
} // namespace

bool read_ktx2(std::span<const std::uint8_t> in, Ktx2Texture& out, std::string& error) {
    out = Ktx2Texture{};
    if (in.size() < kHeaderEnd)
        return error = "file too short for a KTX2 header (" + std::to_string(in.size()) + " bytes)",
               false;
    if (std::memcmp(in.data(), kIdentifier, sizeof kIdentifier) != 0)
        return error = "not a KTX2 file (bad identifier)", false;
    const auto format = static_cast<VkFormat>(get32(in, 12));
    const std::vector<std::uint8_t> expected_dfd = data_format_descriptor(format);
    if (expected_dfd.empty())
        return error = "unsupported vkFormat " + std::to_string(get32(in, 12)), false;
    const std::uint32_t width = get32(in, 20), height = get32(in, 24), levels = get32(in, 40);
    if (get32(in, 16) != 1) return error = "typeSize must be 1", false;
    if (width == 0 || height == 0) return error = "zero width or height", false;
    if (get32(in, 28) != 0 || get32(in, 32) != 0 || get32(in, 36) != 1)
        return error = "only 2D textures without layers or faces are supported", false;
    if (levels == 0 || levels > max_levels(width, height))
        return error = "bad levelCount " + std::to_string(levels), false;
    if (get32(in, 44) != 0) return error = "supercompression is not supported", false;
    const std::size_t dfd_offset = get32(in, 48), dfd_length = get32(in, 52);
    const std::size_t kvd_offset = get32(in, 56), kvd_length = get32(in, 60);
    if (get64(in, 64) != 0 || get64(in, 72) != 0)
        return error = "unexpected supercompression global data", false;
    if (kHeaderEnd + kLevelIndexEntry * levels > in.size())
        return error = "level index overruns the file", false;
    if (dfd_offset + dfd_length > in.size() || dfd_length != expected_dfd.size() ||
        !std::equal(expected_dfd.begin(), expected_dfd.end(),
                    in.begin() + std::ptrdiff_t(dfd_offset)))
        return error = "data format descriptor does not describe " +
                       std::string(vk_format_name(format)),
               false;
    if (kvd_offset + kvd_length > in.size())
        return error = "key/value data overruns the file", false;
    if (!parse_key_values(in.subspan(kvd_offset, kvd_length), out, error)) return false;
    out.format = format, out.width = width, out.height = height;
    for (std::uint32_t l = 0; l < levels; ++l) {
        const std::size_t at = kHeaderEnd + kLevelIndexEntry * l;
        const std::uint64_t offset = get64(in, at), length = get64(in, at + 8);
        const std::size_t expected =
            level_size(format, mip_extent(width, l), mip_extent(height, l));
        if (length != expected || get64(in, at + 16) != length)
            return error = "level " + std::to_string(l) + " has " + std::to_string(length) +
                           " bytes, expected " + std::to_string(expected),
                   false;
        if (offset % level_alignment(format) != 0)
            return error = "level " + std::to_string(l) + " is misaligned", false;
        if (offset > in.size() || length > in.size() - offset)
            return error = "level " + std::to_string(l) + " overruns the file (truncated?)", false;
        out.levels.emplace_back(in.begin() + std::ptrdiff_t(offset),
                                in.begin() + std::ptrdiff_t(offset + length));
    }
    return true;
}

} // namespace sherpa::tex
