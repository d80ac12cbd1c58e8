// A primitive's streams through KHR_mesh_quantization's encodings and meshoptimizer's
// codecs (see mesh_codec.h).
#include "mesh_codec.h"

#include <sherpa/lab/quantize.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <meshoptimizer.h>

namespace sherpa::lab::detail {
namespace {

std::uint64_t pad4(std::uint64_t bytes) {
    return (bytes + 3u) & ~std::uint64_t(3);
}

// `n` elements of `comps` components written as T, each element padded to 4 bytes:
// the layout stream_stride() counts.
template <typename T, typename Get>
std::vector<std::uint8_t> pack(std::size_t n, int comps, Get get) {
    const std::size_t stride = pad4(std::size_t(comps) * sizeof(T));
    std::vector<std::uint8_t> out(n * stride, 0);
    for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < comps; ++a) {
            const T v = T(get(i, a));
            std::memcpy(&out[i * stride + std::size_t(a) * sizeof(T)], &v, sizeof(T));
        }
    return out;
}

// Floats, or the integer type the bit count needs (Small up to 8 bits, else Large).
template <typename Small, typename Large, typename Get>
std::vector<std::uint8_t> pack_bits(int bits, std::size_t n, int comps, Get get) {
    if (bits == 0) return pack<float>(n, comps, get);
    return bits <= 8 ? pack<Small>(n, comps, get) : pack<Large>(n, comps, get);
}

// The index codec may rotate a triangle's corners (keeping its winding).
bool same_elements(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b,
                   bool triangles) {
    if (!triangles || a.size() != b.size()) return a == b;
    for (std::size_t t = 0; t + 2 < a.size(); t += 3) {
        bool match = false;
        for (std::size_t r = 0; r < 3 && !match; ++r)
            match = a[t] == b[t + r] && a[t + 1] == b[t + (r + 1) % 3] &&
                    a[t + 2] == b[t + (r + 2) % 3];
        if (!match) return false;
    }
    return true;
}

// Sums the bytes of the streams and, with meshopt, encodes and decodes each one.
class Buffers {
public:
    explicit Buffers(bool meshopt) : meshopt_(meshopt) {}
    void vertex_stream(const std::vector<std::uint8_t>& stream, std::size_t n) {
        if (!meshopt_ || n == 0) {
            vertex_bytes += pad4(stream.size());
            return;
        }
        const std::size_t stride = stream.size() / n;
        std::vector<std::uint8_t> encoded(meshopt_encodeVertexBufferBound(n, stride));
        encoded.resize(
            meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), stream.data(), n, stride));
        std::vector<std::uint8_t> back(stream.size());
        if (encoded.empty() ||
            meshopt_decodeVertexBuffer(back.data(), n, stride, encoded.data(), encoded.size()) !=
                0 ||
            back != stream)
            error =
                "meshopt vertex codec round trip failed (stride " + std::to_string(stride) + ")";
        vertex_bytes += pad4(encoded.size());
    }
    void indices(const std::vector<std::uint32_t>& idx, std::size_t vertices, bool triangles) {
        if (!meshopt_) {
            index_bytes += pad4(idx.size() * (vertices <= 65536 ? 2u : 4u));
            return;
        }
        const bool list = triangles && idx.size() % 3 == 0;
        std::vector<std::uint8_t> encoded(
            list ? meshopt_encodeIndexBufferBound(idx.size(), vertices)
                 : meshopt_encodeIndexSequenceBound(idx.size(), vertices));
        encoded.resize(
            list ? meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), idx.data(), idx.size())
                 : meshopt_encodeIndexSequence(encoded.data(), encoded.size(), idx.data(),
                                               idx.size()));
        std::vector<std::uint32_t> back(idx.size());
        const int rc = list ? meshopt_decodeIndexBuffer(back.data(), back.size(), 4, encoded.data(),
                                                        encoded.size())
                            : meshopt_decodeIndexSequence(back.data(), back.size(), 4,
                                                          encoded.data(), encoded.size());
        if (rc != 0 || !same_elements(back, idx, list))
            error = "meshopt index codec round trip failed";
        index_bytes += pad4(encoded.size());
    }
    std::uint64_t vertex_bytes = 0, index_bytes = 0;
    std::string error;

private:
    bool meshopt_;
};

// xyz renormalized as a shader does; counts the vectors quantized to zero.
template <int N> void renormalize(std::vector<glm::vec<N, float>>& out, EncodedMesh& e) {
    for (auto& v : out) {
        const float len = glm::length(glm::vec3(v));
        if (!(len > 0.0f)) {
            ++e.zero_normals;
            continue;
        }
        for (int a = 0; a < 3; ++a) v[a] /= len;
    }
}

// Unit vectors (normals: 3 components, tangents: xyz and the handedness w) through
// meshopt's OCTAHEDRAL filter: x/y in `bits` on the octahedron, stored as 8-bit (bits
// <= 8, 4 bytes) or 16-bit components with z = 1 and w, as EXT_meshopt_compression
// carries them; decoded with meshopt_decodeFilterOct. Non-finite input becomes +Z.
template <int N>
std::vector<std::uint8_t> octahedral_stream(const std::vector<glm::vec<N, float>>& in, int bits,
                                            std::vector<glm::vec<N, float>>& out, EncodedMesh& e) {
    const std::size_t n = in.size(), stride = bits <= 8 ? 4 : 8;
    std::vector<float> four(n * 4, 0.0f);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 xyz(in[i]);
        const bool ok = std::isfinite(xyz.x) && std::isfinite(xyz.y) && std::isfinite(xyz.z);
        e.nonfinite_values += !ok;
        const glm::vec3 v = ok ? xyz : glm::vec3(0, 0, 1);
        four[i * 4] = v.x, four[i * 4 + 1] = v.y, four[i * 4 + 2] = v.z;
        if constexpr (N == 4) four[i * 4 + 3] = std::isfinite(in[i].w) ? in[i].w : 1.0f;
    }
    std::vector<std::uint8_t> filtered(n * stride);
    meshopt_encodeFilterOct(filtered.data(), n, stride, bits, four.data());
    std::vector<std::uint8_t> back = filtered;
    meshopt_decodeFilterOct(back.data(), n, stride);
    out = in;
    for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < N; ++a) {
            float c = 0.0f;
            if (stride == 4) {
                c = float(std::int8_t(back[i * 4 + std::size_t(a)])) / 127.0f;
            } else {
                std::int16_t s = 0;
                std::memcpy(&s, &back[i * 8 + std::size_t(a) * 2], 2);
                c = float(s) / 32767.0f;
            }
            out[i][a] = std::max(c, -1.0f);
        }
    renormalize(out, e);
    return filtered;
}

// Unit vectors through signed normalized integers per component.
template <int N>
std::vector<std::uint8_t> snorm_stream(const std::vector<glm::vec<N, float>>& in, int bits,
                                       std::vector<glm::vec<N, float>>& out, EncodedMesh& e) {
    out = in;
    if (bits == 0) return pack<float>(in.size(), N, [&](std::size_t i, int a) { return in[i][a]; });
    const std::span<const float> flat(&in[0][0], in.size() * N);
    std::vector<std::int16_t> codes(flat.size());
    e.nonfinite_values += std::uint64_t(quantize_snorm(flat, bits, codes));
    dequantize_snorm(codes, bits, std::span<float>(&out[0][0], flat.size()));
    renormalize(out, e);
    return pack_bits<std::int8_t, std::int16_t>(
        bits, in.size(), N, [&](std::size_t i, int a) { return codes[i * N + std::size_t(a)]; });
}

// The normal or tangent stream the preset asks for.
template <int N>
std::vector<std::uint8_t> unit_stream(const std::vector<glm::vec<N, float>>& in,
                                      const QuantizationPreset& p,
                                      std::vector<glm::vec<N, float>>& out, EncodedMesh& e) {
    return p.octahedral && p.normal != 0 ? octahedral_stream<N>(in, p.normal, out, e)
                                         : snorm_stream<N>(in, p.normal, out, e);
}

std::vector<std::uint8_t> uv_stream(const std::vector<glm::vec2>& in, int bits,
                                    std::vector<glm::vec2>& out, EncodedMesh& e) {
    out = in;
    UvGrid grid;
    if (bits == 0 || uv_grid(in, bits, grid) != GridStatus::Ok)
        return pack<float>(in.size(), 2, [&](std::size_t i, int a) { return in[i][a]; });
    std::vector<glm::u16vec2> codes(in.size());
    e.nonfinite_values += quantize_uvs(in, grid, codes);
    dequantize_uvs(codes, grid, out);
    return pack_bits<std::uint8_t, std::uint16_t>(
        bits, in.size(), 2, [&](std::size_t i, int a) { return codes[i][a]; });
}

} // namespace

EncodedMesh encode_mesh(const MeshStreams& in, const QuantizationPreset& preset) {
    EncodedMesh e;
    Buffers buffers(preset.meshopt);
    const std::size_t n = in.position.size();
    MeshStreams& out = e.decoded;
    out.position = in.position;
    PositionGrid grid;
    if (preset.position != 0 &&
        position_grid(in.position, preset.position, grid) == GridStatus::Ok) {
        std::vector<glm::u16vec3> codes(n);
        e.nonfinite_values += quantize_positions(in.position, grid, codes);
        dequantize_positions(codes, grid, out.position);
        e.position_step = grid.step;
        buffers.vertex_stream(
            pack_bits<std::uint8_t, std::uint16_t>(
                preset.position, n, 3, [&](std::size_t i, int a) { return codes[i][a]; }),
            n);
    } else {
        buffers.vertex_stream(
            pack<float>(n, 3, [&](std::size_t i, int a) { return in.position[i][a]; }), n);
    }
    if (!in.normal.empty())
        buffers.vertex_stream(unit_stream<3>(in.normal, preset, out.normal, e), n);
    if (!in.tangent.empty())
        buffers.vertex_stream(unit_stream<4>(in.tangent, preset, out.tangent, e), n);
    if (!in.uv0.empty()) buffers.vertex_stream(uv_stream(in.uv0, preset.uv, out.uv0, e), n);
    if (!in.uv1.empty()) buffers.vertex_stream(uv_stream(in.uv1, preset.uv, out.uv1, e), n);
    buffers.indices(in.indices, n, in.triangles);
    e.vertex_bytes = buffers.vertex_bytes, e.index_bytes = buffers.index_bytes;
    e.codec_error = buffers.error;
    return e;
}

} // namespace sherpa::lab::detail
