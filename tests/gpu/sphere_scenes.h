#pragma once
// Test scenes made in code: rows of white spheres (the furnace tests of the raster's
// environment lighting and of the path tracer), written to temporary glTF files.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <sherpa/render/camera.h>
#include <sherpa/render/frame_request.h>

namespace sherpa::test {

inline std::string base64(const std::vector<std::uint8_t>& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const std::uint32_t n = (std::uint32_t(in[i]) << 16) |
                                (i + 1 < in.size() ? std::uint32_t(in[i + 1]) << 8 : 0u) |
                                (i + 2 < in.size() ? std::uint32_t(in[i + 2]) : 0u);
        out += t[(n >> 18) & 63];
        out += t[(n >> 12) & 63];
        out += i + 1 < in.size() ? t[(n >> 6) & 63] : '=';
        out += i + 2 < in.size() ? t[n & 63] : '=';
    }
    return out;
}

// A glTF of `count` unit UV spheres along +X (2.5 apart), sphere i white with
// roughness i / (count - 1) and the given metalness; `rings` x 2 `rings` quads each.
inline std::string sphere_row_gltf(int count, float metallic, int rings = 24) {
    const int segments = 2 * rings;
    std::vector<float> pos, nrm;
    std::vector<std::uint32_t> idx;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const float th = float(M_PI) * float(r) / rings,
                        ph = 2.0f * float(M_PI) * float(s) / segments;
            const float x = std::sin(th) * std::cos(ph), y = std::cos(th),
                        z = std::sin(th) * std::sin(ph);
            pos.insert(pos.end(), {x, y, z});
            nrm.insert(nrm.end(), {x, y, z});
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
            idx.insert(idx.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    std::vector<std::uint8_t> bytes(pos.size() * 8 + idx.size() * 4);
    std::memcpy(bytes.data(), pos.data(), pos.size() * 4);
    std::memcpy(bytes.data() + pos.size() * 4, nrm.data(), nrm.size() * 4);
    std::memcpy(bytes.data() + pos.size() * 8, idx.data(), idx.size() * 4);
    const std::size_t vbytes = pos.size() * 4, n = pos.size() / 3;
    std::ostringstream j;
    j << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)";
    for (int i = 0; i < count; ++i) j << (i ? "," : "") << i;
    j << "]}],\"nodes\":[";
    for (int i = 0; i < count; ++i)
        j << (i ? "," : "") << R"({"mesh":)" << i << R"(,"translation":[)" << 2.5 * i << ",0,0]}";
    j << "],\"meshes\":[";
    for (int i = 0; i < count; ++i)
        j << (i ? "," : "")
          << R"({"primitives":[{"attributes":{"POSITION":0,"NORMAL":1},"indices":2,"material":)"
          << i << "}]}";
    j << "],\"materials\":[";
    for (int i = 0; i < count; ++i)
        j << (i ? "," : "")
          << R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":)" << metallic
          << R"(,"roughnessFactor":)" << float(i) / float(count - 1) << "}}";
    j << R"(],"accessors":[{"bufferView":0,"componentType":5126,"count":)" << n
      << R"(,"type":"VEC3","min":[-1,-1,-1],"max":[1,1,1]},{"bufferView":1,"componentType":5126,"count":)"
      << n << R"(,"type":"VEC3"},{"bufferView":2,"componentType":5125,"count":)" << idx.size()
      << R"(,"type":"SCALAR"}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" << vbytes
      << R"(},{"buffer":0,"byteOffset":)" << vbytes << R"(,"byteLength":)" << vbytes
      << R"(},{"buffer":0,"byteOffset":)" << 2 * vbytes << R"(,"byteLength":)" << idx.size() * 4
      << R"(}],"buffers":[{"byteLength":)" << bytes.size()
      << R"(,"uri":"data:application/octet-stream;base64,)" << base64(bytes) << "\"}]}";
    return j.str();
}

inline std::filesystem::path write_temp(const std::string& name, const std::string& text) {
    const std::filesystem::path p =
        std::filesystem::temp_directory_path() / ("sherpa_env_test_" + name);
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

// An equirectangular environment (environment.h's convention) of radiance f(direction),
// width x width / 2 texels.
template <typename F> render::EnvironmentImage environment_of(std::uint32_t width, F f) {
    render::EnvironmentImage image;
    image.width = width;
    image.height = width / 2;
    image.rgba.resize(std::size_t(image.width) * image.height * 4);
    const double pi = 3.14159265358979323846;
    for (std::uint32_t j = 0; j < image.height; ++j)
        for (std::uint32_t i = 0; i < image.width; ++i) {
            const double v = 1.0 - (j + 0.5) / image.height, u = (i + 0.5) / image.width;
            const double lat = (v - 0.5) * pi, phi = (u - 0.5) * 2.0 * pi;
            const glm::vec3 d(float(std::cos(lat) * std::cos(phi)), float(std::sin(lat)),
                              float(std::cos(lat) * std::sin(phi)));
            const glm::vec3 c = f(d);
            float* t = &image.rgba[4 * (std::size_t(j) * image.width + i)];
            t[0] = c.r, t[1] = c.g, t[2] = c.b, t[3] = 1.0f;
        }
    return image;
}

// The furnace view of sphere_row_gltf(count, ...): `px` pixels a sphere, seen from far
// away with a narrow field of view, no sun or shadows, linear tone mapping at -1 EV (1
// reads 0.5, clear of the 8-bit ceiling), on a black background.
inline render::FrameRequest furnace_view(int count, std::uint32_t px) {
    render::FrameRequest s;
    s.width = px * std::uint32_t(count);
    s.height = px;
    const float mid = 2.5f * float(count - 1) / 2.0f;
    char cam[160];
    std::snprintf(cam, sizeof(cam), "eye=%g,0,%g:target=%g,0,0:fov=%g", mid, 60.0, mid,
                  2.0 * std::atan(1.25 / 60.0) * 180.0 / 3.14159265358979323846);
    std::string error;
    EXPECT_TRUE(render::parse_camera_spec(cam, s.camera, error)) << error;
    s.sun = false;
    s.shadows = false;
    s.tone_map = render::ToneMap::Linear;
    s.exposure = -1.0f;
    s.background = render::Background::Color;
    s.clear_color = glm::vec4(0, 0, 0, 1);
    return s;
}

} // namespace sherpa::test
