#include <sherpa/lab/families.h>
#include <sherpa/lab/family.h>

#include "lab_support.h"

namespace sherpa::lab {

const ErrorFigure* MethodResult::error(std::string_view name) const {
    for (const ErrorFigure& e : errors)
        if (e.name == name) return &e;
    return nullptr;
}

scene::LoadOptions lab_load_options() {
    scene::LoadOptions options;
    options.generate_tangents = false;
    return options;
}

std::vector<std::string_view> family_names() {
    return {"tangents", "textures", "culling", "mesh-compression", "shadows", "lighting"};
}

std::unique_ptr<Family> make_family(std::string_view name) {
    if (name == "tangents") return make_tangent_family();
    if (name == "textures") return make_texture_family();
    if (name == "culling") return make_cull_family();
    if (name == "mesh-compression") return make_mesh_compression_family();
    if (name == "shadows") return make_shadow_family();
    if (name == "lighting") return make_lighting_family();
    return nullptr;
}

bool family_draws_lit_frames(std::string_view name) {
    return name == "shadows" || name == "lighting";
}

std::unique_ptr<Family> make_family(std::string_view name, const render::Lighting& lighting) {
    if (name == "shadows") {
        ShadowFamilyOptions options;
        options.lighting = lighting;
        return make_shadow_family(options);
    }
    if (name == "lighting") {
        LightingFamilyOptions options;
        options.lighting = lighting;
        return make_lighting_family(options);
    }
    return make_family(name);
}

namespace detail {

std::string describe_mesh(const scene::Mesh& mesh) {
    std::string s = "mesh " + std::to_string(mesh.group_id) + " primitive " +
                    std::to_string(mesh.primitive_index);
    if (!mesh.name.empty()) s += " '" + mesh.name + "'";
    return s;
}

FamilyReport cancelled_report(std::string family) {
    FamilyReport r;
    r.family = std::move(family);
    r.cancelled = true;
    return r;
}

} // namespace detail

} // namespace sherpa::lab
