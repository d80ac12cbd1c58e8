#include "draco_attributes.h"

#include "import_error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include <draco/attributes/point_attribute.h>
#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

template <typename T> T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// One component of Draco's type Src as the accessor's type Dst; false when Dst
// cannot hold it (the caller names the point).
template <typename Src, typename Dst>
bool convert(Src in, bool draco_normalized, bool accessor_normalized, Dst& out) {
    if constexpr (std::is_floating_point_v<Dst>) {
        if constexpr (std::is_integral_v<Src>)
            out = draco_normalized
                      ? std::max(Dst(in) / Dst(std::numeric_limits<Src>::max()), Dst(-1))
                      : Dst(in);
        else
            out = Dst(in);
        return true;
    } else if constexpr (std::is_integral_v<Src>) {
        using Wide = std::conditional_t<std::is_signed_v<Src>, std::int64_t, std::uint64_t>;
        const Wide v = Wide(in);
        if constexpr (std::is_signed_v<Src>)
            if (v < std::int64_t(std::numeric_limits<Dst>::min())) return false;
        if (v > Wide(0) && std::uint64_t(v) > std::uint64_t(std::numeric_limits<Dst>::max()))
            return false;
        out = Dst(v);
        return true;
    } else { // float to integer
        const double v = double(in);
        if (!std::isfinite(v)) return false;
        constexpr double hi = double(std::numeric_limits<Dst>::max());
        constexpr double lo = std::is_signed_v<Dst> ? -hi : 0.0;
        if (accessor_normalized) { // glTF: c = round(f * max), f >= -1
            out = Dst(std::clamp(std::round(v * hi), lo, hi));
            return true;
        }
        const double r = std::round(v);
        if (std::abs(v - r) > 1e-4 || r < double(std::numeric_limits<Dst>::min()) || r > hi)
            return false;
        out = Dst(r);
        return true;
    }
}

struct Rows {
    const draco::PointAttribute& att;
    std::size_t points;
    int comps;
    bool normalized;
    unsigned char* out;
    std::size_t stride;
    const std::string& where;
};

template <typename Src, typename Dst> void write_rows(const Rows& r) {
    const std::size_t src_row = std::size_t(r.comps) * sizeof(Src);
    const std::size_t stored = r.att.buffer()->data_size();
    const bool draco_normalized = r.att.normalized();
    for (std::size_t i = 0; i < r.points; ++i) {
        const draco::AttributeValueIndex v =
            r.att.mapped_index(draco::PointIndex(std::uint32_t(i)));
        const std::int64_t at = r.att.byte_offset() + std::int64_t(v.value()) * r.att.byte_stride();
        if (v.value() >= r.att.size() || at < 0 || std::size_t(at) + src_row > stored)
            fail(r.where + ": Draco maps point " + std::to_string(i) + " to value " +
                 std::to_string(v.value()) + " of " + std::to_string(r.att.size()));
        const unsigned char* src = r.att.buffer()->data() + at;
        unsigned char* dst = r.out + i * r.stride;
        for (int c = 0; c < r.comps; ++c) {
            const Src in = load<Src>(src + std::size_t(c) * sizeof(Src));
            Dst value{};
            if (!convert(in, draco_normalized, r.normalized, value))
                fail(r.where + ": Draco's value " + number_text(double(in)) + " (point " +
                     std::to_string(i) + ", component " + std::to_string(c) +
                     ") does not fit the accessor's component type");
            std::memcpy(dst + std::size_t(c) * sizeof(Dst), &value, sizeof value);
        }
    }
}

template <typename Src> void write_rows_from(const Rows& r, int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return write_rows<Src, std::int8_t>(r);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return write_rows<Src, std::uint8_t>(r);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return write_rows<Src, std::int16_t>(r);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return write_rows<Src, std::uint16_t>(r);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return write_rows<Src, std::uint32_t>(r);
    default:
        return write_rows<Src, float>(r);
    }
}

// The Draco data type that stores the accessor's component type as it is.
draco::DataType same_type(int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return draco::DT_INT8;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return draco::DT_UINT8;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return draco::DT_INT16;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return draco::DT_UINT16;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return draco::DT_UINT32;
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return draco::DT_FLOAT32;
    default:
        return draco::DT_INVALID;
    }
}

} // namespace

std::size_t append_draco_attribute(const draco::PointAttribute& att, std::size_t points, int comps,
                                   int component_type, bool normalized,
                                   std::vector<unsigned char>& data, const std::string& where) {
    const int bytes = tinygltf::GetComponentSizeInBytes(std::uint32_t(component_type));
    const std::size_t size = bytes > 0 ? std::size_t(bytes) : 0;
    if (size == 0 || comps <= 0 || !att.buffer())
        fail(where + ": componentType " + std::to_string(component_type) +
             " is not a glTF attribute component type");
    const std::size_t row = std::size_t(comps) * size, stride = (row + 3) / 4 * 4;
    const std::size_t offset = data.size();
    // The whole attribute at once where Draco already holds the rows as they go out.
    if (att.data_type() == same_type(component_type) && stride == row &&
        att.is_mapping_identity() && std::size_t(att.byte_stride()) == row &&
        att.size() >= points && att.byte_offset() >= 0 &&
        std::size_t(att.byte_offset()) + points * row <= att.buffer()->data_size()) {
        const unsigned char* src = att.buffer()->data() + att.byte_offset();
        data.insert(data.end(), src, src + points * row);
        return stride;
    }
    data.resize(offset + points * stride);
    const Rows r{att, points, comps, normalized, data.data() + offset, stride, where};
    switch (att.data_type()) {
    case draco::DT_INT8:
        write_rows_from<std::int8_t>(r, component_type);
        break;
    case draco::DT_UINT8:
    case draco::DT_BOOL:
        write_rows_from<std::uint8_t>(r, component_type);
        break;
    case draco::DT_INT16:
        write_rows_from<std::int16_t>(r, component_type);
        break;
    case draco::DT_UINT16:
        write_rows_from<std::uint16_t>(r, component_type);
        break;
    case draco::DT_INT32:
        write_rows_from<std::int32_t>(r, component_type);
        break;
    case draco::DT_UINT32:
        write_rows_from<std::uint32_t>(r, component_type);
        break;
    case draco::DT_INT64:
        write_rows_from<std::int64_t>(r, component_type);
        break;
    case draco::DT_UINT64:
        write_rows_from<std::uint64_t>(r, component_type);
        break;
    case draco::DT_FLOAT32:
        write_rows_from<float>(r, component_type);
        break;
    case draco::DT_FLOAT64:
        write_rows_from<double>(r, component_type);
        break;
    default:
        fail(where + ": Draco attribute of unknown data type " +
             std::to_string(int(att.data_type())));
    }
    return stride;
}

} // namespace sherpa::scene::detail
