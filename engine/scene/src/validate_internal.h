#pragma once
// Internal: the glTF validator's shared state. It runs in two passes over what the
// importer has parsed anyway: validate_document() over the JSON (schema, references,
// links; before tinygltf sees the file) and validate_data() over the buffers tinygltf
// loaded (accessor values). Codes, severities and JSON pointers follow the Khronos
// glTF-Validator (its ISSUES.md); checks of our own carry SHERPA_ codes.
#include "gltf_validate.h"

#include <sherpa/scene/validation.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace sherpa::scene::detail {

using Json = nlohmann::json;

// A JSON pointer being built: "/meshes/0/primitives/1".
std::string ptr(std::string_view base, std::string_view key);
std::string ptr(std::string_view base, std::size_t index);
// Appends "/key" (escaped) or "/index" to a pointer being built in place.
void push_key(std::string& pointer, std::string_view key);
void push_index(std::string& pointer, std::size_t index);

// Semantic use of an accessor found while validating references; the data pass
// checks the values each use requires.
enum class AccessorUse : std::uint8_t {
    Indices,
    Position,
    Normal,
    Tangent,
    Joints,
    Weights,
    Color,
    AnimationInput,
    AnimationOutputRotation,
    InverseBindMatrices,
};
struct AccessorUsage {
    std::size_t accessor = 0;
    AccessorUse use = AccessorUse::Position;
    std::string pointer;            // where the use is (the Khronos pointer for data messages)
    std::uint64_t limit = 0;        // Indices: vertex count; Joints: joint count
    int mode = 4;                   // Indices: primitive mode
    std::size_t partner = SIZE_MAX; // Joints: its WEIGHTS accessor
};

// What the link checks established about accessors and buffer views, so the data
// pass reads only what fits.
struct AccessorLayout {
    bool readable = false; // resolved and inside its buffer: values can be read
    std::size_t buffer = 0;
    std::uint64_t offset = 0, stride = 0; // absolute offset into the buffer; element stride
    int component_type = 0;
    std::uint32_t components = 0; // 1..16
    std::uint64_t count = 0;
    bool normalized = false;
    bool has_min = false, has_max = false; // declared with the right length
    bool sparse = false;                   // values overridden: see `overrides`
    // Sparse storage, when `sparse`: `overrides` elements whose indices (`index_type`)
    // and values lie in the buffers at these absolute offsets (readable: inside them).
    // The base is the bufferView's data, or zeros when the accessor has none.
    struct Sparse {
        std::uint64_t overrides = 0;
        bool indices_readable = false, values_readable = false;
        std::size_t indices_buffer = 0, values_buffer = 0;
        std::uint64_t indices_offset = 0, values_offset = 0;
        int index_type = 0;
        bool zero_base = false; // no bufferView: the base values are zeros
    } sparse_data;
};

// What an accessor or buffer view is first used for; a second, different use is the
// Khronos ACCESSOR_USAGE_OVERRIDE / BUFFER_VIEW_TARGET_OVERRIDE error. The Khronos
// validator links images, meshes, skins and animations in that order; the passes
// record uses in the same order.
enum class AccessorRole : std::uint8_t {
    None,
    VertexAttribute,
    PrimitiveIndices,
    IBM,
    AnimationInput,
    AnimationOutput
};
enum class ViewRole : std::uint8_t { None, VertexBuffer, IndexBuffer, IBM, Image, Other };

struct Validation {
    ValidationReport& report;
    const Json& root;
    // Key order the parse recorded (null: the JSON's own, sorted, order).
    const DocumentOrder* order = nullptr;
    bool glb = false;
    bool glb_has_bin = false;
    std::vector<AccessorLayout> accessors;
    std::vector<AccessorUsage> usages;
    // Folder external URIs resolve against; empty: files are not looked at (IO_ERROR).
    std::string base_dir;
    // Per buffer, as the file declares them (the importer may rewrite the JSON later).
    std::vector<std::int64_t> declared_buffer_length;
    // A meshopt fallback (no data by design) or a data URI of the wrong media type
    // (Khronos does not read it): its length is not compared with byteLength.
    std::vector<std::uint8_t> length_unchecked;
    std::vector<AccessorRole> accessor_roles;
    std::vector<ViewRole> view_roles;
    // Set by the data pass, per accessor: its values were all read (no sparse
    // overrides) and every one is finite and inside its declared min and max. The
    // importer's declared-range check believes it rather than scanning them again.
    std::vector<std::uint8_t> bounds_hold;
    // Per accessor and buffer view, the properties the buffer pass reads once for the
    // passes after it (the meshes pass asked the JSON for them again per attribute: a
    // map look-up each, most of that pass's time). Defaults where a value is absent, of
    // another type, or the element is no object.
    struct DeclaredAccessor {
        std::int64_t view = -1;          // the bufferView, resolved, or -1
        std::int64_t count = -1;         // integer `count`, or -1
        std::int64_t byte_offset = 0;    // integer `byteOffset` as written (may be < 0)
        std::int64_t component_type = 0; // integer `componentType`, or 0
        std::uint32_t components = 0;    // of a string `type` (1 only for "SCALAR")
        bool normalized = false;         // `normalized` is true
    };
    struct DeclaredView {
        bool object = false;          // the element is an object
        bool has_stride = false;      // it has a byteStride (of any value)
        bool has_target = false;      // it has a target (of any value)
        std::int64_t byte_offset = 0; // integer `byteOffset`, or 0
    };
    std::vector<DeclaredAccessor> declared_accessors{}; // filled by validate_buffers
    std::vector<DeclaredView> declared_views{};
    // array()'s look-ups so far, by the key's address.
    struct CachedArray {
        const char* key = nullptr;
        const Json* array = nullptr;
    };
    mutable std::array<CachedArray, 48> arrays{};
    mutable std::size_t cached_arrays = 0;
    // Records a use of accessor `a` (and of its buffer view) at `pointer`.
    void use_accessor(std::int64_t a, AccessorRole role, ViewRole view_role,
                      const std::string& pointer);
    void use_view(std::int64_t view, ViewRole role, const std::string& pointer);

    void add(std::string_view code, Severity s, std::string pointer, std::string message);
    // Whether the report still takes messages (kMaxValidationMessages): hot loops ask
    // before they build a message that add() would drop.
    bool accepting() const { return report.messages.size() < kMaxValidationMessages; }
    // The array `key` of the root (an empty array when absent or not an array). Keys
    // are string literals: each is looked up in the root once and kept by address.
    const Json& array(const char* key) const;
    // Member `key` of `obj`, or null when `obj` is no object or lacks it.
    static const Json& member(const Json& obj, const char* key);
    // Element `i` of array `a` when it is an object, or an empty object.
    static const Json& member(const Json& a, std::size_t i);
    std::size_t size(const char* key) const { return array(key).size(); }
};

// Passes, in order. Each only reads the JSON; none throws on bad input.
void validate_glb(Validation& v, std::span<const std::uint8_t> glb); // chunks; sets glb_has_bin
void validate_schema(Validation& v);     // types, required, enums, ranges, references
void validate_extensions(Validation& v); // extensionsUsed/Required, where extensions are
void validate_buffers(Validation& v);    // buffers, bufferViews, accessors (links, layout)
void validate_meshes(Validation& v);     // primitives, morph targets, skins on meshes
void validate_nodes(Validation& v);      // node graph, scenes, skins
void validate_animations(Validation& v); // channels, samplers
void validate_materials(Validation& v);  // cameras, materials, textures, images, samplers
void validate_unused(Validation& v);     // UNUSED_OBJECT
// Accessor values (min/max, floats, normals, indices, weights, key times, ...), over
// the buffers' bytes as loaded; `buffers[i]` empty where buffer i could not be read.
void validate_data(Validation& v, std::span<const std::span<const std::uint8_t>> buffers);

// Image headers (format against the declared media type, PNG/JPEG streams cut short,
// dimensions): `images[i]` the bytes of image i loaded from its URI (empty where it
// has none or they could not be read); bufferView images are read from `buffers`.
void validate_images(Validation& v, std::span<const std::span<const std::uint8_t>> buffers,
                     std::span<const std::span<const std::uint8_t>> images);

// Every JSON pass above, in order: what the importer calls before tinygltf parses.
void validate_document(Validation& v);

// JSON helpers shared by the passes.
bool is_int(const Json& j); // an integer, 1.0 included
std::int64_t as_int(const Json& j);
// Integer member `key` of `obj`, or `fallback` when absent or not an integer.
std::int64_t int_or(const Json& obj, const char* key, std::int64_t fallback);
// A valid index into root array `target` at obj[key], or -1.
std::int64_t ref(const Validation& v, const Json& obj, const char* key, const char* target);
std::uint32_t components_of(std::string_view type);        // "VEC3" -> 3, 0 when unknown
std::uint32_t component_size(std::int64_t component_type); // 5126 -> 4, 0 when unknown
// Whether a material needs a tangent space from its primitives: a normal texture, or
// a declared clearcoat normal or anisotropy texture.
bool needs_tangent_space(const Validation& v, const Json& material);

} // namespace sherpa::scene::detail

namespace sherpa::scene::detail {

// The importer's handle on the validator: the GLB and JSON passes run on construction,
// the data pass once tinygltf has loaded the buffers; report.ms sums both.
class DocumentValidator {
public:
    // `base_dir`: where external URIs resolve (empty: not checked).
    DocumentValidator(const Json& root, std::span<const std::uint8_t> file, bool glb,
                      ValidationReport& report, std::string base_dir = {},
                      const DocumentOrder* order = nullptr);
    void check_data(std::span<const std::span<const std::uint8_t>> buffers,
                    std::span<const std::span<const std::uint8_t>> images = {});
    bool glb_has_bin() const { return v_.glb_has_bin; }
    // After check_data: Validation::bounds_hold, per accessor.
    std::vector<std::uint8_t> take_bounds_hold() { return std::move(v_.bounds_hold); }

private:
    Validation v_;
};

// Adds `text` (an importer warning such as "meshes[0].primitives[1]: ...") to `report`
// with `code` and the JSON pointer its leading path names.
void add_import_message(ValidationReport& report, std::string_view code, Severity severity,
                        const std::string& text);
// "meshes[0].primitives[1].attributes.POSITION: ..." ->
// "/meshes/0/primitives/1/attributes/POSITION"
std::string pointer_of_path(std::string_view text);

} // namespace sherpa::scene::detail
