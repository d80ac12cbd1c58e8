// EXT_mesh_gpu_instancing: a node's TRANSLATION / ROTATION / SCALE rows become
// instances of its mesh (select_scene() makes one MeshInstance per row and
// primitive). What the file gets wrong is named and drawn as well as it can be:
// a bad accessor or a node the extension does not apply to draws the node once;
// non-finite rows are left out; counts that differ use the smallest.
#include "accessor_reader.h"
#include "import_context.h"
#include "import_error.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

constexpr const char* kExtension = "EXT_mesh_gpu_instancing";

struct Semantic {
    const char* name;
    std::uint32_t components;
};
constexpr std::array<Semantic, 3> kSemantics{{{"TRANSLATION", 3}, {"ROTATION", 4}, {"SCALE", 3}}};

// Whether the spec allows the accessor's component type for the semantic:
// TRANSLATION and SCALE float, ROTATION float or normalized byte / short.
bool spec_type(const tinygltf::Accessor& a, const Semantic& s) {
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) return true;
    return s.components == 4 && a.normalized &&
           (a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
            a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT);
}

struct Attribute {
    std::vector<float> values; // components per row: the semantic's
    std::uint32_t count = 0;
};

// The attributes of one node's extension; false (with a warning) when the node is
// drawn once instead.
bool read_attributes(ImportContext& ctx, const tinygltf::Value& ext, const std::string& where,
                     NodeInstancing& out, std::array<Attribute, 3>& attrs, std::uint32_t& rows) {
    const auto& model = ctx.model;
    if (!ext.IsObject() || !ext.Has("attributes") || !ext.Get("attributes").IsObject()) {
        ctx.warn(where + ".attributes: required object is missing; the node is drawn once");
        return false;
    }
    const tinygltf::Value& attributes = ext.Get("attributes");
    std::vector<std::pair<std::string, std::uint32_t>> counts;
    for (const std::string& name : attributes.Keys()) {
        const std::string aw = where + ".attributes." + name;
        const tinygltf::Value& id = attributes.Get(name);
        const int index = id.IsNumber() ? id.GetNumberAsInt() : -1;
        const auto semantic = std::find_if(kSemantics.begin(), kSemantics.end(),
                                           [&](const Semantic& s) { return name == s.name; });
        if (semantic == kSemantics.end() && name.rfind('_', 0) != 0) {
            ctx.warn(aw + ": not an instance attribute of " + kExtension +
                     " (TRANSLATION, ROTATION, SCALE, or custom _NAME); ignored");
            continue;
        }
        try {
            if (index < 0 || std::size_t(index) >= model.accessors.size())
                fail("accessor index " + std::to_string(index) + " out of range (file has " +
                     std::to_string(model.accessors.size()) + ")");
            std::uint32_t comps = 0;
            if (semantic == kSemantics.end()) { // custom: its count, backed by its bytes
                const auto values = read_accessor_floats(model, index, {1, 2, 3, 4}, comps, aw);
                counts.emplace_back(name, std::uint32_t(values.size() / std::max(comps, 1u)));
                out.custom_attributes.push_back(name);
                continue;
            }
            const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
            if (!spec_type(a, *semantic))
                ctx.warn(aw + ": componentType " + std::to_string(a.componentType) +
                         (a.normalized ? " normalized" : "") + " is not one " + kExtension +
                         " allows for " + semantic->name +
                         (semantic->components == 4 ? " (FLOAT, normalized BYTE or SHORT)"
                                                    : " (FLOAT)") +
                         "; read as glTF decodes it");
            Attribute& at = attrs[std::size_t(semantic - kSemantics.begin())];
            at.values = read_accessor_floats(model, index, {semantic->components}, comps, aw);
            at.count = std::uint32_t(at.values.size() / semantic->components);
            counts.emplace_back(name, at.count);
            (semantic->components == 4        ? out.rotation
             : semantic == kSemantics.begin() ? out.translation
                                              : out.scale) = index;
        } catch (const ImportError& e) {
            ctx.warn(std::string(e.what()).rfind(aw, 0) == 0
                         ? std::string(e.what()) + "; the node is drawn once"
                         : aw + ": " + e.what() + "; the node is drawn once");
            return false;
        }
    }
    if (counts.empty()) {
        ctx.warn(where + ".attributes: no instance attribute; the node is drawn once");
        return false;
    }
    rows = counts.front().second;
    bool differ = false;
    for (const auto& [name, count] : counts) {
        differ = differ || count != rows;
        rows = std::min(rows, count);
    }
    if (differ) {
        std::string list;
        for (const auto& [name, count] : counts)
            list += (list.empty() ? "" : ", ") + name + " " + std::to_string(count);
        ctx.warn(where + ".attributes: counts differ (" + list +
                 "), which the extension forbids; the first " + std::to_string(rows) +
                 " rows are drawn");
    }
    return true;
}

} // namespace

void import_gpu_instancing(ImportContext& ctx) {
    const auto& model = ctx.model;
    Scene& scene = ctx.scene;
    std::uint64_t budget = kMaxGpuInstanceRows;
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const auto it = model.nodes[i].extensions.find(kExtension);
        if (it == model.nodes[i].extensions.end()) continue;
        const std::string where = "nodes[" + std::to_string(i) + "].extensions." + kExtension;
        Node& node = scene.nodes[i];
        if (node.mesh < 0) {
            ctx.warn(where + ": the node has no mesh, and the extension applies to mesh "
                             "nodes only; ignored");
            continue;
        }
        if (node.skin >= 0) {
            ctx.warn(where + ": the node is skinned, and its joints place the mesh; the " +
                     "instance rows are not drawn (the skin is drawn once)");
            continue;
        }
        NodeInstancing inst;
        std::array<Attribute, 3> attrs;
        std::uint32_t rows = 0;
        if (!read_attributes(ctx, it->second, where, inst, attrs, rows)) continue;
        inst.file_rows = rows;
        std::uint64_t primitives = 0;
        for (const std::int32_t m : scene.mesh_primitives[std::size_t(node.mesh)])
            primitives += m >= 0 ? 1 : 0;
        std::uint32_t dropped = 0, first_dropped = 0;
        inst.rows.reserve(rows);
        for (std::uint32_t r = 0; r < rows; ++r) {
            InstanceRow row;
            row.file_row = r;
            if (!attrs[0].values.empty())
                row.translation = {attrs[0].values[3 * r], attrs[0].values[3 * r + 1],
                                   attrs[0].values[3 * r + 2]};
            if (!attrs[1].values.empty()) { // glTF (x, y, z, w); glm::quat takes w first
                const float* q = &attrs[1].values[4 * std::size_t(r)];
                row.rotation = glm::quat(q[3], q[0], q[1], q[2]);
            }
            if (!attrs[2].values.empty())
                row.scale = {attrs[2].values[3 * r], attrs[2].values[3 * r + 1],
                             attrs[2].values[3 * r + 2]};
            // Quantized rotations are unit length within their step; renormalised. A
            // zero or non-finite quaternion has no rotation to draw.
            const float len = glm::length(row.rotation);
            bool ok = core::is_finite(row.translation) && core::is_finite(row.scale) &&
                      std::isfinite(len) && len > 1e-6f;
            if (ok) {
                row.rotation /= len;
                ok = core::is_finite(row.matrix());
            }
            if (!ok) {
                if (dropped++ == 0) first_dropped = r;
                continue;
            }
            if (primitives > budget) {
                ctx.warn(where + ": rows " + std::to_string(r) + ".." + std::to_string(rows - 1) +
                         " not drawn: the file's instanced rows x primitives reach the limit of " +
                         std::to_string(kMaxGpuInstanceRows) + " instances");
                break;
            }
            budget -= primitives;
            inst.rows.push_back(row);
        }
        if (dropped)
            ctx.warn(where + ": " + std::to_string(dropped) + " of " + std::to_string(rows) +
                     " rows have a non-finite translation, rotation or scale, or a zero "
                     "rotation (first: row " +
                     std::to_string(first_dropped) + "); those rows are not drawn");
        node.instancing = std::move(inst);
    }
}

} // namespace sherpa::scene::detail
