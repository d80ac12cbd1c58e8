// Our meshopt decoders against the npm meshoptimizer package's decoder (a reference we
// did not write, with bitstream version 1): tools/gltf_compress/meshopt_oracle.mjs
// writes every compressed view of gltfpack's corpus (Duck.khr_meshopt.glb's version 1
// streams among them) and synthetic version 1 streams of its own encoder (every stride,
// counts, data kinds, encoder levels, the four filters), each with the oracle's decoded
// bytes. Ours must decode each stream to the same bytes; filtered outputs may differ by
// one unit in the last place where the specification allows it (none for EXPONENTIAL).
#include "meshopt_codec.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

namespace mo = sherpa::scene::meshopt;
using Bytes = std::vector<std::uint8_t>;

struct OracleStream {
    std::uint32_t mode = 0, filter = 0, count = 0, stride = 0;
    Bytes encoded, decoded;
    std::string name;
};

std::vector<OracleStream> read_streams(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const Bytes all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<OracleStream> out;
    std::size_t at = 0;
    const auto u32 = [&]() {
        std::uint32_t v = 0;
        if (at + 4 <= all.size()) std::memcpy(&v, all.data() + at, 4);
        at += 4;
        return v;
    };
    const auto bytes = [&](std::uint32_t n) {
        Bytes b;
        if (at + n <= all.size())
            b.assign(all.begin() + std::ptrdiff_t(at), all.begin() + std::ptrdiff_t(at + n));
        at += n;
        return b;
    };
    while (at < all.size()) {
        OracleStream s;
        s.mode = u32(), s.filter = u32(), s.count = u32(), s.stride = u32();
        s.encoded = bytes(u32());
        s.decoded = bytes(u32());
        const Bytes name = bytes(u32());
        s.name.assign(name.begin(), name.end());
        out.push_back(std::move(s));
    }
    return out;
}

// The largest difference between two outputs, per component of the filter's width
// (signed for OCTAHEDRAL and QUATERNION, unsigned for COLOR, raw bytes otherwise).
long largest_difference(const OracleStream& s, const Bytes& ours) {
    const std::size_t width = s.filter == 0 || s.filter == 3 ? 1 : s.stride / 4;
    long worst = 0;
    for (std::size_t i = 0; i + width <= ours.size(); i += width) {
        long a = 0, b = 0;
        if (width == 1 && (s.filter == 1))
            a = std::int8_t(ours[i]), b = std::int8_t(s.decoded[i]);
        else if (width == 1)
            a = ours[i], b = s.decoded[i];
        else if (s.filter == 4)
            a = ours[i] | ours[i + 1] << 8, b = s.decoded[i] | s.decoded[i + 1] << 8;
        else
            a = std::int16_t(ours[i] | ours[i + 1] << 8),
            b = std::int16_t(s.decoded[i] | s.decoded[i + 1] << 8);
        worst = std::max(worst, std::abs(a - b));
    }
    return worst;
}

TEST(MeshoptOracle, EveryStreamDecodesAsTheNpmDecoderDoes) {
    const std::vector<OracleStream> streams = read_streams(SHERPA_MESHOPT_ORACLE_STREAMS);
    ASSERT_GT(streams.size(), 1000u) << "run the meshopt_oracle_streams fixture (ctest)";
    std::size_t v1 = 0, corpus_v1 = 0, exact = 0, within_ulp = 0;
    bool khr_duck = false;
    for (const OracleStream& s : streams) {
        Bytes ours(s.decoded.size());
        const mo::Result r =
            s.mode == 0   ? mo::decode_vertex_buffer(ours, s.count, s.stride, s.encoded)
            : s.mode == 1 ? mo::decode_index_buffer(ours, s.count, s.stride, s.encoded)
                          : mo::decode_index_sequence(ours, s.count, s.stride, s.encoded);
        ASSERT_TRUE(r) << s.name << ": " << mo::describe(r.status) << " at byte " << r.offset;
        ASSERT_TRUE(mo::apply_filter(mo::Filter(s.filter), ours, s.count, s.stride)) << s.name;
        if (s.mode == 0 && r.version == 1) {
            ++v1;
            if (s.name.find("bufferViews") != std::string::npos) ++corpus_v1;
        }
        khr_duck |= s.name.starts_with("Duck.khr_meshopt.glb");
        if (ours == s.decoded) {
            ++exact;
            continue;
        }
        const long worst = largest_difference(s, ours);
        // Filters 1, 2 and 4 may round one unit apart; EXPONENTIAL and raw data never.
        ASSERT_TRUE(s.filter == 1 || s.filter == 2 || s.filter == 4) << s.name << ": bytes differ";
        EXPECT_LE(worst, 1) << s.name;
        ++within_ulp;
    }
    EXPECT_TRUE(khr_duck) << "Duck.khr_meshopt.glb's streams are not in the oracle's file";
    EXPECT_GT(corpus_v1, 0u) << "no version 1 stream from gltfpack's corpus";
    EXPECT_GT(v1, 1000u);
    std::cout << streams.size() << " streams (" << v1 << " vertex version 1, " << corpus_v1
              << " of them gltfpack's): " << exact << " byte-identical, " << within_ulp
              << " filtered within one unit\n";
}

} // namespace
