// Batch culling over structure-of-arrays boxes: scalar reference kernels and
// AVX2 / AVX-512 p-vertex kernels chosen at run time.
#include <sherpa/scene/culling.h>

#include <algorithm>
#include <cmath>
#include <immintrin.h>
#include <limits>

namespace sherpa::scene {

void BoxesSoA::assign(std::span<const core::Aabb> boxes) {
    for (auto* v : {&min_x, &min_y, &min_z, &max_x, &max_y, &max_z}) v->resize(boxes.size());
    invalid.clear();
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        glm::vec3 lo = boxes[i].min, hi = boxes[i].max;
        if (!boxes[i].valid() || box_is_invalid(lo, hi)) {
            invalid.push_back(static_cast<std::uint32_t>(i));
            lo = hi = glm::vec3(0.0f); // kernels see a harmless point; the result is overridden
        }
        min_x[i] = lo.x, min_y[i] = lo.y, min_z[i] = lo.z;
        max_x[i] = hi.x, max_y[i] = hi.y, max_z[i] = hi.z;
    }
    const std::size_t block_count = (boxes.size() + kBlock - 1) / kBlock;
    for (auto* v : {&block_min_x, &block_min_y, &block_min_z})
        v->assign(block_count, std::numeric_limits<float>::infinity());
    for (auto* v : {&block_max_x, &block_max_y, &block_max_z})
        v->assign(block_count, -std::numeric_limits<float>::infinity());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const std::size_t k = i / kBlock;
        block_min_x[k] = std::min(block_min_x[k], min_x[i]);
        block_min_y[k] = std::min(block_min_y[k], min_y[i]);
        block_min_z[k] = std::min(block_min_z[k], min_z[i]);
        block_max_x[k] = std::max(block_max_x[k], max_x[i]);
        block_max_y[k] = std::max(block_max_y[k], max_y[i]);
        block_max_z[k] = std::max(block_max_z[k], max_z[i]);
    }
}

namespace detail {
namespace {

// Per plane, the p-vertex reads max or min along each axis by the normal's sign:
// choose the arrays once per plane so the inner loop is branch-free.
struct PlaneArrays {
    const float *x, *y, *z;
    float nx, ny, nz, d;
    bool x_max, y_max, z_max; // the p-vertex reads max (else min) on that axis
};

std::uint32_t plane_arrays(const Frustum& f, const BoxesSoA& b, PlaneArrays* out) {
    for (std::uint32_t i = 0; i < f.plane_count; ++i) {
        const Plane& p = f.planes[i];
        const bool x_max = p.normal.x >= 0, y_max = p.normal.y >= 0, z_max = p.normal.z >= 0;
        out[i] = {x_max ? b.max_x.data() : b.min_x.data(),
                  y_max ? b.max_y.data() : b.min_y.data(),
                  z_max ? b.max_z.data() : b.min_z.data(),
                  p.normal.x,
                  p.normal.y,
                  p.normal.z,
                  p.d,
                  x_max,
                  y_max,
                  z_max};
    }
    return f.plane_count;
}

} // namespace

std::size_t pvertex_scalar(const Frustum& f, const BoxesSoA& b, std::size_t begin, std::size_t end,
                           std::uint8_t* out) {
    PlaneArrays pa[6];
    const std::uint32_t n = plane_arrays(f, b, pa);
    std::size_t visible = 0;
    for (std::size_t i = begin; i < end; ++i) {
        bool inside = !f.empty;
        for (std::uint32_t k = 0; k < n; ++k)
            inside &=
                pa[k].nx * pa[k].x[i] + pa[k].ny * pa[k].y[i] + pa[k].nz * pa[k].z[i] + pa[k].d >=
                0.0f;
        out[i] = inside ? 1 : 0;
        visible += inside ? 1 : 0;
    }
    return visible;
}

__attribute__((target("avx2,fma,bmi2,popcnt"))) std::size_t
pvertex_avx2(const Frustum& f, const BoxesSoA& b, std::size_t begin, std::size_t end,
             std::uint8_t* out) {
    PlaneArrays pa[6];
    const std::uint32_t n = plane_arrays(f, b, pa);
    std::size_t i = begin, visible = 0;
    if (!f.empty)
        for (; i + 8 <= end; i += 8) {
            __m256 all = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
            for (std::uint32_t k = 0; k < n; ++k) {
                __m256 dist = _mm256_set1_ps(pa[k].d);
                dist =
                    _mm256_fmadd_ps(_mm256_set1_ps(pa[k].nx), _mm256_loadu_ps(pa[k].x + i), dist);
                dist =
                    _mm256_fmadd_ps(_mm256_set1_ps(pa[k].ny), _mm256_loadu_ps(pa[k].y + i), dist);
                dist =
                    _mm256_fmadd_ps(_mm256_set1_ps(pa[k].nz), _mm256_loadu_ps(pa[k].z + i), dist);
                all = _mm256_and_ps(all, _mm256_cmp_ps(dist, _mm256_setzero_ps(), _CMP_GE_OQ));
                if (_mm256_testz_ps(all, all)) break; // all 8 outside: nothing left to test
            }
            const int mask = _mm256_movemask_ps(all);
            visible += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(mask)));
            // Spread 8 mask bits to 8 bytes of 0/1.
            const std::uint64_t bytes =
                _pdep_u64(static_cast<std::uint64_t>(mask), 0x0101010101010101ull);
            __builtin_memcpy(out + i, &bytes, 8);
        }
    return visible + pvertex_scalar(f, b, i, end, out);
}

namespace {

// Signed distance of 16 corners to plane p: the corner takes max (else min) on each
// axis where `max_x/y/z` says so. arrays: min x, y, z, max x, y, z at i.
__attribute__((target("avx512f,avx512bw,avx512vl,bmi2,popcnt"))) inline __m512
corner_distance16(const PlaneArrays& p, const float* const* arrays, std::size_t i, bool max_x,
                  bool max_y, bool max_z) {
    __m512 dist = _mm512_set1_ps(p.d);
    dist = _mm512_fmadd_ps(_mm512_set1_ps(p.nx), _mm512_loadu_ps(arrays[max_x ? 3 : 0] + i), dist);
    dist = _mm512_fmadd_ps(_mm512_set1_ps(p.ny), _mm512_loadu_ps(arrays[max_y ? 4 : 1] + i), dist);
    return _mm512_fmadd_ps(_mm512_set1_ps(p.nz), _mm512_loadu_ps(arrays[max_z ? 5 : 2] + i), dist);
}

// p-vertex test of 16 boxes (or 16 block bounds) at i: bit j set where box i + j
// passes every plane. With `wholly_inside`, also the n-vertex test: bit j set where
// the whole box is inside every plane. Stops once all 16 have failed a plane.
__attribute__((target("avx512f,avx512bw,avx512vl,bmi2,popcnt"))) inline __mmask16
pvertex16(const PlaneArrays* pa, std::uint32_t n, const float* const* arrays, std::size_t i,
          __mmask16* wholly_inside) {
    const __m512 zero = _mm512_setzero_ps();
    __mmask16 all = 0xFFFF, inside = 0xFFFF;
    for (std::uint32_t k = 0; k < n; ++k) {
        const PlaneArrays& p = pa[k];
        all = _mm512_mask_cmp_ps_mask(
            all, corner_distance16(p, arrays, i, p.x_max, p.y_max, p.z_max), zero, _CMP_GE_OQ);
        if (wholly_inside)
            inside = _mm512_mask_cmp_ps_mask(
                inside, corner_distance16(p, arrays, i, !p.x_max, !p.y_max, !p.z_max), zero,
                _CMP_GE_OQ);
        if (all == 0) break; // all 16 outside: the other planes cannot change that
    }
    if (wholly_inside) *wholly_inside = inside & all;
    return all;
}

// Bit j of a 16-box verdict to out[j] as 0/1; returns the number visible.
__attribute__((target("avx512f,avx512bw,avx512vl,bmi2,popcnt"))) inline std::size_t
store16(std::uint8_t* out, __mmask16 verdict) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_maskz_set1_epi8(verdict, 1));
    return static_cast<std::size_t>(__builtin_popcount(verdict));
}

} // namespace

// Blocks of 16 boxes are first decided 16 at a time from their bounds, with the same
// fused multiply-adds: rounding is monotonic, so a box inside a block's bounds never
// gets a larger p-vertex distance than the bounds' p-vertex, nor a smaller one than
// the bounds' n-vertex. A block outside some plane is all culled, one inside every
// plane all visible, exactly as the per-box test would decide; the rest are tested
// box by box.
__attribute__((target("avx512f,avx512bw,avx512vl,bmi2,popcnt"))) std::size_t
pvertex_avx512(const Frustum& f, const BoxesSoA& b, std::size_t begin, std::size_t end,
               std::uint8_t* out) {
    static_assert(BoxesSoA::kBlock == 16, "one block per AVX-512 vector");
    PlaneArrays pa[6];
    const std::uint32_t n = plane_arrays(f, b, pa);
    const float* boxes[6] = {b.min_x.data(), b.min_y.data(), b.min_z.data(),
                             b.max_x.data(), b.max_y.data(), b.max_z.data()};
    const float* blocks[6] = {b.block_min_x.data(), b.block_min_y.data(), b.block_min_z.data(),
                              b.block_max_x.data(), b.block_max_y.data(), b.block_max_z.data()};
    const bool have_blocks =
        b.block_min_x.size() == (b.size() + BoxesSoA::kBlock - 1) / BoxesSoA::kBlock;
    std::size_t i = begin, visible = 0;
    if (f.empty) return pvertex_scalar(f, b, i, end, out);
    while (i + 16 <= end) {
        if (have_blocks && i % 256 == 0 && i + 256 <= end) {
            __mmask16 inside = 0;
            const __mmask16 some = pvertex16(pa, n, blocks, i / 16, &inside);
            for (std::uint32_t j = 0; j < 16; ++j, i += 16) {
                if (!((some >> j) & 1u)) // block outside a plane
                    visible += store16(out + i, 0);
                else if ((inside >> j) & 1u) // block inside every plane
                    visible += store16(out + i, 0xFFFF);
                else
                    visible += store16(out + i, pvertex16(pa, n, boxes, i, nullptr));
            }
            continue;
        }
        visible += store16(out + i, pvertex16(pa, n, boxes, i, nullptr));
        i += 16;
    }
    return visible + pvertex_scalar(f, b, i, end, out);
}

} // namespace detail

namespace {

std::size_t sphere_range(const Frustum& f, const BoxesSoA& b, std::size_t begin, std::size_t end,
                         std::uint8_t* out) {
    std::size_t visible = 0;
    for (std::size_t i = begin; i < end; ++i) {
        out[i] = sphere_visible(f, b.box(i)) ? 1 : 0;
        visible += out[i];
    }
    return visible;
}

std::size_t run_range(const Frustum& f, const BoxesSoA& b, CullMethod method, core::SimdLevel level,
                      std::size_t begin, std::size_t end, std::uint8_t* out) {
    if (method == CullMethod::Sphere) return sphere_range(f, b, begin, end, out);
    std::size_t visible = 0;
    switch (level) {
    case core::SimdLevel::Avx512:
        visible = detail::pvertex_avx512(f, b, begin, end, out);
        break;
    case core::SimdLevel::Avx2:
        visible = detail::pvertex_avx2(f, b, begin, end, out);
        break;
    default:
        visible = detail::pvertex_scalar(f, b, begin, end, out);
        break;
    }
    if (method == CullMethod::Exact) // the exact test only refines p-vertex survivors
        for (std::size_t i = begin; i < end; ++i)
            if (out[i] && !exact_visible(f, b.box(i))) {
                out[i] = 0;
                --visible;
            }
    return visible;
}

} // namespace

CullCounts cull_boxes(const Frustum& f, const BoxesSoA& boxes, CullMethod method,
                      core::SimdLevel level, std::span<std::uint8_t> visible, int threads) {
    const std::size_t n = boxes.size();
    level = std::min(level, core::best_simd_level());
    std::size_t count = 0;
    if (threads > 1 && n > 4096) {
        const auto chunks = static_cast<std::int64_t>((n + 4095) / 4096);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 4) reduction(+ : count)
        for (std::int64_t c = 0; c < chunks; ++c) {
            const std::size_t begin = static_cast<std::size_t>(c) * 4096;
            count += run_range(f, boxes, method, level, begin, std::min(n, begin + 4096),
                               visible.data());
        }
    } else {
        count = run_range(f, boxes, method, level, 0, n, visible.data());
    }
    // Invalid boxes were stored as a point at the origin; they are kept regardless.
    for (std::uint32_t i : boxes.invalid) {
        count += visible[i] ? 0 : 1;
        visible[i] = 1;
    }
    CullCounts counts;
    counts.tested = n;
    counts.invalid = boxes.invalid.size();
    counts.visible = count;
    counts.culled = n - count;
    return counts;
}

} // namespace sherpa::scene
