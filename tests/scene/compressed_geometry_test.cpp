// Compressed geometry made by the ecosystem's own tools (gltfpack: EXT_meshopt_compression
// with KHR_mesh_quantization; gltf-transform: KHR_draco_mesh_compression) from the
// shared sample models. The reference is the
// uncompressed source model, read by the same importer: every drawn vertex of the
// compressed file (world space: gltfpack moves the dequantization into node
// transforms) must match a vertex of the source within the quantization step, and
// the other way round; drawn triangle counts are equal. Broken variants end in a
// clear error naming the file and the problem.
#include "cli/cli_run.h"
#include "scene/load_error_check.h"
#include "test_support.h"

#include <sherpa/scene/animation.h>
#include <sherpa/scene/scene_loader.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <unistd.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

fs::path corpus_dir() {
    return fs::path(SHERPA_GLTF_COMPRESS_CACHE) / "corpus";
}

struct CorpusFile {
    std::string file, model, codec;
};

// What tools/gltf_compress/make_corpus.sh writes (fixed here: gtest lists the cases
// before the CTest fixture has made the corpus).
std::vector<CorpusFile> corpus() {
    return {
        {"Duck.meshopt.glb", "Duck", "EXT_meshopt_compression"},
        {"DamagedHelmet.meshopt.glb", "DamagedHelmet", "EXT_meshopt_compression"},
        {"BoxTextured.meshopt.glb", "BoxTextured", "EXT_meshopt_compression"},
        {"2CylinderEngine.meshopt.glb", "2CylinderEngine", "EXT_meshopt_compression"},
        {"Duck.meshopt_vpf.glb", "Duck", "EXT_meshopt_compression"},
        {"Duck.meshopt.gltf", "Duck", "EXT_meshopt_compression"},
        {"Duck.khr_meshopt.glb", "Duck", "KHR_meshopt_compression"},
        {"Duck.meshopt_fallback.gltf", "Duck", "EXT_meshopt_compression"},
        {"Duck.draco.glb", "Duck", "KHR_draco_mesh_compression"},
        {"DamagedHelmet.draco.glb", "DamagedHelmet", "KHR_draco_mesh_compression"},
        {"BoxTextured.draco.glb", "BoxTextured", "KHR_draco_mesh_compression"},
        {"2CylinderEngine.draco.glb", "2CylinderEngine", "KHR_draco_mesh_compression"},
        {"Duck.draco.gltf", "Duck", "KHR_draco_mesh_compression"},
        {"RiggedSimple.draco.glb", "RiggedSimple", "KHR_draco_mesh_compression"},
        {"VC.draco.glb", "VC", "KHR_draco_mesh_compression"},
        {"AnimatedMorphSphere.draco.glb", "AnimatedMorphSphere", "KHR_draco_mesh_compression"},
        {"BoxVertexColors.quantized.draco.glb", "BoxVertexColors", "KHR_draco_mesh_compression"}};
}

// One drawn vertex: world position, world normal and the UV the base colour
// texture is sampled at (KHR_texture_transform applied: gltfpack dequantizes UVs
// through it).
struct WorldVertex {
    glm::vec3 position, normal;
    glm::vec2 uv;
};

struct Drawn {
    std::vector<WorldVertex> vertices;
    std::uint64_t triangles = 0;
    std::uint64_t collapsed = 0; // triangles with two corners at the same position
    glm::vec3 extent{0.0f};
    float uv_extent = 0.0f;
};

Drawn drawn(const sherpa::scene::Scene& scene) {
    Drawn d;
    for (const auto& inst : scene.instances) {
        const sherpa::scene::Mesh& mesh = scene.meshes[inst.mesh_id];
        const auto& slot = scene.materials[inst.material_id].base_color;
        const glm::mat3 uv_matrix = slot.transform.present ? slot.transform.matrix() : glm::mat3(1);
        const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(inst.world)));
        d.triangles += mesh.indices.size() / 3;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::vec3 &p0 = mesh.vertices[mesh.indices[t]].position,
                            &p1 = mesh.vertices[mesh.indices[t + 1]].position,
                            &p2 = mesh.vertices[mesh.indices[t + 2]].position;
            if (p0 == p1 || p1 == p2 || p0 == p2) ++d.collapsed;
        }
        for (const auto& v : mesh.vertices) {
            d.vertices.push_back({glm::vec3(inst.world * glm::vec4(v.position, 1.0f)),
                                  glm::normalize(normal_matrix * v.normal),
                                  glm::vec2(uv_matrix * glm::vec3(v.uv0, 1.0f))});
        }
    }
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    glm::vec2 uv_lo(INFINITY), uv_hi(-INFINITY);
    for (const auto& v : d.vertices) {
        lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
        uv_lo = glm::min(uv_lo, v.uv), uv_hi = glm::max(uv_hi, v.uv);
    }
    d.extent = hi - lo;
    d.uv_extent = std::max(uv_hi.x - uv_lo.x, uv_hi.y - uv_lo.y);
    return d;
}

struct Tolerance {
    float position, normal, uv;
};

// How many vertices of `a` have no vertex of `b` within the tolerances (positions
// bucketed on a grid of the position tolerance, so each lookup sees 27 cells).
std::size_t unmatched(const std::vector<WorldVertex>& a, const std::vector<WorldVertex>& b,
                      const Tolerance& tol) {
    const auto cell = [&](const glm::vec3& p) { return glm::ivec3(glm::floor(p / tol.position)); };
    const auto key = [](glm::ivec3 c) { return std::tuple(c.x, c.y, c.z); };
    std::map<std::tuple<int, int, int>, std::vector<std::size_t>> grid;
    for (std::size_t i = 0; i < b.size(); ++i) grid[key(cell(b[i].position))].push_back(i);
    std::size_t misses = 0;
    for (const auto& v : a) {
        bool found = false;
        const glm::ivec3 c = cell(v.position);
        for (int dx = -1; dx <= 1 && !found; ++dx)
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dz = -1; dz <= 1 && !found; ++dz) {
                    const auto it = grid.find(key(c + glm::ivec3(dx, dy, dz)));
                    if (it == grid.end()) continue;
                    for (const std::size_t j : it->second) {
                        const WorldVertex& w = b[j];
                        const glm::vec3 dp = glm::abs(w.position - v.position);
                        if (std::max({dp.x, dp.y, dp.z}) <= tol.position &&
                            glm::length(w.normal - v.normal) <= tol.normal &&
                            glm::length(w.uv - v.uv) <= tol.uv) {
                            found = true;
                            break;
                        }
                    }
                }
        if (!found) ++misses;
    }
    return misses;
}

void PrintTo(const CorpusFile& f, std::ostream* os) {
    *os << f.file;
}

class CompressedFile : public ::testing::TestWithParam<CorpusFile> {};

TEST_P(CompressedFile, DrawsTheSourceWithinTheQuantizationStep) {
    const CorpusFile& f = GetParam();
    const std::string path = (corpus_dir() / f.file).string();
    const sherpa::scene::LoadResult compressed = sherpa::scene::load_scene(path);
    ASSERT_TRUE(compressed) << compressed.error;
    const sherpa::scene::LoadResult source = sherpa::scene::load_scene(test::gltf_asset(f.model));
    ASSERT_TRUE(source) << source.error;
    std::size_t compressed_prims = 0;
    std::uint64_t encoded = 0, decoded = 0;
    for (const auto& p : compressed.scene->primitives)
        if (p.compression) {
            ++compressed_prims;
            EXPECT_EQ(p.compression->codec, f.codec);
            encoded += p.compression->encoded_bytes;
            decoded += p.compression->decoded_bytes;
        }
    // A stream of a few dozen points is mostly Draco's header (VC's small parts).
    if (encoded > 4096) {
        EXPECT_GT(decoded, encoded);
    }
    EXPECT_EQ(compressed_prims, compressed.scene->primitives.size()) << "every primitive decoded";

    const Drawn a = drawn(*compressed.scene), b = drawn(*source.scene);
    // gltfpack welds equal vertices and drops the triangles that then repeat an
    // index (10413 of 2CylinderEngine's 75730 mesh triangles): only triangles with
    // two corners at one position may go; with none such, the counts are equal.
    EXPECT_LE(a.triangles, b.triangles) << "drawn triangles";
    EXPECT_GE(a.triangles, b.triangles - b.collapsed) << "drawn triangles";
    if (b.collapsed == 0) {
        EXPECT_EQ(a.triangles, b.triangles) << "drawn triangles";
    }
    // gltfpack defaults: 14-bit positions over the scene's extent, 8-bit octahedral
    // normals, 12-bit UVs; one step each plus float rounding. Floating-point
    // positions (-vpf, EXPONENTIAL filter) keep 16-bit mantissas of the extent.
    const float extent = std::max({b.extent.x, b.extent.y, b.extent.z});
    const Tolerance tol{extent / float((1 << 14) - 1) * 1.01f, 2.0f / 127.0f * 1.5f,
                        std::max(b.uv_extent, 1.0f) / float((1 << 12) - 1) * 1.5f};
    EXPECT_EQ(unmatched(a.vertices, b.vertices, tol), 0u)
        << "of " << a.vertices.size() << " compressed vertices, none without a source match";
    EXPECT_EQ(unmatched(b.vertices, a.vertices, tol), 0u)
        << "of " << b.vertices.size() << " source vertices, none lost";
}

// The decoded scene draws without a Vulkan validation message.
TEST_P(CompressedFile, RendersValidationClean) {
    const CorpusFile& f = GetParam();
    const std::string png =
        (fs::temp_directory_path() / ("sherpa_compressed_" + std::to_string(::getpid()) + ".png"))
            .string();
    const test::CliRun r = test::run_cli(
        "render '" + (corpus_dir() / f.file).string() + "' -o " + png +
        " --width 64 --height 48 --validation --cache-dir '" + SHERPA_TEST_TEXTURE_CACHE + "'");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    fs::remove(png);
}

// info --json reports how each primitive was stored.
TEST(CompressedCorpus, InfoJsonReportsPerPrimitiveCompression) {
    const test::CliRun r =
        test::run_cli("info '" + (corpus_dir() / "Duck.meshopt_vpf.glb").string() + "' --json");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    const auto& c = j.at("primitives_detail").at(0).at("compression");
    EXPECT_EQ(c.at("codec"), "EXT_meshopt_compression");
    for (const char* part : {"ATTRIBUTES/OCTAHEDRAL", "ATTRIBUTES/EXPONENTIAL", "TRIANGLES"})
        EXPECT_NE(c.at("mode").get<std::string>().find(part), std::string::npos) << part;
    EXPECT_GT(c.at("decoded_bytes").get<double>(), c.at("encoded_bytes").get<double>());
    EXPECT_TRUE(c.at("decode_ms").is_number());
    const nlohmann::json used = j.at("extensions_used");
    EXPECT_NE(std::find(used.begin(), used.end(),
                        nlohmann::json{{"name", "EXT_meshopt_compression"}, {"supported", true}}),
              used.end());
}

std::string corpus_name(const ::testing::TestParamInfo<CorpusFile>& info) {
    std::string n = info.param.file;
    for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
}

INSTANTIATE_TEST_SUITE_P(NpmTools, CompressedFile, ::testing::ValuesIn(corpus()), corpus_name);

TEST(CompressedCorpus, IsPresent) {
    for (const auto& f : corpus())
        EXPECT_TRUE(fs::exists(corpus_dir() / f.file))
            << f.file << ": run the gltf_compress_corpus_make fixture (ctest)";
}

// gltfpack -cc stores BoxAnimated's rotation keys through the QUATERNION filter (and
// translations through EXPONENTIAL): posed at several times, every vertex of the
// compressed file lies on a vertex of the source's pose within 1% of the scene's
// size (rotations are quantized to 12 bits and resampled at 30 Hz; a mis-decoded
// quaternion turns the box by far more).
std::vector<glm::vec3> posed_vertices(const sherpa::scene::Scene& scene, double time) {
    const sherpa::scene::Pose pose = sherpa::scene::evaluate_pose(scene, 0, time);
    std::vector<glm::vec3> out;
    for (std::uint32_t n = 0; n < scene.nodes.size(); ++n)
        for (const sherpa::scene::PrimitiveInfo& p : scene.primitives)
            if (scene.nodes[n].mesh >= 0 && p.mesh == std::uint32_t(scene.nodes[n].mesh)) {
                const auto v = sherpa::scene::posed_positions(scene, pose, n, p);
                out.insert(out.end(), v.begin(), v.end());
            }
    return out;
}

TEST(CompressedCorpus, QuaternionFilteredAnimationPosesLikeTheSource) {
    const fs::path file = corpus_dir() / "BoxAnimated.meshopt.glb";
    const std::vector<unsigned char> glb = test::read_bytes(file);
    ASSERT_GT(glb.size(), 20u) << file;
    std::uint32_t json_length = 0;
    std::memcpy(&json_length, glb.data() + 12, 4);
    const auto doc = nlohmann::json::parse(glb.begin() + 20, glb.begin() + 20 + json_length);
    bool quaternion = false;
    for (const auto& v : doc.at("bufferViews"))
        quaternion =
            quaternion || v.value("extensions", nlohmann::json::object())
                                  .value("EXT_meshopt_compression", nlohmann::json::object())
                                  .value("filter", "") == "QUATERNION";
    ASSERT_TRUE(quaternion) << "gltfpack no longer filters rotations: the test checks nothing";
    const sherpa::scene::LoadResult source =
        sherpa::scene::load_scene(test::gltf_asset("BoxAnimated"));
    const sherpa::scene::LoadResult compressed = sherpa::scene::load_scene(file.string());
    ASSERT_TRUE(source) << source.error;
    ASSERT_TRUE(compressed) << compressed.error;
    ASSERT_FALSE(compressed.scene->animations.empty());
    const glm::vec3 extent = source.scene->bounds.max - source.scene->bounds.min;
    const float tol = 0.01f * std::max({extent.x, extent.y, extent.z});
    for (const double t : {0.4, 1.3, 2.2, 3.1}) {
        const auto a = posed_vertices(*compressed.scene, t), b = posed_vertices(*source.scene, t);
        ASSERT_FALSE(a.empty());
        float worst = 0;
        for (const glm::vec3& p : a) {
            float nearest = INFINITY;
            for (const glm::vec3& q : b) nearest = std::min(nearest, glm::length(p - q));
            worst = std::max(worst, nearest);
        }
        EXPECT_LE(worst, tol) << "time " << t;
    }
}

// A copy of gltf-transform's Duck.draco.gltf (and its .bin), edited.
std::string broken_draco(const std::string& name,
                         const std::function<void(nlohmann::json&)>& edit) {
    const fs::path dir = fs::temp_directory_path() / ("sherpa_draco_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    nlohmann::json doc = test::read_json((corpus_dir() / "Duck.draco.gltf").string());
    for (const auto& b : doc["buffers"])
        fs::copy_file(corpus_dir() / b["uri"].get<std::string>(), dir / b["uri"].get<std::string>(),
                      fs::copy_options::overwrite_existing);
    edit(doc);
    const fs::path out = dir / name;
    std::ofstream(out) << doc.dump();
    return out.string();
}

constexpr const char* kDracoPointer =
    "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression";

nlohmann::json& draco_extension(nlohmann::json& doc) {
    return doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"];
}

TEST(BrokenDraco, BlobCutShortIsNamed) {
    const std::string path = broken_draco("cut_short.gltf", [](nlohmann::json& doc) {
        auto& view = doc["bufferViews"][draco_extension(doc)["bufferView"].get<int>()];
        view["byteLength"] = view["byteLength"].get<int>() / 2;
    });
    test::expect_primitive_skipped(
        path, 0, 0, kDracoPointer,
        "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: the Draco stream");
}

TEST(BrokenDraco, DeclaredCountDisagreeingWithTheStreamIsNamed) {
    const std::string path = broken_draco("count.gltf", [](nlohmann::json& doc) {
        const int a = doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
        doc["accessors"][a]["count"] = doc["accessors"][a]["count"].get<int>() - 1;
    });
    test::expect_primitive_skipped(path, 0, 0, kDracoPointer,
                                   "attributes.POSITION: accessor count 2398 but Draco "
                                   "decoded 2399 points");
}

TEST(BrokenDraco, DeclaredMinMaxDisagreeingWithTheStreamIsNamed) {
    const std::string path = broken_draco("minmax.gltf", [](nlohmann::json& doc) {
        const int a = doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
        doc["accessors"][a]["max"][1] = 100.0; // the duck is 164 units tall
    });
    test::expect_primitive_skipped(path, 0, 0, kDracoPointer,
                                   "lies outside the accessor's declared");
}

TEST(BrokenDraco, MissingAttributeIdIsNamed) {
    const std::string path = broken_draco("attribute_id.gltf", [](nlohmann::json& doc) {
        draco_extension(doc)["attributes"]["POSITION"] = 17;
    });
    test::expect_primitive_skipped(path, 0, 0, kDracoPointer,
                                   "attribute id 17 is not in the Draco stream");
}

} // namespace
