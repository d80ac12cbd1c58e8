#include "gltf_draco.h"

#include "accessor_reader.h"
#include "checked_math.h"
#include "draco_attributes.h"
#include "draco_header.h"
#include "gltf_prepare.h"
#include "import_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <new>

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>
#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

constexpr const char* kCodec = "KHR_draco_mesh_compression";

// What one Draco primitive may declare (docs/robustness.md, "Sizes the file
// declares"). A Draco stream's counts are not backed by its bytes (a constant
// attribute entropy-codes to almost nothing), and neither are the counts of the
// accessors it decodes into, which have no buffer data: these limits bound what
// Draco allocates for a primitive whose counts agree with its accessors.
constexpr std::uint64_t kMaxDracoPoints = std::uint64_t{1} << 24;
constexpr std::uint64_t kMaxDracoTriangles = std::uint64_t{1} << 24;

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
    // Adds a view from `offset` to the end of the data (rows `stride` bytes apart,
    // 0: tightly packed); its index.
    int end_view(std::size_t offset, std::size_t stride = 0) {
        tinygltf::BufferView view;
        view.buffer = index_;
        view.byteOffset = offset;
        view.byteLength = data().size() - offset;
        view.byteStride = stride;
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
    // Draco quantizes every component on one grid over the largest declared range: the
    // slack follows that range, not each component's own (VC's flat parts).
    double range = 1e-6;
    for (int c = 0; c < comps; ++c)
        range = std::max(range, a.maxValues[std::size_t(c)] - a.minValues[std::size_t(c)]);
    for (int c = 0; c < comps; ++c) {
        const double dlo = a.minValues[std::size_t(c)], dhi = a.maxValues[std::size_t(c)];
        const double slack = 1e-3 * range;
        if (lo[c] >= dlo - slack && hi[c] <= dhi + slack) continue;
        fail(where + ": decoded component " + std::to_string(c) + " value " +
             std::to_string(lo[c] < dlo - slack ? lo[c] : hi[c]) +
             " lies outside the accessor's declared [" + std::to_string(dlo) + ", " +
             std::to_string(dhi) + "]");
    }
}

// Draco's mesh decoder gives triangle faces; the primitive must draw them as they
// are. KHR_draco_mesh_compression allows TRIANGLES and TRIANGLE_STRIP, but a
// stream's faces are a list: read as a strip (or any other mode) they draw garbage,
// so another mode is named and the faces are drawn as TRIANGLES. A primitive without
// `indices` draws its points in order, right only when face f is (3f, 3f+1, 3f+2);
// otherwise it is named and given an index accessor over Draco's faces.
void check_mode_and_indices(tinygltf::Model& model, tinygltf::Primitive& prim,
                            const draco::Mesh& mesh, const std::string& prim_path,
                            DecodedDracoPrimitive& out) {
    const std::size_t faces = mesh.num_faces(), points = mesh.num_points();
    if (faces == 0 && prim.mode == TINYGLTF_MODE_POINTS && prim.indices < 0) return;
    if (prim.mode != TINYGLTF_MODE_TRIANGLES) {
        out.warnings.push_back(
            prim_path + ".mode: " + std::to_string(prim.mode) + " (" +
            std::string(to_string(static_cast<PrimitiveMode>(std::clamp(prim.mode, 0, 6)))) +
            ") contradicts the Draco stream, which holds " + std::to_string(faces) +
            " triangles as a list; drawn as TRIANGLES (4)");
        prim.mode = TINYGLTF_MODE_TRIANGLES;
    }
    if (prim.indices >= 0) return;
    bool in_order = points == faces * 3;
    for (std::size_t f = 0; f < faces && in_order; ++f) {
        const draco::Mesh::Face& face = mesh.face(draco::FaceIndex(std::uint32_t(f)));
        in_order = face[0].value() == 3 * f && face[1].value() == 3 * f + 1 &&
                   face[2].value() == 3 * f + 2;
    }
    if (in_order) return;
    out.warnings.push_back(prim_path + ".indices: missing, but the Draco stream's " +
                           std::to_string(faces) + " triangles index its " +
                           std::to_string(points) +
                           " points out of order; drawn with the stream's triangles");
    tinygltf::Accessor a;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.count = faces * 3;
    a.name = "Draco faces";
    model.accessors.push_back(std::move(a));
    prim.indices = static_cast<int>(model.accessors.size() - 1);
}

std::string declared_text(const DracoCounts& c) {
    return c.method == DracoMethod::Sequential
               ? std::to_string(c.points) + " points and " + std::to_string(c.faces) + " triangles"
               : std::to_string(c.encoded_vertices) + " vertices and " + std::to_string(c.faces) +
                     " triangles";
}

// The largest count among the primitive's attribute accessors: what the decoded points
// must fit (decode_primitive requires each Draco-decoded accessor's count to equal the
// stream's points).
std::size_t largest_attribute_count(const tinygltf::Model& model, const tinygltf::Primitive& prim) {
    std::size_t largest = 0;
    for (const auto& [name, index] : prim.attributes)
        if (index >= 0 && std::size_t(index) < model.accessors.size())
            largest = std::max(largest, model.accessors[std::size_t(index)].count);
    return largest;
}

// The stream's declared counts, read before Draco sees the stream and bounded by what
// the glTF declares for the primitive (its attribute and index accessor counts, its
// mapped attributes: `ext` has an "attributes" object) and by the documented limits.
// Draco sizes its tables by these counts before it reads the data behind them; a
// stream over a bound is refused here, unallocated.
DracoCounts check_declared_counts(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                                  const tinygltf::Value& ext, std::span<const std::uint8_t> stream,
                                  int view, const std::string& where) {
    const std::string at = where + ": the Draco stream (bufferViews[" + std::to_string(view) +
                           "], " + std::to_string(stream.size()) + " bytes)";
    DracoCounts c;
    std::string error;
    if (!read_draco_counts(stream, c, error)) fail(at + " does not decode: " + error);
    const std::size_t points = largest_attribute_count(model, prim);
    const bool sequential = c.method == DracoMethod::Sequential;
    const std::uint64_t vertices = sequential ? c.points : c.encoded_vertices;
    const char* what = sequential ? " points" : " vertices";
    // What the file contradicts first, then what it may declare.
    if (vertices > points)
        fail(at + " declares " + std::to_string(vertices) + what +
             ", more than the primitive's attribute accessors hold (count " +
             std::to_string(points) + ")");
    if (prim.indices >= 0 && std::size_t(prim.indices) < model.accessors.size()) {
        const std::size_t indices = model.accessors[std::size_t(prim.indices)].count;
        if (std::uint64_t(c.faces) * 3 > indices)
            fail(at + " declares " + std::to_string(c.faces) + " triangles (" +
                 std::to_string(std::uint64_t(c.faces) * 3) +
                 " indices), more than the indices accessor's count " + std::to_string(indices));
    }
    // Position is the connectivity itself: the other attributes have one each at most.
    const std::size_t attributes = ext.Get("attributes").Keys().size();
    if (!sequential && c.attribute_data > attributes)
        fail(at + " declares " + std::to_string(c.attribute_data) +
             " attribute connectivities for " + std::to_string(attributes) + " attributes");
    if (vertices > kMaxDracoPoints)
        fail(at + " declares " + std::to_string(vertices) + what + "; Sherpa decodes at most " +
             std::to_string(kMaxDracoPoints) + " points per Draco primitive");
    if (c.faces > kMaxDracoTriangles)
        fail(at + " declares " + std::to_string(c.faces) + " triangles; Sherpa decodes at most " +
             std::to_string(kMaxDracoTriangles) + " triangles per Draco primitive");
    return c;
}

void decode_primitive(tinygltf::Model& model, tinygltf::Primitive& prim,
                      const std::string& prim_path, DecodedDracoPrimitive& out) {
    const std::string where = prim_path + ".extensions." + kCodec;
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
    if (!ext.Has("attributes") || !ext.Get("attributes").IsObject())
        fail(where + ".attributes: required object is missing");
    const auto* data = model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset;
    const DracoCounts counts =
        check_declared_counts(model, prim, ext, {data, view.byteLength}, v, where);
    const auto t0 = std::chrono::steady_clock::now();
    draco::DecoderBuffer stream;
    stream.Init(reinterpret_cast<const char*>(data), view.byteLength);
    draco::Decoder decoder;
    // What the counts leave unbounded: Draco's per-point attribute tables, whose
    // component counts (up to 255) come later in the stream.
    auto decoded = [&] {
        try {
            return decoder.DecodeMeshFromBuffer(&stream);
        } catch (const std::bad_alloc&) {
            fail(where + ": the Draco stream (bufferViews[" + std::to_string(v) + "], " +
                 std::to_string(view.byteLength) + " bytes) declares " + declared_text(counts) +
                 "; Draco ran out of memory decoding it");
        }
    }();
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
        const std::size_t stride = append_draco_attribute(*att, points, comps, a.componentType,
                                                          a.normalized, buffer.data(), aw);
        // Dequantized floats get Draco's quantization slack here; integers are exact,
        // and the importer checks them like any other accessor.
        if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
            check_min_max(a, buffer.data().data() + offset, points, comps, aw);
            out.range_checked.push_back(used->second);
        }
        const std::size_t row =
            std::size_t(comps) *
            std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType)));
        a.bufferView = buffer.end_view(offset, stride == row ? 0 : stride);
        a.byteOffset = 0;
        a.sparse = {};
        out.stats.decoded_bytes += points * stride;
    }
    const std::size_t faces = mesh->num_faces();
    check_mode_and_indices(model, prim, *mesh, prim_path, out);
    if (prim.indices >= 0) {
        tinygltf::Accessor& a = model.accessors.at(std::size_t(prim.indices));
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
        a.sparse = {};
        out.stats.decoded_bytes += faces * 3 * sizeof(std::uint32_t);
    }
    out.stats.codec = kCodec;
    out.stats.modes = edgebreaker ? "edgebreaker" : "sequential";
    // Draco holds no morph targets: they stay plain accessors in the stream's point
    // order (which only sequential coding keeps), and info says so.
    if (!prim.targets.empty())
        out.stats.modes +=
            ", " + std::to_string(prim.targets.size()) + " morph targets uncompressed";
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
            DecodedDracoPrimitive d{std::uint32_t(m), std::uint32_t(p), {}, {}, {}, {}};
            try {
                decode_primitive(
                    model, prim,
                    "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]", d);
            } catch (const ImportError& e) {
                // The primitive is skipped by name; the file's other primitives load.
                // Its accessors keep no data (they were never pointed at decoded bytes,
                // or only some were): nothing reads them once the primitive is gone.
                d.failed = e.what();
                d.range_checked.clear();
            }
            decoded.push_back(std::move(d));
        }
    return decoded;
}

void attach_draco_compression(std::span<const DecodedDracoPrimitive> decoded, Scene& scene) {
    for (const auto& d : decoded)
        for (PrimitiveInfo& info : scene.primitives)
            if (d.failed.empty() && info.mesh == d.mesh && info.primitive == d.primitive)
                info.compression = d.stats;
}

} // namespace sherpa::scene::detail
