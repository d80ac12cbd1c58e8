#include "draco_header.h"

#include <cstring>
#include <vector>

namespace sherpa::scene::detail {
namespace {

constexpr unsigned version(unsigned major, unsigned minor) {
    return major << 8 | minor;
}

// Reads the stream front to back as Draco's DecoderBuffer does; every read is checked.
class Reader {
public:
    explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
    std::size_t remaining() const { return bytes_.size() - at_; }
    bool u8(std::uint8_t& v) {
        if (remaining() < 1) return false;
        v = bytes_[at_++];
        return true;
    }
    bool u16(std::uint16_t& v) {
        if (remaining() < 2) return false;
        v = std::uint16_t(bytes_[at_] | bytes_[at_ + 1] << 8);
        at_ += 2;
        return true;
    }
    bool u32(std::uint32_t& v) {
        if (remaining() < 4) return false;
        v = 0;
        for (int i = 3; i >= 0; --i) v = v << 8 | bytes_[at_ + std::size_t(i)];
        at_ += 4;
        return true;
    }
    // Draco's unsigned varint: 7 bits a byte, low bits first, at most 5 bytes for a
    // uint32 (bits past 32 dropped, as Draco's shifts drop them).
    bool varint(std::uint32_t& v) {
        std::uint64_t value = 0;
        for (int i = 0; i < 5; ++i) {
            std::uint8_t b = 0;
            if (!u8(b)) return false;
            value |= std::uint64_t(b & 0x7F) << (7 * i);
            if (!(b & 0x80)) {
                v = std::uint32_t(value);
                return true;
            }
        }
        return false;
    }
    // A count: uint32 in streams older than `varint_from`, a varint from then on.
    bool count(unsigned stream_version, unsigned varint_from, std::uint32_t& v) {
        return stream_version < varint_from ? u32(v) : varint(v);
    }
    bool skip(std::size_t n) {
        if (remaining() < n) return false;
        at_ += n;
        return true;
    }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t at_ = 0;
};

bool skip_name(Reader& r) {
    std::uint8_t length = 0;
    return r.u8(length) && r.skip(length);
}

// One metadata block and its nested blocks, in the order Draco's MetadataDecoder reads
// them: entries (name, varint size > 0, bytes), a varint count of sub-blocks, then each
// sub-block (name, block). Iterative, with Draco's nesting limit.
bool skip_metadata(Reader& r) {
    constexpr std::size_t kMaxDepth = 1000;
    std::vector<std::uint32_t> pending{1}; // blocks left to read at each depth
    while (!pending.empty()) {
        if (pending.back() == 0) {
            pending.pop_back();
            continue;
        }
        --pending.back();
        if (pending.size() > 1 && !skip_name(r)) return false;
        std::uint32_t entries = 0, subs = 0;
        if (!r.varint(entries)) return false;
        for (std::uint32_t i = 0; i < entries; ++i) {
            std::uint32_t size = 0;
            if (!skip_name(r) || !r.varint(size) || size == 0 || !r.skip(size)) return false;
        }
        if (!r.varint(subs) || subs > r.remaining()) return false;
        if (subs == 0) continue;
        if (pending.size() > kMaxDepth) return false;
        pending.push_back(subs);
    }
    return true;
}

bool skip_geometry_metadata(Reader& r) {
    std::uint32_t attributes = 0;
    if (!r.varint(attributes)) return false;
    for (std::uint32_t i = 0; i < attributes; ++i) {
        std::uint32_t id = 0;
        if (!r.varint(id) || !skip_metadata(r)) return false;
    }
    return skip_metadata(r);
}

} // namespace

bool read_draco_counts(std::span<const std::uint8_t> stream, DracoCounts& counts,
                       std::string& error) {
    Reader r(stream);
    const char* cut = "the stream's header is cut short";
    if (stream.size() < 5 || std::memcmp(stream.data(), "DRACO", 5) != 0) {
        error = "not a Draco stream (it does not start with \"DRACO\")";
        return false;
    }
    r.skip(5);
    std::uint8_t type = 0, method = 0;
    std::uint16_t flags = 0;
    if (!r.u8(counts.version_major) || !r.u8(counts.version_minor) || !r.u8(type) ||
        !r.u8(method) || !r.u16(flags)) {
        error = cut;
        return false;
    }
    const unsigned v = version(counts.version_major, counts.version_minor);
    if (counts.version_major < 1 || v > version(2, 2)) {
        error = "Draco bitstream version " + std::to_string(counts.version_major) + "." +
                std::to_string(counts.version_minor) +
                " is not decoded by Debian's Draco 1.5.5 (it decodes 1.0 to 2.2)";
        return false;
    }
    if (type != 1) {
        error = "geometry type " + std::to_string(type) + " is not a triangle mesh (1)";
        return false;
    }
    if (method > 1) {
        error = "encoding method " + std::to_string(method) +
                " is neither sequential (0) nor Edgebreaker (1)";
        return false;
    }
    counts.method = DracoMethod(method);
    if (v >= version(1, 3) && (flags & 0x8000) && !skip_geometry_metadata(r)) {
        error = "the stream's metadata is cut short or malformed";
        return false;
    }
    if (counts.method == DracoMethod::Sequential) {
        if (!r.count(v, version(2, 2), counts.faces) || !r.count(v, version(2, 2), counts.points)) {
            error = cut;
            return false;
        }
        return true;
    }
    // Traversal decoder type; new vertices (before 2.2); vertices; faces; attribute
    // connectivities (then symbols and split symbols, which Draco checks itself).
    std::uint8_t traversal = 0;
    std::uint32_t new_vertices = 0;
    const bool ok = r.u8(traversal) &&
                    (v >= version(2, 2) || r.count(v, version(2, 0), new_vertices)) &&
                    r.count(v, version(2, 0), counts.encoded_vertices) &&
                    r.count(v, version(2, 0), counts.faces) && r.u8(counts.attribute_data);
    if (!ok) {
        error = cut;
        return false;
    }
    return true;
}

} // namespace sherpa::scene::detail
