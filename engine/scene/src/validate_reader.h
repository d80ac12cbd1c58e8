#pragma once
// The data pass's accessor reader (validate_data.cpp) and the sparse accessor copy it
// reads sparse accessors from (validate_sparse.cpp).
#include "validate_internal.h"

#include "checked_math.h"
#include "validate_kernels.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace sherpa::scene::detail {

using Buffers = std::span<const std::span<const std::uint8_t>>;

// One accessor's values, read element by element (sparse overrides applied).
class Reader {
public:
    Reader(const AccessorLayout& a, Buffers buffers) : a_(a) {
        if (!a.readable || a.buffer >= buffers.size()) return;
        const auto& b = buffers[a.buffer];
        const auto last = checked_mul(a.stride, a.count - 1);
        const auto end =
            last ? checked_add(*last, std::size_t{component_size(a.component_type)} * a.components)
                 : std::nullopt;
        if (!end || !range_fits(a.offset, *end, b.size())) return;
        base_ = b.data() + a.offset;
        ok_ = true;
    }
    bool ok() const { return ok_; }
    std::uint64_t count() const { return a_.count; }
    std::uint32_t components() const { return a_.components; }
    // Raw component value (integers as integers).
    double raw(std::uint64_t i, std::uint32_t c) const {
        const std::uint8_t* p = base_ + i * a_.stride + c * component_size(a_.component_type);
        switch (a_.component_type) {
        case 5120:
            return static_cast<std::int8_t>(*p);
        case 5121:
            return *p;
        case 5122: {
            std::int16_t x;
            std::memcpy(&x, p, 2);
            return x;
        }
        case 5123: {
            std::uint16_t x;
            std::memcpy(&x, p, 2);
            return x;
        }
        case 5125: {
            std::uint32_t x;
            std::memcpy(&x, p, 4);
            return x;
        }
        default: {
            float x;
            std::memcpy(&x, p, 4);
            return x;
        }
        }
    }
    // Value as used: normalized integers mapped to [0, 1] or [-1, 1].
    double value(std::uint64_t i, std::uint32_t c) const {
        const double r = raw(i, c);
        if (!a_.normalized) return r;
        switch (a_.component_type) {
        case 5120:
            return std::max(r / 127.0, -1.0);
        case 5121:
            return r / 255.0;
        case 5122:
            return std::max(r / 32767.0, -1.0);
        case 5123:
            return r / 65535.0;
        default:
            return r;
        }
    }
    bool is_float() const { return a_.component_type == 5126; }
    const std::uint8_t* base() const { return base_; }
    std::uint64_t stride() const { return a_.stride; }
    int component_type() const { return a_.component_type; }

private:
    const AccessorLayout& a_;
    const std::uint8_t* base_ = nullptr;
    bool ok_ = false;
};

// A copy of sparse accessor `i`'s values: its base (zeros without a bufferView) with the
// overrides applied, checked first (ACCESSOR_SPARSE_INDICES_NON_INCREASING,
// ACCESSOR_SPARSE_INDEX_OOB). Empty when the indices are bad or a part cannot be read;
// the copy is no larger than the base's bytes, or 64 MiB without a base.
std::vector<std::uint8_t> sparse_values(Validation& v, std::size_t i, Buffers buffers);

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

// The summary of accessor `u.accessor`, read by `r`, where its use reads all of it
// anyway (indices of a supported type; packed float normals); `out` untouched else.
void summarize(const AccessorUsage& u, const Reader& r, int component_type, Summary& out);
// ACCESSOR_INVALID_FLOAT, ACCESSOR_MIN/MAX_MISMATCH and ACCESSOR_ELEMENT_OUT_OF_MIN/MAX_BOUND
// of accessor `index`, and Validation::bounds_hold; the bounds from `known` where it
// has them.
void check_min_max(Validation& v, std::size_t index, const Reader& r, const Summary& known);

} // namespace sherpa::scene::detail
