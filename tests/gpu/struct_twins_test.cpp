// The GLSL twins of the GPU structs agree with the C++ definitions field by field: same
// names, same offsets, same size. The C++ side is read with offsetof; the GLSL side is
// compiled by glslangValidator, whose reflection (-q --reflect-all-block-variables)
// prints every block member's offset as the SPIR-V will have it. Blocks declared in the
// shaders themselves (push constants, the frame's uniform block, the compare statistics)
// are read from the shader that uses them; structs from a probe shader written here, in
// the layout the renderer's shaders declare them with (glslang's reflection does not
// descend into buffer_reference blocks, so a record behind one is a struct of its own).
#include <sherpa/render/gpu_material_ext_structs.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/scene/material.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

namespace {

using namespace sherpa;
using namespace sherpa::gpu;

struct Field {
    std::string name;
    std::size_t offset;
    bool address; // a VkDeviceAddress: a buffer reference (uint64_t) in GLSL
};

#define TWIN_FIELD(T, f)                                                                           \
    Field {                                                                                        \
#f, offsetof(T, f), std::is_same_v < std::remove_cvref_t < decltype(T::f)>,                \
            VkDeviceAddress>                                                                       \
    }

// Where the GLSL side of a twin is read.
enum class Source {
    Shader,      // a block the named shader declares (prefix: its reflected name)
    StructProbe, // a struct type, embedded in a probe block of `layout`
};

struct Twin {
    std::string cpp;
    Source source;
    std::string glsl;   // shader file (Shader) or GLSL type name (probes)
    std::string prefix; // reflected name prefix of the block's members (Shader)
    std::string layout; // StructProbe: std140, std430 or scalar
    std::string include;
    std::size_t size;
    std::vector<Field> fields;
};

std::vector<Twin> twins() {
    return {
        {"GPUMaterialData",
         Source::StructProbe,
         "GPUMaterialData",
         "",
         "std430",
         "common.glsl",
         sizeof(scene::GPUMaterialData),
         {TWIN_FIELD(scene::GPUMaterialData, base_color_factor),
          TWIN_FIELD(scene::GPUMaterialData, emissive_factor),
          TWIN_FIELD(scene::GPUMaterialData, metallic_factor),
          TWIN_FIELD(scene::GPUMaterialData, roughness_factor),
          TWIN_FIELD(scene::GPUMaterialData, normal_scale),
          TWIN_FIELD(scene::GPUMaterialData, occlusion_strength),
          TWIN_FIELD(scene::GPUMaterialData, base_color_tex),
          TWIN_FIELD(scene::GPUMaterialData, emissive_tex),
          TWIN_FIELD(scene::GPUMaterialData, metallic_roughness_tex),
          TWIN_FIELD(scene::GPUMaterialData, normal_tex),
          TWIN_FIELD(scene::GPUMaterialData, occlusion_tex),
          TWIN_FIELD(scene::GPUMaterialData, alpha_cutoff),
          TWIN_FIELD(scene::GPUMaterialData, alpha_mode),
          TWIN_FIELD(scene::GPUMaterialData, double_sided)}},
        {"GPUTextureTransform",
         Source::StructProbe,
         "GPUTextureTransform",
         "",
         "std430",
         "common.glsl",
         sizeof(render::GPUTextureTransform),
         {TWIN_FIELD(render::GPUTextureTransform, row0),
          TWIN_FIELD(render::GPUTextureTransform, row1)}},
        {"GPUMaterialExtra",
         Source::StructProbe,
         "GPUMaterialExtra",
         "",
         "std430",
         "common.glsl",
         sizeof(render::GPUMaterialExtra),
         {TWIN_FIELD(render::GPUMaterialExtra, uv), TWIN_FIELD(render::GPUMaterialExtra, unlit),
          TWIN_FIELD(render::GPUMaterialExtra, workflow),
          TWIN_FIELD(render::GPUMaterialExtra, specular_glossiness_tex),
          TWIN_FIELD(render::GPUMaterialExtra, extensions),
          TWIN_FIELD(render::GPUMaterialExtra, specular_glossiness)}},
        {"GPUExtensionIndex",
         Source::StructProbe,
         "GPUExtensionIndex",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUExtensionIndex),
         {TWIN_FIELD(render::GPUExtensionIndex, ior),
          TWIN_FIELD(render::GPUExtensionIndex, specular),
          TWIN_FIELD(render::GPUExtensionIndex, clearcoat),
          TWIN_FIELD(render::GPUExtensionIndex, sheen),
          TWIN_FIELD(render::GPUExtensionIndex, transmission),
          TWIN_FIELD(render::GPUExtensionIndex, volume),
          TWIN_FIELD(render::GPUExtensionIndex, diffuse_transmission),
          TWIN_FIELD(render::GPUExtensionIndex, dispersion),
          TWIN_FIELD(render::GPUExtensionIndex, anisotropy),
          TWIN_FIELD(render::GPUExtensionIndex, iridescence),
          TWIN_FIELD(render::GPUExtensionIndex, pad0),
          TWIN_FIELD(render::GPUExtensionIndex, pad1)}},
        {"GPUAnisotropyBlock",
         Source::StructProbe,
         "GPUAnisotropyBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUAnisotropyBlock),
         {TWIN_FIELD(render::GPUAnisotropyBlock, factors),
          TWIN_FIELD(render::GPUAnisotropyBlock, texture),
          TWIN_FIELD(render::GPUAnisotropyBlock, pad0),
          TWIN_FIELD(render::GPUAnisotropyBlock, pad1),
          TWIN_FIELD(render::GPUAnisotropyBlock, pad2),
          TWIN_FIELD(render::GPUAnisotropyBlock, uv)}},
        {"GPUIridescenceBlock",
         Source::StructProbe,
         "GPUIridescenceBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUIridescenceBlock),
         {TWIN_FIELD(render::GPUIridescenceBlock, factors),
          TWIN_FIELD(render::GPUIridescenceBlock, texture),
          TWIN_FIELD(render::GPUIridescenceBlock, thickness_tex),
          TWIN_FIELD(render::GPUIridescenceBlock, pad0),
          TWIN_FIELD(render::GPUIridescenceBlock, pad1),
          TWIN_FIELD(render::GPUIridescenceBlock, uv),
          TWIN_FIELD(render::GPUIridescenceBlock, thickness_uv)}},
        {"GPUIorBlock",
         Source::StructProbe,
         "GPUIorBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUIorBlock),
         {TWIN_FIELD(render::GPUIorBlock, ior), TWIN_FIELD(render::GPUIorBlock, pad0),
          TWIN_FIELD(render::GPUIorBlock, pad1), TWIN_FIELD(render::GPUIorBlock, pad2)}},
        {"GPUSpecularBlock",
         Source::StructProbe,
         "GPUSpecularBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUSpecularBlock),
         {TWIN_FIELD(render::GPUSpecularBlock, color_factor),
          TWIN_FIELD(render::GPUSpecularBlock, specular_tex),
          TWIN_FIELD(render::GPUSpecularBlock, specular_color_tex),
          TWIN_FIELD(render::GPUSpecularBlock, pad0), TWIN_FIELD(render::GPUSpecularBlock, pad1),
          TWIN_FIELD(render::GPUSpecularBlock, specular_uv),
          TWIN_FIELD(render::GPUSpecularBlock, color_uv)}},
        {"GPUTransmissionBlock",
         Source::StructProbe,
         "GPUTransmissionBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUTransmissionBlock),
         {TWIN_FIELD(render::GPUTransmissionBlock, factor),
          TWIN_FIELD(render::GPUTransmissionBlock, texture),
          TWIN_FIELD(render::GPUTransmissionBlock, pad0),
          TWIN_FIELD(render::GPUTransmissionBlock, pad1),
          TWIN_FIELD(render::GPUTransmissionBlock, uv)}},
        {"GPUVolumeBlock",
         Source::StructProbe,
         "GPUVolumeBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUVolumeBlock),
         {TWIN_FIELD(render::GPUVolumeBlock, attenuation),
          TWIN_FIELD(render::GPUVolumeBlock, thickness_factor),
          TWIN_FIELD(render::GPUVolumeBlock, thickness_tex),
          TWIN_FIELD(render::GPUVolumeBlock, pad0), TWIN_FIELD(render::GPUVolumeBlock, pad1),
          TWIN_FIELD(render::GPUVolumeBlock, thickness_uv)}},
        {"GPUDiffuseTransmissionBlock",
         Source::StructProbe,
         "GPUDiffuseTransmissionBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUDiffuseTransmissionBlock),
         {TWIN_FIELD(render::GPUDiffuseTransmissionBlock, color_factor),
          TWIN_FIELD(render::GPUDiffuseTransmissionBlock, texture),
          TWIN_FIELD(render::GPUDiffuseTransmissionBlock, color_tex),
          TWIN_FIELD(render::GPUDiffuseTransmissionBlock, pad0),
          TWIN_FIELD(render::GPUDiffuseTransmissionBlock, pad1),
          TWIN_FIELD(render::GPUDiffuseTransmissionBlock, uv),
          TWIN_FIELD(render::GPUDiffuseTransmissionBlock, color_uv)}},
        {"GPUDispersionBlock",
         Source::StructProbe,
         "GPUDispersionBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUDispersionBlock),
         {TWIN_FIELD(render::GPUDispersionBlock, dispersion),
          TWIN_FIELD(render::GPUDispersionBlock, pad0),
          TWIN_FIELD(render::GPUDispersionBlock, pad1),
          TWIN_FIELD(render::GPUDispersionBlock, pad2)}},
        {"GPUClearcoatBlock",
         Source::StructProbe,
         "GPUClearcoatBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUClearcoatBlock),
         {TWIN_FIELD(render::GPUClearcoatBlock, factors),
          TWIN_FIELD(render::GPUClearcoatBlock, clearcoat_tex),
          TWIN_FIELD(render::GPUClearcoatBlock, roughness_tex),
          TWIN_FIELD(render::GPUClearcoatBlock, normal_tex),
          TWIN_FIELD(render::GPUClearcoatBlock, pad0),
          TWIN_FIELD(render::GPUClearcoatBlock, clearcoat_uv),
          TWIN_FIELD(render::GPUClearcoatBlock, roughness_uv),
          TWIN_FIELD(render::GPUClearcoatBlock, normal_uv)}},
        {"GPUSheenBlock",
         Source::StructProbe,
         "GPUSheenBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(render::GPUSheenBlock),
         {TWIN_FIELD(render::GPUSheenBlock, factors), TWIN_FIELD(render::GPUSheenBlock, color_tex),
          TWIN_FIELD(render::GPUSheenBlock, roughness_tex), TWIN_FIELD(render::GPUSheenBlock, pad0),
          TWIN_FIELD(render::GPUSheenBlock, pad1), TWIN_FIELD(render::GPUSheenBlock, color_uv),
          TWIN_FIELD(render::GPUSheenBlock, roughness_uv)}},
        {"GPULight",
         Source::StructProbe,
         "GPULight",
         "",
         "std140",
         "common.glsl",
         sizeof(render::GPULight),
         {TWIN_FIELD(render::GPULight, position_range),
          TWIN_FIELD(render::GPULight, direction_type),
          TWIN_FIELD(render::GPULight, color_intensity), TWIN_FIELD(render::GPULight, cone)}},
        {"GPUInstanceData",
         Source::StructProbe,
         "GPUInstanceData",
         "",
         "scalar",
         "common.glsl",
         sizeof(render::GPUInstanceData),
         {TWIN_FIELD(render::GPUInstanceData, model),
          TWIN_FIELD(render::GPUInstanceData, normal_matrix),
          TWIN_FIELD(render::GPUInstanceData, material), TWIN_FIELD(render::GPUInstanceData, mesh),
          TWIN_FIELD(render::GPUInstanceData, joint_base),
          TWIN_FIELD(render::GPUInstanceData, weight_base)}},
        {"GPUMotionMesh",
         Source::StructProbe,
         "GPUMotionMesh",
         "",
         "scalar",
         "common.glsl",
         sizeof(render::GPUMotionMesh),
         {TWIN_FIELD(render::GPUMotionMesh, joints), TWIN_FIELD(render::GPUMotionMesh, weights),
          TWIN_FIELD(render::GPUMotionMesh, morph_positions),
          TWIN_FIELD(render::GPUMotionMesh, morph_normals),
          TWIN_FIELD(render::GPUMotionMesh, morph_tangents),
          TWIN_FIELD(render::GPUMotionMesh, vertex_count),
          TWIN_FIELD(render::GPUMotionMesh, influence_sets),
          TWIN_FIELD(render::GPUMotionMesh, target_count),
          TWIN_FIELD(render::GPUMotionMesh, flags)}},
        {"GPULineVertex",
         Source::StructProbe,
         "LineVertex",
         "",
         "scalar",
         "common.glsl",
         sizeof(render::GPULineVertex),
         {TWIN_FIELD(render::GPULineVertex, position), TWIN_FIELD(render::GPULineVertex, color)}},
        {"GPUCullObject",
         Source::StructProbe,
         "CullObject",
         "",
         "scalar",
         "cull_structs.glsl",
         sizeof(render::GPUCullObject),
         {TWIN_FIELD(render::GPUCullObject, bmin), TWIN_FIELD(render::GPUCullObject, batch),
          TWIN_FIELD(render::GPUCullObject, bmax), TWIN_FIELD(render::GPUCullObject, instance)}},
        {"GPUCullParams",
         Source::StructProbe,
         "CullParams",
         "",
         "scalar",
         "cull_structs.glsl",
         sizeof(render::GPUCullParams),
         {TWIN_FIELD(render::GPUCullParams, planes), TWIN_FIELD(render::GPUCullParams, sat_axis),
          TWIN_FIELD(render::GPUCullParams, sat_range),
          TWIN_FIELD(render::GPUCullParams, plane_count),
          TWIN_FIELD(render::GPUCullParams, sat_count), TWIN_FIELD(render::GPUCullParams, method),
          TWIN_FIELD(render::GPUCullParams, object_count),
          TWIN_FIELD(render::GPUCullParams, empty)}},
        {"GPUGeometryInfo",
         Source::StructProbe,
         "GeometryInfo",
         "",
         "scalar",
         "rt_geometry.glsl",
         sizeof(render::GPUGeometryInfo),
         {TWIN_FIELD(render::GPUGeometryInfo, stream), TWIN_FIELD(render::GPUGeometryInfo, indices),
          TWIN_FIELD(render::GPUGeometryInfo, material),
          TWIN_FIELD(render::GPUGeometryInfo, flags)}},
        {"GPUFrameData",
         Source::Shader,
         "forward.frag",
         "FrameBlock",
         "",
         "",
         sizeof(render::GPUFrameData),
         {TWIN_FIELD(render::GPUFrameData, view), TWIN_FIELD(render::GPUFrameData, proj),
          TWIN_FIELD(render::GPUFrameData, view_proj),
          TWIN_FIELD(render::GPUFrameData, shadow_view_proj),
          TWIN_FIELD(render::GPUFrameData, camera_position),
          TWIN_FIELD(render::GPUFrameData, cascade_splits),
          TWIN_FIELD(render::GPUFrameData, sun_direction),
          TWIN_FIELD(render::GPUFrameData, sun_radiance), TWIN_FIELD(render::GPUFrameData, ambient),
          TWIN_FIELD(render::GPUFrameData, params), TWIN_FIELD(render::GPUFrameData, overlay),
          TWIN_FIELD(render::GPUFrameData, cascade_texel), TWIN_FIELD(render::GPUFrameData, lights),
          TWIN_FIELD(render::GPUFrameData, environment), TWIN_FIELD(render::GPUFrameData, display),
          TWIN_FIELD(render::GPUFrameData, irradiance_sh)}},
        {"GPUPushConstants",
         Source::Shader,
         "mesh.vert",
         "Push",
         "",
         "",
         sizeof(render::GPUPushConstants),
         {TWIN_FIELD(render::GPUPushConstants, instances),
          TWIN_FIELD(render::GPUPushConstants, positions),
          TWIN_FIELD(render::GPUPushConstants, normals),
          TWIN_FIELD(render::GPUPushConstants, tangents), TWIN_FIELD(render::GPUPushConstants, uv0),
          TWIN_FIELD(render::GPUPushConstants, uv1), TWIN_FIELD(render::GPUPushConstants, colors),
          TWIN_FIELD(render::GPUPushConstants, lines),
          TWIN_FIELD(render::GPUPushConstants, material_id),
          TWIN_FIELD(render::GPUPushConstants, mesh_flags),
          TWIN_FIELD(render::GPUPushConstants, cascade),
          TWIN_FIELD(render::GPUPushConstants, glyph_length),
          TWIN_FIELD(render::GPUPushConstants, color),
          TWIN_FIELD(render::GPUPushConstants, instance_ids),
          TWIN_FIELD(render::GPUPushConstants, motion), TWIN_FIELD(render::GPUPushConstants, pose),
          TWIN_FIELD(render::GPUPushConstants, highlight_base),
          TWIN_FIELD(render::GPUPushConstants, pad)}},
        {"GPURayPushConstants",
         Source::Shader,
         "rt.rgen",
         "RayPush",
         "",
         "",
         sizeof(render::GPURayPushConstants),
         {TWIN_FIELD(render::GPURayPushConstants, inv_view_proj),
          TWIN_FIELD(render::GPURayPushConstants, geometries),
          TWIN_FIELD(render::GPURayPushConstants, view),
          TWIN_FIELD(render::GPURayPushConstants, texture_lod),
          TWIN_FIELD(render::GPURayPushConstants, clear_color),
          TWIN_FIELD(render::GPURayPushConstants, sun),
          TWIN_FIELD(render::GPURayPushConstants, shadow_rays),
          TWIN_FIELD(render::GPURayPushConstants, ao_rays),
          TWIN_FIELD(render::GPURayPushConstants, ao_radius),
          TWIN_FIELD(render::GPURayPushConstants, reserved)}},
        {"GPUPathPushConstants",
         Source::Shader,
         "pt.rgen",
         "PathPush",
         "",
         "",
         sizeof(render::GPUPathPushConstants),
         {TWIN_FIELD(render::GPUPathPushConstants, inv_view_proj),
          TWIN_FIELD(render::GPUPathPushConstants, geometries),
          TWIN_FIELD(render::GPUPathPushConstants, first_sample),
          TWIN_FIELD(render::GPUPathPushConstants, texture_lod),
          TWIN_FIELD(render::GPUPathPushConstants, clear_color),
          TWIN_FIELD(render::GPUPathPushConstants, samples),
          TWIN_FIELD(render::GPUPathPushConstants, max_bounces),
          TWIN_FIELD(render::GPUPathPushConstants, seed),
          TWIN_FIELD(render::GPUPathPushConstants, light_inv_power),
          TWIN_FIELD(render::GPUPathPushConstants, env_size),
          TWIN_FIELD(render::GPUPathPushConstants, sun_cos_radius),
          TWIN_FIELD(render::GPUPathPushConstants, max_radiance)}},
        {"GPUPoseVerticesPush",
         Source::Shader,
         "pose_vertices.comp",
         "Push",
         "",
         "",
         sizeof(render::GPUPoseVerticesPush),
         {TWIN_FIELD(render::GPUPoseVerticesPush, instance),
          TWIN_FIELD(render::GPUPoseVerticesPush, positions),
          TWIN_FIELD(render::GPUPoseVerticesPush, normals),
          TWIN_FIELD(render::GPUPoseVerticesPush, tangents),
          TWIN_FIELD(render::GPUPoseVerticesPush, motion),
          TWIN_FIELD(render::GPUPoseVerticesPush, pose),
          TWIN_FIELD(render::GPUPoseVerticesPush, out_positions),
          TWIN_FIELD(render::GPUPoseVerticesPush, out_normals),
          TWIN_FIELD(render::GPUPoseVerticesPush, out_tangents),
          TWIN_FIELD(render::GPUPoseVerticesPush, mesh_flags),
          TWIN_FIELD(render::GPUPoseVerticesPush, highlight_base),
          TWIN_FIELD(render::GPUPoseVerticesPush, vertex_count),
          TWIN_FIELD(render::GPUPoseVerticesPush, object_space)}},
        {"GPUComparePush",
         Source::Shader,
         "compare.comp",
         "ComparePush",
         "",
         "",
         sizeof(render::GPUComparePush),
         {TWIN_FIELD(render::GPUComparePush, side_size),
          TWIN_FIELD(render::GPUComparePush, target_size), TWIN_FIELD(render::GPUComparePush, mode),
          TWIN_FIELD(render::GPUComparePush, target_srgb),
          TWIN_FIELD(render::GPUComparePush, divider_px),
          TWIN_FIELD(render::GPUComparePush, heat_max)}},
        {"GPUCompareStats",
         Source::Shader,
         "compare.comp",
         "Stats",
         "",
         "",
         sizeof(render::GPUCompareStats),
         {TWIN_FIELD(render::GPUCompareStats, histogram),
          TWIN_FIELD(render::GPUCompareStats, squared_lo),
          TWIN_FIELD(render::GPUCompareStats, squared_hi)}},
    };
}

const std::filesystem::path kShaders = SHERPA_SHADER_DIR;
const std::filesystem::path kGenerated = SHERPA_GLSL_GENERATED_DIR;

// A probe shader in which the twin's GLSL type is used, so that its members reflect.
std::string probe_source(const Twin& t) {
    std::string s = "#version 460\n"
                    "#extension GL_GOOGLE_include_directive : require\n"
                    "#extension GL_EXT_scalar_block_layout : require\n"
                    "#extension GL_EXT_buffer_reference : require\n"
                    "#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require\n"
                    "#extension GL_EXT_nonuniform_qualifier : require\n"
                    "#include \"" +
                    t.include +
                    "\"\n"
                    "layout(local_size_x = 1) in;\n"
                    "layout(std430, set = 7, binding = 1) buffer ProbeOut { uint touched; };\n";
    std::string use;
    for (const Field& f : t.fields) {
        std::string e =
            f.address ? "uint64_t(p." + f.name + ") != 0ul" : "p." + f.name + " == p." + f.name;
        use += (use.empty() ? "" : " || ") + e;
    }
    const std::string kind = t.layout == "std140" ? "uniform" : "buffer";
    s += "layout(" + t.layout + ", set = 7, binding = 0) " + kind + " Probe { " + t.glsl +
         " p; };\n";
    return s + "void main() { touched = uint(" + use + "); }\n";
}

struct Reflection {
    std::map<std::string, std::size_t> members; // top-level member -> offset
    std::map<std::string, std::size_t> blocks;  // block name -> size
    std::string log;
};

std::optional<Reflection> reflect(const std::filesystem::path& shader, const std::string& prefix) {
    const auto out =
        std::filesystem::temp_directory_path() / ("sherpa_twin_" + std::to_string(::getpid()));
    const std::string cmd = std::string(SHERPA_GLSLANG) + " -V --target-env vulkan1.3 -l -q" +
                            " --reflect-all-block-variables -I" + (kShaders / "include").string() +
                            " -I" + kGenerated.string() + " -o " + out.string() + ".spv " +
                            shader.string() + " 2>&1";
    FILE* pipe = ::popen(cmd.c_str(), "r");
    if (!pipe) return std::nullopt;
    Reflection r;
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), buf.size(), pipe)) r.log += buf.data();
    const int status = ::pclose(pipe);
    std::filesystem::remove(out.string() + ".spv");
    if (status != 0) return r.log += "\n(glslangValidator failed)", r;
    // "NAME: offset N, type ..., size ..." in the uniform reflection; block sizes in the
    // block reflection ("BLOCK: offset -1, type ffffffff, size N, ...").
    static const std::regex member(R"(^([\w.\[\]]+): offset (-?\d+), type \w+, size (\d+))");
    bool blocks = false;
    std::istringstream lines(r.log);
    for (std::string line; std::getline(lines, line);) {
        if (line.find("block reflection:") != std::string::npos)
            blocks = line.rfind("Uniform block", 0) == 0 || line.rfind("Buffer block", 0) == 0;
        else if (line.find("reflection:") != std::string::npos)
            blocks = false;
        std::smatch m;
        if (!std::regex_search(line, m, member)) continue;
        if (blocks) {
            r.blocks[m[1]] = std::stoul(m[3]);
            continue;
        }
        const std::string name = m[1];
        if (name.rfind(prefix + ".", 0) != 0) continue;
        // The top-level member: up to the next '.' or '[' (nested members and array
        // elements of a member count toward its lowest offset).
        std::string rest = name.substr(prefix.size() + 1);
        rest = rest.substr(0, rest.find_first_of(".["));
        const std::size_t offset = std::stoul(m[2]);
        auto [it, inserted] = r.members.emplace(rest, offset);
        if (!inserted && offset < it->second) it->second = offset;
    }
    return r;
}

void PrintTo(const Twin& t, std::ostream* os) {
    *os << t.cpp;
}

class StructTwins : public ::testing::TestWithParam<Twin> {};

TEST_P(StructTwins, SameNamesOffsetsAndSize) {
    const Twin& t = GetParam();
    std::filesystem::path shader = kShaders / t.glsl;
    std::string prefix = t.prefix;
    if (t.source != Source::Shader) {
        shader = std::filesystem::temp_directory_path() / ("sherpa_twin_" + t.cpp + ".comp");
        std::ofstream(shader) << probe_source(t);
        prefix = "p";
    }
    const auto r = reflect(shader, prefix);
    ASSERT_TRUE(r.has_value()) << "cannot run " << SHERPA_GLSLANG;
    ASSERT_FALSE(r->members.empty())
        << t.cpp << ": no member of '" << prefix << "' reflected from " << shader << ":\n"
        << r->log;
    for (const Field& f : t.fields) {
        const auto it = r->members.find(f.name);
        if (it == r->members.end()) {
            ADD_FAILURE() << t.cpp << "::" << f.name << " has no GLSL twin of that name in "
                          << t.glsl;
            continue;
        }
        EXPECT_EQ(it->second, f.offset) << t.cpp << "::" << f.name << ": GLSL offset differs";
    }
    for (const auto& [name, offset] : r->members) {
        const bool known = std::any_of(t.fields.begin(), t.fields.end(),
                                       [&](const Field& f) { return f.name == name; });
        EXPECT_TRUE(known) << t.glsl << " member '" << name << "' (offset " << offset
                           << ") is not a field of " << t.cpp;
    }
    // The block's size where the GLSL side is a whole block; a probe's struct size is
    // the member after it (struct probes hold only it, so the block is the struct).
    const std::string block = t.source == Source::Shader ? t.prefix : "Probe";
    if (const auto it = r->blocks.find(block); it != r->blocks.end()) {
        EXPECT_EQ(it->second, t.size) << t.cpp << ": GLSL block size differs from sizeof";
    }
}

// Every GPU struct the render layer defines has a row above: a new struct cannot skip
// the check. (GPUTextureTransform and GPUMaterialData included; host-only structs are
// not named GPU*.)
TEST(StructTwinTable, ListsEveryGpuStructOfTheHeaders) {
    const std::regex head(R"(^struct\s+(?:alignas\(\d+\)\s+)?(GPU\w+)\s*\{)");
    for (const char* header :
         {SHERPA_GPU_STRUCTS_HEADER, SHERPA_GPU_MATERIAL_EXT_HEADER, SHERPA_MATERIAL_HEADER}) {
        std::ifstream in(header);
        ASSERT_TRUE(in) << header;
        for (std::string line; std::getline(in, line);) {
            std::smatch m;
            if (!std::regex_search(line, m, head)) continue;
            const auto all = twins();
            const bool listed = std::any_of(all.begin(), all.end(),
                                            [&](const Twin& t) { return t.cpp == m[1].str(); });
            EXPECT_TRUE(listed) << m[1] << " (" << header
                                << ") has no row in struct_twins_test.cpp";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(GpuStructs, StructTwins, ::testing::ValuesIn(twins()),
                         [](const auto& test) { return test.param.cpp; });

} // namespace
