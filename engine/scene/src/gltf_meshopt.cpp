#include "gltf_meshopt.h"

#include "checked_math.h"
#include "import_error.h"
#include "meshopt_codec.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <set>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

constexpr const char* kCodecs[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::optional<meshopt::Filter> filter_of(const std::string& name) {
    if (name == "NONE") return meshopt::Filter::None;
    if (name == "OCTAHEDRAL") return meshopt::Filter::Octahedral;
    if (name == "QUATERNION") return meshopt::Filter::Quaternion;
    if (name == "EXPONENTIAL") return meshopt::Filter::Exponential;
    if (name == "COLOR") return meshopt::Filter::Color;
    return std::nullopt;
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
    if (s.filter == "COLOR" && s.stride != 4 && s.stride != 8)
        fail(at + "COLOR filter needs byteStride 4 or 8, not " + std::to_string(s.stride));
    if (!filter_of(s.filter))
        fail(at + "filter \"" + s.filter +
             "\" is not NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL or COLOR");
    return s;
}

std::string hex(unsigned byte) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%02X", byte);
    return text;
}

meshopt::Mode mode_of(const Stream& s) {
    return s.mode == "ATTRIBUTES"  ? meshopt::Mode::Attributes
           : s.mode == "TRIANGLES" ? meshopt::Mode::Triangles
                                   : meshopt::Mode::Indices;
}

// Why the stream cannot be decoded, or empty once `out` holds its decoded (and
// filtered) bytes. `out` is allocated only for a stream long enough to hold
// `count` elements at its version (scene::meshopt::minimum_stream_size): the view's declared
// byteLength may claim gigabytes that its fallback buffer does not have.
std::string decode_stream(std::vector<unsigned char>& out, const Stream& s, std::size_t size,
                          std::span<const std::uint8_t> data) {
    const meshopt::Mode mode = mode_of(s);
    const meshopt::Result header = meshopt::read_header(data, meshopt::header_kind(mode));
    if (header.status == meshopt::Status::Truncated) return "the compressed stream is empty";
    if (header.status == meshopt::Status::BadHeader)
        return "the " + s.mode + " stream's header byte " + hex(data[0]) + " is not a meshopt " +
               s.mode + " stream (corrupt)";
    const unsigned version = data[0] & 0x0Fu;
    if (header.status == meshopt::Status::BadVersion)
        return s.mode + " bitstream version " + std::to_string(version) +
               " is not one the specification defines (0 or 1)";
    const std::size_t least = meshopt::minimum_stream_size(mode, version, s.count, s.stride);
    if (data.size() < least)
        return "count " + std::to_string(s.count) + " x byteStride " + std::to_string(s.stride) +
               " = " + std::to_string(size) + " bytes cannot come from a " +
               std::to_string(data.size()) + "-byte " + s.mode + " stream (version " +
               std::to_string(version) + " needs at least " + std::to_string(least) + ")";
    out.assign(size, 0);
    const std::span<std::uint8_t> dst(out.data(), out.size());
    const meshopt::Result r = meshopt::decode(mode, dst, s.count, s.stride, data);
    if (!r)
        return "the " + s.mode + " stream (version " + std::to_string(version) +
               ") does not decode: " + meshopt::describe(r.status) + " at byte " +
               std::to_string(r.offset) + " of " + std::to_string(data.size());
    meshopt::apply_filter(*filter_of(s.filter), dst, s.count, s.stride); // stride checked
    return {};
}

// Whether `view`'s own (uncompressed fallback) range holds bytes of the file: its
// buffer was read (`readable`: empty for a buffer that was not, and a fallback buffer
// without a URI is a 1-byte stand-in) and is long enough.
bool has_fallback_bytes(const tinygltf::BufferView& view,
                        std::span<const std::span<const std::uint8_t>> readable) {
    return view.buffer >= 0 && std::size_t(view.buffer) < readable.size() && view.byteLength > 0 &&
           range_fits(view.byteOffset, view.byteLength, readable[std::size_t(view.buffer)].size());
}

} // namespace

std::vector<DecodedView>
decode_meshopt_views(tinygltf::Model& model,
                     std::span<const std::span<const std::uint8_t>> readable) {
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
            DecodedView d;
            d.view = static_cast<std::int32_t>(v);
            d.codec = codec;
            d.mode = s.mode + (s.filter == "NONE" ? "" : "/" + s.filter);
            d.encoded_bytes = s.length;
            d.decoded_bytes = *size;
            const auto t0 = std::chrono::steady_clock::now();
            tinygltf::Buffer out;
            std::string problem = decode_stream(out.data, s, *size, data);
            d.decode_ms = ms_since(t0);
            if (!problem.empty()) {
                // The view's uncompressed bytes where the file has them, else nothing:
                // the primitives reading it are skipped by name (undecodable_primitives).
                d.failed = where + ": " + problem;
                if (has_fallback_bytes(view, readable)) {
                    d.fell_back = true;
                    d.failed += "; the view's uncompressed fallback bytes (buffers[" +
                                std::to_string(view.buffer) + "]) are shown instead";
                } else {
                    view.byteLength = 0; // nothing decoded: every read of it is refused
                    view.buffer = static_cast<int>(model.buffers.size());
                    model.buffers.emplace_back();
                    view.byteOffset = 0;
                }
                decoded.push_back(std::move(d));
                continue;
            }
            // The view shrinks to the decoded bytes: an accessor reading past them is
            // refused by the accessor reader ("past the end of bufferViews[N]") rather
            // than shown zeros the file never held.
            view.byteLength = *size;
            model.buffers.push_back(std::move(out));
            view.buffer = static_cast<int>(model.buffers.size() - 1);
            view.byteOffset = 0;
            decoded.push_back(std::move(d));
        }
    }
    return decoded;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, std::string>
undecodable_primitives(const tinygltf::Model& model, std::span<const DecodedView> views) {
    std::map<int, const DecodedView*> failed;
    for (const auto& d : views)
        if (!d.failed.empty() && !d.fell_back) failed[d.view] = &d;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> out;
    if (failed.empty()) return out;
    const auto reason = [&](int accessor) -> const DecodedView* {
        if (accessor < 0 || std::size_t(accessor) >= model.accessors.size()) return nullptr;
        const auto it = failed.find(model.accessors[std::size_t(accessor)].bufferView);
        return it == failed.end() ? nullptr : it->second;
    };
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const auto& prim = model.meshes[m].primitives[p];
            const DecodedView* d = reason(prim.indices);
            for (const auto& [name, a] : prim.attributes) d = d ? d : reason(a);
            for (const auto& target : prim.targets)
                for (const auto& [name, a] : target) d = d ? d : reason(a);
            if (d) out.emplace(std::pair{std::uint32_t(m), std::uint32_t(p)}, d->failed);
        }
    return out;
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
            if (it == by_view.end() || !it->second->failed.empty() ||
                !seen.insert(it->first).second)
                continue;
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

} // namespace sherpa::scene::detail
