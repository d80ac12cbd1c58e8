#pragma once
// Internal: the meshopt bitstreams of EXT_meshopt_compression and KHR_meshopt_compression
// (the extension's Appendix A and B), decoded by our own pure functions over spans.
//
// Contracts, shared by every decoder:
// - `dst` holds at least `count * stride` bytes (else BadArgument; nothing is written);
//   exactly that many bytes are written on success, and on failure the bytes written so
//   far are unspecified (the caller discards them).
// - Every read of `src` is bounds-checked; a stream must be consumed exactly (its tail
//   where the format has one: TrailingBytes otherwise) and never read past its end.
// - No allocation and no global state: a few KB of stack per call.
// - A stream the specification calls invalid (unknown header, bitstream version, channel
//   mode, a FIFO entry never written, a varint over 5 bytes) is refused, not guessed at.
#include <cstddef>
#include <cstdint>
#include <span>

namespace sherpa::scene::meshopt {

enum class Status : std::uint8_t {
    Ok,
    BadArgument,   // stride/count/dst the mode does not allow
    BadHeader,     // the header byte names another mode
    BadVersion,    // a bitstream version this decoder does not know
    Truncated,     // the stream ends before the data it describes
    TrailingBytes, // bytes left between the decoded data and the tail
    InvalidData,   // a value the specification forbids (channel mode, FIFO read, varint)
};

struct Result {
    Status status = Status::Ok;
    std::size_t offset = 0; // the stream byte where the problem was found
    std::uint8_t version = 0;
    explicit operator bool() const { return status == Status::Ok; }
};

// "truncated", "trailing bytes", ...: what a Status means, for messages.
const char* describe(Status status);

// Mode ATTRIBUTES (vertex codec, bitstream versions 0 and 1): `count` elements of
// `stride` bytes, stride a multiple of 4 in [4, 256].
Result decode_vertex_buffer(std::span<std::uint8_t> dst, std::size_t count, std::size_t stride,
                            std::span<const std::uint8_t> src);

// Mode TRIANGLES (index codec, versions 0 and 1): `count` indices (a multiple of 3) of
// `index_size` 2 or 4 bytes (16-bit indices wrap, as the specification says).
Result decode_index_buffer(std::span<std::uint8_t> dst, std::size_t count, std::size_t index_size,
                           std::span<const std::uint8_t> src);

// Mode INDICES (index sequence codec): `count` indices of `index_size` 2 or 4 bytes.
Result decode_index_sequence(std::span<std::uint8_t> dst, std::size_t count, std::size_t index_size,
                             std::span<const std::uint8_t> src);

enum class Mode : std::uint8_t { Attributes, Triangles, Indices };

// The high nibble of `mode`'s header byte (its low nibble is the bitstream version).
constexpr unsigned header_kind(Mode mode) {
    return mode == Mode::Attributes ? 0xA0u : mode == Mode::Triangles ? 0xE0u : 0xD0u;
}

// The decoder of `mode` above: `stride` is the vertex stride or the index size.
Result decode(Mode mode, std::span<std::uint8_t> dst, std::size_t count, std::size_t stride,
              std::span<const std::uint8_t> src);

// The fewest bytes a well-formed stream of `count` elements of `stride` bytes takes in
// `mode` at bitstream `version` (header, the least each block, table or index needs, and
// the tail). A shorter stream cannot decode: its output need never be allocated.
std::size_t minimum_stream_size(Mode mode, unsigned version, std::size_t count, std::size_t stride);

enum class Filter : std::uint8_t { None, Octahedral, Quaternion, Exponential, Color };

// Applies a filter in place to `count` decoded elements of `stride` bytes. Octahedral and
// Color need stride 4 or 8, Quaternion 8, Exponential a multiple of 4 (else BadArgument,
// nothing changed). Values the specification leaves unspecified (an octahedral "one" that
// is no power of two minus one, an exponent outside [-100, 100]) give defined, clamped
// results: no undefined float-to-int conversion.
Result apply_filter(Filter filter, std::span<std::uint8_t> data, std::size_t count,
                    std::size_t stride);

// The header byte every stream starts with: its high nibble names the mode (`kind`
// 0xA0, 0xE0 or 0xD0), its low one the bitstream version (0 or 1). Ok with the version,
// else why not.
inline Result read_header(std::span<const std::uint8_t> src, unsigned kind) {
    if (src.empty()) return {Status::Truncated, 0};
    if ((src[0] & 0xF0u) != kind) return {Status::BadHeader, 0};
    const auto version = std::uint8_t(src[0] & 0x0Fu);
    return {version > 1 ? Status::BadVersion : Status::Ok, 0, version};
}

// The byte reader every decoder uses: all reads checked against `end`.
struct StreamReader {
    std::span<const std::uint8_t> bytes;
    std::size_t pos = 0, end = 0;

    bool has(std::size_t n) const { return n <= end - pos; }
    // The next n bytes, or nullptr (and nothing consumed) when fewer are left.
    const std::uint8_t* take(std::size_t n) {
        if (!has(n)) return nullptr;
        const std::uint8_t* p = bytes.data() + pos;
        pos += n;
        return p;
    }
};

} // namespace sherpa::scene::meshopt
