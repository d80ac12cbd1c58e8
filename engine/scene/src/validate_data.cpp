// The data pass: accessor values against their declared min/max and against what
// each use requires (unit normals, index bounds, joint and weight sets, increasing key
// times, unit rotations). Reads the buffers tinygltf loaded; tolerances are the Khronos
// validator's so both report the same elements.
#include "validate_internal.h"

#include "checked_math.h"
#include "validate_kernels.h"
#include "validate_reader.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <unordered_map>

namespace sherpa::detail {
namespace {

// Per-component bounds of the finite values, in the component type itself (one typed
// pass over the bytes; the data pass's hot loop). Returns the first non-finite
// component's flat index, or UINT64_MAX.
template <typename C, std::uint32_t N>
bool scan_fixed(const Reader& r, std::vector<double>& lo, std::vector<double>& hi) {
    C l[N], h[N];
    if (!kernels::bounds<C, N>(r.base(), r.count(), r.stride(), l, h)) return false;
    for (std::uint32_t c = 0; c < N; ++c)
        lo[c] = static_cast<double>(l[c]), hi[c] = static_cast<double>(h[c]);
    return true;
}

template <typename C>
std::uint64_t scan_bounds(const Reader& r, std::vector<double>& lo, std::vector<double>& hi) {
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

// What a use's own pass over an accessor (triangle indices, normals) finds that the
// min/max check needs too: those bytes are read once, for both.
struct Summary {
    enum class Kind : std::uint8_t { None, Indices, Normals } kind = Kind::None;
    bool triangles = false; // Indices: summarized as a triangle list
    kernels::IndexSummary indices;
    bool finite = false, doubtful = false; // Normals: kernels::unit_bounds
    float lo[3] = {}, hi[3] = {};
};

constexpr double kUnitTolerance = 0.00674;

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
    const std::string where = ptr("/accessors", index);
    const std::uint32_t n = r.components();
    if (n == 0 || n > 16) return;
    std::vector<double> lo(n, INFINITY), hi(n, -INFINITY);
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
        v.add("ACCESSOR_INVALID_FLOAT", Severity::Error, where,
              "Accessor element at index " + std::to_string(bad) + " is " +
                  (std::isnan(x) ? "NaN" : "Infinity") + ".");
    }
    auto same = [&](double declared, double actual) {
        return r.is_float() ? static_cast<float>(declared) == static_cast<float>(actual)
                            : declared == actual;
    };
    // Every value finite and inside both declared bounds: what the importer's range
    // check would find too (its values are these, normalized by a monotonic map).
    bool hold = bad == UINT64_MAX && a.has_min && a.has_max && !a.sparse;
    for (std::uint32_t c = 0; c < n && hold; ++c) {
        const Json& dmin = acc["min"][c];
        const Json& dmax = acc["max"][c];
        hold = dmin.is_number() && dmax.is_number() &&
               (lo[c] >= dmin.get<double>() || same(dmin.get<double>(), lo[c])) &&
               (hi[c] <= dmax.get<double>() || same(dmax.get<double>(), hi[c]));
    }
    if (hold && index < v.bounds_hold.size()) v.bounds_hold[index] = 1;
    for (int side = 0; side < 2; ++side) {
        const bool is_min = side == 0;
        if (!(is_min ? a.has_min : a.has_max)) continue;
        const Json& declared = acc[is_min ? "min" : "max"];
        for (std::uint32_t c = 0; c < n; ++c) {
            if (!declared[c].is_number()) continue;
            const double d = declared[c].get<double>();
            const double actual = is_min ? lo[c] : hi[c];
            const bool mismatch = std::isfinite(actual) && !same(d, actual);
            if (!mismatch && bad == UINT64_MAX) continue; // no message: no pointer to build
            const std::string p = ptr(ptr(where, is_min ? "min" : "max"), c);
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

double length3(const Reader& r, std::uint64_t i) {
    const double x = r.value(i, 0), y = r.value(i, 1), z = r.value(i, 2);
    return std::sqrt(x * x + y * y + z * z);
}

void check_use(Validation& v, const AccessorUsage& u, const Reader& r, const Summary& known,
               const std::vector<AccessorLayout>& layouts, Buffers buffers) {
    const std::uint64_t n = r.count();
    auto once = [&](bool& said, std::string_view code, Severity s, std::string message) {
        if (said) return;
        said = true;
        v.add(code, s, u.pointer, std::move(message));
    };
    bool a = false, b = false, c = false;
    switch (u.use) {
    case AccessorUse::Indices: {
        const int type = v.accessors[u.accessor].component_type;
        if (r.components() != 1 || (type != 5121 && type != 5123 && type != 5125)) break;
        const bool triangles = u.mode == 4;
        // The summary the min/max check used, where it was made for this mode.
        const kernels::IndexSummary summary =
            known.kind == Summary::Kind::Indices && known.triangles == triangles ? known.indices
            : type == 5121
                ? kernels::summarize_indices<std::uint8_t>(r.base(), n, r.stride(), triangles)
            : type == 5123
                ? kernels::summarize_indices<std::uint16_t>(r.base(), n, r.stride(), triangles)
                : kernels::summarize_indices<std::uint32_t>(r.base(), n, r.stride(), triangles);
        const kernels::IndexScan s =
            type == 5121 ? kernels::indices<std::uint8_t>(r.base(), n, r.stride(), u.limit, summary)
            : type == 5123
                ? kernels::indices<std::uint16_t>(r.base(), n, r.stride(), u.limit, summary)
                : kernels::indices<std::uint32_t>(r.base(), n, r.stride(), u.limit, summary);
        if (s.first_over != UINT64_MAX)
            v.add("ACCESSOR_INDEX_OOB", Severity::Error, u.pointer,
                  "Indices accessor element at index " + std::to_string(s.first_over) +
                      " has value " +
                      std::to_string(static_cast<std::uint64_t>(r.raw(s.first_over, 0))) +
                      " that is greater than the maximum vertex index available (" +
                      std::to_string(u.limit ? u.limit - 1 : 0) + ").");
        if (s.first_restart != UINT64_MAX)
            v.add("ACCESSOR_INDEX_PRIMITIVE_RESTART", Severity::Error, u.pointer,
                  "Indices accessor contains primitive restart value at index " +
                      std::to_string(s.first_restart) + ".");
        if (s.degenerate)
            v.add("ACCESSOR_INDEX_TRIANGLE_DEGENERATE", Severity::Information, u.pointer,
                  "Indices accessor contains " + std::to_string(s.degenerate) +
                      " degenerate triangles (out of " + std::to_string(n / 3) + ").");
        break;
    }
    case AccessorUse::Normal:
    case AccessorUse::Tangent: {
        if (r.components() < 3) break;
        const bool sign = u.use == AccessorUse::Tangent && r.components() == 4;
        // Float vectors (the common case) in one typed pass, to the first of each problem.
        std::uint64_t from = 0;
        if (r.is_float()) {
            // The first test ran with the min/max check's pass where it was summarized.
            if (known.kind == Summary::Kind::Normals && !sign && !known.doubtful) break;
            const kernels::UnitScan s =
                known.kind == Summary::Kind::Normals && !sign
                    ? kernels::unit_vectors_exact(r.base(), n, r.stride(), kUnitTolerance, sign)
                    : kernels::unit_vectors(r.base(), n, r.stride(), kUnitTolerance, sign);
            if (s.first_non_unit == UINT64_MAX && s.first_bad_sign == UINT64_MAX) break;
            from = std::min(s.first_non_unit, s.first_bad_sign);
        }
        for (std::uint64_t i = from; i < n; ++i) {
            const double len = length3(r, i);
            if (std::isfinite(len) && std::abs(len - 1) > kUnitTolerance)
                once(a, "ACCESSOR_VECTOR3_NON_UNIT", Severity::Error,
                     "Vector3 at accessor element " + std::to_string(i) +
                         " is not of unit length: " + std::to_string(len) + ".");
            if (u.use == AccessorUse::Tangent && r.components() == 4) {
                const double w = r.value(i, 3);
                if (w != 1 && w != -1)
                    once(b, "ACCESSOR_INVALID_SIGN", Severity::Error,
                         "Vector3 with sign at accessor element " + std::to_string(i) +
                             " has invalid w component: " + std::to_string(w) +
                             ". Must be 1.0 or -1.0.");
            }
        }
        break;
    }
    case AccessorUse::Color:
        if (!r.is_float()) break;
        for (std::uint64_t i = 0; i < n; ++i)
            for (std::uint32_t k = 0; k < r.components(); ++k)
                if (const double x = r.raw(i, k); x < 0 || x > 1)
                    once(a, "ACCESSOR_NON_CLAMPED", Severity::Error,
                         "Accessor element at index " + std::to_string(i * r.components() + k) +
                             " is not clamped to 0..1 range: " + std::to_string(x) + ".");
        break;
    case AccessorUse::Joints: {
        // Weights of the same set decide which joints count.
        std::optional<Reader> w;
        if (u.partner < v.accessors.size()) {
            w.emplace(layouts[u.partner], buffers);
            if (!w->ok() || w->count() != n || w->components() != 4) w.reset();
        }
        const std::string wp = u.pointer.substr(0, u.pointer.rfind('/')) + "/WEIGHTS_" +
                               u.pointer.substr(u.pointer.rfind('_') + 1);
        bool neg = false, sum_said = false;
        for (std::uint64_t i = 0; i < n && r.components() == 4; ++i) {
            float sum = 0;
            double tolerance = 0;
            for (std::uint32_t k = 0; k < 4; ++k) {
                const double j = r.raw(i, k);
                if (u.limit && j > static_cast<double>(u.limit) - 1) {
                    once(a, "ACCESSOR_JOINTS_INDEX_OOB", Severity::Error,
                         "Joints accessor element at index " + std::to_string(i * 4 + k) +
                             " has value " + std::to_string(static_cast<std::uint64_t>(j)) +
                             " that is greater than the maximum joint index (" +
                             std::to_string(u.limit - 1) + ").");
                    continue;
                }
                if (!w) continue;
                const double wk = w->value(i, k);
                if (wk != 0) {
                    for (std::uint32_t m = 0; m < k; ++m)
                        if (r.raw(i, m) == j && w->value(i, m) != 0)
                            once(b, "ACCESSOR_JOINTS_INDEX_DUPLICATE", Severity::Error,
                                 "Joints accessor element at index " + std::to_string(i * 4 + k) +
                                     " has value " + std::to_string(static_cast<std::uint64_t>(j)) +
                                     " that is already in use for the vertex.");
                    if (wk < 0) {
                        if (!neg)
                            v.add("ACCESSOR_WEIGHTS_NEGATIVE", Severity::Error, wp,
                                  "Weights accessor element at index " + std::to_string(i * 4 + k) +
                                      " has negative value " + std::to_string(wk) + ".");
                        neg = true;
                    } else {
                        sum += static_cast<float>(wk);
                        tolerance += 2e-7;
                    }
                } else if (j != 0) {
                    once(c, "ACCESSOR_JOINTS_USED_ZERO_WEIGHT", Severity::Warning,
                         "Joints accessor element at index " + std::to_string(i * 4 + k) +
                             " is used with zero weight but has non-zero value (" +
                             std::to_string(static_cast<std::uint64_t>(j)) + ").");
                }
            }
            if (w && std::abs(static_cast<double>(sum) - 1) > tolerance && !sum_said) {
                sum_said = true;
                v.add("ACCESSOR_WEIGHTS_NON_NORMALIZED", Severity::Error, wp,
                      "Weights accessor elements (at indices " + std::to_string(i * 4) + ".." +
                          std::to_string(i * 4 + 3) +
                          ") have non-normalized sum: " + std::to_string(sum) + ".");
            }
        }
        break;
    }
    case AccessorUse::AnimationInput:
        for (std::uint64_t i = 0; i < n; ++i) {
            const double t = r.raw(i, 0);
            if (t < 0)
                once(a, "ACCESSOR_ANIMATION_INPUT_NEGATIVE", Severity::Error,
                     "Animation input accessor element at index " + std::to_string(i) +
                         " is negative: " + std::to_string(t) + ".");
            else if (i > 0 && t <= r.raw(i - 1, 0))
                once(b, "ACCESSOR_ANIMATION_INPUT_NON_INCREASING", Severity::Error,
                     "Animation input accessor element at index " + std::to_string(i) +
                         " is less than or equal to previous: " + std::to_string(t) +
                         " <= " + std::to_string(r.raw(i - 1, 0)) + ".");
        }
        break;
    case AccessorUse::AnimationOutputRotation:
        if (r.components() != 4) break;
        for (std::uint64_t i = 0; i < n; ++i) {
            if (u.mode == 1 && i % 3 != 1) continue; // cubic: in-tangent, value, out-tangent
            double len2 = 0;
            for (std::uint32_t k = 0; k < 4; ++k) len2 += r.value(i, k) * r.value(i, k);
            if (std::isfinite(len2) && std::abs(std::sqrt(len2) - 1) > 0.00769)
                once(a, "ACCESSOR_ANIMATION_SAMPLER_OUTPUT_NON_NORMALIZED_QUATERNION",
                     Severity::Error,
                     "Animation sampler output accessor element " + std::to_string(i) +
                         " is not of unit length: " + std::to_string(std::sqrt(len2)) + ".");
        }
        break;
    case AccessorUse::InverseBindMatrices:
        // The last row of each matrix is (0, 0, 0, 1): an affine transform.
        if (r.components() != 16) break;
        for (std::uint64_t i = 0; i < n && !a; ++i)
            for (std::uint32_t k : {3u, 7u, 11u, 15u})
                if (const double x = r.value(i, k); x != (k == 15 ? 1.0 : 0.0)) {
                    once(a, "ACCESSOR_INVALID_IBM", Severity::Error,
                         "Matrix element at index " + std::to_string(i * 16 + k) +
                             " (component index " + std::to_string(k) +
                             ") contains invalid value: " + std::to_string(x) + ".");
                    break;
                }
        break;
    default:
        break;
    }
}

} // namespace

void validate_data(Validation& v, Buffers buffers) {
    v.bounds_hold.assign(v.accessors.size(), 0);
    // The lengths the file declared (the importer may have rewritten the JSON since).
    for (std::size_t i = 0; i < v.declared_buffer_length.size() && i < buffers.size(); ++i) {
        const std::int64_t declared = v.declared_buffer_length[i];
        if (!buffers[i].empty() && declared > 0 && !v.length_unchecked[i] &&
            buffers[i].size() < static_cast<std::uint64_t>(declared))
            v.add("BUFFER_BYTE_LENGTH_MISMATCH", Severity::Error, ptr("/buffers", i),
                  "Actual data byte length (" + std::to_string(buffers[i].size()) +
                      ") is less than the declared buffer byte length (" +
                      std::to_string(declared) + ").");
    }
    // Sparse accessors are read from a copy with their overrides applied, as one more
    // buffer; the others from the file's buffers.
    std::vector<AccessorLayout> layouts = v.accessors;
    std::vector<std::span<const std::uint8_t>> spans(buffers.begin(), buffers.end());
    std::vector<std::vector<std::uint8_t>> copies;
    for (std::size_t i = 0; i < layouts.size(); ++i) {
        if (!layouts[i].sparse) continue;
        std::vector<std::uint8_t> values = sparse_values(v, i, buffers);
        if (values.empty()) continue;
        copies.push_back(std::move(values)); // its bytes stay put when `copies` grows
        spans.emplace_back(copies.back().data(), copies.back().size());
        AccessorLayout& l = layouts[i];
        l.sparse = false;
        l.readable = true;
        l.buffer = spans.size() - 1;
        l.offset = 0;
        l.stride = std::uint64_t{component_size(l.component_type)} * l.components;
    }
    // The first use of an accessor that reads all of it anyway summarizes it first.
    std::vector<Summary> summaries(layouts.size());
    for (const AccessorUsage& u : v.usages) {
        if (u.accessor >= layouts.size() || layouts[u.accessor].sparse ||
            summaries[u.accessor].kind != Summary::Kind::None)
            continue;
        const Reader r(layouts[u.accessor], spans);
        if (r.ok() && r.count() > 0)
            summarize(u, r, layouts[u.accessor].component_type, summaries[u.accessor]);
    }
    for (std::size_t i = 0; i < layouts.size(); ++i) {
        if (layouts[i].sparse) continue; // overrides that could not be applied: not read
        const Reader r(layouts[i], spans);
        if (r.ok()) check_min_max(v, i, r, summaries[i]);
    }
    for (const AccessorUsage& u : v.usages) {
        if (u.accessor >= layouts.size() || layouts[u.accessor].sparse) continue;
        const Reader r(layouts[u.accessor], spans);
        if (r.ok()) check_use(v, u, r, summaries[u.accessor], layouts, spans);
    }
}

} // namespace sherpa::detail
