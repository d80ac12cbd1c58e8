// Basis Universal KTX2 files: container validation (KTX 2.0 spec sections 3-4,
// Data Format Descriptor of the UASTC and ETC1S color models) and UASTC levels.
// All arithmetic on file offsets is 64-bit and checked as `offset <= size &&
// length <= size - offset`, so no sum can wrap.
#include "ktx2_basis.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

#include <zstd.h>

#include <sherpa/texture/texel_budget.h>

#include "uastc.h"

namespace sherpa::tex {

namespace {
constexpr std::uint8_t kIdentifier[12] = {0xAB, 'K',  'T',  'X',  ' ',  '2',
                                          '0',  0xBB, '\r', '\n', 0x1A, '\n'};
constexpr std::size_t kHeaderEnd = 80, kLevelEntry = 24;
constexpr std::uint8_t kModelEtc1s = 163, kModelUastc = 166;
constexpr std::uint8_t kTransferSrgb = 2;

std::uint64_t le(std::span<const std::uint8_t> in, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= std::uint64_t{in[at + i]} << (8 * i);
    return v;
}
bool inside(std::uint64_t offset, std::uint64_t length, std::size_t size) {
    return offset <= size && length <= size - offset;
}
std::string str(std::uint64_t v) {
    return std::to_string(v);
}

// Reads the basic DFD block: color model, transfer function and whether a
// sample carries alpha (UASTC RGBA=3 / RRRG=5, ETC1S AAA=15).
bool parse_dfd(std::span<const std::uint8_t> dfd, Ktx2BasisFile& out, std::string& error) {
    if (dfd.size() < 28 || le(dfd, 0, 4) != dfd.size())
        return error = "data format descriptor: bad dfdTotalSize", false;
    const std::uint64_t block_size = le(dfd, 10, 2);
    if (block_size < 24 || (block_size - 24) % 16 != 0 || block_size > dfd.size() - 4)
        return error = "data format descriptor: bad descriptorBlockSize " + str(block_size), false;
    if (le(dfd, 4, 4) != 0)
        return error = "data format descriptor: not a Khronos basic block", false;
    const std::uint8_t model = dfd[12];
    if (model == kModelUastc)
        out.payload = BasisPayload::Uastc;
    else if (model == kModelEtc1s)
        out.payload = BasisPayload::Etc1s;
    else
        return error = "data format descriptor: color model " + str(model) +
                       " is neither UASTC (166) nor ETC1S (163)",
               false;
    out.srgb = dfd[14] == kTransferSrgb;
    const std::size_t samples = (block_size - 24) / 16;
    if (samples == 0) return error = "data format descriptor: no samples", false;
    for (std::size_t s = 0; s < samples; ++s) {
        const unsigned channel = dfd[28 + 16 * s + 3] & 0x0F;
        if (out.payload == BasisPayload::Uastc ? (channel == 3 || channel == 5) : channel == 15)
            out.has_alpha = true;
    }
    if (out.payload == BasisPayload::Etc1s && samples > 2)
        return error = "data format descriptor: ETC1S with " + str(samples) + " samples", false;
    return true;
}
} // namespace

bool is_ktx2(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= sizeof kIdentifier &&
           std::memcmp(bytes.data(), kIdentifier, sizeof kIdentifier) == 0;
}

std::string_view basis_payload_name(BasisPayload p) {
    return p == BasisPayload::Uastc ? "ktx2-uastc" : "ktx2-etc1s";
}
std::string_view supercompression_name(BasisSupercompression s) {
    switch (s) {
    case BasisSupercompression::BasisLZ:
        return "basislz";
    case BasisSupercompression::Zstandard:
        return "zstd";
    case BasisSupercompression::None:
        break;
    }
    return "none";
}

bool parse_ktx2_basis(std::span<const std::uint8_t> in, Ktx2BasisFile& out, std::string& error) {
    out = Ktx2BasisFile{};
    if (in.size() < kHeaderEnd)
        return error = "file too short for a KTX2 header (" + str(in.size()) + " bytes)", false;
    if (!is_ktx2(in)) return error = "not a KTX2 file (bad identifier)", false;
    if (le(in, 12, 4) != 0)
        return error = "vkFormat " + str(le(in, 12, 4)) +
                       " is not VK_FORMAT_UNDEFINED, so this is not a Basis Universal texture",
               false;
    if (le(in, 16, 4) != 1) return error = "typeSize must be 1", false;
    const std::uint64_t width = le(in, 20, 4), height = le(in, 24, 4);
    if (width == 0 || height == 0) return error = "zero width or height (1D textures)", false;
    // Bounds the RGBA8 output and, through uncompressedByteLength (which must equal
    // the level's block count x 16), every Zstandard level's inflated size: a small
    // supercompressed file asks for no more than the texel budget.
    if (!check_texel_budget(width, height, {}, error)) return false;
    if (le(in, 28, 4) != 0 || le(in, 32, 4) > 1 || le(in, 36, 4) != 1)
        return error = "only 2D textures without layers or faces are supported", false;
    std::uint64_t levels = le(in, 40, 4);
    std::uint64_t max_levels = 1;
    for (std::uint64_t s = std::max(width, height); s > 1; s >>= 1) ++max_levels;
    if (levels == 0) levels = 1; // "generate mipmaps": only the base level is stored
    if (levels > max_levels) return error = "bad levelCount " + str(levels), false;
    const std::uint64_t scheme = le(in, 44, 4);
    if (scheme > 2) return error = "unknown supercompressionScheme " + str(scheme), false;
    out.scheme = static_cast<BasisSupercompression>(scheme);
    const std::uint64_t dfd_offset = le(in, 48, 4), dfd_length = le(in, 52, 4);
    const std::uint64_t sgd_offset = le(in, 64, 8), sgd_length = le(in, 72, 8);
    if (!inside(dfd_offset, dfd_length, in.size()))
        return error = "data format descriptor overruns the file", false;
    if (!inside(sgd_offset, sgd_length, in.size()))
        return error = "supercompression global data overruns the file (offset " + str(sgd_offset) +
                       ", length " + str(sgd_length) + ")",
               false;
    if (kHeaderEnd + kLevelEntry * levels > in.size())
        return error = "level index overruns the file", false;
    if (!parse_dfd(in.subspan(dfd_offset, dfd_length), out, error)) return false;
    const bool uastc = out.payload == BasisPayload::Uastc;
    if (uastc && out.scheme == BasisSupercompression::BasisLZ)
        return error = "UASTC payload with BasisLZ supercompression", false;
    if (!uastc && out.scheme != BasisSupercompression::BasisLZ)
        return error = "ETC1S payload without BasisLZ supercompression", false;
    if (out.scheme != BasisSupercompression::BasisLZ && sgd_length != 0)
        return error = "unexpected supercompression global data", false;
    out.global_data = in.subspan(sgd_offset, sgd_length);
    out.width = static_cast<std::uint32_t>(width), out.height = static_cast<std::uint32_t>(height);
    for (std::uint64_t l = 0; l < levels; ++l) {
        const std::size_t at = kHeaderEnd + kLevelEntry * l;
        const std::uint64_t offset = le(in, at, 8), length = le(in, at + 8, 8);
        Ktx2BasisLevel level;
        level.width = std::max<std::uint32_t>(1, out.width >> l);
        level.height = std::max<std::uint32_t>(1, out.height >> l);
        level.uncompressed_length = le(in, at + 16, 8);
        if (!inside(offset, length, in.size()))
            return error = "level " + str(l) + " (offset " + str(offset) + ", " + str(length) +
                           " bytes) overruns the file (truncated?)",
                   false;
        level.bytes = in.subspan(offset, length);
        if (uastc) {
            const std::uint64_t blocks =
                std::uint64_t{(level.width + 3u) / 4u} * ((level.height + 3u) / 4u) * 16u;
            if (level.uncompressed_length != blocks ||
                (out.scheme == BasisSupercompression::None && length != blocks))
                return error = "level " + str(l) + " has " + str(length) + " bytes (" +
                               str(level.uncompressed_length) + " uncompressed), expected " +
                               str(blocks) + " for " + str(level.width) + "x" + str(level.height) +
                               " UASTC blocks",
                       false;
        }
        out.levels.push_back(level);
    }
    return true;
}

namespace {
// One Zstandard decompression context for all levels of a file: creating one
// per call costs more than inflating a small level.
struct ZstdContext {
    ZSTD_DCtx* context = nullptr;
    ~ZstdContext() { ZSTD_freeDCtx(context); }
    ZstdContext() = default;
    ZstdContext(const ZstdContext&) = delete;
    ZstdContext& operator=(const ZstdContext&) = delete;
};

bool decode_uastc_level(const Ktx2BasisFile& file, std::size_t index, ZstdContext& zstd,
                        RgbaImage& image, std::string& error) {
    const Ktx2BasisLevel& level = file.levels[index];
    std::vector<std::uint8_t> inflated;
    std::span<const std::uint8_t> blocks = level.bytes;
    if (file.scheme == BasisSupercompression::Zstandard) {
        if (!zstd.context && !(zstd.context = ZSTD_createDCtx()))
            return error = "out of memory for a Zstandard context", false;
        inflated.resize(level.uncompressed_length);
        const std::size_t got = ZSTD_decompressDCtx(zstd.context, inflated.data(), inflated.size(),
                                                    blocks.data(), blocks.size());
        if (ZSTD_isError(got))
            return error = "level " + str(index) + ": Zstandard: " + ZSTD_getErrorName(got), false;
        if (got != inflated.size())
            return error = "level " + str(index) + ": Zstandard data inflates to " + str(got) +
                           " bytes, expected " + str(inflated.size()),
                   false;
        blocks = inflated;
    }
    const std::uint32_t bw = (level.width + 3) / 4, bh = (level.height + 3) / 4;
    image.width = level.width, image.height = level.height;
    image.pixels.assign(std::size_t{level.width} * level.height * 4, 0);
    // UASTC's decoder (unlike ASTC hardware) interpolates with linear endpoint
    // expansion; the spec's reference encoder always assumes it.
    constexpr bool kSrgbInterpolation = false;
    std::uint8_t texels[64];
    for (std::uint32_t by = 0; by < bh; ++by)
        for (std::uint32_t bx = 0; bx < bw; ++bx) {
            const std::uint8_t* block = blocks.data() + (std::size_t{by} * bw + bx) * 16;
            const auto status = uastc::decode_block(block, texels, kSrgbInterpolation);
            if (status != uastc::BlockStatus::Ok)
                return error = "level " + str(index) + " block (" + str(bx) + ", " + str(by) +
                               "): " +
                               (status == uastc::BlockStatus::ReservedMode
                                    ? "reserved UASTC mode"
                                    : "UASTC partition pattern index out of range"),
                       false;
            const std::uint32_t w = std::min(4u, level.width - bx * 4),
                                h = std::min(4u, level.height - by * 4);
            for (std::uint32_t y = 0; y < h; ++y)
                std::memcpy(image.pixels.data() +
                                (std::size_t{by * 4 + y} * level.width + bx * 4) * 4,
                            texels + y * 16, w * 4);
        }
    return true;
}
} // namespace

bool transcode_ktx2_basis(std::span<const std::uint8_t> ktx2, BasisTexture& out, std::string& error,
                          bool base_level_only) {
    out = BasisTexture{};
    Ktx2BasisFile file;
    if (!parse_ktx2_basis(ktx2, file, error)) return false;
    out.payload = file.payload, out.supercompression = file.scheme;
    out.srgb = file.srgb, out.has_alpha = file.has_alpha;
    // ETC1S global data describes every level, so the file keeps them all.
    if (file.payload == BasisPayload::Etc1s)
        return decode_etc1s_levels(file, out.levels, error, base_level_only ? 1 : SIZE_MAX);
    if (base_level_only) file.levels.resize(1);
    out.levels.resize(file.levels.size());
    ZstdContext zstd;
    for (std::size_t l = 0; l < file.levels.size(); ++l)
        if (!decode_uastc_level(file, l, zstd, out.levels[l], error)) return false;
    return true;
}

bool decode_image_or_ktx2(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                          RgbaImage& out, std::string& error) {
    if (!is_ktx2(bytes)) return decode_encoded_image(bytes, name_hint, out, error);
    BasisTexture texture;
    if (!transcode_ktx2_basis(bytes, texture, error, true))
        return error = std::string(name_hint) + ": " + error, false;
    out = std::move(texture.levels.front());
    return true;
}

bool probe_ktx2_basis(std::span<const std::uint8_t> ktx2, std::string& error) {
    Ktx2BasisFile file;
    return parse_ktx2_basis(ktx2, file, error);
}

bool read_basis_ktx2_file(const std::filesystem::path& path, BasisTexture& out,
                          std::string& error) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return error = path.string() + ": cannot open", false;
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(f)),
                                          std::istreambuf_iterator<char>());
    if (!transcode_ktx2_basis(bytes, out, error))
        return error = path.string() + ": " + error, false;
    return true;
}

} // namespace sherpa::tex
