// Build-time host tool: writes the GLSL constants the shaders share with the C++
// engine (shaders/include/*.glsl include the result) from the C++ definitions
// themselves, so no value is copied by hand. Usage: sherpa_glsl_constants OUT_DIR
//
// Each constant keeps the form (const uint or #define, literal spelling) its
// hand-written copy had, so the compiled SPIR-V does not change.
#include <sherpa/render/debug_views.h>
#include <sherpa/render/gpu_material_ext_structs.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/material.h>
#include <sherpa/scene/vertex.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace sherpa;

// "tangent-w" -> "TANGENT_W": a table name as a GLSL identifier suffix.
std::string glsl_name(std::string_view name) {
    std::string out;
    for (char c : name) out += c == '-' ? '_' : static_cast<char>(std::toupper(c));
    return out;
}

std::string hex(std::uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08xu", v);
    return buf;
}

template <typename E> unsigned u(E e) {
    return static_cast<unsigned>(e);
}

struct Section {
    const char* file;    // written into the output directory
    const char* comment; // where the values come from
    std::string body;
};

std::string views() {
    std::ostringstream o;
    for (const render::DebugViewInfo& v : render::kDebugViews)
        o << "const uint VIEW_" << glsl_name(v.name) << " = " << u(v.id) << ";\n";
    const auto& f = render::kSpecGlossFlagColor;
    o << "// The metallic view on specular-glossiness materials (no metallic value).\n"
      << "const vec3 SPEC_GLOSS_FLAG = vec3(" << f[0] << ", " << f[1] << ", " << f[2] << ");\n";
    const std::pair<const char*, const std::array<float, 3>*> classes[] = {
        {"SHADOW_AGREE_LIT", &render::kShadowAgreeLitColor},
        {"SHADOW_AGREE_SHADOWED", &render::kShadowAgreeShadowedColor},
        {"SHADOW_FALSE_SHADOW", &render::kShadowFalseShadowColor},
        {"SHADOW_FALSE_LIGHT", &render::kShadowFalseLightColor}};
    o << "// The shadow-error view's classes.\n";
    for (auto [name, c] : classes)
        o << "const vec3 " << name << " = vec3(" << (*c)[0] << ", " << (*c)[1] << ", " << (*c)[2]
          << ");\n";
    o << "// The provenance view's colours: authored, generated, defaulted.\n"
      << "const vec3 PROVENANCE_COLORS[3] = vec3[3](";
    for (std::size_t i = 0; i < render::kProvenanceColors.size(); ++i) {
        const auto& c = render::kProvenanceColors[i];
        o << (i ? ", " : "") << "vec3(" << c[0] << ", " << c[1] << ", " << c[2] << ")";
    }
    o << ");\n";
    return o.str();
}

std::string overlays() {
    std::ostringstream o;
    for (const render::OverlayEntry& ov : render::kOverlays)
        o << "const uint OVERLAY_" << glsl_name(ov.name) << " = " << u(ov.bit) << "u;\n";
    return o.str();
}

std::string mesh_flags() {
    std::ostringstream o;
    const std::pair<scene::VertexAttribute, const char*> streams[] = {
        {scene::VertexAttribute::Position, "POSITION"}, {scene::VertexAttribute::Normal, "NORMAL"},
        {scene::VertexAttribute::Tangent, "TANGENT"},   {scene::VertexAttribute::TexCoord0, "UV0"},
        {scene::VertexAttribute::TexCoord1, "UV1"},     {scene::VertexAttribute::Color0, "COLOR"}};
    static_assert(std::size(streams) == scene::kVertexAttributeCount);
    for (auto [a, name] : streams) o << "const uint HAS_" << name << " = 1u << " << u(a) << ";\n";
    o << "const uint MESH_LINES = " << hex(render::kMeshLinesBit) << "; // topology bits\n";
    o << "const uint MESH_POINTS = " << hex(render::kMeshPointsBit) << ";\n";
    o << "const uint TANGENT_PROVENANCE_SHIFT = " << render::kTangentProvenanceShift
      << "; // 0 authored, 1 generated, 2 defaulted\n";
    o << "const uint NORMAL_PROVENANCE_SHIFT = " << render::kNormalProvenanceShift << ";\n";
    o << "const uint GLYPH_KIND_SHIFT = " << render::kGlyphKindShift
      << "; // 0 normal, 1 tangent, 2 bitangent\n";
    o << "const uint NO_CASCADE = " << hex(render::kNoCascade) << ";\n";
    o << "const uint MESH_MOTION = " << hex(render::kMeshMotionBit) << "; // skins or morphs\n";
    o << "const uint MOTION_SKIN = " << hex(render::kMotionSkin) << "; // GPUMotionMesh.flags\n";
    o << "const uint MOTION_MORPH_POSITIONS = " << hex(render::kMotionMorphPositions) << ";\n";
    o << "const uint MOTION_MORPH_NORMALS = " << hex(render::kMotionMorphNormals) << ";\n";
    o << "const uint MOTION_MORPH_TANGENTS = " << hex(render::kMotionMorphTangents) << ";\n";
    return o.str();
}

std::string texture_slots() {
    std::ostringstream o;
    const std::pair<render::TextureSlotIndex, const char*> slots[] = {
        {render::kSlotBaseColor, "BASE_COLOR"},
        {render::kSlotMetallicRoughness, "METALLIC_ROUGHNESS"},
        {render::kSlotNormal, "NORMAL"},
        {render::kSlotOcclusion, "OCCLUSION"},
        {render::kSlotEmissive, "EMISSIVE"},
        {render::kSlotSpecularGlossiness, "SPECULAR_GLOSSINESS"}};
    static_assert(std::size(slots) == render::kSlotCount);
    for (auto [slot, name] : slots) o << "const uint SLOT_" << name << " = " << u(slot) << ";\n";
    o << "const uint SLOT_COUNT = " << u(render::kSlotCount) << ";\n";
    o << "const uint WORKFLOW_METALLIC_ROUGHNESS = " << u(render::kWorkflowMetallicRoughness)
      << ";\n";
    o << "const uint WORKFLOW_SPECULAR_GLOSSINESS = " << u(render::kWorkflowSpecularGlossiness)
      << ";\n";
    return o.str();
}

// One file per group, included where its hand-written copy stood: glslang numbers
// even unused constants, so a shader that got constants it does not use (or got
// them in another order) would compile to different SPIR-V.
std::vector<Section> sections() {
    std::ostringstream limits, textures, alpha, cull;
    limits << "const uint MAX_LIGHTS = " << render::kMaxLights << ";\n"
           << "const uint MAX_CASCADES = " << render::kMaxCascades
           << "; // array size in the frame block\n"
           << "const uint SHADOW_CASCADES = " << render::kShadowCascades
           << "; // cascades actually used\n";
    textures << "const uint TEX_WHITE = " << gpu::kWhiteTexture << "u;\n"
             << "const uint TEX_FLAT_NORMAL = " << gpu::kFlatNormalTexture << "u;\n"
             << "const uint TEX_BLACK = " << gpu::kBlackTexture << "u;\n";
    alpha << "#define SHERPA_ALPHA_OPAQUE " << u(scene::AlphaMode::Opaque) << "u\n"
          << "#define SHERPA_ALPHA_MASK " << u(scene::AlphaMode::Mask) << "u\n"
          << "#define SHERPA_ALPHA_BLEND " << u(scene::AlphaMode::Blend) << "u\n";
    cull << "#define CULL_SPHERE " << u(scene::CullMethod::Sphere) << "u\n"
         << "#define CULL_PVERTEX " << u(scene::CullMethod::PVertex) << "u\n"
         << "#define CULL_EXACT " << u(scene::CullMethod::Exact) << "u\n"
         << "#define CULL_INVALID_BIT " << hex(render::kCullInvalidBit) << "\n"
         << "#define CULL_MAX_SAT_AXES " << render::kCullMaxSatAxes << "\n";
    return {
        {"sherpa_frame_limits.glsl", "sherpa::render::kMaxLights, kMaxCascades, kShadowCascades",
         limits.str()},
        {"sherpa_mesh_flags.glsl",
         "push constant mesh_flags: stream bits (sherpa::scene::VertexAttribute), provenance and "
         "glyph "
         "shifts (gpu_structs.h)",
         mesh_flags()},
        {"sherpa_views.glsl", "debug views, sherpa::render::kDebugViews (debug_views.h)", views()},
        {"sherpa_overlays.glsl",
         "overlay bits of FrameRequest::overlays, sherpa::render::kOverlays (debug_views.h)",
         overlays()},
        {"sherpa_texture_slots.glsl",
         "texture slots of GPUMaterialExtra.uv, in this order, and its workflows", texture_slots()},
        {"sherpa_material_ext.glsl",
         "sherpa::render::kNoExtension: material extension blocks (gpu_material_ext_structs.h)",
         "const uint NO_EXTENSION = " + hex(render::kNoExtension) + ";\n"},
        {"sherpa_default_textures.glsl", "default bindless textures, sherpa::gpu::kWhiteTexture...",
         textures.str()},
        {"sherpa_alpha_modes.glsl", "sherpa::scene::AlphaMode (scene/material.h)", alpha.str()},
        {"sherpa_cull.glsl",
         "sherpa::scene::CullMethod (scene/culling.h), sherpa::render::kCullInvalidBit, "
         "kCullMaxSatAxes",
         cull.str()},
    };
}

std::string file_text(const Section& s) {
    std::string guard = "SHERPA_GENERATED_";
    for (const char* c = s.file; *c && *c != '.'; ++c) guard += static_cast<char>(std::toupper(*c));
    return std::string("// Generated at build time by sherpa_glsl_constants (engine/gpu/tools/\n"
                       "// glsl_constants.cpp) from the C++ definitions; do not edit.\n// ") +
           s.comment + "\n#ifndef " + guard + "\n#define " + guard + "\n" + s.body + "#endif\n";
}

// Writes `text` unless the file already holds it, so shaders recompile only on change.
bool write_if_changed(const std::string& path, const std::string& text) {
    {
        std::ifstream old(path, std::ios::binary);
        std::ostringstream old_text;
        old_text << old.rdbuf();
        if (old && old_text.str() == text) return true;
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    if (out.flush()) return true;
    std::fprintf(stderr, "%s: cannot write\n", path.c_str());
    return false;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: sherpa_glsl_constants OUT_DIR\n");
        return 2;
    }
    for (const Section& section : sections())
        if (!write_if_changed(std::string(argv[1]) + "/" + section.file, file_text(section)))
            return 1;
    return 0;
}
