// KHR_materials_variants -> Scene::variants. A mapping that names a material or a
// variant that does not exist is a warning with its JSON pointer, and that variant
// then shows the primitive's default material: the file still loads and every valid
// mapping is kept.
#include "import_context.h"
#include "validate_internal.h"

#include <algorithm>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

constexpr const char* kExtension = "KHR_materials_variants";
constexpr std::string_view kCode = "SHERPA_MATERIAL_VARIANT_INVALID";
// The Khronos validator's codes where it has one (all errors there): the message list
// then agrees with it, and the file still loads.
constexpr std::string_view kUnresolved = "UNRESOLVED_REFERENCE";
constexpr std::string_view kUndefined = "UNDEFINED_PROPERTY";
constexpr std::string_view kNonUnique = "KHR_MATERIALS_VARIANTS_NON_UNIQUE_VARIANT";

void warn(ImportContext& ctx, const std::string& message, std::string_view code = kCode,
          Severity severity = Severity::Warning) {
    ctx.scene.warnings.push_back(message);
    add_import_message(ctx.scene.validation, code, severity, message);
}

// An index value of the JSON, or -1 (and a warning) where it is not a non-negative
// integer below `count`.
std::int32_t index_in(ImportContext& ctx, const tinygltf::Value& v, std::size_t count,
                      const std::string& where, const char* what) {
    if (!v.IsNumber() || v.GetNumberAsDouble() != double(v.GetNumberAsInt()) ||
        v.GetNumberAsInt() < 0) {
        warn(ctx, where + ": not a " + what + " index; ignored");
        return -1;
    }
    const int i = v.GetNumberAsInt();
    if (static_cast<std::size_t>(i) >= count) {
        warn(ctx,
             where + ": " + what + " " + std::to_string(i) + " out of range (file has " +
                 std::to_string(count) + "); ignored",
             kUnresolved, Severity::Error);
        return -1;
    }
    return i;
}

void read_names(ImportContext& ctx) {
    const auto it = ctx.model.extensions.find(kExtension);
    if (it == ctx.model.extensions.end()) return;
    const std::string where = std::string("extensions.") + kExtension + ".variants";
    const tinygltf::Value& list = it->second.Get("variants");
    if (!list.IsArray()) {
        warn(ctx, where + ": missing or not an array; the file has no variants");
        return;
    }
    for (std::size_t i = 0; i < list.ArrayLen(); ++i) {
        const tinygltf::Value& name = list.Get(int(i)).Get("name");
        std::string text = name.IsString() ? name.Get<std::string>() : std::string();
        if (text.empty()) {
            text = "variant " + std::to_string(i);
            warn(ctx, where + "[" + std::to_string(i) + "].name: missing; called \"" + text + "\"");
        }
        ctx.scene.variants.names.push_back(std::move(text));
    }
}

// The mappings of one primitive (its engine mesh `mesh`), or nothing.
void read_mappings(ImportContext& ctx, const tinygltf::Primitive& prim, std::uint32_t mesh,
                   const std::string& where) {
    const auto it = prim.extensions.find(kExtension);
    if (it == prim.extensions.end()) return;
    Scene& scene = ctx.scene;
    const std::size_t variants = scene.variants.names.size();
    const std::size_t materials = ctx.model.materials.size();
    const std::string base = where + ".extensions." + kExtension + ".mappings";
    const tinygltf::Value& list = it->second.Get("mappings");
    if (!list.IsArray()) {
        warn(ctx, base + ": missing or not an array; the primitive keeps its material");
        return;
    }
    VariantMeshMapping out;
    out.mesh = mesh;
    out.default_material = scene.meshes[mesh].material_id;
    out.materials.assign(variants, -1);
    for (std::size_t k = 0; k < list.ArrayLen(); ++k) {
        const std::string at = base + "[" + std::to_string(k) + "]";
        const tinygltf::Value& mapping = list.Get(int(k));
        const std::int32_t material =
            index_in(ctx, mapping.Get("material"), materials, at + ".material", "material");
        const tinygltf::Value& names = mapping.Get("variants");
        if (!names.IsArray()) {
            if (names.Type() == tinygltf::NULL_TYPE)
                warn(ctx, at + ": property 'variants' must be defined; mapping ignored", kUndefined,
                     Severity::Error);
            else
                warn(ctx, at + ".variants: not an array; mapping ignored");
            continue;
        }
        if (material < 0) continue; // its variants show the default material
        for (std::size_t j = 0; j < names.ArrayLen(); ++j) {
            const std::string vat = at + ".variants[" + std::to_string(j) + "]";
            const std::int32_t v = index_in(ctx, names.Get(int(j)), variants, vat, "variant");
            if (v < 0) continue;
            std::int32_t& slot = out.materials[std::size_t(v)];
            if (slot >= 0)
                warn(ctx,
                     vat + ": variant " + std::to_string(v) +
                         " is mapped more than once for this primitive; the first mapping "
                         "(material " +
                         std::to_string(slot) + ") is kept",
                     kNonUnique, Severity::Error);
            else
                slot = material;
        }
    }
    if (std::any_of(out.materials.begin(), out.materials.end(), [](auto m) { return m >= 0; }))
        scene.variants.meshes.push_back(std::move(out));
}

} // namespace

void import_material_variants(ImportContext& ctx) {
    read_names(ctx);
    const Scene& scene = ctx.scene;
    for (const PrimitiveInfo& p : scene.primitives) {
        const auto& prim = ctx.model.meshes[p.mesh].primitives[p.primitive];
        if (prim.extensions.find(kExtension) == prim.extensions.end()) continue;
        const std::string where = "meshes[" + std::to_string(p.mesh) + "].primitives[" +
                                  std::to_string(p.primitive) + "]";
        if (p.engine_mesh < 0) continue; // skipped primitives have said why
        if (scene.variants.names.empty()) {
            warn(ctx, where + ".extensions." + kExtension +
                          ": the file declares no variants (extensions." + kExtension +
                          ".variants); mappings ignored");
            continue;
        }
        read_mappings(ctx, prim, static_cast<std::uint32_t>(p.engine_mesh), where);
    }
}

} // namespace sherpa::scene::detail
