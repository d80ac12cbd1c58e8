#include "accessor_reader.h"

#include "checked_math.h"
#include "import_error.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

std::uint32_t component_size(int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

std::string accessor_path(int index) {
    return "accessors[" + std::to_string(index) + "]";
}

const tinygltf::Accessor& checked_accessor(const tinygltf::Model& model, int index,
                                           const std::string& where) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        fail(where + ": accessor index " + std::to_string(index) + " out of range (file has " +
             std::to_string(model.accessors.size()) + " accessors)");
    return model.accessors[static_cast<std::size_t>(index)];
}

// Returns a pointer to `needed` bytes at `offset` within bufferView `view_index`,
// with every range checked against the bufferView and its buffer (overflow-proof:
// offsets near 2^64 must not wrap into a passing check).
const std::uint8_t* checked_view_bytes(const tinygltf::Model& model, int view_index,
                                       std::size_t offset, std::size_t needed,
                                       const std::string& where) {
    if (view_index < 0 || static_cast<std::size_t>(view_index) >= model.bufferViews.size())
        fail(where + ": bufferView index " + std::to_string(view_index) +
             " out of range (file has " + std::to_string(model.bufferViews.size()) +
             " bufferViews)");
    const auto& view = model.bufferViews[static_cast<std::size_t>(view_index)];
    const std::string view_path = "bufferViews[" + std::to_string(view_index) + "]";
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        fail(view_path + ": buffer index " + std::to_string(view.buffer) + " out of range");
    const auto& buffer = model.buffers[static_cast<std::size_t>(view.buffer)];
    if (!range_fits(view.byteOffset, view.byteLength, buffer.data.size()))
        fail(view_path + ": byteOffset " + std::to_string(view.byteOffset) + " + byteLength " +
             std::to_string(view.byteLength) + " exceeds buffers[" + std::to_string(view.buffer) +
             "] size " + std::to_string(buffer.data.size()) + " (missing or short buffer)");
    if (!range_fits(offset, needed, view.byteLength))
        fail(where + ": reads " + std::to_string(needed) + " bytes at offset " +
             std::to_string(offset) + " past the end of " + view_path + " (byteLength " +
             std::to_string(view.byteLength) + ")");
    return buffer.data.data() + view.byteOffset + offset;
}

float decode_component(const std::uint8_t* p, int component_type, bool normalized) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<std::int8_t>(*p);
        return normalized ? std::max(static_cast<float>(v) / 127.0f, -1.0f) : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? static_cast<float>(*p) / 255.0f : static_cast<float>(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(static_cast<float>(v) / 32767.0f, -1.0f)
                          : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? static_cast<float>(v) / 65535.0f : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return normalized ? static_cast<float>(static_cast<double>(v) / 4294967295.0)
                          : static_cast<float>(v);
    }
    default:
        return 0.0f;
    }
}

std::uint32_t decode_index(const std::uint8_t* p, int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    default: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

// `count` elements of `components` components each in a (possibly strided)
// bufferView, located and range-checked before anything is allocated for them.
struct StridedRegion {
    const std::uint8_t* base = nullptr;
    std::size_t stride = 0;
    std::uint32_t component_bytes = 0;
};

StridedRegion locate_strided(const tinygltf::Model& model, int view_index, std::size_t byte_offset,
                             std::size_t count, std::uint32_t components, int component_type,
                             const std::string& where) {
    StridedRegion r;
    r.component_bytes = component_size(component_type);
    const std::uint32_t elem = components * r.component_bytes;
    const auto& views = model.bufferViews;
    r.stride = elem;
    if (view_index >= 0 && static_cast<std::size_t>(view_index) < views.size() &&
        views[static_cast<std::size_t>(view_index)].byteStride != 0) {
        r.stride = views[static_cast<std::size_t>(view_index)].byteStride;
        if (r.stride < elem)
            fail(where + ": bufferViews[" + std::to_string(view_index) + "].byteStride " +
                 std::to_string(r.stride) + " is smaller than the element size " +
                 std::to_string(elem));
    }
    if (count == 0) return r;
    const auto span = checked_mul(r.stride, count - 1);
    const auto needed = span ? checked_add(*span, elem) : std::nullopt;
    if (!needed)
        fail(where + ": count " + std::to_string(count) + " x byteStride " +
             std::to_string(r.stride) + " overflows the address space");
    r.base = checked_view_bytes(model, view_index, byte_offset, *needed, where);
    return r;
}

// Calls `store(element, component, bytes)` for each component of a located region.
template <typename Store>
void read_region(const StridedRegion& r, std::size_t count, std::uint32_t components,
                 Store&& store) {
    for (std::size_t i = 0; i < count; ++i)
        for (std::uint32_t c = 0; c < components; ++c)
            store(i, c, r.base + i * r.stride + c * r.component_bytes);
}

void validate_accessor_shape(const tinygltf::Accessor& acc, const std::string& where) {
    if (component_size(acc.componentType) == 0)
        fail(where + ": componentType " + std::to_string(acc.componentType) + " is not valid");
    if (type_components(acc.type) == 0)
        fail(where + ": accessor type " + std::to_string(acc.type) +
             " is not SCALAR/VEC2/VEC3/VEC4/MAT4");
}

} // namespace

std::uint32_t type_components(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
        return 4;
    case TINYGLTF_TYPE_MAT4:
        return 16; // skins' inverseBindMatrices: 4-byte columns, no padding
    default:
        return 0; // MAT2/MAT3 (column padding) are never used by what Sherpa reads
    }
}

std::uint32_t accessor_count(const tinygltf::Model& model, int index, const std::string& where) {
    const auto& acc = checked_accessor(model, index, where);
    if (acc.count > 0xFFFFFFFFull / 64)
        fail(where + ": accessor count " + std::to_string(acc.count) + " is absurd");
    return static_cast<std::uint32_t>(acc.count);
}

namespace {

// An accessor without a bufferView is all zeros (plus its sparse substitutions): its
// count costs the file nothing, so a 1 KB file could ask for gigabytes. Such counts
// are capped at one element per byte of buffer data the file carries, and never
// below kZeroFillMinElements (sparse morph targets over small meshes stay legal).
constexpr std::size_t kZeroFillMinElements = std::size_t{1} << 20;

std::size_t zero_fill_limit(const tinygltf::Model& model) {
    std::size_t bytes = 0;
    for (const auto& b : model.buffers)
        bytes = checked_add(bytes, b.data.size()).value_or(SIZE_MAX);
    return std::max(kZeroFillMinElements, bytes);
}

// Decodes `count` x `components` values of an accessor (dense data, then sparse
// substitution) with `decode(bytes)`. Every region is located and range-checked
// before the output is allocated, so its size is always backed by the file's data.
template <typename T, typename Decode>
std::vector<T> decode_accessor(const tinygltf::Model& model, const tinygltf::Accessor& acc,
                               std::size_t count, std::uint32_t components, const std::string& path,
                               Decode&& decode) {
    StridedRegion dense;
    if (acc.bufferView >= 0)
        dense = locate_strided(model, acc.bufferView, acc.byteOffset, count, components,
                               acc.componentType, path);
    else if (count > zero_fill_limit(model))
        fail(path + ": count " + std::to_string(count) +
             " without a bufferView (all zeros) exceeds Sherpa's limit of " +
             std::to_string(zero_fill_limit(model)) +
             " elements for such accessors (one per byte of buffer data, at least 2^20)");
    const auto& sp = acc.sparse;
    const std::string sp_path = path + ".sparse";
    StridedRegion sp_indices, sp_values;
    std::size_t sp_count = 0;
    const int itype = sp.indices.componentType;
    if (sp.isSparse) {
        if (sp.count < 0 || static_cast<std::size_t>(sp.count) > count)
            fail(sp_path + ": count " + std::to_string(sp.count) + " exceeds accessor count " +
                 std::to_string(count));
        if (itype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            itype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            itype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(sp_path + ".indices: componentType " + std::to_string(itype) +
                 " is not an unsigned integer type");
        sp_count = static_cast<std::size_t>(sp.count);
        sp_indices = locate_strided(model, sp.indices.bufferView,
                                    static_cast<std::size_t>(sp.indices.byteOffset), sp_count, 1,
                                    itype, sp_path + ".indices");
        // Sparse values are tightly packed: the bufferView must not be strided.
        sp_values = locate_strided(model, sp.values.bufferView,
                                   static_cast<std::size_t>(sp.values.byteOffset), sp_count,
                                   components, acc.componentType, sp_path + ".values");
    }
    // count <= 2^32 / 64 (accessor_count) and components <= 16: no overflow.
    std::vector<T> out(count * components, T{});
    if (acc.bufferView >= 0)
        read_region(dense, count, components,
                    [&](std::size_t i, std::uint32_t c, const std::uint8_t* p) {
                        out[i * components + c] = decode(p);
                    });
    for (std::size_t i = 0; i < sp_count; ++i) {
        // Indices are integers: decoded as such, never through float.
        const std::uint32_t target = decode_index(sp_indices.base + i * sp_indices.stride, itype);
        if (target >= count)
            fail(sp_path + ".indices[" + std::to_string(i) + "] = " + std::to_string(target) +
                 " is beyond the accessor count " + std::to_string(count));
        for (std::uint32_t c = 0; c < components; ++c)
            out[target * components + c] =
                decode(sp_values.base + i * sp_values.stride + c * sp_values.component_bytes);
    }
    return out;
}

} // namespace

std::vector<float> read_accessor_floats(const tinygltf::Model& model, int index,
                                        std::initializer_list<std::uint32_t> allowed_components,
                                        std::uint32_t& components, const std::string& where) {
    const auto& acc = checked_accessor(model, index, where);
    const std::string path = where + " (" + accessor_path(index) + ")";
    validate_accessor_shape(acc, path);
    components = type_components(acc.type);
    if (std::find(allowed_components.begin(), allowed_components.end(), components) ==
        allowed_components.end())
        fail(path + ": has " + std::to_string(components) +
             " components per element, which this attribute does not allow");
    if (acc.normalized && (acc.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                           acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail(path + ": normalized is true for a FLOAT or UNSIGNED_INT accessor, which glTF "
                    "forbids");
    const std::size_t count = accessor_count(model, index, where);
    const int ct = acc.componentType;
    const bool normalized = acc.normalized;
    return decode_accessor<float>(model, acc, count, components, path, [&](const std::uint8_t* p) {
        return decode_component(p, ct, normalized);
    });
}

std::vector<std::uint32_t> read_accessor_indices(const tinygltf::Model& model, int index,
                                                 const std::string& where) {
    const auto& acc = checked_accessor(model, index, where);
    const std::string path = where + " (" + accessor_path(index) + ")";
    validate_accessor_shape(acc, path);
    if (acc.type != TINYGLTF_TYPE_SCALAR) fail(path + ": indices must be SCALAR");
    const int ct = acc.componentType;
    if (ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(path + ": indices componentType " + std::to_string(ct) +
             " is not an unsigned integer type");
    // Normalized indices would be fractions of a vertex: meaningless, so refused.
    if (acc.normalized) fail(path + ": indices must not be normalized");
    const std::size_t count = accessor_count(model, index, where);
    return decode_accessor<std::uint32_t>(
        model, acc, count, 1, path, [&](const std::uint8_t* p) { return decode_index(p, ct); });
}

std::span<const std::uint8_t> buffer_view_bytes(const tinygltf::Model& model, int view_index,
                                                const std::string& where) {
    const std::size_t length =
        view_index >= 0 && static_cast<std::size_t>(view_index) < model.bufferViews.size()
            ? model.bufferViews[static_cast<std::size_t>(view_index)].byteLength
            : 0;
    return {checked_view_bytes(model, view_index, 0, length, where), length};
}

AccessorSource describe_accessor(const tinygltf::Model& model, int index) {
    AccessorSource s;
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) return s;
    const auto& acc = model.accessors[static_cast<std::size_t>(index)];
    s.accessor = index;
    s.component_type = acc.componentType;
    s.normalized = acc.normalized;
    s.components = type_components(acc.type);
    s.count = static_cast<std::uint32_t>(acc.count);
    s.buffer_view = acc.bufferView;
    if (acc.bufferView >= 0 &&
        static_cast<std::size_t>(acc.bufferView) < model.bufferViews.size()) {
        const auto stride = model.bufferViews[static_cast<std::size_t>(acc.bufferView)].byteStride;
        s.byte_stride = static_cast<std::uint32_t>(
            stride ? stride : s.components * component_size(acc.componentType));
    }
    s.sparse = acc.sparse.isSparse;
    s.sparse_count = acc.sparse.isSparse ? static_cast<std::uint32_t>(acc.sparse.count) : 0;
    s.min = acc.minValues;
    s.max = acc.maxValues;
    return s;
}

} // namespace sherpa::scene::detail
