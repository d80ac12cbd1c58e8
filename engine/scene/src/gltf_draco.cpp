#include "gltf_draco.h"

#include "accessor_reader.h"
#include "checked_math.h"
#include "gltf_prepare.h"
#include "import_error.h"

#include <chrono>
#include <cmath>
#include <cstring>

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>
#include <tiny_gltf.h>

namespace sherpa::detail {
namespace {

constexpr const char* kCodec = "KHR_draco_mesh_compression";

// Largest value of a normalized integer component type (glTF's normalization).
float normalized_max(int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return 127.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 255.0f;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return 32767.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 65535.0f;
    default:
        return 1.0f;
    }
}

// The decoded data of one primitive goes to one new buffer, written in place (no
// intermediate copies): views are appended 4-byte aligned. Its bytes are reserved
// up front for every attribute of the mesh, so the appends do not reallocate.
class OutputBuffer {
public:
    OutputBuffer(tinygltf::Model& model, std::size_t reserve)
        : model_(model), index_(static_cast<int>(model.buffers.size())) {
        model.buffers.emplace_back().data.reserve(reserve);
    }
    std::vector<unsigned char>& data() { return model_.buffers[std::size_t(index_)].data; }
    // Starts a view: its offset (the data is padded to 4 bytes).
    std::size_t begin_view() {
        data().resize((data().size() + 3) / 4 * 4);
        return data().size();
    }
    // Adds a view from `offset` to the end of the data; its index.
    int end_view(std::size_t offset) {
        tinygltf::BufferView view;
        view.buffer = index_;
        view.byteOffset = offset;
        view.byteLength = data().size() - offset;
        model_.bufferViews.push_back(view);
        return static_cast<int>(model_.bufferViews.size() - 1);
    }

private:
    tinygltf::Model& model_;
    int index_;
};

float load_float(const unsigned char* p) {
    float v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// The declared min/max must hold what Draco produced, up to its quantization (a
// small fraction of the declared range). One pass gathers each component's range
// (no branch per value); only a failure names the offending value.
template <int Comps>
void value_range(const unsigned char* values, std::size_t points, float* lo, float* hi) {
    for (int c = 0; c < Comps; ++c) lo[c] = hi[c] = load_float(values + 4 * c);
    for (std::size_t i = 0; i < points; ++i)
        for (int c = 0; c < Comps; ++c) {
            const float v = load_float(values + (i * Comps + std::size_t(c)) * 4);
            lo[c] = std::min(lo[c], v);
            hi[c] = std::max(hi[c], v);
        }
}

void check_min_max(const tinygltf::Accessor& a, const unsigned char* values, std::size_t points,
                   int comps, const std::string& where) {
    if (a.minValues.size() != std::size_t(comps) || a.maxValues.size() != std::size_t(comps) ||
        points == 0 || comps > 4)
        return;
    float lo[4], hi[4];
    switch (comps) {
    case 1:
        value_range<1>(values, points, lo, hi);
        break;
    case 2:
        value_range<2>(values, points, lo, hi);
        break;
    case 3:
        value_range<3>(values, points, lo, hi);
        break;
    default:
        value_range<4>(values, points, lo, hi);
        break;
    }
    for (int c = 0; c < comps; ++c) {
        const double dlo = a.minValues[std::size_t(c)], dhi = a.maxValues[std::size_t(c)];
        const double slack = 1e-3 * std::max(dhi - dlo, 1e-6);
        if (lo[c] >= dlo - slack && hi[c] <= dhi + slack) continue;
        fail(where + ": decoded component " + std::to_string(c) + " value " +
             std::to_string(lo[c] < dlo - slack ? lo[c] : hi[c]) +
             " lies outside the accessor's declared [" + std::to_string(dlo) + ", " +
             std::to_string(dhi) + "]");
    }
}

// Gathers each point's float32 value through Draco's point-to-value map.
template <int Comps>
void gather_floats(const draco::PointAttribute& att, std::size_t points, unsigned char* out,
                   const std::string& where) {
    constexpr std::size_t row = Comps * sizeof(float);
    const std::size_t stored = att.buffer()->data_size();
    for (std::size_t i = 0; i < points; ++i) {
        const draco::AttributeValueIndex v = att.mapped_index(draco::PointIndex(std::uint32_t(i)));
        if (v.value() >= att.size() ||
            std::size_t(att.byte_offset() + std::int64_t(v.value()) * att.byte_stride()) + row >
                stored)
            fail(where + ": Draco maps point " + std::to_string(i) + " to value " +
                 std::to_string(v.value()) + " of " + std::to_string(att.size()));
        std::memcpy(out + i * row, att.GetAddress(v), row);
    }
}

// Appends each point's value of `att` as `comps` floats to `data`. Draco dequantizes
// positions, normals and UVs to float32 itself: those are copied (the whole
// attribute at once when points map to values one to one), others converted.
void append_as_float(const draco::PointAttribute& att, std::size_t points, int comps,
                     std::vector<unsigned char>& data, const std::string& where) {
    const std::size_t row = std::size_t(comps) * sizeof(float), offset = data.size();
    const bool float32 = att.data_type() == draco::DT_FLOAT32 && att.buffer() && comps <= 4;
    if (float32 && att.is_mapping_identity() && std::size_t(att.byte_stride()) == row &&
        att.size() >= points &&
        std::size_t(att.byte_offset()) + points * row <= att.buffer()->data_size()) {
        const unsigned char* src = att.buffer()->data() + att.byte_offset();
        data.insert(data.end(), src, src + points * row);
        return;
    }
    data.resize(offset + points * row);
    unsigned char* out = data.data() + offset;
    if (float32) {
        switch (comps) {
        case 1:
            gather_floats<1>(att, points, out, where);
            return;
        case 2:
            gather_floats<2>(att, points, out, where);
            return;
        case 3:
            gather_floats<3>(att, points, out, where);
            return;
        default:
            gather_floats<4>(att, points, out, where);
            return;
        }
    }
    std::vector<float> value(static_cast<std::size_t>(comps));
    for (std::size_t i = 0; i < points; ++i) {
        if (!att.ConvertValue<float>(att.mapped_index(draco::PointIndex(std::uint32_t(i))),
                                     std::int8_t(comps), value.data()))
            fail(where + ": Draco could not convert point " + std::to_string(i) + " to float");
        std::memcpy(out + i * row, value.data(), row);
    }
}

void decode_primitive(tinygltf::Model& model, tinygltf::Primitive& prim, const std::string& where,
                      DecodedDracoPrimitive& out) {
    const tinygltf::Value& ext = prim.extensions.at(kCodec);
    if (ext.Has(kDracoIndicesKey)) prim.indices = ext.Get(kDracoIndicesKey).GetNumberAsInt();
    if (!ext.Has("bufferView") || !ext.Get("bufferView").IsNumber())
        fail(where + ".bufferView: required index is missing");
    const int v = ext.Get("bufferView").GetNumberAsInt();
    if (v < 0 || std::size_t(v) >= model.bufferViews.size())
        fail(where + ".bufferView: index " + std::to_string(v) + " out of range");
    const auto& view = model.bufferViews[std::size_t(v)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size() ||
        !range_fits(view.byteOffset, view.byteLength,
                    model.buffers[std::size_t(view.buffer)].data.size()))
        fail(where + ": bufferViews[" + std::to_string(v) + "] lies outside its buffer");
    const auto* data = model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset;
    const auto t0 = std::chrono::steady_clock::now();
    draco::DecoderBuffer stream;
    stream.Init(reinterpret_cast<const char*>(data), view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&stream);
    if (!decoded.ok())
        fail(where + ": the Draco stream (bufferViews[" + std::to_string(v) + "], " +
             std::to_string(view.byteLength) +
             " bytes) does not decode: " + decoded.status().error_msg_string());
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    // Read before new buffers and views are appended (which moves `view` and `data`).
    // The stream header: "DRACO", version major/minor, geometry type, method.
    const std::size_t encoded_bytes = view.byteLength;
    const bool edgebreaker = encoded_bytes > 8 && data[8] == 1;
    const std::size_t points = mesh->num_points();

    if (!ext.Has("attributes") || !ext.Get("attributes").IsObject())
        fail(where + ".attributes: required object is missing");
    const tinygltf::Value& ids = ext.Get("attributes");
    // The decoded data goes to one new buffer; the accessors are pointed at it.
    std::size_t reserve =
        mesh->num_faces() * 3 * sizeof(std::uint32_t) + 4 * (ids.Keys().size() + 1);
    for (int i = 0; i < mesh->num_attributes(); ++i)
        reserve += points * std::size_t(mesh->attribute(i)->num_components()) * sizeof(float);
    OutputBuffer buffer(model, reserve);
    for (const auto& name : ids.Keys()) {
        const std::string aw = where + ".attributes." + name;
        const auto used = prim.attributes.find(name);
        if (used == prim.attributes.end())
            fail(aw + ": the primitive has no " + name + " accessor for this Draco attribute");
        if (!ids.Get(name).IsNumber()) fail(aw + ": not an attribute id");
        const draco::PointAttribute* att =
            mesh->GetAttributeByUniqueId(std::uint32_t(ids.Get(name).GetNumberAsInt()));
        if (!att)
            fail(aw + ": attribute id " + std::to_string(ids.Get(name).GetNumberAsInt()) +
                 " is not in the Draco stream");
        tinygltf::Accessor& a = model.accessors.at(std::size_t(used->second));
        const int comps = static_cast<int>(type_components(a.type));
        if (a.count != points)
            fail(aw + ": accessor count " + std::to_string(a.count) + " but Draco decoded " +
                 std::to_string(points) + " points");
        if (comps == 0 || att->num_components() != comps)
            fail(aw + ": accessor has " + std::to_string(comps) + " components but Draco decoded " +
                 std::to_string(int(att->num_components())));
        const std::size_t offset = buffer.begin_view();
        append_as_float(*att, points, comps, buffer.data(), aw);
        unsigned char* values = buffer.data().data() + offset;
        const std::size_t count = points * std::size_t(comps);
        if (a.normalized && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT &&
            att->data_type() != draco::DT_FLOAT32) {
            const float scale = normalized_max(a.componentType);
            for (std::size_t i = 0; i < count; ++i) {
                const float x = std::max(load_float(values + i * 4) / scale, -1.0f);
                std::memcpy(values + i * 4, &x, sizeof x);
            }
        }
        check_min_max(a, values, points, comps, aw);
        out.range_checked.push_back(used->second);
        a.bufferView = buffer.end_view(offset);
        a.byteOffset = 0;
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.normalized = false;
        a.sparse = {};
        out.stats.decoded_bytes += count * sizeof(float);
    }
    if (prim.indices >= 0) {
        tinygltf::Accessor& a = model.accessors.at(std::size_t(prim.indices));
        const std::size_t faces = mesh->num_faces();
        if (a.count != faces * 3)
            fail(where + ": indices accessor count " + std::to_string(a.count) +
                 " but Draco decoded " + std::to_string(faces * 3) + " indices");
        const std::size_t offset = buffer.begin_view();
        buffer.data().resize(offset + faces * 3 * sizeof(std::uint32_t));
        unsigned char* indices = buffer.data().data() + offset;
        for (std::size_t f = 0; f < faces; ++f) {
            const draco::Mesh::Face& face = mesh->face(draco::FaceIndex(std::uint32_t(f)));
            const std::uint32_t tri[3] = {face[0].value(), face[1].value(), face[2].value()};
            std::memcpy(indices + f * sizeof tri, tri, sizeof tri);
        }
        a.bufferView = buffer.end_view(offset);
        a.byteOffset = 0;
        a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        out.stats.decoded_bytes += faces * 3 * sizeof(std::uint32_t);
    }
    out.stats.codec = kCodec;
    out.stats.modes = edgebreaker ? "edgebreaker" : "sequential";
    out.stats.encoded_bytes = encoded_bytes;
    out.stats.decode_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

std::vector<DecodedDracoPrimitive> decode_draco_primitives(tinygltf::Model& model) {
    std::vector<DecodedDracoPrimitive> decoded;
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            auto& prim = model.meshes[m].primitives[p];
            if (!prim.extensions.count(kCodec)) continue;
            DecodedDracoPrimitive d{std::uint32_t(m), std::uint32_t(p), {}, {}};
            decode_primitive(model, prim,
                             "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) +
                                 "]." + kCodec,
                             d);
            decoded.push_back(std::move(d));
        }
    return decoded;
}

void attach_draco_compression(std::span<const DecodedDracoPrimitive> decoded, Scene& scene) {
    for (const auto& d : decoded)
        for (PrimitiveInfo& info : scene.primitives)
            if (info.mesh == d.mesh && info.primitive == d.primitive) info.compression = d.stats;
}

} // namespace sherpa::detail
