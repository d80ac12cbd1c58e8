#include "gltf_meshopt.h"

#include "checked_math.h"
#include "import_error.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>

#include <meshoptimizer.h>
#include <tiny_gltf.h>

namespace sherpa::detail {
namespace {

constexpr const char* kCodecs[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};

// "0.18" for MESHOPTIMIZER_VERSION 180.
std::string library_version() {
    return std::to_string(MESHOPTIMIZER_VERSION / 1000) + "." +
           std::to_string(MESHOPTIMIZER_VERSION % 1000 / 10);
}

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

struct Stream {
    std::size_t buffer = 0, offset = 0, length = 0, stride = 0, count = 0;
    std::string mode, filter = "NONE";
};

// An integer property of the extension object. validate_gltf_bytes checked it in the
// raw JSON (within int's range: tinygltf wraps larger values; see json_checker.h).
std::size_t number(const tinygltf::Value& ext, const char* key, const std::string& where,
                   bool required) {
    if (!ext.Has(key)) {
        if (required) fail(where + "." + key + ": required property is missing");
        return 0;
    }
    const tinygltf::Value& v = ext.Get(key);
    const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (!(d >= 0 && d <= 9.0e15) || d != static_cast<double>(static_cast<std::uint64_t>(d)))
        fail(where + "." + key + ": not a non-negative integer");
    return static_cast<std::size_t>(d);
}

std::string text(const tinygltf::Value& ext, const char* key, const std::string& where,
                 bool required) {
    if (!ext.Has(key)) {
        if (required) fail(where + "." + key + ": required property is missing");
        return {};
    }
    if (!ext.Get(key).IsString()) fail(where + "." + key + ": not a string");
    return ext.Get(key).Get<std::string>();
}

// The stream a view's extension object describes, checked against the extension's
// rules (strides, counts, modes, filters).
Stream read_stream(const tinygltf::Value& ext, const std::string& where) {
    Stream s;
    s.buffer = number(ext, "buffer", where, true);
    s.offset = number(ext, "byteOffset", where, false);
    s.length = number(ext, "byteLength", where, true);
    s.stride = number(ext, "byteStride", where, true);
    s.count = number(ext, "count", where, true);
    s.mode = text(ext, "mode", where, true);
    if (ext.Has("filter")) s.filter = text(ext, "filter", where, false);
    const std::string at = where + ": ";
    if (s.mode == "ATTRIBUTES") {
        if (s.stride == 0 || s.stride % 4 || s.stride > 256)
            fail(at + "byteStride " + std::to_string(s.stride) +
                 " is not a multiple of 4 in [4, 256], as ATTRIBUTES needs");
    } else if (s.mode == "TRIANGLES" || s.mode == "INDICES") {
        if (s.stride != 2 && s.stride != 4)
            fail(at + "byteStride " + std::to_string(s.stride) + " is not 2 or 4, as " + s.mode +
                 " needs");
        if (s.mode == "TRIANGLES" && s.count % 3)
            fail(at + "count " + std::to_string(s.count) + " is not a multiple of 3 (TRIANGLES)");
        if (s.filter != "NONE") fail(at + "filter " + s.filter + " on " + s.mode + " data");
    } else {
        fail(at + "mode \"" + s.mode + "\" is not ATTRIBUTES, TRIANGLES or INDICES");
    }
    if (s.filter == "OCTAHEDRAL" && s.stride != 4 && s.stride != 8)
        fail(at + "OCTAHEDRAL filter needs byteStride 4 or 8, not " + std::to_string(s.stride));
    if (s.filter == "QUATERNION" && s.stride != 8)
        fail(at + "QUATERNION filter needs byteStride 8, not " + std::to_string(s.stride));
    if (s.filter != "NONE" && s.filter != "OCTAHEDRAL" && s.filter != "QUATERNION" &&
        s.filter != "EXPONENTIAL")
        fail(at + "filter \"" + s.filter + "\" is not decoded by Debian's meshoptimizer " +
             library_version() + " (it knows NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL)");
    return s;
}

std::string hex(unsigned byte);

// The bitstream version the stream's header byte names, checked against what this
// meshoptimizer decodes: vertex streams 0xA0|v (v 0 here; version 1 came with
// meshoptimizer 0.23 and KHR_meshopt_compression), index streams 0xE0|v / 0xD0|v.
void check_version(std::span<const std::uint8_t> data, const Stream& s, const std::string& where) {
    if (data.empty()) fail(where + ": the compressed stream is empty");
    const unsigned kind = data[0] & 0xF0u, version = data[0] & 0x0Fu;
    const unsigned expected = s.mode == "ATTRIBUTES"  ? 0xA0u
                              : s.mode == "TRIANGLES" ? 0xE0u
                                                      : 0xD0u;
    const unsigned newest = s.mode == "ATTRIBUTES" ? 0u : 1u;
    if (kind != expected)
        fail(where + ": the " + s.mode + " stream's header byte " + hex(data[0]) +
             " is not a meshopt " + s.mode + " stream (corrupt)");
    if (version > newest)
        fail(where + ": " + s.mode + " bitstream version " + std::to_string(version) +
             " is not supported by Debian's meshoptimizer " + library_version() +
             " (it decodes version " + std::to_string(newest) + (newest ? " and older" : " only") +
             ")");
}

std::string hex(unsigned byte) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%02X", byte);
    return text;
}

// The most bytes `length` compressed bytes can decode to, from the minimum sizes
// meshoptimizer's decoders (bitstream version 0, the one check_version lets through)
// demand before decoding: a vertex block spends at least 2 header bits per 16 bytes of
// a byte column (64:1), an index buffer 1 byte per triangle plus 17 (3 indices of at
// most 4 bytes: 12:1), an index sequence 1 byte per index plus 5 (4:1).
std::uint64_t max_decoded_bytes(const Stream& s, std::uint64_t length) {
    const std::uint64_t ratio = s.mode == "ATTRIBUTES" ? 64 : s.mode == "TRIANGLES" ? 12 : 4;
    return length * ratio; // length < 2^53: no wrap
}

int decode(std::uint8_t* out, const Stream& s, std::span<const std::uint8_t> data) {
    if (s.mode == "ATTRIBUTES")
        return meshopt_decodeVertexBuffer(out, s.count, s.stride, data.data(), data.size());
    if (s.mode == "TRIANGLES")
        return meshopt_decodeIndexBuffer(out, s.count, s.stride, data.data(), data.size());
    return meshopt_decodeIndexSequence(out, s.count, s.stride, data.data(), data.size());
}

void apply_filter(std::uint8_t* out, const Stream& s) {
    if (s.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out, s.count, s.stride);
    if (s.filter == "QUATERNION") meshopt_decodeFilterQuat(out, s.count, s.stride);
    if (s.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out, s.count, s.stride);
}

} // namespace

std::vector<DecodedView> decode_meshopt_views(tinygltf::Model& model) {
    std::vector<DecodedView> decoded;
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        for (const char* codec : kCodecs) {
            const auto ext = model.bufferViews[v].extensions.find(codec);
            if (ext == model.bufferViews[v].extensions.end()) continue;
            const std::string where = "bufferViews[" + std::to_string(v) + "].extensions." + codec;
            const Stream s = read_stream(ext->second, where);
            if (s.buffer >= model.buffers.size())
                fail(where + ".buffer: buffer index " + std::to_string(s.buffer) + " out of range");
            const auto& source = model.buffers[s.buffer].data;
            if (!range_fits(s.offset, s.length, source.size()))
                fail(where + ": byteOffset " + std::to_string(s.offset) + " + byteLength " +
                     std::to_string(s.length) + " exceeds buffers[" + std::to_string(s.buffer) +
                     "] (" + std::to_string(source.size()) + " bytes)");
            const auto size = checked_mul(s.count, s.stride);
            tinygltf::BufferView& view = model.bufferViews[v];
            if (!size || *size > view.byteLength)
                fail(where + ": count " + std::to_string(s.count) + " x byteStride " +
                     std::to_string(s.stride) + " exceeds the view's byteLength " +
                     std::to_string(view.byteLength));
            const std::span<const std::uint8_t> data(source.data() + s.offset, s.length);
            check_version(data, s, where);
            // The view's byteLength is only declared (its fallback buffer has no bytes,
            // and may claim gigabytes): what is allocated is what the stream decodes,
            // and that is bounded by the stream's own size first.
            if (*size > max_decoded_bytes(s, s.length))
                fail(where + ": count " + std::to_string(s.count) + " x byteStride " +
                     std::to_string(s.stride) + " = " + std::to_string(*size) +
                     " bytes cannot come from a " + std::to_string(s.length) + "-byte " + s.mode +
                     " stream (at most " + std::to_string(max_decoded_bytes(s, s.length)) +
                     "): corrupt");
            const auto t0 = std::chrono::steady_clock::now();
            // The view shrinks to the decoded bytes: an accessor reading past them is
            // refused by the accessor reader ("past the end of bufferViews[N]") rather
            // than shown zeros the file never held.
            tinygltf::Buffer out;
            out.data.assign(*size, 0);
            view.byteLength = *size;
            if (const int rc = decode(out.data.data(), s, data); rc != 0)
                fail(where + ": the " + s.mode + " stream does not decode (meshoptimizer error " +
                     std::to_string(rc) + ": truncated or corrupt data)");
            apply_filter(out.data.data(), s);
            const double ms = ms_since(t0);
            model.buffers.push_back(std::move(out));
            view.buffer = static_cast<int>(model.buffers.size() - 1);
            view.byteOffset = 0;
            decoded.push_back({static_cast<std::int32_t>(v), codec,
                               s.mode + (s.filter == "NONE" ? "" : "/" + s.filter), s.length, *size,
                               ms});
        }
    }
    return decoded;
}

void attach_meshopt_compression(const tinygltf::Model& model, std::span<const DecodedView> views,
                                Scene& scene) {
    if (views.empty()) return;
    std::map<int, const DecodedView*> by_view;
    for (const auto& d : views) by_view[d.view] = &d;
    for (PrimitiveInfo& info : scene.primitives) {
        const auto& prim = model.meshes.at(info.mesh).primitives.at(info.primitive);
        std::vector<int> accessors;
        for (const auto& [name, a] : prim.attributes) accessors.push_back(a);
        if (prim.indices >= 0) accessors.push_back(prim.indices);
        PrimitiveCompression c;
        std::set<int> seen;
        std::set<std::string> modes;
        for (const int a : accessors) {
            if (a < 0 || std::size_t(a) >= model.accessors.size()) continue;
            const auto it = by_view.find(model.accessors[std::size_t(a)].bufferView);
            if (it == by_view.end() || !seen.insert(it->first).second) continue;
            c.codec = it->second->codec;
            if (modes.insert(it->second->mode).second)
                c.modes += (c.modes.empty() ? "" : ", ") + it->second->mode;
            c.encoded_bytes += it->second->encoded_bytes;
            c.decoded_bytes += it->second->decoded_bytes;
            c.decode_ms += it->second->decode_ms;
        }
        if (!c.codec.empty()) info.compression = std::move(c);
    }
}

} // namespace sherpa::detail
