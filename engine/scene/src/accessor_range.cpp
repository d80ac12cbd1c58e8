// Declared accessor min/max against the decoded data (glTF: they must be exact).
#include "accessor_reader.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

// The declared bound in the decoded domain: glTF states min/max of normalized
// accessors in raw integers, the data we compare with is already normalised.
double normalised_bound(double raw, int component_type, bool normalized) {
    if (!normalized) return raw;
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return std::max(raw / 127.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return raw / 255.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return std::max(raw / 32767.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return raw / 65535.0;
    default:
        return raw;
    }
}

template <typename T> std::string list(const std::vector<T>& v) {
    std::ostringstream s;
    s << '[';
    for (std::size_t i = 0; i < v.size(); ++i) s << (i ? " " : "") << v[i];
    s << ']';
    return s.str();
}

} // namespace

std::optional<AccessorRangeViolation> check_declared_range(const tinygltf::Model& model, int index,
                                                           const std::vector<float>& values,
                                                           std::uint32_t components,
                                                           const std::string& where) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size() || components == 0)
        return std::nullopt;
    const auto& acc = model.accessors[static_cast<std::size_t>(index)];
    if (acc.minValues.size() != components || acc.maxValues.size() != components)
        return std::nullopt; // not declared (optional except for POSITION)
    AccessorRangeViolation v;
    v.accessor = index;
    v.where = where;
    v.elements = static_cast<std::uint32_t>(values.size() / components);
    for (std::uint32_t c = 0; c < components; ++c) {
        v.declared_min.push_back(
            normalised_bound(acc.minValues[c], acc.componentType, acc.normalized));
        v.declared_max.push_back(
            normalised_bound(acc.maxValues[c], acc.componentType, acc.normalized));
    }
    v.data_min.assign(components, INFINITY);
    v.data_max.assign(components, -INFINITY);
    for (std::uint32_t e = 0; e < v.elements; ++e) {
        bool outside = false;
        for (std::uint32_t c = 0; c < components; ++c) {
            const float x = values[e * components + c];
            v.data_min[c] = std::min(v.data_min[c], x);
            v.data_max[c] = std::max(v.data_max[c], x);
            // Exporters print bounds rounded to 6-9 significant digits: allow that much,
            // relative to the declared range, and nothing a corrupt byte could hide in.
            const double lo = v.declared_min[c], hi = v.declared_max[c];
            const double slack = 1e-5 * std::max({std::abs(lo), std::abs(hi), hi - lo, 1e-6});
            if (!(x >= lo - slack && x <= hi + slack)) outside = true;
        }
        v.elements_outside += outside ? 1u : 0u;
    }
    if (v.elements_outside == 0) return std::nullopt;
    return v;
}

std::string describe_range_violation(const AccessorRangeViolation& v) {
    return v.where + " (accessors[" + std::to_string(v.accessor) +
           "]): " + std::to_string(v.elements_outside) + " of " + std::to_string(v.elements) +
           " elements lie outside the declared min " + list(v.declared_min) + " / max " +
           list(v.declared_max) + " (data spans " + list(v.data_min) + " .. " + list(v.data_max) +
           "); glTF requires exact bounds, the buffer may be corrupt";
}

} // namespace sherpa::scene::detail
