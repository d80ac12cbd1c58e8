// The data pass's min/max check (validate_data.cpp runs it per accessor): per-component
// bounds of each accessor's values against its declared min and max, and the summaries
// a use's pass shares with it (triangle indices, normals: their bytes read once).
#include "validate_internal.h"

#include "validate_kernels.h"
#include "validate_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace sherpa::scene::detail {
namespace {

// Per-component bounds of the finite values, in the component type itself (one typed
// pass over the bytes; the data pass's hot loop). Returns the first non-finite
// component's flat index, or UINT64_MAX.
template <typename C, std::uint32_t N> bool scan_fixed(const Reader& r, double* lo, double* hi) {
    C l[N], h[N];
    if (!kernels::bounds<C, N>(r.base(), r.count(), r.stride(), l, h)) return false;
    for (std::uint32_t c = 0; c < N; ++c)
        lo[c] = static_cast<double>(l[c]), hi[c] = static_cast<double>(h[c]);
    return true;
}

template <typename C> std::uint64_t scan_bounds(const Reader& r, double* lo, double* hi) {
    const std::uint32_t n = r.components();
    // The common shapes in one typed pass; non-finite floats and other shapes below.
    if (r.count() > 0 &&
        ((n == 1 && scan_fixed<C, 1>(r, lo, hi)) || (n == 2 && scan_fixed<C, 2>(r, lo, hi)) ||
         (n == 3 && scan_fixed<C, 3>(r, lo, hi)) || (n == 4 && scan_fixed<C, 4>(r, lo, hi)) ||
         (n == 16 && scan_fixed<C, 16>(r, lo, hi))))
        return UINT64_MAX;
    C l[16], h[16];
    for (std::uint32_t c = 0; c < n; ++c) {
        l[c] = std::numeric_limits<C>::max();
        h[c] = std::numeric_limits<C>::lowest();
    }
    std::uint64_t first_bad = UINT64_MAX;
    bool seen[16] = {};
    const std::uint8_t* p = r.base();
    for (std::uint64_t i = 0; i < r.count(); ++i, p += r.stride())
        for (std::uint32_t c = 0; c < n; ++c) {
            C x;
            std::memcpy(&x, p + c * sizeof(C), sizeof(C));
            if constexpr (std::is_floating_point_v<C>) {
                if (!std::isfinite(x)) {
                    first_bad = std::min(first_bad, i * n + c);
                    continue;
                }
            }
            seen[c] = true;
            l[c] = std::min(l[c], x);
            h[c] = std::max(h[c], x);
        }
    for (std::uint32_t c = 0; c < n; ++c)
        if (seen[c]) lo[c] = static_cast<double>(l[c]), hi[c] = static_cast<double>(h[c]);
    return first_bad;
}

} // namespace

void summarize(const AccessorUsage& u, const Reader& r, int component_type, Summary& out) {
    if (u.use == AccessorUse::Indices && r.components() == 1) {
        const bool triangles = u.mode == 4;
        if (component_type == 5121)
            out.indices = kernels::summarize_indices<std::uint8_t>(r.base(), r.count(), r.stride(),
                                                                   triangles);
        else if (component_type == 5123)
            out.indices = kernels::summarize_indices<std::uint16_t>(r.base(), r.count(), r.stride(),
                                                                    triangles);
        else if (component_type == 5125)
            out.indices = kernels::summarize_indices<std::uint32_t>(r.base(), r.count(), r.stride(),
                                                                    triangles);
        else
            return;
        out.kind = Summary::Kind::Indices;
        out.triangles = triangles;
    } else if (u.use == AccessorUse::Normal && r.is_float() && r.components() == 3 &&
               r.stride() == 3 * sizeof(float)) {
        out.finite = kernels::unit_bounds(r.base(), r.count(), kernels::unit_band(kUnitTolerance),
                                          out.lo, out.hi, out.doubtful);
        out.kind = Summary::Kind::Normals;
    }
}

void check_min_max(Validation& v, std::size_t index, const Reader& r, const Summary& known) {
    const AccessorLayout& a = v.accessors[index];
    const Json& acc = v.array("accessors")[index];
    // Built only for a message (per accessor, allocations were a share of this check).
    auto where = [&] { return ptr("/accessors", index); };
    const std::uint32_t n = r.components();
    if (n == 0 || n > 16) return;
    double lo[16], hi[16];
    std::fill_n(lo, n, INFINITY);
    std::fill_n(hi, n, -INFINITY);
    std::uint64_t bad = UINT64_MAX;
    if (known.kind == Summary::Kind::Indices) {
        lo[0] = static_cast<double>(known.indices.low);
        hi[0] = static_cast<double>(known.indices.high);
    } else if (known.kind == Summary::Kind::Normals && known.finite) {
        for (std::uint32_t c = 0; c < 3; ++c) lo[c] = known.lo[c], hi[c] = known.hi[c];
    } else {
        switch (r.component_type()) {
        case 5120:
            bad = scan_bounds<std::int8_t>(r, lo, hi);
            break;
        case 5121:
            bad = scan_bounds<std::uint8_t>(r, lo, hi);
            break;
        case 5122:
            bad = scan_bounds<std::int16_t>(r, lo, hi);
            break;
        case 5123:
            bad = scan_bounds<std::uint16_t>(r, lo, hi);
            break;
        case 5125:
            bad = scan_bounds<std::uint32_t>(r, lo, hi);
            break;
        default:
            bad = scan_bounds<float>(r, lo, hi);
            break;
        }
    }
    if (bad != UINT64_MAX) {
        const double x = r.raw(bad / n, static_cast<std::uint32_t>(bad % n));
        v.add("ACCESSOR_INVALID_FLOAT", Severity::Error, where(),
              "Accessor element at index " + std::to_string(bad) + " is " +
                  (std::isnan(x) ? "NaN" : "Infinity") + ".");
    }
    auto same = [&](double declared, double actual) {
        return r.is_float() ? static_cast<float>(declared) == static_cast<float>(actual)
                            : declared == actual;
    };
    // Every value finite and inside both declared bounds: what the importer's range
    // check would find too (its values are these, normalized by a monotonic map).
    // The declared arrays, looked up once (has_min/has_max: present with n numbers).
    const Json* declared_min = a.has_min ? &acc["min"] : nullptr;
    const Json* declared_max = a.has_max ? &acc["max"] : nullptr;
    bool hold = bad == UINT64_MAX && declared_min && declared_max && !a.sparse;
    for (std::uint32_t c = 0; c < n && hold; ++c) {
        const Json& dmin = (*declared_min)[c];
        const Json& dmax = (*declared_max)[c];
        hold = dmin.is_number() && dmax.is_number() &&
               (lo[c] >= dmin.get<double>() || same(dmin.get<double>(), lo[c])) &&
               (hi[c] <= dmax.get<double>() || same(dmax.get<double>(), hi[c]));
    }
    if (hold && index < v.bounds_hold.size()) v.bounds_hold[index] = 1;
    for (int side = 0; side < 2; ++side) {
        const bool is_min = side == 0;
        if (!(is_min ? declared_min : declared_max)) continue;
        const Json& declared = *(is_min ? declared_min : declared_max);
        for (std::uint32_t c = 0; c < n; ++c) {
            if (!declared[c].is_number()) continue;
            const double d = declared[c].get<double>();
            const double actual = is_min ? lo[c] : hi[c];
            const bool mismatch = std::isfinite(actual) && !same(d, actual);
            if (!mismatch && bad == UINT64_MAX) continue; // no message: no pointer to build
            const std::string p = ptr(ptr(where(), is_min ? "min" : "max"), c);
            if (mismatch)
                v.add(is_min ? "ACCESSOR_MIN_MISMATCH" : "ACCESSOR_MAX_MISMATCH", Severity::Error,
                      p,
                      std::string("Declared ") + (is_min ? "minimum" : "maximum") +
                          " value for this component (" + std::to_string(d) +
                          ") does not match actual " + (is_min ? "minimum" : "maximum") + " (" +
                          std::to_string(actual) + ").");
            // Infinities are outside the bounds too (the finite bounds above leave them
            // out), as the Khronos validator counts them.
            if ((mismatch && (is_min ? actual < d : actual > d)) || bad != UINT64_MAX) {
                std::uint64_t outside = 0;
                for (std::uint64_t i = 0; i < r.count(); ++i) {
                    const double x = r.raw(i, c);
                    outside += is_min ? (x < d && !same(d, x)) : (x > d && !same(d, x));
                }
                if (outside)
                    v.add(is_min ? "ACCESSOR_ELEMENT_OUT_OF_MIN_BOUND"
                                 : "ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND",
                          Severity::Error, p,
                          "Accessor contains " + std::to_string(outside) + " element(s) " +
                              (is_min ? "less than declared minimum"
                                      : "greater than declared maximum") +
                              " value " + std::to_string(d) + ".");
            }
        }
    }
}

} // namespace sherpa::scene::detail
