// Buffers, buffer views, accessors and the GLB container: the links that decide
// which bytes an accessor reads (validate_internal.h).
#include "validate_internal.h"

#include "checked_math.h"

#include <cstring>
#include <filesystem>

namespace sherpa::scene::detail {
namespace {

bool is_data_uri(std::string_view uri) {
    return uri.size() >= 5 && uri.compare(0, 5, "data:") == 0;
}

// "http://...", "/abs/path", "//host": anything a relative-path resolver would not read.
bool non_relative(std::string_view uri) {
    if (uri.empty() || is_data_uri(uri)) return false;
    if (uri[0] == '/' || uri[0] == '\\') return true;
    const auto colon = uri.find(':');
    if (colon == std::string_view::npos || colon == 0) return false;
    for (std::size_t i = 0; i < colon; ++i) {
        const char c = uri[i];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
              (i > 0 && ((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.'))))
            return false;
    }
    return true;
}

// Decodes %XX escapes; false when an escape is malformed or decodes to NUL.
bool percent_decode(std::string_view in, std::string& out) {
    auto hex = [](char c) {
        return c >= '0' && c <= '9'   ? c - '0'
               : c >= 'a' && c <= 'f' ? c - 'a' + 10
               : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                      : -1;
    };
    out.clear();
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (in[i] != '%') {
            out += in[i];
            continue;
        }
        if (i + 2 >= in.size() || hex(in[i + 1]) < 0 || hex(in[i + 2]) < 0) return false;
        const char c = static_cast<char>(hex(in[i + 1]) * 16 + hex(in[i + 2]));
        if (c == '\0') return false;
        out += c;
        i += 2;
    }
    return true;
}

// A relative URI that names no readable file next to the glTF (missing, a folder, an
// undecodable name): the Khronos IO_ERROR. Only looked at, never read here.
void check_file(Validation& v, std::string_view uri, const std::string& p) {
    if (v.base_dir.empty() && v.glb) return;
    std::string name;
    std::error_code ec;
    const bool decoded = percent_decode(uri, name);
    const std::filesystem::path path =
        std::filesystem::path(v.base_dir.empty() ? "." : v.base_dir) /
        std::filesystem::path(name).relative_path();
    if (decoded && !name.empty() && std::filesystem::is_regular_file(path, ec)) return;
    v.add("IO_ERROR", Severity::Error, p,
          decoded ? "Could not read the file '" + std::string(uri) + "'."
                  : "Could not decode the URI '" + std::string(uri) + "'.");
}

// Returns false when a buffer's data URI has a media type Khronos does not read.
bool check_uri(Validation& v, const Json& obj, const std::string& where, bool buffer) {
    const auto uri = obj.find("uri");
    if (uri == obj.end() || !uri->is_string()) return true;
    const std::string& u = uri->get_ref<const std::string&>();
    const std::string p = ptr(where, "uri");
    if (v.glb) v.add("URI_GLB", Severity::Information, p, "URI is used in GLB container.");
    if (is_data_uri(u)) {
        if (v.glb)
            v.add("DATA_URI_GLB", Severity::Warning, p, "Data URI is used in GLB container.");
        if (buffer) {
            const std::string_view media = std::string_view(u).substr(5, u.find_first_of(";,") - 5);
            if (media != "application/octet-stream" && media != "application/gltf-buffer")
                v.add("BUFFER_DATA_URI_MIME_TYPE_INVALID", Severity::Error, p,
                      "Data URI media type must be 'application/octet-stream' or "
                      "'application/gltf-buffer'. Found '" +
                          std::string(media) + "' instead.");
            return media == "application/octet-stream" || media == "application/gltf-buffer";
        }
    } else {
        const bool absolute = non_relative(u);
        if (absolute)
            v.add("NON_RELATIVE_URI", Severity::Warning, p, "Non-relative URI found: '" + u + "'.");
        if ((!absolute || u[0] == '/') && !v.base_dir.empty()) check_file(v, u, p);
    }
    return true;
}

std::uint32_t le32(std::span<const std::uint8_t> b, std::size_t at) {
    return static_cast<std::uint32_t>(b[at]) | static_cast<std::uint32_t>(b[at + 1]) << 8 |
           static_cast<std::uint32_t>(b[at + 2]) << 16 |
           static_cast<std::uint32_t>(b[at + 3]) << 24;
}

} // namespace

namespace {

struct View {
    std::int64_t buffer = -1;
    std::uint64_t offset = 0, length = 0, stride = 0;
    bool fits = false, compressed = false;
};

// Where a sparse accessor's indices and values lie (`element`: one value's bytes), and
// ACCESSOR_TOO_LONG for either that does not fit its view.
void sparse_layout(Validation& v, const Json& sparse, const std::vector<View>& views,
                   const std::string& where, std::uint64_t element, AccessorLayout& out) {
    const std::int64_t count = int_or(sparse, "count", 0);
    if (count <= 0) return;
    AccessorLayout::Sparse& sd = out.sparse_data;
    sd.overrides = static_cast<std::uint64_t>(count);
    for (const char* part : {"indices", "values"}) {
        const bool indices = part[0] == 'i';
        const Json& pj = Validation::member(sparse, part);
        const std::int64_t vi = ref(v, pj, "bufferView", "bufferViews");
        const std::int64_t ct = int_or(pj, "componentType", 0);
        const std::uint64_t size =
            indices ? (ct == 5121 || ct == 5123 || ct == 5125 ? component_size(ct) : 0) : element;
        if (vi < 0 || size == 0) continue;
        const View& view = views[static_cast<std::size_t>(vi)];
        const std::uint64_t offset =
            static_cast<std::uint64_t>(std::max<std::int64_t>(int_or(pj, "byteOffset", 0), 0));
        const auto length = checked_mul(size, sd.overrides);
        const auto end = length ? checked_add(*length, offset) : std::nullopt;
        if (!end || *end > view.length) {
            v.add("ACCESSOR_TOO_LONG", Severity::Error, ptr(ptr(where, "sparse"), part),
                  "Accessor (offset: " + std::to_string(offset) +
                      ", length: " + (length ? std::to_string(*length) : std::string("too large")) +
                      ") does not fit referenced bufferView [" + std::to_string(vi) + "] length " +
                      std::to_string(view.length) + ".");
            if (!length) continue;
        }
        // Read where the buffer holds the bytes, past the view too (as the Khronos
        // validator does): the data pass checks the range against the loaded buffer.
        if (view.compressed || view.buffer < 0) continue;
        (indices ? sd.indices_readable : sd.values_readable) = true;
        (indices ? sd.indices_buffer : sd.values_buffer) = static_cast<std::size_t>(view.buffer);
        (indices ? sd.indices_offset : sd.values_offset) = view.offset + offset;
        if (indices) sd.index_type = static_cast<int>(ct);
    }
}

} // namespace

void validate_buffers(Validation& v) {
    const Json& buffers = v.array("buffers");
    std::vector<std::uint64_t> buffer_length(buffers.size(), 0);
    v.declared_buffer_length.assign(buffers.size(), 0);
    v.length_unchecked.assign(buffers.size(), 0);
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const Json& b = buffers[i];
        if (!b.is_object()) continue;
        v.declared_buffer_length[i] = int_or(b, "byteLength", 0);
        const Json& ext = Validation::member(b, "extensions");
        for (const char* codec : {"EXT_meshopt_compression", "KHR_meshopt_compression"})
            v.length_unchecked[i] |=
                Validation::member(Validation::member(ext, codec), "fallback") == true;
        const std::string where = ptr("/buffers", i);
        buffer_length[i] =
            static_cast<std::uint64_t>(std::max<std::int64_t>(int_or(b, "byteLength", 0), 0));
        if (!check_uri(v, b, where, true)) v.length_unchecked[i] = 1;
        if (v.glb && i == 0 && !b.contains("uri") && !v.glb_has_bin)
            v.add("BUFFER_MISSING_GLB_DATA", Severity::Error, where,
                  "Buffer refers to an unresolved GLB binary chunk.");
    }

    const Json& views_json = v.array("bufferViews");
    std::vector<View> views(views_json.size());
    v.view_roles.assign(views_json.size(), ViewRole::None);
    v.declared_views.assign(views_json.size(), {});
    for (std::size_t i = 0; i < views_json.size(); ++i) {
        const Json& bv = views_json[i];
        View& view = views[i];
        Validation::DeclaredView& declared = v.declared_views[i];
        declared.object = bv.is_object();
        declared.has_stride = declared.object && bv.contains("byteStride");
        declared.has_target = declared.object && bv.contains("target");
        declared.byte_offset = int_or(bv, "byteOffset", 0);
        view.buffer = ref(v, bv, "buffer", "buffers");
        view.offset = static_cast<std::uint64_t>(std::max<std::int64_t>(declared.byte_offset, 0));
        view.length =
            static_cast<std::uint64_t>(std::max<std::int64_t>(int_or(bv, "byteLength", 0), 0));
        view.stride =
            static_cast<std::uint64_t>(std::max<std::int64_t>(int_or(bv, "byteStride", 0), 0));
        if (view.stride < 4 || view.stride > 252)
            view.stride = 0; // out of range: ignored, as Khronos does
        view.compressed = bv.is_object() && bv.contains("extensions") &&
                          bv["extensions"].is_object() &&
                          (bv["extensions"].contains("EXT_meshopt_compression") ||
                           bv["extensions"].contains("KHR_meshopt_compression"));
        const std::int64_t target = int_or(bv, "target", 0);
        v.view_roles[i] = target == 34962   ? ViewRole::VertexBuffer
                          : target == 34963 ? ViewRole::IndexBuffer
                                            : ViewRole::None;
        const std::string where = ptr("/bufferViews", i);
        if (view.buffer >= 0) {
            const std::uint64_t size = buffer_length[static_cast<std::size_t>(view.buffer)];
            view.fits = range_fits(view.offset, view.length, size);
            if (!view.fits)
                v.add("BUFFER_VIEW_TOO_LONG", Severity::Error,
                      ptr(where, view.offset >= size ? "byteOffset" : "byteLength"),
                      "BufferView does not fit buffer (" + std::to_string(view.buffer) +
                          ") byteLength (" + std::to_string(size) + ").");
        }
        if (view.stride) {
            if (view.stride % 4)
                v.add("VALUE_MULTIPLE_OF", Severity::Error, ptr(where, "byteStride"),
                      "Value " + std::to_string(view.stride) + " is not a multiple of 4.");
            if (view.stride > view.length && view.length > 0)
                v.add("BUFFER_VIEW_TOO_BIG_BYTE_STRIDE", Severity::Error, ptr(where, "byteStride"),
                      "Buffer view's byteStride (" + std::to_string(view.stride) +
                          ") is greater than byteLength (" + std::to_string(view.length) + ").");
            if (int_or(bv, "target", 0) == 34963)
                v.add("BUFFER_VIEW_INVALID_BYTE_STRIDE", Severity::Error, ptr(where, "byteStride"),
                      "Only buffer views with raw vertex data can have byteStride.");
        }
    }

    const Json& accessors = v.array("accessors");
    v.accessors.assign(accessors.size(), {});
    v.accessor_roles.assign(accessors.size(), AccessorRole::None);
    v.declared_accessors.assign(accessors.size(), {});
    for (std::size_t i = 0; i < accessors.size(); ++i) {
        const Json& a = accessors[i];
        if (!a.is_object()) continue;
        AccessorLayout& out = v.accessors[i];
        const std::string where = ptr("/accessors", i);
        const std::int64_t ct = int_or(a, "componentType", 0);
        const std::uint32_t csize = component_size(ct);
        const auto type = a.find("type");
        const std::uint32_t comps = type != a.end() && type->is_string()
                                        ? components_of(type->get_ref<const std::string&>())
                                        : 0;
        const std::int64_t declared_count = int_or(a, "count", -1);
        const std::int64_t count = std::max<std::int64_t>(declared_count, 0);
        const auto norm_it = a.find("normalized");
        const bool normalized = norm_it != a.end() && norm_it->is_boolean() && norm_it->get<bool>();
        if (normalized && (ct == 5126 || ct == 5125))
            v.add("ACCESSOR_NORMALIZED_INVALID", Severity::Error, ptr(where, "normalized"),
                  "Only (u)byte and (u)short accessors can be normalized.");
        for (const char* key : {"min", "max"}) {
            const auto m = a.find(key);
            // Without a valid componentType, Khronos does not read the bounds at all.
            if (m == a.end() || !m->is_array() || comps == 0 || csize == 0) continue;
            if (m->size() != comps)
                v.add("ARRAY_LENGTH_NOT_IN_LIST", Severity::Error, ptr(where, key),
                      "Invalid array length " + std::to_string(m->size()) +
                          ". Valid lengths are: (" + std::to_string(comps) + ").");
            else
                (key[1] == 'i' ? out.has_min : out.has_max) = true;
        }
        if (a.contains("sparse") && a["sparse"].is_object()) {
            out.sparse = true;
            for (const char* part : {"indices", "values"}) {
                const Json& sp = Validation::member(a["sparse"], part);
                v.use_view(ref(v, sp, "bufferView", "bufferViews"), ViewRole::Other,
                           ptr(ptr(ptr(where, "sparse"), part), "bufferView"));
            }
            const std::int64_t sc = int_or(a["sparse"], "count", 0);
            if (sc > count && count > 0)
                v.add("ACCESSOR_SPARSE_COUNT_OUT_OF_RANGE", Severity::Error,
                      ptr(ptr(where, "sparse"), "count"),
                      "Sparse accessor overrides more elements (" + std::to_string(sc) +
                          ") than the base accessor contains (" + std::to_string(count) + ").");
        }
        const std::int64_t declared_offset = int_or(a, "byteOffset", 0);
        const std::int64_t offset = std::max<std::int64_t>(declared_offset, 0);
        const std::int64_t vi = ref(v, a, "bufferView", "bufferViews");
        v.declared_accessors[i] = {vi, declared_count, declared_offset, ct, comps, normalized};
        if (csize && offset % csize)
            v.add("ACCESSOR_OFFSET_ALIGNMENT", Severity::Error, ptr(where, "byteOffset"),
                  "Offset " + std::to_string(offset) +
                      " is not a multiple of componentType length " + std::to_string(csize) + ".");
        if (out.sparse && csize && comps && count > 0)
            sparse_layout(v, a["sparse"], views, where, std::uint64_t{csize} * comps, out);
        if (vi < 0 || !csize || !comps || count <= 0) {
            if (out.sparse && vi < 0 && csize && comps && count > 0) {
                out.sparse_data.zero_base = true;
                out.component_type = static_cast<int>(ct);
                out.components = comps;
                out.count = static_cast<std::uint64_t>(count);
                out.normalized = normalized;
                out.stride = std::uint64_t{csize} * comps;
            }
            continue;
        }
        const View& view = views[static_cast<std::size_t>(vi)];
        if (csize && view.offset < (std::uint64_t{1} << 53) &&
            (view.offset + static_cast<std::uint64_t>(offset)) % csize)
            v.add("ACCESSOR_TOTAL_OFFSET_ALIGNMENT", Severity::Error, where,
                  "Accessor's total byteOffset " + std::to_string(view.offset + offset) +
                      " isn't a multiple of componentType length " + std::to_string(csize) + ".");
        const std::uint64_t element = std::uint64_t{csize} * comps;
        if (view.stride && view.stride < element)
            v.add("ACCESSOR_SMALL_BYTESTRIDE", Severity::Error, where,
                  "Referenced bufferView's byteStride value " + std::to_string(view.stride) +
                      " is less than accessor element's length " + std::to_string(element) + ".");
        const std::uint64_t stride = view.stride ? view.stride : element;
        const auto span = checked_mul(stride, static_cast<std::uint64_t>(count - 1));
        const auto end = span ? checked_add(*span, element) : std::nullopt;
        const auto total =
            end ? checked_add(*end, static_cast<std::uint64_t>(offset)) : std::nullopt;
        if (!total || *total > view.length) {
            v.add("ACCESSOR_TOO_LONG", Severity::Error,
                  static_cast<std::uint64_t>(offset) >= view.length ? ptr(where, "byteOffset")
                                                                    : where,
                  "Accessor (offset: " + std::to_string(offset) +
                      ", length: " + (end ? std::to_string(*end) : std::string("too large")) +
                      ") does not fit referenced bufferView [" + std::to_string(vi) + "] length " +
                      std::to_string(view.length) + ".");
            // Its values are still read where the buffer holds them (the Khronos
            // validator reads them too); the data pass checks the range.
            if (!total) continue;
        }
        out.readable = view.buffer >= 0 && !view.compressed &&
                       (view.offset + offset) % csize == 0 &&
                       (!view.stride || (view.stride >= element && view.stride % 4 == 0));
        out.buffer = static_cast<std::size_t>(view.buffer);
        out.offset = view.offset + static_cast<std::uint64_t>(offset);
        out.stride = stride;
        out.component_type = static_cast<int>(ct);
        out.components = comps;
        out.count = static_cast<std::uint64_t>(count);
        out.normalized = normalized;
    }
    // Images are linked before meshes by the Khronos validator: their views' use first.
    const Json& images = v.array("images");
    for (std::size_t i = 0; i < images.size(); ++i) {
        if (!images[i].is_object()) continue;
        const std::string where = ptr("/images", i);
        check_uri(v, images[i], where, false);
        v.use_view(ref(v, images[i], "bufferView", "bufferViews"), ViewRole::Image,
                   ptr(where, "bufferView"));
    }
}

void validate_glb(Validation& v, std::span<const std::uint8_t> b) {
    if (b.size() < 12) return; // refused before (the header alone is 12 bytes)
    const std::uint64_t declared = le32(b, 8);
    if (declared < b.size())
        v.add("GLB_EXTRA_DATA", Severity::Warning, "", "Extra data after the end of GLB stream.");
    else if (declared > b.size())
        v.add("GLB_LENGTH_MISMATCH", Severity::Error, "",
              "Declared length (" + std::to_string(declared) + ") does not match GLB length (" +
                  std::to_string(b.size()) + ").");
    const std::size_t end = static_cast<std::size_t>(std::min<std::uint64_t>(declared, b.size()));
    std::size_t at = 12;
    bool json = false, bin = false;
    std::uint64_t bin_length = 0;
    for (int chunk = 0; at + 8 <= end; ++chunk) {
        const std::uint32_t length = le32(b, at);
        const std::uint32_t type = le32(b, at + 4);
        const char* name = type == 0x4E4F534Au ? "JSON" : type == 0x004E4942u ? "BIN" : nullptr;
        if (length % 4)
            v.add("GLB_CHUNK_LENGTH_UNALIGNED", Severity::Error, "",
                  std::string("Length of ") + (name ? name : "unknown") +
                      " chunk is not aligned to 4-byte boundaries.");
        if (!range_fits(at + 8, length, end)) {
            v.add("GLB_CHUNK_TOO_BIG", Severity::Error, "",
                  std::string("Chunk (") + (name ? name : "unknown") + ") length (" +
                      std::to_string(length) + ") does not fit total GLB length.");
            break;
        }
        if (!name) {
            v.add("GLB_UNKNOWN_CHUNK_TYPE", Severity::Warning, "",
                  "Unknown GLB chunk type: " + std::to_string(type) + ".");
        } else if ((name[0] == 'J' && json) || (name[0] == 'B' && bin)) {
            v.add("GLB_DUPLICATE_CHUNK", Severity::Error, "",
                  std::string("Chunk of type ") + name + " has already been used.");
        } else if (name[0] == 'B') {
            bin = true;
            v.glb_has_bin = true;
            bin_length = length;
            if (chunk != 1)
                v.add("GLB_UNEXPECTED_BIN_CHUNK", Severity::Error, "",
                      "BIN chunk must be the second chunk.");
            if (length == 0)
                v.add("GLB_EMPTY_BIN_CHUNK", Severity::Information, "",
                      "Empty BIN chunk should be omitted.");
        } else {
            json = true;
        }
        at += 8 + length;
    }
    const Json& buffers = v.array("buffers");
    if (bin && !buffers.empty() && buffers[0].is_object() && !buffers[0].contains("uri")) {
        const std::int64_t declared_length = int_or(buffers[0], "byteLength", 0);
        if (declared_length >= 0 && bin_length > static_cast<std::uint64_t>(declared_length) + 3)
            v.add("BUFFER_GLB_CHUNK_TOO_BIG", Severity::Warning, "/buffers/0",
                  "GLB-stored BIN chunk contains " +
                      std::to_string(bin_length - static_cast<std::uint64_t>(declared_length)) +
                      " extra padding byte(s).");
    }
}

} // namespace sherpa::scene::detail
