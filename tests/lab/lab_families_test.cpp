// Known answers of the Lab's families on small synthetic scenes.
#include "lab/lab_scenes.h"

#include <sherpa/lab/families.h>
#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/quality.h>

#include "lab/lab_figures.h"
#include <gtest/gtest.h>

namespace {

using namespace sherpa;
using sherpa::test::failures;
using sherpa::test::figure;

TEST(LabTangents, WeldedDiffersFromExactInTheKnownCorners) {
    scene::Scene scene = test::scene_of({test::mirrored_strip()});
    const lab::FamilyReport r = lab::make_tangent_family()->run(scene, {});
    ASSERT_EQ(r.methods.size(), 3u);
    EXPECT_EQ(r.methods[0].method.name, "mikktspace");
    EXPECT_EQ(figure(r.methods[0], "differing_corners"), 0.0);
    EXPECT_EQ(figure(r.methods[0], "angle_max_deg"), 0.0);
    // The left quad's corners at the seam: one of triangle a b d, two of a d c.
    EXPECT_EQ(figure(r.methods[1], "differing_corners"), 3.0);
    EXPECT_EQ(figure(r.methods[1], "angle_flips"), 3.0);
    EXPECT_NEAR(figure(r.methods[1], "angle_max_deg"), 180.0, 1e-6);
    EXPECT_GT(figure(r.methods[2], "differing_corners"), 0.0) << "lengyel sums the seam";
    EXPECT_EQ(r.methods[0].error("authored_mean_deg"), nullptr) << "no authored tangents";
    for (const lab::MethodResult& m : r.methods) {
        EXPECT_TRUE(m.ran);
        EXPECT_TRUE(m.failures.empty()) << m.method.name;
        EXPECT_GE(m.time, 0.0);
    }
}

TEST(LabTangents, AuthoredTangentsAreASecondReference) {
    scene::Mesh strip = test::mirrored_strip();
    strip.provenance[std::size_t(scene::VertexAttribute::Tangent)] = scene::Provenance::Authored;
    for (scene::Vertex& v : strip.vertices)
        v.tangent = {1, 0, 0, 1}; // right for the left quad only
    const lab::FamilyReport r = lab::make_tangent_family()->run(test::scene_of({strip}), {});
    // Exact MikkTSpace gives the right quad's 6 corners (-1,0,0,-1).
    EXPECT_EQ(figure(r.methods[0], "authored_flips"), 6.0);
    EXPECT_NEAR(figure(r.methods[0], "authored_max_deg"), 180.0, 1e-6);
}

TEST(LabTangents, FailuresNameThePrimitiveAndTheCause) {
    scene::Mesh flat_uv = test::mirrored_strip();
    for (scene::Vertex& v : flat_uv.vertices) v.uv0 = {0.5f, 0.5f};
    scene::Mesh no_uv = test::mirrored_strip();
    no_uv.provenance[std::size_t(scene::VertexAttribute::TexCoord0)] = scene::Provenance::Defaulted;
    const lab::FamilyReport r = lab::make_tangent_family()->run(
        test::scene_of({test::mirrored_strip(), flat_uv, no_uv}), {});
    for (const lab::MethodResult& m : r.methods) {
        EXPECT_EQ(failures(m, "degenerate_uv"), 12u) << m.method.name;
        EXPECT_EQ(failures(m, "no TEXCOORD_0"), 12u) << m.method.name;
        for (const lab::Failure& f : m.failures)
            EXPECT_NE(f.where.find(f.cause == "degenerate_uv" ? "mesh 1 primitive 0" : "mesh 2"),
                      std::string::npos)
                << f.where;
    }
}

TEST(LabFamilies, CancelStopsWithNoMethodsAndProgressReachesTheEnd) {
    const scene::Scene scene = test::scene_of({test::mirrored_strip(), test::mirrored_strip()});
    core::CancelToken token;
    token.cancel();
    lab::RunControl cancelled;
    cancelled.cancel = &token;
    for (std::string_view name : lab::family_names()) {
        const lab::FamilyReport r = lab::make_family(name)->run(scene, cancelled);
        EXPECT_TRUE(r.cancelled) << name;
        EXPECT_TRUE(r.methods.empty()) << name;
    }
    std::size_t last_done = 0, last_total = 1;
    lab::RunControl watched;
    watched.progress = [&](std::size_t done, std::size_t total) {
        last_done = done, last_total = total;
    };
    lab::make_tangent_family()->run(scene, watched);
    EXPECT_EQ(last_done, last_total);
    EXPECT_EQ(last_total, 6u); // 2 meshes x 3 methods
    for (std::string_view name : lab::family_names()) {
        last_done = 0;
        lab::make_family(name)->run(test::scene_of({}), watched);
        EXPECT_EQ(last_done, last_total) << name << " on an empty scene";
    }
    EXPECT_EQ(lab::make_family("no-such-family"), nullptr);
}

// Camera at the origin looking down -Z, 90 degrees, square, near 1, far 10: inside
// means |x| <= -z, |y| <= -z, -10 <= z <= -1.
scene::Scene cull_scene() {
    scene::Scene s = test::scene_of({test::mirrored_strip()});
    const core::Aabb boxes[] = {
        core::Aabb::from_min_max({-0.5f, -0.5f, -5.5f}, {0.5f, 0.5f, -4.5f}), // in view
        core::Aabb::from_min_max({-0.5f, -0.5f, 4.5f}, {0.5f, 0.5f, 5.5f}),   // behind
        // Outside the right plane by 0.1 at its nearest corner; its bounding sphere
        // (radius 1.5, centre 1.13 outside) reaches in: a sphere false positive only.
        core::Aabb::from_min_max({10.6f, -1.0f, -10.5f}, {12.6f, 1.0f, -9.5f}),
        // Beyond the right plane wherever it is in front of the far plane, but not wholly
        // outside either plane: kept by sphere and p-vertex, culled by the exact test.
        core::Aabb::from_min_max({10.5f, -1.0f, -12.0f}, {20.0f, 1.0f, -9.0f})};
    s.instances.clear();
    for (const core::Aabb& b : boxes) {
        scene::MeshInstance inst;
        inst.world_bounds = b;
        s.instances.push_back(inst);
        s.bounds.expand(b);
    }
    return s;
}

lab::CullFamilyOptions cull_options(bool gpu) {
    lab::CullFamilyOptions o;
    scene::CameraSpec c;
    c.eye = {0, 0, 0}, c.target = {0, 0, -1};
    c.fov_y_degrees = 90.0f, c.aspect = 1.0f, c.near_plane = 1.0f, c.far_plane = 10.0f;
    o.path = {c, c};
    o.gpu = gpu;
    o.gpu_validation = true;
    return o;
}

TEST(LabCulling, FalsePositivesOnAKnownPath) {
    const lab::FamilyReport r = lab::make_cull_family(cull_options(false))->run(cull_scene(), {});
    ASSERT_EQ(r.methods.size(), 4u);
    EXPECT_EQ(figure(r.methods[0], "false_positives"), 4.0) << "sphere: 2 boxes x 2 cameras";
    EXPECT_EQ(figure(r.methods[1], "false_positives"), 2.0) << "p-vertex: 1 box x 2 cameras";
    EXPECT_EQ(figure(r.methods[2], "false_positives"), 0.0) << "exact";
    EXPECT_EQ(figure(r.methods[1], "false_positive_rate"), 2.0 / 8.0);
    for (int m = 0; m < 3; ++m) {
        EXPECT_EQ(figure(r.methods[std::size_t(m)], "false_negatives"), 0.0);
        EXPECT_TRUE(r.methods[std::size_t(m)].failures.empty());
    }
    EXPECT_FALSE(r.methods[3].ran) << "GPU not asked for";
}

TEST(LabCulling, GpuAgreesWithPVertexUnderValidation) {
    const lab::FamilyReport r = lab::make_cull_family(cull_options(true))->run(cull_scene(), {});
    const lab::MethodResult& gpu = r.methods.at(3);
    ASSERT_TRUE(gpu.ran) << gpu.note;
    EXPECT_EQ(figure(gpu, "false_positives"), 2.0);
    EXPECT_EQ(figure(gpu, "false_negatives"), 0.0);
    EXPECT_TRUE(gpu.failures.empty())
        << gpu.failures.front().cause << ": " << gpu.failures.front().where;
}

TEST(LabCulling, DefaultPathSeesEverythingFromOutsideAndHalfFromInside) {
    const core::Aabb box = core::Aabb::from_min_max(glm::vec3(-1), glm::vec3(1));
    const std::vector<scene::CameraSpec> path = lab::camera_path(box, 8);
    ASSERT_EQ(path.size(), 8u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_GT(glm::length(path[i].eye), std::sqrt(3.0f));
    for (std::size_t i = 4; i < 8; ++i) EXPECT_LT(glm::length(path[i].eye), 1.0f);
}

scene::ImageRecord generated(std::uint32_t w, std::uint32_t h, bool normal) {
    scene::ImageRecord img;
    img.width = w, img.height = h;
    img.mime_type = "image/x-sherpa-rgba8";
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const auto a = std::uint8_t((x * 37 + y * 11) & 255), b = std::uint8_t((y * 23) & 255);
            if (normal)
                img.pixels.insert(img.pixels.end(),
                                  {std::uint8_t(96 + a / 4), std::uint8_t(96 + b / 4), 230, 255});
            else
                img.pixels.insert(img.pixels.end(), {a, b, std::uint8_t(a ^ b), 255});
        }
    return img;
}

scene::Scene texture_scene() {
    scene::Scene s = test::scene_of({test::mirrored_strip()});
    s.images = {generated(24, 20, false), generated(16, 16, true), scene::ImageRecord{}};
    s.images[2].uri = "missing.png";
    for (int i = 0; i < 3; ++i)
        s.textures.push_back(scene::TextureRecord{"", i, -1, scene::kRoleNone});
    s.materials[0].base_color.texture = 0;
    s.materials[0].normal.texture = 1;
    s.materials[0].occlusion.texture = 2;
    return s;
}

TEST(LabTextures, PsnrIsTheCodecsOwnAndMissingImagesAreFailures) {
    const scene::Scene scene = texture_scene();
    const lab::FamilyReport r = lab::make_texture_family()->run(scene, {});
    ASSERT_EQ(r.methods.size(), std::size_t(tex::kBc7MaxLevel + 1 + tex::kBc5MaxLevel + 1));
    const scene::ImageRecord& color = scene.images[0];
    for (const lab::MethodResult& m : r.methods) {
        ASSERT_TRUE(m.ran) << m.method.name << " " << m.note;
        // The missing image is an occlusion map: BC7's failure, not BC5's.
        EXPECT_EQ(failures(m, "missing"), m.method.name == "bc7" ? 1u : 0u) << m.method.name;
        EXPECT_GT(m.time, 0.0);
        if (m.method.name != "bc7") {
            EXPECT_GT(figure(m, "angle_mean_deg"), 0.0);
            continue;
        }
        const int level = std::stoi(m.method.parameters.substr(6));
        const auto blocks = tex::encode_image(tex::BlockFormat::Bc7, color.pixels, 24, 20,
                                              {level, tex::best_simd_level()});
        const auto decoded = tex::decode_image(tex::BlockFormat::Bc7, blocks, 24, 20);
        EXPECT_DOUBLE_EQ(figure(m, "psnr_db"),
                         tex::squared_error(color.pixels, decoded, tex::kChannelsRgb).psnr());
    }
    EXPECT_GT(figure(r.methods[4], "psnr_db"), figure(r.methods[0], "psnr_db"));
}

TEST(LabTextures, LargeImagesAreSampledAndSaySo) {
    scene::Scene scene = texture_scene();
    scene.images[0] = generated(300, 260, false);
    lab::TextureFamilyOptions o;
    o.sample_texels = 64 * 64 * 4;
    const lab::FamilyReport r = lab::make_texture_family(o)->run(scene, {});
    ASSERT_EQ(r.notes.size(), 1u);
    EXPECT_NE(r.notes[0].find("mosaic"), std::string::npos);
    EXPECT_NE(r.methods[0].note.find("0.016384 MPix"), std::string::npos) << r.methods[0].note;
}

} // namespace
