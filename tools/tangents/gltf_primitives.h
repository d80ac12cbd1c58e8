#pragma once
// glTF primitives as plain arrays for tangent tests, benchmarks and reports: every
// triangle primitive as the engine's importer reads it (glTF triangle order after
// strip/fan conversion), with only the attributes the file provides.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sherpa::tools {

struct GltfPrimitive {
    std::uint32_t mesh = 0, primitive = 0;
    std::vector<glm::vec3> positions, normals; // normals empty if absent
    std::vector<glm::vec2> uvs;                // the set below, empty if absent
    std::vector<glm::vec4> tangents;           // authored TANGENT, empty if absent
    std::vector<std::uint32_t> indices;        // triangle list
    std::uint32_t tex_coord = 0;               // normal texture's set, else 0
    bool has_normal_texture = false;
};

// Reads every triangle-topology primitive of a .gltf/.glb (no tangent generation).
// Throws std::runtime_error with the importer's message.
std::vector<GltfPrimitive> read_gltf_primitives(const std::string& path);

// Model names under SHERPA_ASSETS_DIR/gltf, sorted, whose NAME/glTF/NAME.gltf exists.
std::vector<std::string> sample_models(const std::string& assets_dir);
std::string sample_model_path(const std::string& assets_dir, const std::string& name);

} // namespace sherpa::tools
