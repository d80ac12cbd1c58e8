// The meshopt vertex codec (mode ATTRIBUTES), bitstream versions 0 and 1, written from
// the KHR_meshopt_compression specification (Appendix A, "Mode 0: attributes").
//
// A stream is a header byte 0xA0 | version, attribute blocks, zero padding and a tail:
// the baseline element (and, in version 1, one channel-mode byte per 4 bytes of it),
// the tail padded to at least 32 (v0) or 24 (v1) bytes. Each block holds up to
// min((8192 / stride) & ~15, 256) elements; per byte of the element ("byte column") it
// stores the deltas of that byte in groups of 16, each group's bit width chosen by 2
// header bits (in v1 from a table picked by the column's 2-bit control mode, or the
// column stored literally or all zero). Deltas are zigzag bytes (channel mode 0), zigzag
// 16-bit words (mode 1, v1) or rotated 32-bit XORs (mode 2, v1) against the element
// before.
#include "meshopt_codec.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace sherpa::scene::meshopt {
namespace {

constexpr std::size_t kGroup = 16;     // elements per delta group
constexpr std::size_t kMaxBlock = 256; // elements per block, at most
constexpr std::size_t kBlockBytes = 8192;

std::size_t block_elements(std::size_t stride) {
    return std::min((kBlockBytes / stride) & ~(kGroup - 1), kMaxBlock);
}

// Bit widths of the four group encodings: version 0, then version 1 control modes 0 and 1.
// 0 is "all deltas zero", 8 "16 bytes stored as they are".
constexpr std::array<std::array<std::uint8_t, 4>, 3> kWidths = {
    {{0, 2, 4, 8}, {0, 1, 2, 4}, {1, 2, 4, 8}}};

// One group of 16 deltas of W bits (1, 2 or 4) with sentinels: a value of all ones
// means the delta is the next byte after the packed bits. 1-bit deltas are packed from
// the least significant bit, 2- and 4-bit ones from the most significant. W is a
// template argument so that the bit positions are constants (the loop unrolls), and the
// sentinel is resolved without a branch.
// Per packed byte of W-bit deltas (W = 2 or 4): its 8 / W deltas as bytes, in stream
// order, and a mask of those that are sentinels. Most bytes hold no sentinel: their
// deltas are copied from the table whole.
template <unsigned W> struct ByteTable {
    std::uint32_t deltas[256]{};
    std::uint8_t escapes[256]{};
    constexpr ByteTable() {
        constexpr unsigned kSentinel = (1u << W) - 1, kPerByte = 8 / W;
        for (unsigned b = 0; b < 256; ++b)
            for (unsigned k = 0; k < kPerByte; ++k) {
                const unsigned d = (b >> (8 - W * (k + 1))) & kSentinel;
                deltas[b] |= std::uint32_t(d) << (8 * k);
                escapes[b] |= std::uint8_t((d == kSentinel ? 1u : 0u) << k);
            }
    }
};

template <unsigned W, bool kChecked>
std::size_t unpack_group(const std::uint8_t* packed, std::size_t available, std::uint8_t* out) {
    constexpr unsigned kSentinel = (1u << W) - 1, kPerByte = 8 / W;
    const std::uint8_t* extra = packed + 2 * W;
    std::size_t used = 0;
    for (unsigned p = 0; p < 2 * W; ++p, out += kPerByte) {
        const unsigned byte = packed[p];
        unsigned escapes = byte; // W = 1: a 1 bit is the sentinel (least significant first)
        if constexpr (W != 1) {
            static constexpr ByteTable<W> kTable;
            escapes = kTable.escapes[byte];
            if (escapes == 0) {
                std::memcpy(out, &kTable.deltas[byte], kPerByte);
                continue;
            }
        } else if (escapes == 0) {
            std::memset(out, 0, kPerByte);
            continue;
        }
        for (unsigned k = 0; k < kPerByte; ++k) {
            const unsigned shift = W == 1 ? k : 8 - W * (k + 1);
            const unsigned delta = (byte >> shift) & kSentinel;
            const bool escaped = (escapes >> k) & 1;
            const std::uint8_t value = !kChecked || used < available ? extra[used] : 0;
            out[k] = escaped ? value : std::uint8_t(delta);
            used += escaped;
        }
    }
    return used;
}

template <unsigned W> bool decode_group(StreamReader& in, std::uint8_t* out) {
    if (!in.has(2 * W)) return false; // 16 * W bits
    const std::uint8_t* packed = in.bytes.data() + in.pos;
    const std::size_t available = in.end - in.pos - 2 * W;
    // With 16 bytes left after the bits, no escape can run past the stream: unchecked.
    const std::size_t used = available >= kGroup ? unpack_group<W, false>(packed, available, out)
                                                 : unpack_group<W, true>(packed, available, out);
    if (used > available) return false;
    in.pos += 2 * W + used;
    return true;
}

// One byte column of a block: header bits (2 per group, low bits first, byte-aligned),
// then each group. `groups` groups of 16 are written to `out`.
bool decode_column(StreamReader& in, std::uint8_t* out, std::size_t groups,
                   const std::array<std::uint8_t, 4>& widths) {
    const std::uint8_t* header = in.take((groups + 3) / 4);
    if (!header) return false;
    for (std::size_t g = 0; g < groups; ++g) {
        const unsigned width = widths[(header[g / 4] >> (2 * (g % 4))) & 3];
        std::uint8_t* dst = out + g * kGroup;
        if (width == 0) {
            std::memset(dst, 0, kGroup);
        } else if (width == 8) {
            const std::uint8_t* raw = in.take(kGroup);
            if (!raw) return false;
            std::memcpy(dst, raw, kGroup);
        } else if (!(width == 1   ? decode_group<1>(in, dst)
                     : width == 2 ? decode_group<2>(in, dst)
                                  : decode_group<4>(in, dst))) {
            return false;
        }
    }
    return true;
}

// (v & 1) ? ~(v >> 1) : (v >> 1), without a branch.
std::uint8_t unzigzag8(std::uint8_t v) {
    return std::uint8_t((v >> 1) ^ -(v & 1));
}

std::uint16_t unzigzag16(std::uint16_t v) {
    return std::uint16_t((v >> 1) ^ -(v & 1));
}

std::uint32_t rotate_right(std::uint32_t v, unsigned r) {
    return r == 0 ? v : (v >> r) | (v << (32 - r));
}

// The 4 byte columns of one channel (bytes k..k+3 of each element) turned from deltas
// into values, per the channel's mode; `last` is the element before the block.
void apply_deltas(const std::uint8_t (*columns)[kMaxBlock], std::size_t n, std::uint8_t* out,
                  std::size_t stride, std::uint8_t* last, std::uint8_t channel) {
    const unsigned mode = channel & 15;
    if (mode == 0) { // the 4 bytes side by side: 4 independent sums per element
        std::uint8_t p0 = last[0], p1 = last[1], p2 = last[2], p3 = last[3];
        for (std::size_t i = 0; i < n; ++i) {
            p0 = std::uint8_t(p0 + unzigzag8(columns[0][i]));
            p1 = std::uint8_t(p1 + unzigzag8(columns[1][i]));
            p2 = std::uint8_t(p2 + unzigzag8(columns[2][i]));
            p3 = std::uint8_t(p3 + unzigzag8(columns[3][i]));
            const std::uint8_t value[4] = {p0, p1, p2, p3};
            std::memcpy(out + i * stride, value, 4);
        }
        last[0] = p0, last[1] = p1, last[2] = p2, last[3] = p3;
    } else if (mode == 1) {
        for (std::size_t h = 0; h < 4; h += 2) {
            std::uint16_t p = std::uint16_t(last[h] | last[h + 1] << 8);
            for (std::size_t i = 0; i < n; ++i) {
                const auto d = std::uint16_t(columns[h][i] | columns[h + 1][i] << 8);
                p = std::uint16_t(p + unzigzag16(d));
                out[i * stride + h] = std::uint8_t(p);
                out[i * stride + h + 1] = std::uint8_t(p >> 8);
            }
            last[h] = std::uint8_t(p), last[h + 1] = std::uint8_t(p >> 8);
        }
    } else { // 2: XOR of 32-bit words, the delta rotated left by the high 4 bits
        const unsigned r = channel >> 4;
        std::uint32_t p = std::uint32_t(last[0]) | std::uint32_t(last[1]) << 8 |
                          std::uint32_t(last[2]) << 16 | std::uint32_t(last[3]) << 24;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t d =
                std::uint32_t(columns[0][i]) | std::uint32_t(columns[1][i]) << 8 |
                std::uint32_t(columns[2][i]) << 16 | std::uint32_t(columns[3][i]) << 24;
            p ^= rotate_right(d, r);
            for (std::size_t j = 0; j < 4; ++j) out[i * stride + j] = std::uint8_t(p >> (8 * j));
        }
        for (std::size_t j = 0; j < 4; ++j) last[j] = std::uint8_t(p >> (8 * j));
    }
}

// One block of n elements into `out` (n * stride bytes).
Result decode_block(StreamReader& in, std::uint8_t* out, std::size_t n, std::size_t stride,
                    std::uint8_t* last, const std::uint8_t* channels, unsigned version) {
    const std::size_t groups = (n + kGroup - 1) / kGroup;
    const std::uint8_t* control = nullptr;
    if (version == 1 && !(control = in.take(stride / 4))) return {Status::Truncated, in.pos};
    std::uint8_t columns[4][kMaxBlock];
    for (std::size_t k = 0; k < stride; k += 4) {
        const unsigned controls = control ? control[k / 4] : 0;
        for (std::size_t j = 0; j < 4; ++j) {
            const unsigned c = (controls >> (2 * j)) & 3;
            if (version == 0) {
                if (!decode_column(in, columns[j], groups, kWidths[0]))
                    return {Status::Truncated, in.pos};
            } else if (c == 2) { // all deltas zero, nothing stored
                std::memset(columns[j], 0, n);
            } else if (c == 3) { // literal: one byte per element, no header bits
                const std::uint8_t* raw = in.take(n);
                if (!raw) return {Status::Truncated, in.pos};
                std::memcpy(columns[j], raw, n);
            } else if (!decode_column(in, columns[j], groups, kWidths[1 + c])) {
                return {Status::Truncated, in.pos};
            }
        }
        apply_deltas(columns, n, out + k, stride, last + k, channels ? channels[k / 4] : 0);
    }
    return {};
}

} // namespace

Result decode_vertex_buffer(std::span<std::uint8_t> dst, std::size_t count, std::size_t stride,
                            std::span<const std::uint8_t> src) {
    if (stride == 0 || stride % 4 != 0 || stride > 256 || dst.size() / stride < count)
        return {Status::BadArgument, 0};
    const Result header = read_header(src, header_kind(Mode::Attributes));
    if (!header) return header;
    const unsigned version = header.version;
    const std::size_t tail = stride + (version == 1 ? stride / 4 : 0);
    const std::size_t padded_tail = std::max<std::size_t>(tail, version == 1 ? 24 : 32);
    if (src.size() - 1 < padded_tail) return {Status::Truncated, src.size(), std::uint8_t(version)};
    const std::uint8_t* baseline = src.data() + src.size() - tail;
    const std::uint8_t* channels = version == 1 ? baseline + stride : nullptr;
    for (std::size_t c = 0; channels && c < stride / 4; ++c) {
        const unsigned mode = channels[c] & 15;
        if (mode > 2 || (mode < 2 && channels[c] >> 4))
            return {Status::InvalidData, src.size() - stride / 4 + c, std::uint8_t(version)};
    }
    std::uint8_t last[256];
    std::memcpy(last, baseline, stride);
    StreamReader in{src, 1, src.size() - padded_tail};
    const std::size_t block = block_elements(stride);
    for (std::size_t done = 0; done < count;) {
        const std::size_t n = std::min(block, count - done);
        Result r = decode_block(in, dst.data() + done * stride, n, stride, last, channels, version);
        if (!r) return r.version = std::uint8_t(version), r;
        done += n;
    }
    if (in.pos != in.end) return {Status::TrailingBytes, in.pos, std::uint8_t(version)};
    return {Status::Ok, src.size(), std::uint8_t(version)};
}

std::size_t minimum_stream_size(Mode mode, unsigned version, std::size_t count,
                                std::size_t stride) {
    if (mode == Mode::Triangles) return 1 + count / 3 + 16; // a code per triangle, the table
    if (mode == Mode::Indices) return 1 + count + 4;        // a byte per index, the tail
    if (stride == 0 || stride > 256) return 0;
    // Per block: v1 its control bytes (every column "all zero"), v0 every column's
    // header bits (every group "all zero").
    const auto block_bytes = [&](std::size_t n) {
        return version == 1 ? stride / 4 : stride * (((n + kGroup - 1) / kGroup + 3) / 4);
    };
    const std::size_t block = block_elements(stride);
    const std::size_t tail = stride + (version == 1 ? stride / 4 : 0);
    return 1 + count / block * block_bytes(block) +
           (count % block ? block_bytes(count % block) : 0) +
           std::max<std::size_t>(tail, version == 1 ? 24 : 32);
}

const char* describe(Status status) {
    switch (status) {
    case Status::Ok:
        return "decoded";
    case Status::BadArgument:
        return "count or stride not allowed for the mode";
    case Status::BadHeader:
        return "the header byte names another mode";
    case Status::BadVersion:
        return "unknown bitstream version";
    case Status::Truncated:
        return "truncated (the stream ends before its data)";
    case Status::TrailingBytes:
        return "trailing bytes before the stream's tail";
    case Status::InvalidData:
        return "invalid data";
    }
    return "unknown";
}

} // namespace sherpa::scene::meshopt
