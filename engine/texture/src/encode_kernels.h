#pragma once
// Inner loops shared by the BC7 and BC5 encoders. This header is included only by
// the per-instruction-set translation units (encode_bc7.cpp, encode_bc5.cpp), each
// compiled several times with different -m flags into a namespace named by
// SHERPA_KERNEL_NS, so every function here exists once per instruction set and the
// linker can never mix them up.
#include <cstdint>
#include <cstring>

#if defined(__AVX512F__) || defined(__AVX2__)
#include <immintrin.h>
#endif

#ifndef SHERPA_KERNEL_NS
#error "SHERPA_KERNEL_NS must name the instruction-set namespace"
#endif

namespace sherpa::tex::SHERPA_KERNEL_NS {

// 16 texels as floats in 0..255, one row per channel (structure of arrays, so one
// AVX-512 register holds a channel of the whole block).
struct alignas(64) Texels {
    float ch[4][16];
};

// Up to 16 candidate colours (palette entries) of one subset, channel-major.
struct alignas(64) Palette {
    float ch[4][16];
    int count = 0;
};

inline Texels load_texels(const std::uint8_t rgba[64]) {
    Texels t;
    for (int i = 0; i < 16; ++i)
        for (int c = 0; c < 4; ++c) t.ch[c][i] = static_cast<float>(rgba[i * 4 + c]);
    return t;
}

// For each texel whose bit is set in `mask`, picks the nearest palette entry over
// the first `channels` channels (squared distance). Writes the index for masked
// texels only and returns the summed squared error over them.
#if defined(__AVX512F__)
inline float select_indices(const Texels& t, std::uint32_t mask, const Palette& p, int channels,
                            std::uint8_t idx[16]) {
    __m512 best = _mm512_set1_ps(3.0e38f);
    __m512i best_i = _mm512_setzero_si512();
    __m512 x[4];
    for (int c = 0; c < channels; ++c) x[c] = _mm512_load_ps(t.ch[c]);
    for (int k = 0; k < p.count; ++k) {
        __m512 d = _mm512_sub_ps(x[0], _mm512_set1_ps(p.ch[0][k]));
        __m512 e = _mm512_mul_ps(d, d);
        for (int c = 1; c < channels; ++c) {
            d = _mm512_sub_ps(x[c], _mm512_set1_ps(p.ch[c][k]));
            e = _mm512_fmadd_ps(d, d, e);
        }
        const __mmask16 better = _mm512_cmp_ps_mask(e, best, _CMP_LT_OQ);
        best = _mm512_mask_mov_ps(best, better, e);
        best_i = _mm512_mask_mov_epi32(best_i, better, _mm512_set1_epi32(k));
    }
    alignas(64) std::int32_t chosen[16];
    alignas(64) float err[16];
    _mm512_store_si512(chosen, best_i);
    _mm512_store_ps(err, best);
    float total = 0.0f;
    for (int i = 0; i < 16; ++i)
        if (mask >> i & 1u) idx[i] = static_cast<std::uint8_t>(chosen[i]), total += err[i];
    return total;
}
#elif defined(__AVX2__)
inline float select_indices(const Texels& t, std::uint32_t mask, const Palette& p, int channels,
                            std::uint8_t idx[16]) {
    float total = 0.0f;
    for (int half = 0; half < 2; ++half) {
        __m256 best = _mm256_set1_ps(3.0e38f);
        __m256i best_i = _mm256_setzero_si256();
        __m256 x[4];
        for (int c = 0; c < channels; ++c) x[c] = _mm256_load_ps(t.ch[c] + half * 8);
        for (int k = 0; k < p.count; ++k) {
            __m256 d = _mm256_sub_ps(x[0], _mm256_set1_ps(p.ch[0][k]));
            __m256 e = _mm256_mul_ps(d, d);
            for (int c = 1; c < channels; ++c) {
                d = _mm256_sub_ps(x[c], _mm256_set1_ps(p.ch[c][k]));
                e = _mm256_fmadd_ps(d, d, e);
            }
            const __m256 better = _mm256_cmp_ps(e, best, _CMP_LT_OQ);
            best = _mm256_blendv_ps(best, e, better);
            best_i = _mm256_castps_si256(_mm256_blendv_ps(
                _mm256_castsi256_ps(best_i), _mm256_castsi256_ps(_mm256_set1_epi32(k)), better));
        }
        alignas(32) float err[8];
        alignas(32) std::int32_t chosen[8];
        _mm256_store_ps(err, best);
        _mm256_store_si256(reinterpret_cast<__m256i*>(chosen), best_i);
        for (int i = 0; i < 8; ++i) {
            const int texel = half * 8 + i;
            if (mask >> texel & 1u) {
                idx[texel] = static_cast<std::uint8_t>(chosen[i]);
                total += err[i];
            }
        }
    }
    return total;
}
#else
inline float select_indices(const Texels& t, std::uint32_t mask, const Palette& p, int channels,
                            std::uint8_t idx[16]) {
    float total = 0.0f;
    for (int i = 0; i < 16; ++i) {
        if (!(mask >> i & 1u)) continue;
        float best = 3.0e38f;
        int best_k = 0;
        for (int k = 0; k < p.count; ++k) {
            float e = 0.0f;
            for (int c = 0; c < channels; ++c) {
                const float d = t.ch[c][i] - p.ch[c][k];
                e += d * d;
            }
            if (e < best) best = e, best_k = k;
        }
        idx[i] = static_cast<std::uint8_t>(best_k);
        total += best;
    }
    return total;
}
#endif

// Texel membership as 0/1 weights, so the loops below have no branches and the
// compiler vectorises them across the 16 texels.
struct alignas(64) MaskWeights {
    float w[16];
    explicit MaskWeights(std::uint32_t mask) {
        for (int i = 0; i < 16; ++i) w[i] = static_cast<float>((mask >> i) & 1u);
    }
};

// Least-squares endpoints for fixed interpolation weights: minimises
// sum |(1 - w_i) e0 + w_i e1 - x_i|^2 over the masked texels. Returns false when
// the weights are all equal (the system is singular); endpoints are unchanged then.
template <int channels>
inline bool solve_endpoints(const Texels& t, std::uint32_t mask, const std::uint8_t idx[16],
                            const std::uint8_t* weights, float e0[4], float e1[4]) {
    const MaskWeights m(mask);
    alignas(64) float wb[16], wa[16];
    for (int i = 0; i < 16; ++i) {
        const float w = static_cast<float>(weights[idx[i] & 15]) * (1.0f / 64.0f);
        wb[i] = w * m.w[i];
        wa[i] = (1.0f - w) * m.w[i];
    }
    float aa = 0, ab = 0, bb = 0;
    for (int i = 0; i < 16; ++i) aa += wa[i] * wa[i], ab += wa[i] * wb[i], bb += wb[i] * wb[i];
    float ax[4] = {0, 0, 0, 0}, bx[4] = {0, 0, 0, 0};
    for (int c = 0; c < channels; ++c)
        for (int i = 0; i < 16; ++i) ax[c] += wa[i] * t.ch[c][i], bx[c] += wb[i] * t.ch[c][i];
    const float det = aa * bb - ab * ab;
    if (det < 1e-6f) return false;
    const float inv = 1.0f / det;
    for (int c = 0; c < channels; ++c) {
        const float v0 = (bb * ax[c] - ab * bx[c]) * inv;
        const float v1 = (aa * bx[c] - ab * ax[c]) * inv;
        e0[c] = v0 < 0.0f ? 0.0f : (v0 > 255.0f ? 255.0f : v0);
        e1[c] = v1 < 0.0f ? 0.0f : (v1 > 255.0f ? 255.0f : v1);
    }
    return true;
}

// Endpoints along the principal axis of the masked texels: the mean plus the
// extreme projections. The axis comes from a few power iterations on the
// covariance, started from the bounding-box diagonal.
template <int channels>
inline void principal_endpoints(const Texels& t, std::uint32_t mask, float e0[4], float e1[4]) {
    const MaskWeights m(mask);
    float n = 0.0f;
    for (int i = 0; i < 16; ++i) n += m.w[i];
    float mean[4] = {0, 0, 0, 0}, lo[4] = {0, 0, 0, 0}, hi[4] = {0, 0, 0, 0};
    alignas(64) float d[4][16];
    for (int c = 0; c < channels; ++c) {
        float sum = 0.0f, mn = 255.0f, mx = 0.0f;
        for (int i = 0; i < 16; ++i) {
            const float v = t.ch[c][i];
            sum += v * m.w[i];
            // Texels outside the subset are pushed out of the min/max race.
            const float up = v + (1.0f - m.w[i]) * 1024.0f, down = v - (1.0f - m.w[i]) * 1024.0f;
            mn = up < mn ? up : mn;
            mx = down > mx ? down : mx;
        }
        mean[c] = sum / n, lo[c] = mn, hi[c] = mx;
        for (int i = 0; i < 16; ++i) d[c][i] = (t.ch[c][i] - mean[c]) * m.w[i];
    }
    float cov[4][4] = {};
    for (int a = 0; a < channels; ++a)
        for (int b = a; b < channels; ++b) {
            float s = 0.0f;
            for (int i = 0; i < 16; ++i) s += d[a][i] * d[b][i];
            cov[a][b] = cov[b][a] = s;
        }
    float axis[4];
    for (int c = 0; c < channels; ++c) axis[c] = hi[c] - lo[c];
    // Orient the diagonal by the sign of the covariance with the widest channel, so
    // anti-correlated channels start on the right diagonal.
    int widest = 0;
    for (int c = 1; c < channels; ++c)
        if (cov[c][c] > cov[widest][widest]) widest = c;
    for (int c = 0; c < channels; ++c)
        if (cov[widest][c] < 0.0f) axis[c] = -axis[c];
    for (int iter = 0; iter < 3; ++iter) {
        float next[4] = {0, 0, 0, 0}, len = 0.0f;
        for (int a = 0; a < channels; ++a) {
            for (int b = 0; b < channels; ++b) next[a] += cov[a][b] * axis[b];
            const float mag = next[a] < 0.0f ? -next[a] : next[a];
            len = mag > len ? mag : len;
        }
        if (len < 1e-9f) break;
        for (int c = 0; c < channels; ++c) axis[c] = next[c] / len;
    }
    float norm2 = 0.0f;
    for (int c = 0; c < channels; ++c) norm2 += axis[c] * axis[c];
    float tmin = 0.0f, tmax = 0.0f;
    if (norm2 > 1e-12f) {
        tmin = 3.0e38f, tmax = -3.0e38f;
        for (int i = 0; i < 16; ++i) {
            float s = 0.0f;
            for (int c = 0; c < channels; ++c) s += d[c][i] * axis[c];
            // Masked-out texels project to 0, which lies inside [tmin, tmax] anyway
            // because the mean is inside the subset's extent.
            tmin = s < tmin ? s : tmin;
            tmax = s > tmax ? s : tmax;
        }
        tmin /= norm2, tmax /= norm2;
    }
    for (int c = 0; c < channels; ++c) {
        const float a = mean[c] + tmin * axis[c], b = mean[c] + tmax * axis[c];
        e0[c] = a < 0.0f ? 0.0f : (a > 255.0f ? 255.0f : a);
        e1[c] = b < 0.0f ? 0.0f : (b > 255.0f ? 255.0f : b);
    }
}

} // namespace sherpa::tex::SHERPA_KERNEL_NS
