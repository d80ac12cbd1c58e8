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

// Appends `bytes` to `buffer` 4-byte aligned and adds a view on them; its index.
int add_view(tinygltf::Model& model, int buffer, const void* bytes, std::size_t size) {
    auto& data = model.buffers[std::size_t(buffer)].data;
    data.resize((data.size() + 3) / 4 * 4);
    tinygltf::BufferView view;
    view.buffer = buffer;
    view.byteOffset = data.size();
    view.byteLength = size;
    const auto* b = static_cast<const std::uint8_t*>(bytes);
    data.insert(data.end(), b, b + size);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size() - 1);
}

// The declared min/max must hold what Draco produced, up to its quantization (a
// small fraction of the declared range).
void check_min_max(const tinygltf::Accessor& a, const std::vector<float>& values, int comps,
                   const std::string& where) {
    if (a.minValues.size() != std::size_t(comps) || a.maxValues.size() != std::size_t(comps))
        return;
    for (int c = 0; c < comps; ++c) {
        const double lo = a.minValues[std::size_t(c)], hi = a.maxValues[std::size_t(c)];
        const double slack = 1e-3 * std::max(hi - lo, 1e-6);
        for (std::size_t i = std::size_t(c); i < values.size(); i += std::size_t(comps))
            if (values[i] < lo - slack || values[i] > hi + slack)
                fail(where + ": decoded component " + std::to_string(c) + " value " +
                     std::to_string(values[i]) + " lies outside the accessor's declared [" +
                     std::to_string(lo) + ", " + std::to_string(hi) + "]");
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

    // The decoded data goes to one new buffer; the accessors are pointed at it.
    model.buffers.emplace_back();
    const int buffer = static_cast<int>(model.buffers.size() - 1);
    if (!ext.Has("attributes") || !ext.Get("attributes").IsObject())
        fail(where + ".attributes: required object is missing");
    const tinygltf::Value& ids = ext.Get("attributes");
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
        std::vector<float> values(points * std::size_t(comps));
        for (std::size_t i = 0; i < points; ++i)
            if (!att->ConvertValue<float>(att->mapped_index(draco::PointIndex(std::uint32_t(i))),
                                          std::int8_t(comps), &values[i * std::size_t(comps)]))
                fail(aw + ": Draco could not convert point " + std::to_string(i) + " to float");
        if (a.normalized && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT &&
            att->data_type() != draco::DT_FLOAT32) {
            const float scale = normalized_max(a.componentType);
            for (float& x : values) x = std::max(x / scale, -1.0f);
        }
        check_min_max(a, values, comps, aw);
        out.range_checked.push_back(used->second);
        a.bufferView = add_view(model, buffer, values.data(), values.size() * sizeof(float));
        a.byteOffset = 0;
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.normalized = false;
        a.sparse = {};
        out.stats.decoded_bytes += values.size() * sizeof(float);
    }
    if (prim.indices >= 0) {
        tinygltf::Accessor& a = model.accessors.at(std::size_t(prim.indices));
        std::vector<std::uint32_t> indices;
        indices.reserve(mesh->num_faces() * 3);
        for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
            for (const auto& p : mesh->face(f)) indices.push_back(p.value());
        if (a.count != indices.size())
            fail(where + ": indices accessor count " + std::to_string(a.count) +
                 " but Draco decoded " + std::to_string(indices.size()) + " indices");
        a.bufferView =
            add_view(model, buffer, indices.data(), indices.size() * sizeof(std::uint32_t));
        a.byteOffset = 0;
        a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        out.stats.decoded_bytes += indices.size() * sizeof(std::uint32_t);
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
