// The meshopt index codecs, written from the KHR_meshopt_compression specification
// (Appendix A, "Mode 1: triangles" and "Mode 2: indices").
//
// TRIANGLES: header 0xE0 | version, one code byte per triangle, extra data (varints and
// explicit bytes), a 16-byte table. Codes name an edge of a 16-entry edge FIFO and a
// third vertex (the next new index, a vertex FIFO entry, last +- 1 in version 1, or an
// explicit delta), or three vertices through the table or an explicit byte. Version 0
// and 1 differ in one place: version 1 spends third-vertex codes 0xXd / 0xXe on
// last - 1 / last + 1, version 0 on vertex FIFO entries 13 and 14.
// INDICES: header 0xD0 | version, one varint per index (a zigzag delta against one of two
// baselines chosen by its low bit), 4 tail bytes.
#include "meshopt_codec.h"

namespace sherpa::scene::meshopt {
namespace {

// Unsigned LEB128 of 1-5 bytes; a 5th byte that says "more follows" is invalid.
bool read_varint(StreamReader& in, std::uint32_t& value) {
    value = 0;
    for (unsigned i = 0; i < 5; ++i) {
        const std::uint8_t* b = in.take(1);
        if (!b) return false;
        value |= std::uint32_t(*b & 127) << (7 * i);
        if (*b < 128) return true;
    }
    return false;
}

void write_index(std::uint8_t* dst, std::size_t i, std::size_t index_size, std::uint32_t v) {
    std::uint8_t* p = dst + i * index_size;
    p[0] = std::uint8_t(v), p[1] = std::uint8_t(v >> 8);
    if (index_size == 4) p[2] = std::uint8_t(v >> 16), p[3] = std::uint8_t(v >> 24);
}

// A FIFO of the 16 most recent entries that knows how many were ever written, so a read
// of an entry never written is caught (the specification calls such streams invalid).
template <typename T> struct Fifo {
    T items[16]{};
    std::size_t written = 0;
    void push(const T& v) { items[written++ & 15] = v; }
    // The entry `age` steps back (0: the most recent); false if it was never written.
    bool get(std::size_t age, T& out) const {
        if (age >= written || age >= 16) return false;
        out = items[(written - 1 - age) & 15];
        return true;
    }
};

struct Edge {
    std::uint32_t a = 0, b = 0;
};

struct TriangleState {
    Fifo<Edge> edges;
    Fifo<std::uint32_t> vertices;
    std::uint32_t next = 0, last = 0;

    // An explicit index: a zigzag delta against `last`.
    bool explicit_index(StreamReader& in, std::uint32_t& out) {
        std::uint32_t v = 0;
        if (!read_varint(in, v)) return false;
        last += (v & 1) ? ~(v >> 1) : (v >> 1);
        out = last;
        return true;
    }
    // A vertex named by a table or explicit byte nibble: 0 the next new index, 1-14
    // vertex FIFO entry nibble - 1, 15 (explicit byte only) an explicit index.
    bool nibble_vertex(StreamReader& in, unsigned nibble, std::uint32_t fifo_value,
                       std::uint32_t& out) {
        if (nibble == 0) return out = next++, true;
        if (nibble < 15) return out = fifo_value, true;
        return explicit_index(in, out);
    }
};

} // namespace

Result decode_index_buffer(std::span<std::uint8_t> dst, std::size_t count, std::size_t index_size,
                           std::span<const std::uint8_t> src) {
    if ((index_size != 2 && index_size != 4) || count % 3 != 0 || dst.size() / index_size < count)
        return {Status::BadArgument, 0};
    const Result header = read_header(src, header_kind(Mode::Triangles));
    if (!header) return header;
    const unsigned version = header.version;
    const auto v8 = header.version;
    const std::size_t triangles = count / 3;
    if (src.size() - 1 < 16 || src.size() - 1 - 16 < triangles)
        return {Status::Truncated, src.size(), v8};
    const std::uint8_t* codes = src.data() + 1;
    const std::uint8_t* table = src.data() + src.size() - 16;
    for (std::size_t i = 0; i < 16; ++i)
        if ((table[i] & 0x0F) == 0x0F || (table[i] >> 4) == 0x0F || (i >= 14 && table[i] != 0))
            return {Status::InvalidData, src.size() - 16 + i, v8};
    StreamReader in{src, 1 + triangles, src.size() - 16};
    const unsigned fifo_codes = version == 1 ? 13 : 15; // 0xX1..0xXc (v1) / 0xXe (v0)
    TriangleState s;
    for (std::size_t t = 0; t < triangles; ++t) {
        const unsigned code = codes[t];
        const std::size_t at = in.pos;
        std::uint32_t a = 0, b = 0, c = 0;
        if (code < 0xF0) { // an edge from the FIFO and a third vertex
            Edge e;
            if (!s.edges.get(code >> 4, e)) return {Status::InvalidData, 1 + t, v8};
            a = e.a, b = e.b;
            const unsigned third = code & 15;
            if (third == 0) {
                c = s.next++;
                s.vertices.push(c);
            } else if (third < fifo_codes) {
                if (!s.vertices.get(third, c)) return {Status::InvalidData, 1 + t, v8};
            } else {
                if (third == 15) {
                    if (!s.explicit_index(in, c)) return {Status::Truncated, at, v8};
                } else {
                    c = s.last = third == 13 ? s.last - 1 : s.last + 1;
                }
                s.vertices.push(c);
            }
            s.edges.push({c, b});
            s.edges.push({a, c});
        } else { // three vertices: the table (0xf0-0xfd) or an explicit byte (0xfe, 0xff)
            unsigned aux = 0;
            if (code < 0xFE) {
                aux = table[code & 15];
            } else {
                const std::uint8_t* byte = in.take(1);
                if (!byte) return {Status::Truncated, at, v8};
                aux = *byte;
                if (aux == 0) s.next = 0; // restart: the streams of a concatenation
            }
            const unsigned nb = aux >> 4, nc = aux & 15;
            std::uint32_t fb = 0, fc = 0; // FIFO reads before this triangle's pushes
            if ((nb > 0 && nb < 15 && !s.vertices.get(nb - 1, fb)) ||
                (nc > 0 && nc < 15 && !s.vertices.get(nc - 1, fc)))
                return {Status::InvalidData, 1 + t, v8};
            // New indices are numbered a, b, c before any explicit one is read.
            const bool explicit_a = code == 0xFF;
            if (!explicit_a) a = s.next++;
            if (nb == 0) b = s.next++;
            if (nc == 0) c = s.next++;
            if ((explicit_a && !s.explicit_index(in, a)) ||
                (nb != 0 && !s.nibble_vertex(in, nb, fb, b)) ||
                (nc != 0 && !s.nibble_vertex(in, nc, fc, c)))
                return {Status::Truncated, at, v8};
            s.vertices.push(a);
            if (nb == 0 || nb == 15) s.vertices.push(b);
            if (nc == 0 || nc == 15) s.vertices.push(c);
            s.edges.push({b, a});
            s.edges.push({c, b});
            s.edges.push({a, c});
        }
        write_index(dst.data(), 3 * t, index_size, a);
        write_index(dst.data(), 3 * t + 1, index_size, b);
        write_index(dst.data(), 3 * t + 2, index_size, c);
    }
    if (in.pos != in.end) return {Status::TrailingBytes, in.pos, v8};
    return {Status::Ok, src.size(), v8};
}

Result decode_index_sequence(std::span<std::uint8_t> dst, std::size_t count, std::size_t index_size,
                             std::span<const std::uint8_t> src) {
    if ((index_size != 2 && index_size != 4) || dst.size() / index_size < count)
        return {Status::BadArgument, 0};
    const Result header = read_header(src, header_kind(Mode::Indices));
    if (!header) return header;
    const auto v8 = header.version;
    if (src.size() - 1 < 4 || src.size() - 1 - 4 < count)
        return {Status::Truncated, src.size(), v8};
    StreamReader in{src, 1, src.size() - 4};
    std::uint32_t last[2] = {0, 0};
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t v = 0;
        const std::size_t at = in.pos;
        if (!read_varint(in, v))
            return {in.has(1) ? Status::InvalidData : Status::Truncated, at, v8};
        std::uint32_t& base = last[v & 1];
        base += (v & 2) ? ~(v >> 2) : (v >> 2);
        write_index(dst.data(), i, index_size, base);
    }
    if (in.pos != in.end) return {Status::TrailingBytes, in.pos, v8};
    return {Status::Ok, src.size(), v8};
}

Result decode(Mode mode, std::span<std::uint8_t> dst, std::size_t count, std::size_t stride,
              std::span<const std::uint8_t> src) {
    switch (mode) {
    case Mode::Attributes:
        return decode_vertex_buffer(dst, count, stride, src);
    case Mode::Triangles:
        return decode_index_buffer(dst, count, stride, src);
    case Mode::Indices:
        return decode_index_sequence(dst, count, stride, src);
    }
    return {Status::BadArgument, 0};
}

} // namespace sherpa::scene::meshopt
