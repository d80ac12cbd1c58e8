// Geometry decoding checked against independent reads of the real .bin files,
// plus materials, samplers, lights, cameras and scene selection.
#include "load_error_check.h"
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <cstring>
#include <set>

#include <gtest/gtest.h>

namespace {

using sherpa::scene::VertexAttribute;
namespace test = sherpa::test;

glm::vec3 vec3_at(const std::vector<unsigned char>& bin, std::size_t offset) {
    glm::vec3 v;
    std::memcpy(&v, bin.data() + offset, 12);
    return v;
}

TEST(FlatNormals, TriangleWithoutIndicesGetsPerpendicularFaceNormals) {
    auto scene = sherpa::test::load_scene_or_fail(test::gltf_asset("TriangleWithoutIndices"));
    ASSERT_TRUE(scene);
    const sherpa::scene::Mesh& m = scene->meshes.at(0);
    EXPECT_TRUE(m.unwelded);
    EXPECT_EQ(m.provenance_of(VertexAttribute::Normal), sherpa::scene::Provenance::Generated);
    ASSERT_EQ(m.indices.size(), 3u);
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}))
        << "non-indexed primitives get sequential indices";
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.vertices[m.indices[t]].position,
                        b = m.vertices[m.indices[t + 1]].position,
                        c = m.vertices[m.indices[t + 2]].position;
        const glm::vec3 face = glm::normalize(glm::cross(b - a, c - a));
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 n = m.vertices[m.indices[t + k]].normal;
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
            EXPECT_NEAR(glm::dot(n, b - a), 0.0f, 1e-6f);
            EXPECT_NEAR(glm::dot(n, c - a), 0.0f, 1e-6f);
            EXPECT_GT(glm::dot(n, face), 0.999f) << "normal must follow counter-clockwise winding";
        }
    }
}

TEST(FlatNormals, SharedVerticesAreUnweldedPerFace) {
    // SimpleMeshes has indexed triangles and no normals.
    auto scene = sherpa::test::load_scene_or_fail(test::gltf_asset("SimpleMeshes"));
    ASSERT_TRUE(scene);
    const sherpa::scene::Mesh& m = scene->meshes.at(0);
    EXPECT_EQ(m.vertices.size(), m.indices.size());
    EXPECT_EQ(m.source_vertex_count, 3u);
}

// Corner positions of the mesh's triangles (after unwelding for flat normals).
std::vector<glm::vec3> corner_positions(const sherpa::scene::Mesh& m) {
    std::vector<glm::vec3> out;
    for (std::uint32_t i : m.indices) out.push_back(m.vertices[i].position);
    return out;
}

TEST(SparseAccessor, SubstitutesValuesFromTheBin) {
    const auto dir = test::assets_dir() / "gltf/SimpleSparseAccessor/glTF";
    auto scene = sherpa::test::load_scene_or_fail((dir / "SimpleSparseAccessor.gltf").string());
    ASSERT_TRUE(scene);
    const auto bin = test::read_bytes(dir / "SimpleSparseAccessor.bin");
    ASSERT_GE(bin.size(), 284u);
    // Independent decode: base positions at 72, sparse indices at 240, values at 248.
    std::vector<glm::vec3> expected(14);
    for (std::size_t v = 0; v < 14; ++v) expected[v] = vec3_at(bin, 72 + 12 * v);
    for (int i = 0; i < 3; ++i) {
        std::uint16_t idx;
        std::memcpy(&idx, bin.data() + 240 + 2 * i, 2);
        expected[idx] = vec3_at(bin, 248 + 12 * i);
    }
    std::vector<glm::vec3> want;
    for (int i = 0; i < 36; ++i) {
        std::uint16_t idx;
        std::memcpy(&idx, bin.data() + 2 * i, 2);
        want.push_back(expected[idx]);
    }
    const sherpa::scene::Mesh& m = scene->meshes.at(0);
    EXPECT_EQ(corner_positions(m), want);
    EXPECT_EQ(m.source_vertex_count, 14u);
    EXPECT_FLOAT_EQ(scene->bounds.max.y, 4.0f) << "the sparse values raise the top row to y = 4";
    ASSERT_TRUE(m.sources[0].has_value());
    EXPECT_TRUE(m.sources[0]->sparse);
    EXPECT_EQ(m.sources[0]->sparse_count, 3u);
}

TEST(Interleaved, StridedAttributesMatchTheBin) {
    const auto dir = test::assets_dir() / "gltf/BoxInterleaved/glTF";
    auto scene = sherpa::test::load_scene_or_fail((dir / "BoxInterleaved.gltf").string());
    ASSERT_TRUE(scene);
    const auto bin = test::read_bytes(dir / "BoxInterleaved.bin");
    const sherpa::scene::Mesh& m = scene->meshes.at(0);
    ASSERT_EQ(m.vertices.size(), 24u);
    const auto doc = test::read_json((dir / "BoxInterleaved.gltf").string());
    const auto& attrs = doc["meshes"][0]["primitives"][0]["attributes"];
    const auto pos_off = doc["accessors"][attrs["POSITION"].get<int>()].value("byteOffset", 0);
    const auto nrm_off = doc["accessors"][attrs["NORMAL"].get<int>()].value("byteOffset", 0);
    for (std::size_t v = 0; v < 24; ++v) {
        EXPECT_EQ(m.vertices[v].position, vec3_at(bin, pos_off + 24 * v));
        EXPECT_EQ(m.vertices[v].normal, vec3_at(bin, nrm_off + 24 * v));
    }
    EXPECT_EQ(m.sources[static_cast<int>(VertexAttribute::Position)]->byte_stride, 24u);
    // Same box as the non-interleaved sample: identical vertex set.
    auto plain = sherpa::test::load_scene_or_fail(test::gltf_asset("Box"));
    ASSERT_TRUE(plain);
    auto key = [](const sherpa::scene::Vertex& x) {
        return std::array<float, 6>{x.position.x, x.position.y, x.position.z,
                                    x.normal.x,   x.normal.y,   x.normal.z};
    };
    std::multiset<std::array<float, 6>> a, b;
    for (const auto& x : m.vertices) a.insert(key(x));
    for (const auto& x : plain->meshes.at(0).vertices) b.insert(key(x));
    EXPECT_EQ(a, b);
}

TEST(Topology, StripsAndFansBecomeListsWithGltfWinding) {
    auto strip = sherpa::test::load_scene_or_fail((test::data_dir() / "strip.gltf").string());
    ASSERT_TRUE(strip);
    // Strip vertices (0,0) (1,0) (0,1) (1,1): triangles {0,1,2} and {1,3,2}.
    EXPECT_EQ(
        corner_positions(strip->meshes.at(0)),
        (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    auto fan = sherpa::test::load_scene_or_fail((test::data_dir() / "fan.gltf").string());
    ASSERT_TRUE(fan);
    // Fan vertices (0,0) (1,0) (1,1) (0,1): triangles {1,2,0} and {2,3,0}.
    EXPECT_EQ(
        corner_positions(fan->meshes.at(0)),
        (std::vector<glm::vec3>{{1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}}));
    EXPECT_EQ(fan->counts.triangles, 2u);
}

TEST(VertexColors, Color0IsKeptAsItsOwnStream) {
    auto scene = sherpa::test::load_scene_or_fail(test::gltf_asset("BoxVertexColors"));
    ASSERT_TRUE(scene);
    const sherpa::scene::Mesh& m = scene->meshes.at(0);
    EXPECT_EQ(m.provenance_of(VertexAttribute::Color0), sherpa::scene::Provenance::Authored);
    ASSERT_EQ(m.colors.size(), m.vertices.size());
    for (const auto& c : m.colors) {
        EXPECT_GE(c.a, 0.0f);
        EXPECT_LE(c.r, 1.0f);
    }
}

TEST(Materials, AlphaModesAndGpuLayout) {
    auto scene = sherpa::test::load_scene_or_fail(test::gltf_asset("AlphaBlendModeTest"));
    ASSERT_TRUE(scene);
    std::set<sherpa::scene::AlphaMode> modes;
    for (const auto& m : scene->materials) modes.insert(m.alpha_mode);
    EXPECT_EQ(modes.size(), 3u);
    for (const auto& m : scene->materials) {
        const sherpa::scene::GPUMaterialData g = sherpa::scene::to_gpu_material(m);
        EXPECT_EQ(g.alpha_mode, static_cast<std::uint32_t>(m.alpha_mode));
        EXPECT_EQ(g.normal_tex, m.normal.present() ? static_cast<std::uint32_t>(m.normal.texture)
                                                   : sherpa::scene::kTextureSentinel);
        EXPECT_EQ(g.emissive_tex, m.emissive.present()
                                      ? static_cast<std::uint32_t>(m.emissive.texture)
                                      : sherpa::scene::kTextureSentinel);
    }
    // Roles follow use: the normal map texture is a normal-role texture.
    for (const auto& m : scene->materials)
        if (m.normal.present()) {
            EXPECT_TRUE(scene->textures[m.normal.texture].roles & sherpa::scene::kRoleNormal);
        }
}

TEST(Materials, ExtensionsAndTexCoordSets) {
    auto scene = sherpa::test::load_scene_or_fail(
        (test::data_dir() / "lights_and_extensions.gltf").string());
    ASSERT_TRUE(scene);
    const auto& m = scene->materials.at(0);
    EXPECT_FLOAT_EQ(m.emissive_strength, 4.0f);
    EXPECT_EQ(m.emissive_factor, glm::vec3(1.0f, 0.5f, 0.0f));
    ASSERT_TRUE(m.base_color.transform.present);
    EXPECT_EQ(m.base_color.transform.offset, glm::vec2(0.5f, 0.25f));
    EXPECT_EQ(m.base_color.transform.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_FLOAT_EQ(m.base_color.transform.rotation, 0.5f);
    EXPECT_EQ(m.base_color.tex_coord, 1u)
        << "KHR_texture_transform.texCoord overrides the slot's set";
    EXPECT_EQ(scene->images.at(0).mime_type, "image/png");
    EXPECT_GT(scene->images.at(0).byte_size, 0u) << "data-URI image bytes are kept encoded";
    auto multi = sherpa::test::load_scene_or_fail(test::gltf_asset("MultiUVTest"));
    ASSERT_TRUE(multi);
    bool uses_set1 = false;
    for (const auto& mat : multi->materials)
        for (const auto* s :
             {&mat.base_color, &mat.emissive, &mat.normal, &mat.occlusion, &mat.metallic_roughness})
            uses_set1 |= s->present() && s->tex_coord == 1;
    EXPECT_TRUE(uses_set1);
}

TEST(Samplers, AllFiltersAndWrapModes) {
    auto scene = sherpa::test::load_scene_or_fail(test::gltf_asset("TextureSettingsTest"));
    ASSERT_TRUE(scene);
    EXPECT_EQ(scene->samplers.size(), 5u);
    using sherpa::scene::sampler_from_gltf;
    EXPECT_EQ(sampler_from_gltf(9728, 9728, 33071, 33648).max_lod, 0.0f)
        << "NEAREST has no mip mode";
    EXPECT_EQ(sampler_from_gltf(9729, 9729, 0, 0).max_lod, 0.0f);
    EXPECT_EQ(sampler_from_gltf(9729, 9984, 0, 0).mipmap_mode, sherpa::scene::MipmapMode::Nearest);
    EXPECT_EQ(sampler_from_gltf(9729, 9985, 0, 0).min_filter, sherpa::scene::Filter::Linear);
    EXPECT_EQ(sampler_from_gltf(9729, 9986, 0, 0).min_filter, sherpa::scene::Filter::Nearest);
    EXPECT_EQ(sampler_from_gltf(9729, 9986, 0, 0).mipmap_mode, sherpa::scene::MipmapMode::Linear);
    EXPECT_EQ(sampler_from_gltf(-1, -1, 33071, 33648).wrap_v,
              sherpa::scene::AddressMode::MirroredRepeat);
    EXPECT_EQ(sampler_from_gltf(-1, -1, 33071, 33648).wrap_u,
              sherpa::scene::AddressMode::ClampToEdge);
    EXPECT_THROW(sampler_from_gltf(9999, 9728, 0, 0), std::invalid_argument);
    sherpa::scene::TextureRecord no_sampler;
    EXPECT_EQ(scene->sampler_of(no_sampler), sherpa::scene::SamplerDesc{});
}

TEST(LightsAndCameras, WorldPlacement) {
    auto scene = sherpa::test::load_scene_or_fail(
        (test::data_dir() / "lights_and_extensions.gltf").string());
    ASSERT_TRUE(scene);
    ASSERT_EQ(scene->placed_lights.size(), 2u);
    const auto& sun = scene->placed_lights[0];
    EXPECT_EQ(scene->lights[sun.light].type, sherpa::scene::LightType::Directional);
    EXPECT_NEAR(sun.direction.y, -1.0f, 1e-5f);
    const auto& spot = scene->placed_lights[1];
    EXPECT_EQ(scene->lights[spot.light].type, sherpa::scene::LightType::Spot);
    EXPECT_EQ(spot.position, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(scene->lights[spot.light].outer_cone, 0.5f);
    auto cams = sherpa::test::load_scene_or_fail(test::gltf_asset("Cameras"));
    ASSERT_TRUE(cams);
    ASSERT_EQ(cams->cameras.size(), 2u);
    EXPECT_EQ(cams->cameras[0].type, sherpa::scene::CameraType::Perspective);
    EXPECT_EQ(cams->cameras[1].type, sherpa::scene::CameraType::Orthographic);
    EXPECT_EQ(cams->placed_cameras.size(), 2u);
}

TEST(Scenes, MultipleScenesAreSelectable) {
    const std::string path = (test::data_dir() / "two_scenes.gltf").string();
    auto scene = sherpa::test::load_scene_or_fail(path);
    ASSERT_TRUE(scene);
    EXPECT_EQ(scene->scenes.size(), 2u);
    EXPECT_FLOAT_EQ(scene->bounds.min.x, 0.0f);
    std::string error;
    ASSERT_TRUE(sherpa::scene::select_scene(*scene, 1, error)) << error;
    EXPECT_FLOAT_EQ(scene->bounds.min.x, 10.0f);
    EXPECT_EQ(scene->instances.at(0).node_id, 1u);
    sherpa::scene::LoadOptions opt;
    opt.scene_index = 1;
    auto second = sherpa::scene::load_scene(path, opt);
    ASSERT_TRUE(second) << second.error;
    EXPECT_EQ(second.scene->displayed_scene, 1);
}

} // namespace
