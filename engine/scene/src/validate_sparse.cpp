// Sparse accessors for the data pass: the indices checked, then the values copied with
// the overrides applied, so that every other check reads them like any accessor.
#include "validate_reader.h"

#include <string>

namespace sherpa::scene::detail {
namespace {

constexpr std::uint64_t kMaxZeroBase = std::uint64_t{64} << 20; // without a base view

std::uint64_t read_index(const std::uint8_t* p, int type) {
    if (type == 5121) return *p;
    if (type == 5123) {
        std::uint16_t x;
        std::memcpy(&x, p, 2);
        return x;
    }
    std::uint32_t x;
    std::memcpy(&x, p, 4);
    return x;
}

} // namespace

std::vector<std::uint8_t> sparse_values(Validation& v, std::size_t i, Buffers buffers) {
    const AccessorLayout& a = v.accessors[i];
    const AccessorLayout::Sparse& sd = a.sparse_data;
    const std::uint64_t element = std::uint64_t{component_size(a.component_type)} * a.components;
    if (!(a.readable || sd.zero_base) || element == 0 || !sd.indices_readable ||
        sd.indices_buffer >= buffers.size())
        return {};
    const std::uint32_t isize = component_size(sd.index_type);
    const auto& ib = buffers[sd.indices_buffer];
    if (!range_fits(sd.indices_offset, sd.overrides * isize, ib.size())) return {};
    const std::string where = ptr(ptr("/accessors", i), "sparse");
    bool bad = false;
    for (std::uint64_t k = 0; k < sd.overrides; ++k) {
        const std::uint64_t index =
            read_index(ib.data() + sd.indices_offset + k * isize, sd.index_type);
        const std::uint64_t previous =
            k ? read_index(ib.data() + sd.indices_offset + (k - 1) * isize, sd.index_type) : 0;
        if (k && index <= previous && !bad)
            v.add("ACCESSOR_SPARSE_INDICES_NON_INCREASING", Severity::Error, where,
                  "Accessor sparse indices element at index " + std::to_string(k) +
                      " is less than or equal to previous: " + std::to_string(index) +
                      " <= " + std::to_string(previous) + ".");
        else if (index >= a.count && !bad)
            v.add("ACCESSOR_SPARSE_INDEX_OOB", Severity::Error, where,
                  "Accessor sparse indices element at index " + std::to_string(k) +
                      " is greater than or equal to the number of accessor elements: " +
                      std::to_string(index) + " >= " + std::to_string(a.count) + ".");
        else
            continue;
        bad = true;
    }
    if (bad || !sd.values_readable || sd.values_buffer >= buffers.size()) return {};
    const auto& vb = buffers[sd.values_buffer];
    if (!range_fits(sd.values_offset, sd.overrides * element, vb.size())) return {};
    std::vector<std::uint8_t> out;
    if (a.readable) {
        const Reader base(a, buffers);
        if (!base.ok()) return {};
        out.resize(a.count * element);
        for (std::uint64_t e = 0; e < a.count; ++e)
            std::memcpy(out.data() + e * element, base.base() + e * a.stride, element);
    } else {
        if (a.count > kMaxZeroBase / element) return {};
        out.assign(a.count * element, 0);
    }
    for (std::uint64_t k = 0; k < sd.overrides; ++k)
        std::memcpy(out.data() +
                        read_index(ib.data() + sd.indices_offset + k * isize, sd.index_type) *
                            element,
                    vb.data() + sd.values_offset + k * element, element);
    return out;
}

} // namespace sherpa::scene::detail
