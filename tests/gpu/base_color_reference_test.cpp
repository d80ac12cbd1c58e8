// `sherpa-cli render --view base-color` against the source images read by libpng and
// libjpeg (not OpenImageIO, which Sherpa decodes with), over every shared sample
// model with base-colour textures. For sampled pixels the test casts the pixel's
// ray on the CPU, finds the triangle and its UV, and compares the rendered colour
// with the texels there, where the texture is smooth enough that filtering, mips
// and BC7 cannot move the colour by more than a few levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <glm/glm.hpp>

#include <sherpa/scene/scene_loader.h>

#include "cli/cli_run.h"
#include "reference/reference_images.h"
#include "test_support.h"

namespace {

using sherpa::test::ReferenceImage;

constexpr float kFovDegrees = 40.0f; // vertical
// Texels within this range (levels, every channel) around a pixel's UV make it a
// checked pixel; the expected colour is their mean, and the rendered one may differ
// by kTolerance plus half their range (filtering, mips and BC7 move it that far).
constexpr int kSmooth = 24;
constexpr int kTolerance = 6;

struct Model {
    const char* name;
    std::uint32_t size = 192; // rendered width and height
    std::uint32_t stride = 3; // checks every stride-th pixel in x and y
};

struct Camera {
    glm::vec3 eye, forward, right, up;
    float tan_half = 0;
};

// Looks at the bounds' centre from the front-right-above, far enough to see it all.
Camera fixed_camera(const sherpa::core::Aabb& bounds) {
    const glm::vec3 centre = 0.5f * (bounds.min + bounds.max);
    const float radius = 0.5f * glm::length(bounds.max - bounds.min);
    Camera c;
    c.eye = centre + glm::normalize(glm::vec3(0.45f, 0.35f, 1.0f)) * radius * 2.4f;
    c.forward = glm::normalize(centre - c.eye);
    c.right = glm::normalize(glm::cross(c.forward, glm::vec3(0, 1, 0)));
    c.up = glm::cross(c.right, c.forward);
    c.tan_half = std::tan(glm::radians(kFovDegrees) * 0.5f);
    return c;
}

struct Hit {
    float t = INFINITY;
    const sherpa::scene::MeshInstance* instance = nullptr;
    std::size_t triangle = 0; // first index of the triangle hit
    glm::vec2 uv{0};
    bool front = true;
};

// World-space positions per instance, computed once per scene.
using WorldPositions = std::vector<std::vector<glm::vec3>>;
WorldPositions world_positions(const sherpa::scene::Scene& scene) {
    WorldPositions out;
    for (const sherpa::scene::MeshInstance& inst : scene.instances) {
        const sherpa::scene::Mesh& mesh = scene.meshes[inst.mesh_id];
        auto& world = out.emplace_back(mesh.vertices.size());
        for (std::size_t i = 0; i < world.size(); ++i)
            world[i] = glm::vec3(inst.world * glm::vec4(mesh.vertices[i].position, 1.0f));
    }
    return out;
}

// Nearest triangle along the ray through pixel (x, y) (pixel centres, row 0 on top).
Hit cast(const sherpa::scene::Scene& scene, const WorldPositions& positions, const Camera& c,
         float x, float y, std::uint32_t size) {
    const float nx = 2.0f * (x + 0.5f) / float(size) - 1.0f;
    const float ny = 1.0f - 2.0f * (y + 0.5f) / float(size);
    const glm::vec3 dir =
        glm::normalize(c.forward + nx * c.tan_half * c.right + ny * c.tan_half * c.up);
    Hit best;
    for (std::size_t k = 0; k < scene.instances.size(); ++k) {
        const sherpa::scene::MeshInstance& inst = scene.instances[k];
        // Slab test against the instance's world bounds first.
        float t0 = 0, t1 = best.t;
        for (int a = 0; a < 3; ++a) {
            const float inv = 1.0f / dir[a];
            float ta = (inst.world_bounds.min[a] - c.eye[a]) * inv;
            float tb = (inst.world_bounds.max[a] - c.eye[a]) * inv;
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta), t1 = std::min(t1, tb);
        }
        if (t0 > t1) continue;
        const sherpa::scene::Mesh& mesh = scene.meshes[inst.mesh_id];
        const std::vector<glm::vec3>& world = positions[k];
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const std::uint32_t i0 = mesh.indices[i], i1 = mesh.indices[i + 1],
                                i2 = mesh.indices[i + 2];
            // Möller-Trumbore.
            const glm::vec3 e1 = world[i1] - world[i0], e2 = world[i2] - world[i0];
            const glm::vec3 p = glm::cross(dir, e2);
            const float det = glm::dot(e1, p);
            if (std::abs(det) < 1e-12f) continue;
            const glm::vec3 s = c.eye - world[i0];
            const float u = glm::dot(s, p) / det;
            const glm::vec3 q = glm::cross(s, e1);
            const float v = glm::dot(dir, q) / det, t = glm::dot(e2, q) / det;
            if (u < 0 || v < 0 || u + v > 1 || t <= 0 || t >= best.t) continue;
            best.t = t;
            best.instance = &inst;
            best.triangle = i;
            best.uv = (1 - u - v) * mesh.vertices[i0].uv0 + u * mesh.vertices[i1].uv0 +
                      v * mesh.vertices[i2].uv0;
            // Counter-clockwise front faces, mirrored by a negative-determinant world.
            best.front = (glm::dot(glm::cross(e1, e2), dir) < 0) ==
                         (glm::determinant(glm::mat3(inst.world)) > 0);
        }
    }
    return best;
}

float srgb_to_linear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
int linear_to_srgb8(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return int(std::lround(s * 255.0f));
}

int wrap(int i, int n, sherpa::scene::AddressMode mode) {
    if (mode == sherpa::scene::AddressMode::ClampToEdge) return std::clamp(i, 0, n - 1);
    if (mode == sherpa::scene::AddressMode::MirroredRepeat) {
        const int period = ((i % (2 * n)) + 2 * n) % (2 * n);
        return period < n ? period : 2 * n - 1 - period;
    }
    return ((i % n) + n) % n;
}

// The source image as a box-filtered pyramid in linear colour (alpha as is), so a
// pixel covering many texels is compared with the average it should show.
struct Level {
    int width = 0, height = 0;
    std::vector<glm::vec4> texels;
    const glm::vec4& at(int x, int y) const { return texels[std::size_t(y) * width + x]; }
};
using Pyramid = std::vector<Level>;

Pyramid linear_pyramid(const ReferenceImage& img) {
    Pyramid p(1);
    p[0].width = int(img.width), p[0].height = int(img.height);
    for (std::size_t i = 0; i < img.rgba.size(); i += 4)
        p[0].texels.emplace_back(
            srgb_to_linear(img.rgba[i] / 255.0f), srgb_to_linear(img.rgba[i + 1] / 255.0f),
            srgb_to_linear(img.rgba[i + 2] / 255.0f), img.rgba[i + 3] / 255.0f);
    while (p.back().width > 1 || p.back().height > 1) {
        const Level& a = p.back();
        Level b;
        b.width = std::max(1, a.width / 2), b.height = std::max(1, a.height / 2);
        for (int y = 0; y < b.height; ++y)
            for (int x = 0; x < b.width; ++x) {
                const int x1 = std::min(2 * x + 1, a.width - 1),
                          y1 = std::min(2 * y + 1, a.height - 1);
                b.texels.push_back(0.25f * (a.at(2 * x, 2 * y) + a.at(x1, 2 * y) + a.at(2 * x, y1) +
                                            a.at(x1, y1)));
            }
        p.push_back(std::move(b));
    }
    return p;
}

struct Expected {
    glm::ivec4 srgb; // mean colour (sRGB), mean alpha (0..255)
    int range = 0;   // largest range (levels) over the channels of the texels looked at
};

// The texels around `uv` at the pyramid levels a pixel covering `footprint` level-0
// texels samples (the level where it covers one or two texels, and the next): their
// mean, if they all lie within kSmooth levels of each other in every channel (alpha
// too), else nullopt.
std::optional<Expected> smooth_texels(const Pyramid& pyramid, glm::vec2 uv, float footprint,
                                      const sherpa::scene::SamplerDesc& sampler) {
    const int first = std::clamp(int(std::floor(std::log2(std::max(footprint, 1.0f)))), 0,
                                 int(pyramid.size()) - 1);
    const int last = std::min(first + 1, int(pyramid.size()) - 1);
    glm::ivec4 lo(255), hi(0);
    glm::vec4 sum(0);
    int n = 0;
    for (int l = first; l <= last; ++l) {
        const Level& level = pyramid[std::size_t(l)];
        const int cx = int(std::floor(uv.x * float(level.width)));
        const int cy = int(std::floor(uv.y * float(level.height)));
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const glm::vec4& t = level.at(wrap(cx + dx, level.width, sampler.wrap_u),
                                              wrap(cy + dy, level.height, sampler.wrap_v));
                const glm::ivec4 s(linear_to_srgb8(t.r), linear_to_srgb8(t.g), linear_to_srgb8(t.b),
                                   int(std::lround(t.a * 255.0f)));
                lo = glm::min(lo, s), hi = glm::max(hi, s);
                sum += t;
                ++n;
            }
    }
    const glm::ivec4 range = hi - lo;
    const int widest = std::max({range.r, range.g, range.b, range.a});
    if (widest > kSmooth) return std::nullopt;
    const glm::vec4 mean = sum / float(n);
    return Expected{glm::ivec4(linear_to_srgb8(mean.r), linear_to_srgb8(mean.g),
                               linear_to_srgb8(mean.b), int(std::lround(mean.a * 255.0f))),
                    widest};
}

struct Tally {
    // translucent: texel alpha < 250, where premultiplied storage would darken colour
    std::size_t checked = 0, wrong = 0, translucent = 0, translucent_wrong = 0;
    std::size_t hits = 0, unsupported = 0, edge = 0, rough = 0; // pixels skipped, and why
    int worst = 0;
};

class BaseColorAgainstSourceImages : public ::testing::TestWithParam<Model> {};

} // namespace

TEST_P(BaseColorAgainstSourceImages, RenderedTexelsEqualTheFilesUnassociatedColour) {
    const std::string model = GetParam().name;
    const std::uint32_t size = GetParam().size, stride = GetParam().stride;
    const std::string path = sherpa::test::gltf_asset(model);
    const sherpa::scene::LoadResult loaded = sherpa::scene::load_scene(path);
    ASSERT_TRUE(loaded) << loaded.error;
    const sherpa::scene::Scene& scene = *loaded.scene;
    const Camera cam = fixed_camera(scene.bounds);
    const glm::vec3 target = cam.eye + cam.forward;

    const auto dir = std::filesystem::temp_directory_path() / ("sherpa-basecolor-" + model);
    std::filesystem::create_directories(dir);
    const std::string png = (dir / "base.png").string();
    char camera[256];
    std::snprintf(camera, sizeof camera, "eye=%.6g,%.6g,%.6g:target=%.6g,%.6g,%.6g:fov=%g",
                  cam.eye.x, cam.eye.y, cam.eye.z, target.x, target.y, target.z, kFovDegrees);
    const sherpa::test::CliRun r = sherpa::test::run_cli(
        "render '" + path + "' -o '" + png + "' --width " + std::to_string(size) + " --height " +
        std::to_string(size) + " --view base-color --no-shadows --validation --camera " + camera +
        " --cache-dir '" + SHERPA_TEST_TEXTURE_CACHE + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    ReferenceImage rendered;
    std::string error;
    ASSERT_TRUE(sherpa::test::read_png_reference(png, rendered, error)) << error;
    std::filesystem::remove_all(dir);

    // Source images by glTF image index, read once.
    std::vector<std::optional<Pyramid>> sources(scene.images.size());
    const auto base_dir = std::filesystem::path(path).parent_path();
    Tally tally;
    const WorldPositions positions = world_positions(scene);
    for (std::uint32_t y = 1; y + 1 < size; y += stride)
        for (std::uint32_t x = 1; x + 1 < size; x += stride) {
            const Hit h = cast(scene, positions, cam, float(x), float(y), size);
            if (!h.instance) continue;
            ++tally.hits;
            const sherpa::scene::MaterialInstance& m = scene.materials[h.instance->material_id];
            const sherpa::scene::Mesh& mesh = scene.meshes[h.instance->mesh_id];
            // Only what base colour = factor x texel describes: opaque, UV set 0, no
            // transform or vertex colours, front faces (or double-sided).
            if (!m.base_color.present() || m.base_color.tex_coord != 0 ||
                m.base_color.transform.present || !mesh.colors.empty() ||
                m.alpha_mode != sherpa::scene::AlphaMode::Opaque || (!h.front && !m.double_sided)) {
                ++tally.unsupported;
                continue;
            }
            // The pixel's footprint in UV, from its neighbours on the same surface.
            const Hit hx = cast(scene, positions, cam, float(x + 1), float(y), size);
            const Hit hy = cast(scene, positions, cam, float(x), float(y + 1), size);
            // Neighbours on another triangle may sit across a UV seam: no footprint there.
            if (hx.instance != h.instance || hy.instance != h.instance ||
                hx.triangle != h.triangle || hy.triangle != h.triangle) {
                ++tally.edge;
                continue;
            }
            const sherpa::scene::TextureRecord& tex =
                scene.textures[std::size_t(m.base_color.texture)];
            auto& src = sources[std::size_t(tex.image)];
            if (!src) {
                const auto file = base_dir / scene.images[std::size_t(tex.image)].uri;
                ReferenceImage image;
                ASSERT_TRUE(sherpa::test::read_reference_image(file, image, error)) << error;
                src = linear_pyramid(image);
            }
            const glm::vec2 texels(float((*src)[0].width), float((*src)[0].height));
            const float footprint = std::max(glm::length((hx.uv - h.uv) * texels),
                                             glm::length((hy.uv - h.uv) * texels));
            const auto expected = smooth_texels(*src, h.uv, footprint, scene.sampler_of(tex));
            if (!expected) {
                ++tally.rough;
                continue;
            }
            const std::uint8_t* got = rendered.texel(x, y);
            int diff = 0;
            for (int ch = 0; ch < 3; ++ch) {
                const float factor = m.base_color_factor[ch];
                const int want =
                    linear_to_srgb8(factor * srgb_to_linear(float(expected->srgb[ch]) / 255.0f));
                diff = std::max(diff, std::abs(int(got[ch]) - want));
            }
            ++tally.checked;
            const bool translucent = expected->srgb.a < 250;
            tally.translucent += translucent;
            tally.worst = std::max(tally.worst, diff);
            if (diff > kTolerance + expected->range / 2) {
                ++tally.wrong;
                tally.translucent_wrong += translucent;
                if (std::getenv("SHERPA_TEST_VERBOSE"))
                    std::printf("  off: pixel %u,%u uv %.4f,%.4f footprint %.2f got %d,%d,%d want "
                                "%d,%d,%d range %d\n",
                                x, y, h.uv.x, h.uv.y, footprint, got[0], got[1], got[2],
                                expected->srgb.r, expected->srgb.g, expected->srgb.b,
                                expected->range);
            }
        }
    std::printf("%s: %zu pixels checked (%zu where the texel's alpha < 250, %zu of them off), %zu "
                "off by more "
                "than %d levels + half the texels' range, worst %d; of %zu hits skipped: %zu "
                "unsupported material, %zu "
                "at edges, %zu where the texture is not smooth\n",
                model.c_str(), tally.checked, tally.translucent, tally.translucent_wrong,
                tally.wrong, kTolerance, tally.worst, tally.hits, tally.unsupported, tally.edge,
                tally.rough);
    EXPECT_GE(tally.checked, 30u) << "too few smooth texels to judge";
    // A handful may sit where a silhouette or a seam hides the ray-cast surface.
    EXPECT_LE(tally.wrong, std::max<std::size_t>(2, tally.checked / 100));
    // Where alpha < 1 the colour must be the file's at every checked pixel: reading
    // alpha premultiplied put 3 of AlphaBlendModeTest's 90 such pixels off, by up to
    // 255 levels (measured with the fix reverted).
    EXPECT_EQ(tally.translucent_wrong, 0u);
    // Its opaque panel reads the label atlas where alpha < 1: those texels must be
    // among the checked ones, or premultiplied alpha would go unseen.
    if (model == "AlphaBlendModeTest") {
        EXPECT_GE(tally.translucent, 20u);
    }
}

// AlphaBlendModeTest densely: its opaque panel is where premultiplied alpha shows.
// VC is left out: at this camera 1549 of its 1586 hits land where the test's model
// of base colour does not apply (measured), too few to judge.
INSTANTIATE_TEST_SUITE_P(
    SampleModels, BaseColorAgainstSourceImages,
    ::testing::Values(Model{"AlphaBlendModeTest", 384, 2}, Model{"AnimatedCube"},
                      Model{"BoxTextured"}, Model{"BoxTexturedNonPowerOfTwo"}, Model{"Cube"},
                      Model{"DamagedHelmet"}, Model{"Duck"}, Model{"MultiUVTest"},
                      Model{"NormalTangentMirrorTest"}, Model{"NormalTangentTest"},
                      Model{"Suzanne"}, Model{"TextureCoordinateTest"},
                      Model{"TextureSettingsTest"}, Model{"TwoSidedPlane"},
                      Model{"VertexColorTest"}),
    [](const ::testing::TestParamInfo<Model>& param) { return std::string(param.param.name); });
