// The path tracer through KHR_materials_transmission + KHR_materials_volume: slabs of
// three thicknesses in a uniform environment of radiance 1, seen face on. With ior 1
// (no refraction, no reflection at normal incidence) and a smooth surface, the light
// through a slab of thickness L is Beer-Lambert's attenuationColor^(L /
// attenuationDistance), exactly; the path tracer measures the real path inside.
#include "gpu_test_support.h"
#include "sphere_scenes.h"

#include <sherpa/render/path_trace.h>

#include <cmath>
#include <cstdio>

namespace sherpa::test {
namespace {

// `thickness.size()` boxes 1.6 x 1.6 x L along +X (2.5 apart, as sphere_row_gltf), each
// transmissive (factor 1, ior 1, roughness 0, white) with a volume of attenuationColor
// (c, c, c) at attenuationDistance d. Single-sided: a volume's back faces bound it all
// the same.
std::string slab_row_gltf(const std::vector<float>& thickness, float c, float d) {
    std::vector<float> data; // per box: 24 positions, then 24 normals
    std::vector<std::uint32_t> idx;
    const int n = int(thickness.size());
    for (int i = 0; i < 6; ++i) {
        const int axis = i / 2;
        const float sign = i % 2 ? -1.0f : 1.0f;
        for (int k = 0; k < 4; ++k) {
            const float u = (k == 1 || k == 2) ? 1.0f : -1.0f, v = k >= 2 ? 1.0f : -1.0f;
            glm::vec3 p;
            p[axis] = sign;
            p[(axis + 1) % 3] = sign * u; // counter-clockwise seen from outside
            p[(axis + 2) % 3] = v;
            data.insert(data.end(), {p.x, p.y, p.z});
        }
        const std::uint32_t b = std::uint32_t(i) * 4;
        idx.insert(idx.end(), {b, b + 1, b + 2, b, b + 2, b + 3});
    }
    for (int i = 0; i < 6; ++i)
        for (int k = 0; k < 4; ++k) {
            glm::vec3 nrm(0.0f);
            nrm[i / 2] = i % 2 ? -1.0f : 1.0f;
            data.insert(data.end(), {nrm.x, nrm.y, nrm.z});
        }
    std::vector<std::uint8_t> bytes(data.size() * 4 + idx.size() * 4);
    std::memcpy(bytes.data(), data.data(), data.size() * 4);
    std::memcpy(bytes.data() + data.size() * 4, idx.data(), idx.size() * 4);
    std::ostringstream j;
    j << R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_materials_transmission",)"
      << R"("KHR_materials_volume","KHR_materials_ior"],"scene":0,"scenes":[{"nodes":[)";
    for (int i = 0; i < n; ++i) j << (i ? "," : "") << i;
    j << "]}],\"nodes\":[";
    for (int i = 0; i < n; ++i)
        j << (i ? "," : "") << R"({"mesh":0,"translation":[)" << 2.5 * i
          << ",0,0],\"scale\":[0.8,0.8," << thickness[std::size_t(i)] / 2.0f << "]}";
    j << R"(],"meshes":[)";
    j << R"({"primitives":[{"attributes":{"POSITION":0,"NORMAL":1},"indices":2,"material":0}]})";
    j << R"(],"materials":[{"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],)"
      << R"("metallicFactor":0,"roughnessFactor":0},"extensions":{"KHR_materials_ior":{"ior":1},)"
      << R"("KHR_materials_transmission":{"transmissionFactor":1},"KHR_materials_volume":)"
      << R"({"thicknessFactor":1,"attenuationDistance":)" << d << R"(,"attenuationColor":[)" << c
      << "," << c << "," << c << "]}}}]";
    j << R"(,"accessors":[{"bufferView":0,"componentType":5126,"count":24,"type":"VEC3",)"
      << R"("min":[-1,-1,-1],"max":[1,1,1]},{"bufferView":0,"byteOffset":288,"componentType":5126,)"
      << R"("count":24,"type":"VEC3"},{"bufferView":1,"componentType":5125,"count":36,)"
      << R"("type":"SCALAR"}],"bufferViews":[{"buffer":0,"byteLength":576},{"buffer":0,)"
      << R"("byteOffset":576,"byteLength":144}],"buffers":[{"byteLength":)" << bytes.size()
      << R"(,"uri":"data:application/octet-stream;base64,)" << base64(bytes) << "\"}]}";
    return j.str();
}

class PathTraceVolumeTest : public GpuTest {};

TEST_F(PathTraceVolumeTest, SlabTransmittanceFollowsBeerLambert) {
    render::RendererOptions options;
    options.ray_tracing = true;
    options.textures = test_texture_settings();
    render::Renderer rt(*GpuEnvironment::get().context, options);
    const render::EnvironmentImage uniform = render::uniform_environment(glm::vec3(1.0f));
    rt.set_environment(&uniform);
    const std::vector<float> thickness = {0.5f, 1.0f, 2.0f};
    const float colour = 0.5f, distance = 1.0f;
    auto scene =
        load(write_temp("pt_slabs.gltf", slab_row_gltf(thickness, colour, distance)).string());
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    rt.load(*scene);
    render::FrameRequest s = furnace_view(int(thickness.size()), 48);
    s.renderer = render::RendererKind::RayTraced;
    s.path.restart = true;
    s.path.samples = 16;
    rt.render(s);
    const render::PathTraceImage img = render::read_path_trace(rt);
    ASSERT_EQ(img.samples, 16u);
    for (std::size_t i = 0; i < thickness.size(); ++i) {
        // The middle of the slab's face: 16 x 16 pixels about the box's centre.
        double sum = 0.0;
        int n = 0;
        for (std::uint32_t y = 16; y < 32; ++y)
            for (std::uint32_t x = 48 * std::uint32_t(i) + 16; x < 48 * std::uint32_t(i) + 32;
                 ++x) {
                const float* p = &img.sums[(std::size_t(y) * img.width + x) * 4];
                sum += p[0] / img.samples;
                ++n;
            }
        const double measured = sum / n;
        const double expected = std::pow(double(colour), double(thickness[i]) / distance);
        std::printf("slab thickness %.1f: path traced %.4f, Beer-Lambert %.4f\n",
                    double(thickness[i]), measured, expected);
        EXPECT_NEAR(measured, expected, 0.01 * expected + 0.002) << thickness[i];
    }
    rt.unload();
    rt.set_environment(nullptr);
}

} // namespace
} // namespace sherpa::test
