// Our meshopt decoders (engine/scene/src/meshopt_codec.h) against a reference we did not
// write: Debian's libmeshoptimizer (0.18) encodes random and real vertex/index data and
// filters (bitstream version 0 vertex streams; index versions 0 and 1), its decoders
// decode them, and ours must produce the same bytes. Edge cases: count 0, every stride,
// every truncation, wrong header versions, trailing bytes, short outputs.
// Version 1 vertex streams are checked against the npm meshoptimizer decoder
// (meshopt_oracle_test.cpp).
#include "meshopt_codec.h"
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <meshoptimizer.h>

namespace {

namespace mo = sherpa::scene::meshopt;
using Bytes = std::vector<std::uint8_t>;

Bytes encode_vertices(const Bytes& data, std::size_t count, std::size_t stride) {
    Bytes out(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data.data(), count, stride));
    return out;
}

// Element data of several kinds: random bytes, slow ramps (small deltas), constant
// columns (zero deltas), and a mix per byte column.
Bytes vertex_data(std::size_t count, std::size_t stride, int kind, std::mt19937& rng) {
    Bytes d(count * stride);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t k = 0; k < stride; ++k) {
            const unsigned r = rng();
            const unsigned column = kind == 3 ? unsigned(k % 3) : unsigned(kind);
            d[i * stride + k] = std::uint8_t(column == 0   ? r
                                             : column == 1 ? (i * (k + 1) / 7 + (r & 1))
                                                           : k * 31);
        }
    return d;
}

TEST(MeshoptVertexV0, EveryStrideAndCountMatchesTheLibrary) {
    std::mt19937 rng(7);
    for (std::size_t stride = 4; stride <= 256; stride += 4)
        for (const std::size_t count : {0, 1, 15, 16, 17, 33, 255, 256, 257, 700})
            for (int kind = 0; kind < 4; ++kind) {
                const Bytes data = vertex_data(count, stride, kind, rng);
                const Bytes enc = encode_vertices(data, count, stride);
                Bytes ref(count * stride + 1), ours(count * stride + 1);
                ASSERT_EQ(
                    meshopt_decodeVertexBuffer(ref.data(), count, stride, enc.data(), enc.size()),
                    0);
                const mo::Result r = mo::decode_vertex_buffer(ours, count, stride, enc);
                ASSERT_TRUE(r) << "stride " << stride << " count " << count << " kind " << kind
                               << ": " << mo::describe(r.status) << " at " << r.offset;
                ASSERT_EQ(ours, ref) << "stride " << stride << " count " << count;
                ASSERT_TRUE(std::equal(data.begin(), data.end(), ours.begin()));
                EXPECT_LE(mo::minimum_stream_size(mo::Mode::Attributes, 0, count, stride),
                          enc.size());
            }
}

// Real vertex rows: the engine's decoded vertices of sample models (positions, normals,
// UVs, tangents as floats), as the library's encoder sees them.
TEST(MeshoptVertexV0, RealMeshesMatchTheLibrary) {
    for (const char* model : {"Duck", "DamagedHelmet", "BoxTextured"}) {
        const sherpa::scene::LoadResult r =
            sherpa::scene::load_scene(sherpa::test::gltf_asset(model));
        ASSERT_TRUE(r) << r.error;
        for (const sherpa::scene::Mesh& mesh : r.scene->meshes) {
            constexpr std::size_t stride = sizeof(mesh.vertices[0]);
            static_assert(stride % 4 == 0 && stride <= 256);
            const std::size_t count = mesh.vertices.size();
            Bytes data(count * stride);
            std::memcpy(data.data(), mesh.vertices.data(), data.size());
            const Bytes enc = encode_vertices(data, count, stride);
            Bytes ours(data.size());
            ASSERT_TRUE(mo::decode_vertex_buffer(ours, count, stride, enc)) << model;
            EXPECT_EQ(ours, data) << model;
            // Real indices through both index codecs.
            const std::size_t n = mesh.indices.size() / 3 * 3;
            for (const int version : {0, 1}) {
                meshopt_encodeIndexVersion(version);
                Bytes ienc(meshopt_encodeIndexBufferBound(n, count));
                ienc.resize(
                    meshopt_encodeIndexBuffer(ienc.data(), ienc.size(), mesh.indices.data(), n));
                std::vector<std::uint32_t> ref(n), got(n);
                ASSERT_EQ(meshopt_decodeIndexBuffer(ref.data(), n, 4, ienc.data(), ienc.size()), 0);
                std::span<std::uint8_t> dst(reinterpret_cast<std::uint8_t*>(got.data()), n * 4);
                ASSERT_TRUE(mo::decode_index_buffer(dst, n, 4, ienc)) << model << " v" << version;
                EXPECT_EQ(got, ref);
            }
        }
    }
}

// Triangle lists of several shapes: a vertex-cache-optimized grid (mostly 1-byte codes),
// random triangles (explicit indices), and a restart (two lists concatenated).
std::vector<std::uint32_t> triangles(int kind, std::mt19937& rng) {
    std::vector<std::uint32_t> ib;
    if (kind == 0) {
        const std::uint32_t w = 40;
        for (std::uint32_t y = 0; y + 1 < w; ++y)
            for (std::uint32_t x = 0; x + 1 < w; ++x) {
                const std::uint32_t a = y * w + x;
                ib.insert(ib.end(), {a, a + w, a + 1, a + 1, a + w, a + w + 1});
            }
        std::vector<std::uint32_t> opt(ib.size());
        meshopt_optimizeVertexCache(opt.data(), ib.data(), ib.size(), w * w);
        std::vector<std::uint32_t> remap(w * w);
        meshopt_optimizeVertexFetchRemap(remap.data(), opt.data(), opt.size(), w * w);
        meshopt_remapIndexBuffer(ib.data(), opt.data(), opt.size(), remap.data());
    } else {
        for (int t = 0; t < 3000; ++t)
            for (int c = 0; c < 3; ++c) ib.push_back(rng() % (kind == 1 ? 70000u : 500u));
    }
    return ib;
}

TEST(MeshoptIndexBuffer, BothVersionsAndIndexSizesMatchTheLibrary) {
    std::mt19937 rng(11);
    for (int kind = 0; kind < 3; ++kind)
        for (const int version : {0, 1})
            for (const std::size_t size : {2, 4}) {
                std::vector<std::uint32_t> ib = triangles(kind, rng);
                if (size == 2)
                    for (auto& i : ib) i &= 0xFFFF;
                meshopt_encodeIndexVersion(version);
                Bytes enc(meshopt_encodeIndexBufferBound(ib.size(), 70000));
                enc.resize(meshopt_encodeIndexBuffer(enc.data(), enc.size(), ib.data(), ib.size()));
                ASSERT_EQ(enc[0], 0xE0 | version);
                Bytes ref(ib.size() * size), ours(ib.size() * size);
                ASSERT_EQ(
                    meshopt_decodeIndexBuffer(ref.data(), ib.size(), size, enc.data(), enc.size()),
                    0);
                const mo::Result r = mo::decode_index_buffer(ours, ib.size(), size, enc);
                ASSERT_TRUE(r) << mo::describe(r.status) << " at " << r.offset;
                EXPECT_EQ(ours, ref) << "kind " << kind << " v" << version << " size " << size;
            }
}

TEST(MeshoptIndexSequence, SequencesMatchTheLibrary) {
    std::mt19937 rng(13);
    for (const std::size_t size : {2, 4})
        for (int kind = 0; kind < 3; ++kind) {
            std::vector<std::uint32_t> seq;
            for (std::uint32_t i = 0; i < 5000; ++i)
                seq.push_back(kind == 0   ? i / 2 + (i & 1) * 1000 // two interleaved runs (a strip)
                              : kind == 1 ? rng()                  // anything (5-byte varints)
                                          : rng() % 300);
            if (size == 2)
                for (auto& i : seq) i &= 0xFFFF;
            Bytes enc(meshopt_encodeIndexSequenceBound(seq.size(), ~0u));
            enc.resize(meshopt_encodeIndexSequence(enc.data(), enc.size(), seq.data(), seq.size()));
            Bytes ref(seq.size() * size), ours(seq.size() * size);
            ASSERT_EQ(
                meshopt_decodeIndexSequence(ref.data(), seq.size(), size, enc.data(), enc.size()),
                0);
            ASSERT_TRUE(mo::decode_index_sequence(ours, seq.size(), size, enc));
            EXPECT_EQ(ours, ref) << "kind " << kind << " size " << size;
        }
}

// Filters on the library's own filter encodings. The specification allows one unit in
// the last place for octahedral and quaternion outputs, none for exponential.
void expect_filter_matches(mo::Filter filter, Bytes encoded, std::size_t count, std::size_t stride,
                           int ulp, int component_bytes) {
    Bytes ref = encoded, ours = encoded;
    if (filter == mo::Filter::Octahedral) meshopt_decodeFilterOct(ref.data(), count, stride);
    if (filter == mo::Filter::Quaternion) meshopt_decodeFilterQuat(ref.data(), count, stride);
    if (filter == mo::Filter::Exponential) meshopt_decodeFilterExp(ref.data(), count, stride);
    ASSERT_TRUE(mo::apply_filter(filter, ours, count, stride));
    std::size_t differ = 0;
    for (std::size_t i = 0; i < ref.size(); i += component_bytes) {
        std::int32_t a = 0, b = 0;
        if (component_bytes == 1) a = std::int8_t(ref[i]), b = std::int8_t(ours[i]);
        if (component_bytes == 2) {
            std::int16_t x, y;
            std::memcpy(&x, &ref[i], 2), std::memcpy(&y, &ours[i], 2);
            a = x, b = y;
        }
        if (component_bytes == 4) std::memcpy(&a, &ref[i], 4), std::memcpy(&b, &ours[i], 4);
        EXPECT_LE(std::abs(a - b), ulp) << "component " << i / component_bytes;
        differ += a != b;
    }
    ::testing::Test::RecordProperty("components_differing_by_one_ulp", int(differ));
}

TEST(MeshoptFilters, MatchTheLibraryWithinTheSpecificationsTolerance) {
    std::mt19937 rng(17);
    std::normal_distribution<float> normal;
    const std::size_t count = 4096;
    std::vector<float> unit(count * 4), wide(count * 4);
    for (std::size_t i = 0; i < count; ++i) {
        float v[4] = {normal(rng), normal(rng), normal(rng), normal(rng)};
        const float l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
        for (int c = 0; c < 4; ++c) unit[i * 4 + c] = v[c] / l, wide[i * 4 + c] = v[c] * 1e3f;
    }
    std::vector<float> unit3 = unit;
    for (std::size_t i = 0; i < count; ++i) { // octahedral takes unit 3-vectors (+ w)
        float* v = &unit3[i * 4];
        const float l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        v[0] /= l, v[1] /= l, v[2] /= l, v[3] = v[3] > 0 ? 1.0f : -1.0f;
    }
    for (const int bits : {4, 8}) {
        Bytes e(count * 4);
        meshopt_encodeFilterOct(e.data(), count, 4, bits, unit3.data());
        expect_filter_matches(mo::Filter::Octahedral, e, count, 4, 1, 1);
    }
    for (const int bits : {8, 12, 16}) {
        Bytes e(count * 8);
        meshopt_encodeFilterOct(e.data(), count, 8, bits, unit3.data());
        expect_filter_matches(mo::Filter::Octahedral, e, count, 8, 1, 2);
        meshopt_encodeFilterQuat(e.data(), count, 8, bits, unit.data());
        expect_filter_matches(mo::Filter::Quaternion, e, count, 8, 1, 2);
    }
    for (const int bits : {8, 15, 24}) {
        Bytes e(count * 16);
        meshopt_encodeFilterExp(e.data(), count, 16, bits, wide.data());
        expect_filter_matches(mo::Filter::Exponential, e, count, 16, 0, 4);
    }
}

// --- edge cases ----------------------------------------------------------------------

TEST(MeshoptEdgeCases, StrideAndIndexSizeLimits) {
    Bytes out(4096), enc = encode_vertices(Bytes(64, 1), 16, 4);
    for (const std::size_t stride : {0, 2, 3, 5, 258, 260, 512})
        EXPECT_EQ(mo::decode_vertex_buffer(out, 1, stride, enc).status, mo::Status::BadArgument)
            << stride;
    for (const std::size_t size : {0, 1, 3, 8})
        EXPECT_EQ(mo::decode_index_buffer(out, 3, size, enc).status, mo::Status::BadArgument);
    EXPECT_EQ(mo::decode_index_buffer(out, 4, 4, enc).status, mo::Status::BadArgument); // not 3n
    // An output one byte short of count * stride is refused before anything is written.
    Bytes small(63, 0xCD);
    EXPECT_EQ(mo::decode_vertex_buffer(small, 16, 4, enc).status, mo::Status::BadArgument);
    EXPECT_EQ(small, Bytes(63, 0xCD));
    for (const mo::Filter f : {mo::Filter::Octahedral, mo::Filter::Color})
        EXPECT_EQ(mo::apply_filter(f, out, 1, 12).status, mo::Status::BadArgument);
    EXPECT_EQ(mo::apply_filter(mo::Filter::Quaternion, out, 1, 4).status, mo::Status::BadArgument);
    EXPECT_EQ(mo::apply_filter(mo::Filter::Exponential, out, 1, 6).status, mo::Status::BadArgument);
}

TEST(MeshoptEdgeCases, CountZeroStreamsDecode) {
    Bytes none;
    for (std::size_t stride = 4; stride <= 256; stride += 4)
        EXPECT_TRUE(mo::decode_vertex_buffer(none, 0, stride, encode_vertices({}, 0, stride)));
    Bytes ienc(64);
    ienc.resize(
        meshopt_encodeIndexBuffer(ienc.data(), ienc.size(), static_cast<unsigned*>(nullptr), 0));
    EXPECT_TRUE(mo::decode_index_buffer(none, 0, 2, ienc));
    Bytes senc(64);
    senc.resize(
        meshopt_encodeIndexSequence(senc.data(), senc.size(), static_cast<unsigned*>(nullptr), 0));
    EXPECT_TRUE(mo::decode_index_sequence(none, 0, 4, senc));
}

struct Stream {
    mo::Mode mode;
    std::size_t count, stride;
    Bytes bytes;
};

mo::Result decode(const Stream& s, Bytes& out, std::span<const std::uint8_t> src) {
    out.assign(s.count * s.stride, 0);
    return s.mode == mo::Mode::Attributes  ? mo::decode_vertex_buffer(out, s.count, s.stride, src)
           : s.mode == mo::Mode::Triangles ? mo::decode_index_buffer(out, s.count, s.stride, src)
                                           : mo::decode_index_sequence(out, s.count, s.stride, src);
}

int decode_library(const Stream& s, Bytes& out, std::span<const std::uint8_t> src) {
    out.assign(s.count * s.stride, 0);
    return s.mode == mo::Mode::Attributes
               ? meshopt_decodeVertexBuffer(out.data(), s.count, s.stride, src.data(), src.size())
           : s.mode == mo::Mode::Triangles
               ? meshopt_decodeIndexBuffer(out.data(), s.count, s.stride, src.data(), src.size())
               : meshopt_decodeIndexSequence(out.data(), s.count, s.stride, src.data(), src.size());
}

std::vector<Stream> small_streams() {
    std::mt19937 rng(19);
    std::vector<Stream> out;
    for (const std::size_t stride : {4, 12, 64})
        out.push_back({mo::Mode::Attributes, 40, stride,
                       encode_vertices(vertex_data(40, stride, 3, rng), 40, stride)});
    meshopt_encodeIndexVersion(1);
    for (const int kind : {0, 2}) {
        std::vector<std::uint32_t> ib = triangles(kind, rng);
        ib.resize(90);
        Bytes enc(meshopt_encodeIndexBufferBound(ib.size(), 70000));
        enc.resize(meshopt_encodeIndexBuffer(enc.data(), enc.size(), ib.data(), ib.size()));
        out.push_back({mo::Mode::Triangles, ib.size(), 4, enc});
        Bytes seq(meshopt_encodeIndexSequenceBound(ib.size(), 70000));
        seq.resize(meshopt_encodeIndexSequence(seq.data(), seq.size(), ib.data(), ib.size()));
        out.push_back({mo::Mode::Indices, ib.size(), 4, seq});
    }
    return out;
}

// Every prefix of a stream: ours never reads past it (the sanitizer build runs this),
// never accepts what the library refuses, and where both accept, agrees byte for byte.
TEST(MeshoptEdgeCases, TruncatedAtEveryByte) {
    for (const Stream& s : small_streams()) {
        Bytes ours, ref;
        for (std::size_t n = 0; n < s.bytes.size(); ++n) {
            const Bytes cut(s.bytes.begin(), s.bytes.begin() + std::ptrdiff_t(n));
            const mo::Result r = decode(s, ours, cut);
            if (!r) continue;
            ASSERT_EQ(decode_library(s, ref, cut), 0)
                << "accepted what the library refuses, n " << n;
            EXPECT_EQ(ours, ref);
        }
        // And every stream with a byte inserted before its tail (trailing bytes).
        Bytes longer = s.bytes;
        longer.insert(longer.end() - 4, 0);
        EXPECT_FALSE(decode(s, ours, longer)) << int(s.mode);
    }
}

TEST(MeshoptEdgeCases, WrongHeaderVersionsAreNamed) {
    for (const Stream& s : small_streams()) {
        Bytes out;
        for (unsigned version = 2; version < 16; ++version) {
            Bytes b = s.bytes;
            b[0] = std::uint8_t((b[0] & 0xF0) | version);
            const mo::Result r = decode(s, out, b);
            EXPECT_EQ(r.status, mo::Status::BadVersion);
            EXPECT_EQ(r.version, version);
        }
        Bytes b = s.bytes;
        b[0] ^= 0x40; // another mode's nibble
        EXPECT_EQ(decode(s, out, b).status, mo::Status::BadHeader);
    }
}

// Every single-byte change of the small streams, ours against the library: never
// accepted where the library refuses, equal output where both accept.
TEST(MeshoptEdgeCases, EveryByteFlippedAgreesWithTheLibrary) {
    for (const Stream& s : small_streams())
        for (std::size_t i = 1; i < s.bytes.size(); ++i)
            for (const std::uint8_t x : {0x01, 0x80, 0xFF}) {
                Bytes b = s.bytes, ours, ref;
                b[i] ^= x;
                if (!decode(s, ours, b)) continue;
                ASSERT_EQ(decode_library(s, ref, b), 0) << "byte " << i;
                EXPECT_EQ(ours, ref) << "byte " << i;
            }
}

} // namespace
