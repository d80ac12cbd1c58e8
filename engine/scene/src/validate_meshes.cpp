// Mesh primitives: attribute semantics and formats, counts, indices, morph targets,
// and what their materials need from them (validate_internal.h).
#include "validate_internal.h"

#include <algorithm>
#include <map>
#include <set>

namespace sherpa::scene::detail {
namespace {

bool numbered(std::string_view name, std::string_view prefix, int& n) {
    if (!name.starts_with(prefix) || name.size() == prefix.size()) return false;
    n = 0;
    for (char c : name.substr(prefix.size())) {
        if (c < '0' || c > '9' || n > 100000) return false;
        n = n * 10 + (c - '0');
    }
    return name.size() == prefix.size() + 1 || name[prefix.size()] != '0';
}

struct Format {
    std::uint32_t components;
    int component_type;
    bool normalized;
};

std::string format_text(const AccessorLayout& a, const Json& acc) {
    const auto type = acc.find("type");
    return "{" + (type != acc.end() && type->is_string() ? type->get<std::string>() : "null") +
           ", " + (a.component_type ? std::to_string(a.component_type) : "null") +
           (a.normalized ? " normalized" : "") + "}";
}

// Whether an attribute's accessor format is one glTF allows for its semantic.
bool format_ok(std::string_view semantic, std::uint32_t comps, int ct, bool norm, bool quantized) {
    const bool f = ct == 5126 && !norm;
    const bool unorm = (ct == 5121 || ct == 5123) && norm;
    const bool snorm = (ct == 5120 || ct == 5122) && norm;
    const bool small_int = ct >= 5120 && ct <= 5123;
    int n = 0;
    if (semantic == "POSITION") return comps == 3 && (f || (quantized && small_int));
    if (semantic == "NORMAL") return comps == 3 && (f || (quantized && snorm));
    if (semantic == "TANGENT") return comps == 4 && (f || (quantized && snorm));
    if (numbered(semantic, "TEXCOORD_", n))
        return comps == 2 && (f || unorm || (quantized && small_int));
    if (numbered(semantic, "COLOR_", n)) return (comps == 3 || comps == 4) && (f || unorm);
    if (numbered(semantic, "JOINTS_", n)) return comps == 4 && (ct == 5121 || ct == 5123) && !norm;
    if (numbered(semantic, "WEIGHTS_", n)) return comps == 4 && (f || unorm);
    return true;
}

// texCoord sets and the normal texture a material uses (any *Texture object).
void material_needs(const Json& j, std::set<std::int64_t>& sets, int depth) {
    if (depth > 8 || !j.is_object()) return;
    for (const auto& [key, value] : j.items()) {
        if (!value.is_object()) continue;
        if (key.ends_with("Texture") || key.ends_with("texture")) {
            std::int64_t set = int_or(value, "texCoord", 0);
            const Json& ext = Validation::member(value, "extensions");
            const Json& transform = Validation::member(ext, "KHR_texture_transform");
            set = int_or(transform, "texCoord", set);
            sets.insert(set);
        }
        material_needs(value, sets, depth + 1);
    }
}

// A primitive's attributes as the file lists them (the Khronos validator's order, which
// decides which of two accessors sharing a view is named), from the parse's record;
// the JSON's sorted order where there is none.
std::vector<std::pair<std::string_view, const Json*>>
in_document_order(const Validation& v, const Json& attributes, std::size_t m, std::size_t p) {
    std::vector<std::pair<std::string_view, const Json*>> out;
    if (!attributes.is_object()) return out;
    out.reserve(attributes.size());
    const std::vector<std::string>* names = v.order ? v.order->attributes_of(m, p) : nullptr;
    if (!names || names->size() < attributes.size()) {
        for (const auto& [name, value] : attributes.items()) out.emplace_back(name, &value);
        return out;
    }
    std::set<std::string_view> seen; // a repeated key: its value is the last, its place the first
    const bool repeats = names->size() != attributes.size();
    for (const std::string& name : *names) {
        if (repeats && !seen.insert(name).second) continue;
        const auto it = attributes.find(name);
        if (it != attributes.end()) out.emplace_back(it.key(), &*it);
    }
    return out;
}

} // namespace

void validate_meshes(Validation& v) {
    bool quantized = false;
    for (const Json& e : v.array("extensionsUsed")) quantized |= e == "KHR_mesh_quantization";
    const Json& meshes = v.array("meshes");
    const Json& accessors = v.array("accessors");
    const Json& views = v.array("bufferViews");
    // The buffer pass's reading of each accessor and view (validate_internal.h).
    const auto& declared = v.declared_accessors;
    auto view_of = [&](std::int64_t a) {
        const std::int64_t vi = declared[static_cast<std::size_t>(a)].view;
        return vi >= 0 ? v.declared_views[static_cast<std::size_t>(vi)]
                       : Validation::DeclaredView{};
    };
    // Per buffer view without byteStride: the vertex accessors that read it.
    std::vector<std::vector<std::int64_t>> view_readers(views.size());
    // A view without `target` is hinted at its first vertex or index use only.
    std::vector<std::uint8_t> target_hinted(views.size());
    auto target_missing = [&](std::int64_t a) {
        const std::int64_t vi = declared[static_cast<std::size_t>(a)].view;
        if (vi < 0 || target_hinted[static_cast<std::size_t>(vi)]) return false;
        target_hinted[static_cast<std::size_t>(vi)] = 1;
        const Validation::DeclaredView& view = v.declared_views[static_cast<std::size_t>(vi)];
        return view.object && !view.has_target;
    };
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const Json& prim_array = Validation::member(meshes[m], "primitives");
        if (!prim_array.is_array()) continue;
        std::size_t first_targets = SIZE_MAX;
        for (std::size_t p = 0; p < prim_array.size(); ++p) {
            const Json& prim = prim_array[p];
            if (!prim.is_object()) continue;
            const std::string where = ptr(ptr(ptr(ptr("", "meshes"), m), "primitives"), p);
            const std::string attr_where = ptr(where, "attributes");
            const Json& attributes = Validation::member(prim, "attributes");
            std::int64_t position_count = -1, first_count = -1;
            std::map<std::string, std::int64_t, std::less<>> resolved;
            int joints = 0, weights = 0;
            std::set<int> texcoords, colors, joint_sets, weight_sets;
            bool has_normal = false, has_tangent = false, has_position = false;
            for (const auto& [name, value_at] : in_document_order(v, attributes, m, p)) {
                const Json& value = *value_at;
                const std::string ap = ptr(attr_where, name);
                int n = 0;
                if (name == "POSITION")
                    has_position = true;
                else if (name == "NORMAL")
                    has_normal = true;
                else if (name == "TANGENT")
                    has_tangent = true;
                else if (numbered(name, "TEXCOORD_", n))
                    texcoords.insert(n);
                else if (numbered(name, "COLOR_", n))
                    colors.insert(n);
                else if (numbered(name, "JOINTS_", n))
                    ++joints, joint_sets.insert(n);
                else if (numbered(name, "WEIGHTS_", n))
                    ++weights, weight_sets.insert(n);
                else if (!name.starts_with("_"))
                    v.add("MESH_PRIMITIVE_INVALID_ATTRIBUTE", Severity::Error, ap,
                          "Invalid attribute name.");
                if (!value.is_number() || !is_int(value)) {
                    v.add("TYPE_MISMATCH", Severity::Error, ap,
                          "Type mismatch. Property value is not a 'integer'.");
                    continue;
                }
                const std::int64_t a = as_int(value);
                if (a < 0) {
                    v.add("INVALID_INDEX", Severity::Error, ap,
                          "Index must be a non-negative integer.");
                    continue;
                }
                if (static_cast<std::size_t>(a) >= accessors.size()) {
                    v.add("UNRESOLVED_REFERENCE", Severity::Error, ap,
                          "Unresolved reference: " + std::to_string(a) + ".");
                    continue;
                }
                resolved.emplace(name, a);
                v.use_accessor(a, AccessorRole::VertexAttribute, ViewRole::VertexBuffer, ap);
                const Json& acc = accessors[static_cast<std::size_t>(a)];
                const AccessorLayout& layout = v.accessors[static_cast<std::size_t>(a)];
                const Validation::DeclaredAccessor& d = declared[static_cast<std::size_t>(a)];
                const std::uint32_t comps = d.components;
                const int ct = static_cast<int>(d.component_type);
                const bool norm = d.normalized;
                if (ct == 5125)
                    v.add("MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_UNSIGNED_INT", Severity::Error, ap,
                          "Mesh attributes cannot use UNSIGNED_INT component type.");
                else if (!format_ok(name, comps, component_size(ct) ? ct : 0, norm, quantized))
                    v.add("MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT", Severity::Error, ap,
                          "Invalid accessor format '" + format_text(layout, acc) +
                              "' for this attribute semantic.");
                if (name == "POSITION" && (!layout.has_min || !layout.has_max))
                    v.add("MESH_PRIMITIVE_POSITION_ACCESSOR_WITHOUT_BOUNDS", Severity::Error, ap,
                          "accessor.min and accessor.max must be defined for POSITION attribute "
                          "accessor.");
                const Validation::DeclaredView view = view_of(a);
                if (target_missing(a))
                    v.add("BUFFER_VIEW_TARGET_MISSING", Severity::Hint, ap,
                          "bufferView.target should be set for vertex or index data.");
                const std::int64_t view_offset = view.byte_offset;
                if (view.object && view_offset >= 0 && view_offset < (std::int64_t{1} << 53)) {
                    // Offsets and, without a stride, the element size: 4-byte multiples.
                    const std::int64_t offset = d.byte_offset;
                    if (offset % 4 || (view_offset + offset) % 4 ||
                        (!view.has_stride && (std::int64_t{component_size(ct)} * comps) % 4))
                        v.add("MESH_PRIMITIVE_ACCESSOR_UNALIGNED", Severity::Error, ap,
                              "Vertex attribute data must be aligned to 4-byte boundaries.");
                    const std::int64_t vi = d.view;
                    auto& readers = view_readers[static_cast<std::size_t>(vi)];
                    if (!view.has_stride &&
                        std::find(readers.begin(), readers.end(), a) == readers.end()) {
                        readers.push_back(a);
                        if (readers.size() > 1)
                            v.add("MESH_PRIMITIVE_ACCESSOR_WITHOUT_BYTESTRIDE", Severity::Error, ap,
                                  "bufferView.byteStride must be defined when two or more "
                                  "accessors use the same buffer view.");
                    }
                }
                const std::int64_t count = d.count;
                if (name == "POSITION") position_count = count;
                if (first_count < 0) first_count = count;
                AccessorUse use = AccessorUse::Position;
                if (name == "NORMAL")
                    use = AccessorUse::Normal;
                else if (name == "TANGENT")
                    use = AccessorUse::Tangent;
                else if (name.starts_with("JOINTS_"))
                    use = AccessorUse::Joints;
                else if (name.starts_with("WEIGHTS_"))
                    use = AccessorUse::Weights;
                else if (name.starts_with("COLOR_"))
                    use = AccessorUse::Color;
                else if (name != "POSITION")
                    continue;
                v.usages.push_back({static_cast<std::size_t>(a), use, ap});
            }
            const std::int64_t vertex_count = position_count >= 0 ? position_count : first_count;
            for (const auto& [name, a] : resolved)
                if (const std::int64_t c = declared[static_cast<std::size_t>(a)].count;
                    c >= 0 && vertex_count >= 0 && c != vertex_count)
                    v.add("MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT", Severity::Error,
                          ptr(attr_where, name),
                          "All accessors of the same primitive must have the same count.");
            if (attributes.is_object() && !has_position)
                v.add("MESH_PRIMITIVE_NO_POSITION", Severity::Warning, attr_where,
                      "No POSITION attribute found.");
            if (has_tangent && !has_normal)
                v.add("MESH_PRIMITIVE_TANGENT_WITHOUT_NORMAL", Severity::Warning,
                      ptr(attr_where, "TANGENT"), "TANGENT attribute without NORMAL found.");
            if (joints != weights)
                v.add("MESH_PRIMITIVE_JOINTS_WEIGHTS_MISMATCH", Severity::Error, attr_where,
                      "Number of JOINTS attribute semantics (" + std::to_string(joints) +
                          ") does not match the number of WEIGHTS (" + std::to_string(weights) +
                          ").");
            for (const auto* sets : {&texcoords, &colors, &joint_sets, &weight_sets})
                if (!sets->empty() && (*sets->rbegin() + 1 != static_cast<int>(sets->size())))
                    v.add("MESH_PRIMITIVE_INDEXED_SEMANTIC_CONTINUITY", Severity::Error, attr_where,
                          "Indices for indexed attribute semantic must start with 0 and be "
                          "continuous.");
            // Pair each JOINTS_n with WEIGHTS_n for the data pass.
            for (auto& u : v.usages)
                if (u.use == AccessorUse::Joints && u.pointer.starts_with(attr_where + "/")) {
                    const std::string set = u.pointer.substr(u.pointer.rfind('_') + 1);
                    if (const auto w = resolved.find("WEIGHTS_" + set); w != resolved.end())
                        u.partner = static_cast<std::size_t>(w->second);
                }

            const int mode = static_cast<int>(int_or(prim, "mode", 4));
            std::int64_t element_count = vertex_count;
            if (const std::int64_t ia = ref(v, prim, "indices", "accessors"); ia >= 0) {
                const std::string ip = ptr(where, "indices");
                v.use_accessor(ia, AccessorRole::PrimitiveIndices, ViewRole::IndexBuffer, ip);
                const Validation::DeclaredAccessor& d = declared[static_cast<std::size_t>(ia)];
                const std::int64_t ct = d.component_type;
                const bool format_ok = d.components == 1 && // "SCALAR"
                                       (ct == 5121 || ct == 5123 || ct == 5125) && !d.normalized;
                if (!format_ok)
                    v.add("MESH_PRIMITIVE_INDICES_ACCESSOR_INVALID_FORMAT", Severity::Error, ip,
                          "Invalid indices accessor format. Must be one of ('{SCALAR, "
                          "UNSIGNED_BYTE}', "
                          "'{SCALAR, UNSIGNED_SHORT}', '{SCALAR, UNSIGNED_INT}').");
                const Validation::DeclaredView view = view_of(ia);
                if (view.object && view.has_stride)
                    v.add("MESH_PRIMITIVE_INDICES_ACCESSOR_WITH_BYTESTRIDE", Severity::Error, ip,
                          "bufferView.byteStride must not be defined for indices accessor.");
                if (target_missing(ia))
                    v.add("BUFFER_VIEW_TARGET_MISSING", Severity::Hint, ip,
                          "bufferView.target should be set for vertex or index data.");
                element_count = d.count;
                AccessorUsage u{static_cast<std::size_t>(ia), AccessorUse::Indices, ip};
                u.limit = vertex_count > 0 ? static_cast<std::uint64_t>(vertex_count) : 0;
                u.mode = mode;
                // Khronos reads no index data of another format or through a stride; with
                // no vertex count known (no attribute resolves) every index is past it.
                if (format_ok && !(view.object && view.has_stride)) v.usages.push_back(u);
            }
            if (element_count >= 0 && mode >= 0 && mode <= 6) {
                const bool ok = mode == 0   ? element_count > 0
                                : mode == 1 ? element_count >= 2 && element_count % 2 == 0
                                : mode <= 3 ? element_count >= 2
                                : mode == 4 ? element_count >= 3 && element_count % 3 == 0
                                            : element_count >= 3;
                if (!ok)
                    v.add("MESH_PRIMITIVE_INCOMPATIBLE_MODE", Severity::Warning, where,
                          "Number of vertices or indices (" + std::to_string(element_count) +
                              ") is not compatible with used drawing mode (" +
                              std::to_string(mode) + ").");
            }

            // Morph targets.
            std::size_t target_count = 0;
            if (prim.contains("targets") && prim["targets"].is_array()) {
                const Json& ts = prim["targets"];
                target_count = ts.size();
                for (std::size_t t = 0; t < ts.size(); ++t)
                    for (const auto& [name, value] : Validation::member(ts, t).items()) {
                        const std::string tp = ptr(ptr(ptr(where, "targets"), t), name);
                        if (!is_int(value) || as_int(value) < 0 ||
                            static_cast<std::size_t>(as_int(value)) >= accessors.size()) {
                            v.add("UNRESOLVED_REFERENCE", Severity::Error, tp,
                                  "Unresolved reference.");
                            continue;
                        }
                        if (target_missing(as_int(value)))
                            v.add("BUFFER_VIEW_TARGET_MISSING", Severity::Hint, tp,
                                  "bufferView.target should be set for vertex or index data.");
                        if (name == "POSITION" &&
                            (!v.accessors[static_cast<std::size_t>(as_int(value))].has_min ||
                             !v.accessors[static_cast<std::size_t>(as_int(value))].has_max))
                            v.add("MESH_PRIMITIVE_POSITION_ACCESSOR_WITHOUT_BOUNDS",
                                  Severity::Error, tp,
                                  "accessor.min and accessor.max must be defined for POSITION "
                                  "attribute accessor.");
                        if (!resolved.contains(name))
                            v.add("MESH_PRIMITIVE_MORPH_TARGET_NO_BASE_ACCESSOR", Severity::Error,
                                  tp,
                                  "The mesh primitive does not define this attribute semantic.");
                        else if (declared[static_cast<std::size_t>(as_int(value))].count !=
                                 vertex_count)
                            v.add("MESH_PRIMITIVE_MORPH_TARGET_INVALID_ATTRIBUTE_COUNT",
                                  Severity::Error, tp, "Base accessor has different count.");
                    }
            }
            if (first_targets == SIZE_MAX)
                first_targets = target_count;
            else if (first_targets != target_count)
                v.add("MESH_PRIMITIVES_UNEQUAL_TARGETS_COUNT", Severity::Error, where,
                      "All primitives must have the same number of morph targets.");

            // What the material needs: texture coordinate sets and a tangent space.
            std::set<std::int64_t> sets;
            bool normal_texture = false, tangent_space = false;
            if (const std::int64_t mi = ref(v, prim, "material", "materials"); mi >= 0) {
                const Json& material = v.array("materials")[static_cast<std::size_t>(mi)];
                material_needs(material, sets, 0);
                normal_texture = Validation::member(material, "normalTexture").is_object() &&
                                 material.contains("normalTexture");
                for (std::int64_t s : sets)
                    if (!texcoords.contains(static_cast<int>(s))) {
                        v.add("MESH_PRIMITIVE_TOO_FEW_TEXCOORDS", Severity::Error,
                              ptr(where, "material"),
                              "Material is incompatible with mesh primitive: needs 'TEXCOORD_" +
                                  std::to_string(s) + "' attribute.");
                        break;
                    }
                tangent_space = needs_tangent_space(v, material);
                if (normal_texture && !has_tangent && has_normal)
                    v.add("MESH_PRIMITIVE_GENERATED_TANGENT_SPACE", Severity::Warning,
                          ptr(where, "material"),
                          "Material requires a tangent space but the mesh primitive does not "
                          "provide it. "
                          "Runtime-generated tangent space may be non-portable across "
                          "implementations.");
                else if (tangent_space && !normal_texture && !has_tangent)
                    v.add("MESH_PRIMITIVE_NO_TANGENT_SPACE", Severity::Error,
                          ptr(where, "material"),
                          "Material requires a tangent space but the mesh primitive does not "
                          "provide it and the material does not contain a normal map to "
                          "generate it.");
            }
            if (has_tangent && !tangent_space)
                v.add("UNUSED_MESH_TANGENT", Severity::Information, ptr(attr_where, "TANGENT"),
                      "Tangents are not used because the material has no normal texture.");
            for (int t : texcoords)
                if (!sets.contains(t))
                    v.add("UNUSED_OBJECT", Severity::Information,
                          ptr(attr_where, "TEXCOORD_" + std::to_string(t)),
                          "This object may be unused.");
        }
        if (meshes[m].is_object() && meshes[m].contains("weights") &&
            meshes[m]["weights"].is_array() && first_targets != SIZE_MAX &&
            meshes[m]["weights"].size() != first_targets)
            v.add("MESH_INVALID_WEIGHTS_COUNT", Severity::Error, ptr(ptr("/meshes", m), "weights"),
                  "The length of weights array (" + std::to_string(meshes[m]["weights"].size()) +
                      ") does not match the number of morph targets (" +
                      std::to_string(first_targets) + ").");
    }
}

} // namespace sherpa::scene::detail
