#include "accessor_reader.h"

#include "import_error.h"

#include <algorithm>
#include <cstring>

#include <tiny_gltf.h>

namespace sherpa::detail {
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
    default:
        return 0; // matrices are never vertex attributes or indices
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
// with every range checked against the bufferView and its buffer.
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
    if (view.byteOffset + view.byteLength > buffer.data.size())
        fail(view_path + ": byteOffset " + std::to_string(view.byteOffset) + " + byteLength " +
             std::to_string(view.byteLength) + " exceeds buffers[" + std::to_string(view.buffer) +
             "] size " + std::to_string(buffer.data.size()) + " (missing or short buffer)");
    if (offset > view.byteLength || needed > view.byteLength - offset)
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

// Reads `count` elements of `components` components each from a (possibly strided)
// bufferView region, calling `store(element, component, bytes)` for each.
template <typename Store>
void read_strided(const tinygltf::Model& model, int view_index, std::size_t byte_offset,
                  std::size_t count, std::uint32_t components, int component_type,
                  const std::string& where, Store&& store) {
    if (count == 0) return;
    const std::uint32_t elem = components * component_size(component_type);
    const auto& views = model.bufferViews;
    std::size_t stride = elem;
    if (view_index >= 0 && static_cast<std::size_t>(view_index) < views.size() &&
        views[static_cast<std::size_t>(view_index)].byteStride != 0) {
        stride = views[static_cast<std::size_t>(view_index)].byteStride;
        if (stride < elem)
            fail(where + ": bufferViews[" + std::to_string(view_index) + "].byteStride " +
                 std::to_string(stride) + " is smaller than the element size " +
                 std::to_string(elem));
    }
    const std::size_t needed = stride * (count - 1) + elem;
    const std::uint8_t* base = checked_view_bytes(model, view_index, byte_offset, needed, where);
    const std::uint32_t csize = component_size(component_type);
    for (std::size_t i = 0; i < count; ++i)
        for (std::uint32_t c = 0; c < components; ++c) store(i, c, base + i * stride + c * csize);
}

void validate_accessor_shape(const tinygltf::Accessor& acc, const std::string& where) {
    if (component_size(acc.componentType) == 0)
        fail(where + ": componentType " + std::to_string(acc.componentType) + " is not valid");
    if (type_components(acc.type) == 0)
        fail(where + ": accessor type " + std::to_string(acc.type) +
             " is not SCALAR/VEC2/VEC3/VEC4");
}

} // namespace

std::uint32_t accessor_count(const tinygltf::Model& model, int index, const std::string& where) {
    const auto& acc = checked_accessor(model, index, where);
    if (acc.count > 0xFFFFFFFFull / 64)
        fail(where + ": accessor count " + std::to_string(acc.count) + " is absurd");
    return static_cast<std::uint32_t>(acc.count);
}

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
    const std::size_t count = accessor_count(model, index, where);
    std::vector<float> out(count * components, 0.0f);
    if (acc.bufferView >= 0) {
        read_strided(model, acc.bufferView, acc.byteOffset, count, components, acc.componentType,
                     path, [&](std::size_t i, std::uint32_t c, const std::uint8_t* p) {
                         out[i * components + c] =
                             decode_component(p, acc.componentType, acc.normalized);
                     });
    }
    if (acc.sparse.isSparse) {
        const auto& sp = acc.sparse;
        const std::string sp_path = path + ".sparse";
        if (sp.count < 0 || static_cast<std::size_t>(sp.count) > count)
            fail(sp_path + ": count " + std::to_string(sp.count) + " exceeds accessor count " +
                 std::to_string(count));
        const int itype = sp.indices.componentType;
        if (itype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            itype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            itype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(sp_path + ".indices: componentType " + std::to_string(itype) +
                 " is not an unsigned integer type");
        std::vector<std::uint32_t> targets(static_cast<std::size_t>(sp.count));
        read_strided(model, sp.indices.bufferView, static_cast<std::size_t>(sp.indices.byteOffset),
                     targets.size(), 1, itype, sp_path + ".indices",
                     [&](std::size_t i, std::uint32_t, const std::uint8_t* p) {
                         targets[i] = decode_index(p, itype);
                     });
        std::vector<float> values(targets.size() * components);
        // Sparse values are tightly packed: the bufferView must not be strided.
        read_strided(model, sp.values.bufferView, static_cast<std::size_t>(sp.values.byteOffset),
                     targets.size(), components, acc.componentType, sp_path + ".values",
                     [&](std::size_t i, std::uint32_t c, const std::uint8_t* p) {
                         values[i * components + c] =
                             decode_component(p, acc.componentType, acc.normalized);
                     });
        for (std::size_t i = 0; i < targets.size(); ++i) {
            if (targets[i] >= count)
                fail(sp_path + ".indices[" + std::to_string(i) +
                     "] = " + std::to_string(targets[i]) + " is beyond the accessor count " +
                     std::to_string(count));
            std::copy_n(&values[i * components], components, &out[targets[i] * components]);
        }
    }
    return out;
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
    if (acc.sparse.isSparse) {
        // Rare but legal: decode via the float path (exact for values < 2^24), then convert.
        std::uint32_t comps = 0;
        const auto f = read_accessor_floats(model, index, {1}, comps, where);
        std::vector<std::uint32_t> out(f.size());
        for (std::size_t i = 0; i < f.size(); ++i) out[i] = static_cast<std::uint32_t>(f[i]);
        return out;
    }
    const std::size_t count = accessor_count(model, index, where);
    std::vector<std::uint32_t> out(count, 0);
    if (acc.bufferView < 0) return out;
    read_strided(
        model, acc.bufferView, acc.byteOffset, count, 1, ct, path,
        [&](std::size_t i, std::uint32_t, const std::uint8_t* p) { out[i] = decode_index(p, ct); });
    return out;
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

} // namespace sherpa::detail
