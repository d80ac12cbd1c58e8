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

namespace sherpa::scene::detail {
namespace {

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

} // namespace sherpa::scene::detail
