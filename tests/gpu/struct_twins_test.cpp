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
         sizeof(GPUMaterialData),
         {TWIN_FIELD(GPUMaterialData, base_color_factor),
          TWIN_FIELD(GPUMaterialData, emissive_factor),
          TWIN_FIELD(GPUMaterialData, metallic_factor),
          TWIN_FIELD(GPUMaterialData, roughness_factor), TWIN_FIELD(GPUMaterialData, normal_scale),
          TWIN_FIELD(GPUMaterialData, occlusion_strength),
          TWIN_FIELD(GPUMaterialData, base_color_tex), TWIN_FIELD(GPUMaterialData, emissive_tex),
          TWIN_FIELD(GPUMaterialData, metallic_roughness_tex),
          TWIN_FIELD(GPUMaterialData, normal_tex), TWIN_FIELD(GPUMaterialData, occlusion_tex),
          TWIN_FIELD(GPUMaterialData, alpha_cutoff), TWIN_FIELD(GPUMaterialData, alpha_mode),
          TWIN_FIELD(GPUMaterialData, double_sided)}},
        {"GPUTextureTransform",
         Source::StructProbe,
         "GPUTextureTransform",
         "",
         "std430",
         "common.glsl",
         sizeof(GPUTextureTransform),
         {TWIN_FIELD(GPUTextureTransform, row0), TWIN_FIELD(GPUTextureTransform, row1)}},
        {"GPUMaterialExtra",
         Source::StructProbe,
         "GPUMaterialExtra",
         "",
         "std430",
         "common.glsl",
         sizeof(GPUMaterialExtra),
         {TWIN_FIELD(GPUMaterialExtra, uv), TWIN_FIELD(GPUMaterialExtra, unlit),
          TWIN_FIELD(GPUMaterialExtra, workflow),
          TWIN_FIELD(GPUMaterialExtra, specular_glossiness_tex),
          TWIN_FIELD(GPUMaterialExtra, extensions),
          TWIN_FIELD(GPUMaterialExtra, specular_glossiness)}},
        {"GPUExtensionIndex",
         Source::StructProbe,
         "GPUExtensionIndex",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUExtensionIndex),
         {TWIN_FIELD(GPUExtensionIndex, ior), TWIN_FIELD(GPUExtensionIndex, specular),
          TWIN_FIELD(GPUExtensionIndex, clearcoat), TWIN_FIELD(GPUExtensionIndex, sheen),
          TWIN_FIELD(GPUExtensionIndex, transmission), TWIN_FIELD(GPUExtensionIndex, volume),
          TWIN_FIELD(GPUExtensionIndex, diffuse_transmission),
          TWIN_FIELD(GPUExtensionIndex, dispersion), TWIN_FIELD(GPUExtensionIndex, anisotropy),
          TWIN_FIELD(GPUExtensionIndex, iridescence), TWIN_FIELD(GPUExtensionIndex, pad0),
          TWIN_FIELD(GPUExtensionIndex, pad1)}},
        {"GPUAnisotropyBlock",
         Source::StructProbe,
         "GPUAnisotropyBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUAnisotropyBlock),
         {TWIN_FIELD(GPUAnisotropyBlock, factors), TWIN_FIELD(GPUAnisotropyBlock, texture),
          TWIN_FIELD(GPUAnisotropyBlock, pad0), TWIN_FIELD(GPUAnisotropyBlock, pad1),
          TWIN_FIELD(GPUAnisotropyBlock, pad2), TWIN_FIELD(GPUAnisotropyBlock, uv)}},
        {"GPUIridescenceBlock",
         Source::StructProbe,
         "GPUIridescenceBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUIridescenceBlock),
         {TWIN_FIELD(GPUIridescenceBlock, factors), TWIN_FIELD(GPUIridescenceBlock, texture),
          TWIN_FIELD(GPUIridescenceBlock, thickness_tex), TWIN_FIELD(GPUIridescenceBlock, pad0),
          TWIN_FIELD(GPUIridescenceBlock, pad1), TWIN_FIELD(GPUIridescenceBlock, uv),
          TWIN_FIELD(GPUIridescenceBlock, thickness_uv)}},
        {"GPUIorBlock",
         Source::StructProbe,
         "GPUIorBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUIorBlock),
         {TWIN_FIELD(GPUIorBlock, ior), TWIN_FIELD(GPUIorBlock, pad0),
          TWIN_FIELD(GPUIorBlock, pad1), TWIN_FIELD(GPUIorBlock, pad2)}},
        {"GPUSpecularBlock",
         Source::StructProbe,
         "GPUSpecularBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUSpecularBlock),
         {TWIN_FIELD(GPUSpecularBlock, color_factor), TWIN_FIELD(GPUSpecularBlock, specular_tex),
          TWIN_FIELD(GPUSpecularBlock, specular_color_tex), TWIN_FIELD(GPUSpecularBlock, pad0),
          TWIN_FIELD(GPUSpecularBlock, pad1), TWIN_FIELD(GPUSpecularBlock, specular_uv),
          TWIN_FIELD(GPUSpecularBlock, color_uv)}},
        {"GPUTransmissionBlock",
         Source::StructProbe,
         "GPUTransmissionBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUTransmissionBlock),
         {TWIN_FIELD(GPUTransmissionBlock, factor), TWIN_FIELD(GPUTransmissionBlock, texture),
          TWIN_FIELD(GPUTransmissionBlock, pad0), TWIN_FIELD(GPUTransmissionBlock, pad1),
          TWIN_FIELD(GPUTransmissionBlock, uv)}},
        {"GPUVolumeBlock",
         Source::StructProbe,
         "GPUVolumeBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUVolumeBlock),
         {TWIN_FIELD(GPUVolumeBlock, attenuation), TWIN_FIELD(GPUVolumeBlock, thickness_factor),
          TWIN_FIELD(GPUVolumeBlock, thickness_tex), TWIN_FIELD(GPUVolumeBlock, pad0),
          TWIN_FIELD(GPUVolumeBlock, pad1), TWIN_FIELD(GPUVolumeBlock, thickness_uv)}},
        {"GPUDiffuseTransmissionBlock",
         Source::StructProbe,
         "GPUDiffuseTransmissionBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUDiffuseTransmissionBlock),
         {TWIN_FIELD(GPUDiffuseTransmissionBlock, color_factor),
          TWIN_FIELD(GPUDiffuseTransmissionBlock, texture),
          TWIN_FIELD(GPUDiffuseTransmissionBlock, color_tex),
          TWIN_FIELD(GPUDiffuseTransmissionBlock, pad0),
          TWIN_FIELD(GPUDiffuseTransmissionBlock, pad1),
          TWIN_FIELD(GPUDiffuseTransmissionBlock, uv),
          TWIN_FIELD(GPUDiffuseTransmissionBlock, color_uv)}},
        {"GPUDispersionBlock",
         Source::StructProbe,
         "GPUDispersionBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUDispersionBlock),
         {TWIN_FIELD(GPUDispersionBlock, dispersion), TWIN_FIELD(GPUDispersionBlock, pad0),
          TWIN_FIELD(GPUDispersionBlock, pad1), TWIN_FIELD(GPUDispersionBlock, pad2)}},
        {"GPUClearcoatBlock",
         Source::StructProbe,
         "GPUClearcoatBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUClearcoatBlock),
         {TWIN_FIELD(GPUClearcoatBlock, factors), TWIN_FIELD(GPUClearcoatBlock, clearcoat_tex),
          TWIN_FIELD(GPUClearcoatBlock, roughness_tex), TWIN_FIELD(GPUClearcoatBlock, normal_tex),
          TWIN_FIELD(GPUClearcoatBlock, pad0), TWIN_FIELD(GPUClearcoatBlock, clearcoat_uv),
          TWIN_FIELD(GPUClearcoatBlock, roughness_uv), TWIN_FIELD(GPUClearcoatBlock, normal_uv)}},
        {"GPUSheenBlock",
         Source::StructProbe,
         "GPUSheenBlock",
         "",
         "std430",
         "material_ext_structs.glsl",
         sizeof(GPUSheenBlock),
         {TWIN_FIELD(GPUSheenBlock, factors), TWIN_FIELD(GPUSheenBlock, color_tex),
          TWIN_FIELD(GPUSheenBlock, roughness_tex), TWIN_FIELD(GPUSheenBlock, pad0),
          TWIN_FIELD(GPUSheenBlock, pad1), TWIN_FIELD(GPUSheenBlock, color_uv),
          TWIN_FIELD(GPUSheenBlock, roughness_uv)}},
        {"GPULight",
         Source::StructProbe,
         "GPULight",
         "",
         "std140",
         "common.glsl",
         sizeof(GPULight),
         {TWIN_FIELD(GPULight, position_range), TWIN_FIELD(GPULight, direction_type),
          TWIN_FIELD(GPULight, color_intensity), TWIN_FIELD(GPULight, cone)}},
        {"GPUInstanceData",
         Source::StructProbe,
         "GPUInstanceData",
         "",
         "scalar",
         "common.glsl",
         sizeof(GPUInstanceData),
         {TWIN_FIELD(GPUInstanceData, model), TWIN_FIELD(GPUInstanceData, normal_matrix),
          TWIN_FIELD(GPUInstanceData, material), TWIN_FIELD(GPUInstanceData, mesh),
          TWIN_FIELD(GPUInstanceData, joint_base), TWIN_FIELD(GPUInstanceData, weight_base)}},
        {"GPUMotionMesh",
         Source::StructProbe,
         "GPUMotionMesh",
         "",
         "scalar",
         "common.glsl",
         sizeof(GPUMotionMesh),
         {TWIN_FIELD(GPUMotionMesh, joints), TWIN_FIELD(GPUMotionMesh, weights),
          TWIN_FIELD(GPUMotionMesh, morph_positions), TWIN_FIELD(GPUMotionMesh, morph_normals),
          TWIN_FIELD(GPUMotionMesh, morph_tangents), TWIN_FIELD(GPUMotionMesh, vertex_count),
          TWIN_FIELD(GPUMotionMesh, influence_sets), TWIN_FIELD(GPUMotionMesh, target_count),
          TWIN_FIELD(GPUMotionMesh, flags)}},
        {"GPULineVertex",
         Source::StructProbe,
         "LineVertex",
         "",
         "scalar",
         "common.glsl",
         sizeof(GPULineVertex),
         {TWIN_FIELD(GPULineVertex, position), TWIN_FIELD(GPULineVertex, color)}},
        {"GPUCullObject",
         Source::StructProbe,
         "CullObject",
         "",
         "scalar",
         "cull_structs.glsl",
         sizeof(GPUCullObject),
         {TWIN_FIELD(GPUCullObject, bmin), TWIN_FIELD(GPUCullObject, batch),
          TWIN_FIELD(GPUCullObject, bmax), TWIN_FIELD(GPUCullObject, instance)}},
        {"GPUCullParams",
         Source::StructProbe,
         "CullParams",
         "",
         "scalar",
         "cull_structs.glsl",
         sizeof(GPUCullParams),
         {TWIN_FIELD(GPUCullParams, planes), TWIN_FIELD(GPUCullParams, sat_axis),
          TWIN_FIELD(GPUCullParams, sat_range), TWIN_FIELD(GPUCullParams, plane_count),
          TWIN_FIELD(GPUCullParams, sat_count), TWIN_FIELD(GPUCullParams, method),
          TWIN_FIELD(GPUCullParams, object_count), TWIN_FIELD(GPUCullParams, empty)}},
        {"GPUGeometryInfo",
         Source::StructProbe,
         "GeometryInfo",
         "",
         "scalar",
         "rt_geometry.glsl",
         sizeof(GPUGeometryInfo),
         {TWIN_FIELD(GPUGeometryInfo, stream), TWIN_FIELD(GPUGeometryInfo, indices),
          TWIN_FIELD(GPUGeometryInfo, material), TWIN_FIELD(GPUGeometryInfo, flags)}},
        {"GPUFrameData",
         Source::Shader,
         "forward.frag",
         "FrameBlock",
         "",
         "",
         sizeof(GPUFrameData),
         {TWIN_FIELD(GPUFrameData, view), TWIN_FIELD(GPUFrameData, proj),
          TWIN_FIELD(GPUFrameData, view_proj), TWIN_FIELD(GPUFrameData, shadow_view_proj),
          TWIN_FIELD(GPUFrameData, camera_position), TWIN_FIELD(GPUFrameData, cascade_splits),
          TWIN_FIELD(GPUFrameData, sun_direction), TWIN_FIELD(GPUFrameData, sun_radiance),
          TWIN_FIELD(GPUFrameData, ambient), TWIN_FIELD(GPUFrameData, params),
          TWIN_FIELD(GPUFrameData, overlay), TWIN_FIELD(GPUFrameData, cascade_texel),
          TWIN_FIELD(GPUFrameData, lights), TWIN_FIELD(GPUFrameData, environment),
          TWIN_FIELD(GPUFrameData, display), TWIN_FIELD(GPUFrameData, irradiance_sh)}},
        {"GPUPushConstants",
         Source::Shader,
         "mesh.vert",
         "Push",
         "",
         "",
         sizeof(GPUPushConstants),
         {TWIN_FIELD(GPUPushConstants, instances), TWIN_FIELD(GPUPushConstants, positions),
          TWIN_FIELD(GPUPushConstants, normals), TWIN_FIELD(GPUPushConstants, tangents),
          TWIN_FIELD(GPUPushConstants, uv0), TWIN_FIELD(GPUPushConstants, uv1),
          TWIN_FIELD(GPUPushConstants, colors), TWIN_FIELD(GPUPushConstants, lines),
          TWIN_FIELD(GPUPushConstants, material_id), TWIN_FIELD(GPUPushConstants, mesh_flags),
          TWIN_FIELD(GPUPushConstants, cascade), TWIN_FIELD(GPUPushConstants, glyph_length),
          TWIN_FIELD(GPUPushConstants, color), TWIN_FIELD(GPUPushConstants, instance_ids),
          TWIN_FIELD(GPUPushConstants, motion), TWIN_FIELD(GPUPushConstants, pose),
          TWIN_FIELD(GPUPushConstants, highlight_base), TWIN_FIELD(GPUPushConstants, pad)}},
        {"GPURayPushConstants",
         Source::Shader,
         "rt.rgen",
         "RayPush",
         "",
         "",
         sizeof(GPURayPushConstants),
         {TWIN_FIELD(GPURayPushConstants, inv_view_proj),
          TWIN_FIELD(GPURayPushConstants, geometries), TWIN_FIELD(GPURayPushConstants, view),
          TWIN_FIELD(GPURayPushConstants, texture_lod),
          TWIN_FIELD(GPURayPushConstants, clear_color), TWIN_FIELD(GPURayPushConstants, sun),
          TWIN_FIELD(GPURayPushConstants, shadow_rays), TWIN_FIELD(GPURayPushConstants, ao_rays),
          TWIN_FIELD(GPURayPushConstants, ao_radius), TWIN_FIELD(GPURayPushConstants, reserved)}},
        {"GPUPathPushConstants",
         Source::Shader,
         "pt.rgen",
         "PathPush",
         "",
         "",
         sizeof(GPUPathPushConstants),
         {TWIN_FIELD(GPUPathPushConstants, inv_view_proj),
          TWIN_FIELD(GPUPathPushConstants, geometries),
          TWIN_FIELD(GPUPathPushConstants, first_sample),
          TWIN_FIELD(GPUPathPushConstants, texture_lod),
          TWIN_FIELD(GPUPathPushConstants, clear_color), TWIN_FIELD(GPUPathPushConstants, samples),
          TWIN_FIELD(GPUPathPushConstants, max_bounces), TWIN_FIELD(GPUPathPushConstants, seed),
          TWIN_FIELD(GPUPathPushConstants, light_inv_power),
          TWIN_FIELD(GPUPathPushConstants, env_size),
          TWIN_FIELD(GPUPathPushConstants, sun_cos_radius),
          TWIN_FIELD(GPUPathPushConstants, max_radiance)}},
        {"GPUPoseVerticesPush",
         Source::Shader,
         "pose_vertices.comp",
         "Push",
         "",
         "",
         sizeof(GPUPoseVerticesPush),
         {TWIN_FIELD(GPUPoseVerticesPush, instance), TWIN_FIELD(GPUPoseVerticesPush, positions),
          TWIN_FIELD(GPUPoseVerticesPush, normals), TWIN_FIELD(GPUPoseVerticesPush, tangents),
          TWIN_FIELD(GPUPoseVerticesPush, motion), TWIN_FIELD(GPUPoseVerticesPush, pose),
          TWIN_FIELD(GPUPoseVerticesPush, out_positions),
          TWIN_FIELD(GPUPoseVerticesPush, out_normals),
          TWIN_FIELD(GPUPoseVerticesPush, out_tangents),
          TWIN_FIELD(GPUPoseVerticesPush, mesh_flags),
          TWIN_FIELD(GPUPoseVerticesPush, highlight_base),
          TWIN_FIELD(GPUPoseVerticesPush, vertex_count),
          TWIN_FIELD(GPUPoseVerticesPush, object_space)}},
        {"GPUComparePush",
         Source::Shader,
         "compare.comp",
         "ComparePush",
         "",
         "",
         sizeof(GPUComparePush),
         {TWIN_FIELD(GPUComparePush, side_size), TWIN_FIELD(GPUComparePush, target_size),
          TWIN_FIELD(GPUComparePush, mode), TWIN_FIELD(GPUComparePush, target_srgb),
          TWIN_FIELD(GPUComparePush, divider_px), TWIN_FIELD(GPUComparePush, heat_max)}},
        {"GPUCompareStats",
         Source::Shader,
         "compare.comp",
         "Stats",
         "",
         "",
         sizeof(GPUCompareStats),
         {TWIN_FIELD(GPUCompareStats, histogram), TWIN_FIELD(GPUCompareStats, squared_lo),
          TWIN_FIELD(GPUCompareStats, squared_hi)}},
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
