#include "gltf_primitives.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <tiny_gltf.h>

namespace sherpa::test {
namespace {

// One component of an accessor element as float, normalised integers mapped as glTF says.
float component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? *p / 255.0f : *p;
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<float>(static_cast<std::int8_t>(*p));
        return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return static_cast<float>(v);
    }
    }
    throw std::runtime_error("unsupported component type");
}

std::uint32_t index_value(const unsigned char* p, int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    default: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

// Accessor as `count * comps` floats, sparse substitution applied.
std::vector<float> read_floats(const tinygltf::Model& m, int index, int comps) {
    const tinygltf::Accessor& a = m.accessors.at(index);
    const int size = tinygltf::GetComponentSizeInBytes(a.componentType);
    std::vector<float> out(a.count * comps, 0.0f);
    if (a.bufferView >= 0) {
        const tinygltf::BufferView& v = m.bufferViews.at(a.bufferView);
        const unsigned char* base =
            m.buffers.at(v.buffer).data.data() + v.byteOffset + a.byteOffset;
        const int stride = a.ByteStride(v);
        for (std::size_t e = 0; e < a.count; ++e)
            for (int c = 0; c < comps; ++c)
                out[e * comps + c] =
                    component(base + e * stride + c * size, a.componentType, a.normalized);
    }
    if (a.sparse.isSparse) {
        const auto& s = a.sparse;
        const tinygltf::BufferView& iv = m.bufferViews.at(s.indices.bufferView);
        const tinygltf::BufferView& vv = m.bufferViews.at(s.values.bufferView);
        const unsigned char* ib =
            m.buffers.at(iv.buffer).data.data() + iv.byteOffset + s.indices.byteOffset;
        const unsigned char* vb =
            m.buffers.at(vv.buffer).data.data() + vv.byteOffset + s.values.byteOffset;
        const int isize = tinygltf::GetComponentSizeInBytes(s.indices.componentType);
        for (int k = 0; k < s.count; ++k) {
            const std::uint32_t e = index_value(ib + k * isize, s.indices.componentType);
            for (int c = 0; c < comps; ++c)
                out[e * comps + c] =
                    component(vb + (k * comps + c) * size, a.componentType, a.normalized);
        }
    }
    return out;
}

// Index accessor as integers (floats would lose indices above 2^24).
std::vector<std::uint32_t> read_indices(const tinygltf::Model& m, int index) {
    const tinygltf::Accessor& a = m.accessors.at(index);
    const tinygltf::BufferView& v = m.bufferViews.at(a.bufferView);
    const unsigned char* base = m.buffers.at(v.buffer).data.data() + v.byteOffset + a.byteOffset;
    const int stride = a.ByteStride(v);
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t e = 0; e < a.count; ++e)
        out[e] = index_value(base + e * stride, a.componentType);
    return out;
}

template <class Vec> std::vector<Vec> read_vectors(const tinygltf::Model& m, int index) {
    const std::vector<float> f = read_floats(m, index, Vec::length());
    std::vector<Vec> out(f.size() / Vec::length());
    std::memcpy(out.data(), f.data(), f.size() * sizeof(float));
    return out;
}

int attribute(const tinygltf::Primitive& p, const std::string& name) {
    const auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}

// glTF's strip and fan orderings (spec 3.7.2.1), degenerate triangles kept.
std::vector<std::uint32_t> triangle_list(const std::vector<std::uint32_t>& v, int mode) {
    std::vector<std::uint32_t> out;
    if (mode == TINYGLTF_MODE_TRIANGLES)
        return std::vector<std::uint32_t>(v.begin(), v.end() - v.size() % 3);
    for (std::size_t i = 0; i + 2 < v.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
            out.insert(out.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
        else
            out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
    }
    return out;
}

} // namespace

std::vector<GltfPrimitive> read_gltf_primitives(const std::string& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    const bool binary = path.size() > 4 && path.substr(path.size() - 4) == ".glb";
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                           : loader.LoadASCIIFromFile(&model, &error, &warning, path);
    if (!ok) throw std::runtime_error(path + ": " + error);
    std::vector<GltfPrimitive> out;
    for (std::size_t mi = 0; mi < model.meshes.size(); ++mi) {
        const auto& mesh = model.meshes[mi];
        for (std::size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
            const tinygltf::Primitive& p = mesh.primitives[pi];
            const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
            if (mode < TINYGLTF_MODE_TRIANGLES || attribute(p, "POSITION") < 0) continue;
            GltfPrimitive g;
            g.mesh = static_cast<std::uint32_t>(mi);
            g.primitive = static_cast<std::uint32_t>(pi);
            g.positions = read_vectors<glm::vec3>(model, attribute(p, "POSITION"));
            if (p.material >= 0) {
                const auto& normal = model.materials.at(p.material).normalTexture;
                g.has_normal_texture = normal.index >= 0;
                if (g.has_normal_texture) g.tex_coord = static_cast<std::uint32_t>(normal.texCoord);
            }
            if (int a = attribute(p, "NORMAL"); a >= 0)
                g.normals = read_vectors<glm::vec3>(model, a);
            if (int a = attribute(p, "TEXCOORD_" + std::to_string(g.tex_coord)); a >= 0)
                g.uvs = read_vectors<glm::vec2>(model, a);
            if (int a = attribute(p, "TANGENT"); a >= 0)
                g.tangents = read_vectors<glm::vec4>(model, a);
            std::vector<std::uint32_t> order;
            if (p.indices >= 0) {
                order = read_indices(model, p.indices);
            } else {
                order.resize(g.positions.size());
                for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
            }
            g.indices = triangle_list(order, mode);
            out.push_back(std::move(g));
        }
    }
    return out;
}

std::vector<std::string> sample_models(const std::string& assets_dir) {
    std::vector<std::string> names;
    const std::filesystem::path root = std::filesystem::path(assets_dir) / "gltf";
    if (!std::filesystem::is_directory(root)) return names;
    for (const auto& entry : std::filesystem::directory_iterator(root)) {
        const std::string name = entry.path().filename().string();
        if (std::filesystem::exists(sample_model_path(assets_dir, name))) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string sample_model_path(const std::string& assets_dir, const std::string& name) {
    return assets_dir + "/gltf/" + name + "/glTF/" + name + ".gltf";
}

} // namespace sherpa::test
