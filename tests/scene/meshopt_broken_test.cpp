// Broken variants of gltfpack's meshopt files (tools/gltf_compress/make_corpus.sh): an
// extension object that is wrong refuses the file with a clear error; a stream that
// does not decode shows the view's uncompressed fallback bytes where the file has them,
// else skips the primitives reading it by name while the rest of the file loads.
#include "scene/load_error_check.h"
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

fs::path meshopt_corpus() {
    return fs::path(SHERPA_GLTF_COMPRESS_CACHE) / "corpus";
}

// A copy of the gltfpack .gltf (and its .bin) whose first compressed view is edited.
std::string broken_copy(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
    const fs::path dir =
        fs::temp_directory_path() / ("sherpa_meshopt_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::copy_file(meshopt_corpus() / "Duck.meshopt.bin", dir / "Duck.meshopt.bin",
                  fs::copy_options::overwrite_existing);
    nlohmann::json doc = test::read_json((meshopt_corpus() / "Duck.meshopt.gltf").string());
    for (auto& view : doc["bufferViews"])
        if (view.contains("extensions")) {
            edit(view["extensions"]["EXT_meshopt_compression"]);
            break;
        }
    const fs::path out = dir / name;
    std::ofstream(out) << doc.dump();
    return out.string();
}

// A stream that does not decode skips the primitives reading its view, by name (the
// file's fallback buffer has no bytes to show instead); the rest of the file loads.
constexpr const char* kFirstViewPointer = "/bufferViews/0/extensions/EXT_meshopt_compression";

TEST(BrokenMeshopt, TruncatedStreamSkipsItsPrimitiveByName) {
    const std::string path = broken_copy("truncated.gltf", [](nlohmann::json& e) {
        e["byteLength"] = e["byteLength"].get<int>() / 3;
    });
    test::expect_primitive_skipped(path, 0, 0, kFirstViewPointer,
                                   "EXT_meshopt_compression: the ATTRIBUTES stream (version 0) "
                                   "does not decode: truncated");
}

// A stream declared one byte longer (the next stream's first byte): its tail, read from
// the end, is not the tail, and the blocks do not end where it begins.
TEST(BrokenMeshopt, StreamOneByteLongSkipsItsPrimitive) {
    const std::string path = broken_copy(
        "long.gltf", [](nlohmann::json& e) { e["byteLength"] = e["byteLength"].get<int>() + 1; });
    test::expect_primitive_skipped(path, 0, 0, kFirstViewPointer,
                                   "EXT_meshopt_compression: the ATTRIBUTES stream (version 0) "
                                   "does not decode");
}

// Where the file has the view's uncompressed bytes (gltfpack -cf), a stream that does
// not decode shows those instead, and says so.
TEST(BrokenMeshopt, UndecodableStreamShowsTheFallbackBytes) {
    const fs::path dir =
        fs::temp_directory_path() / ("sherpa_meshopt_cf_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    nlohmann::json doc =
        test::read_json((meshopt_corpus() / "Duck.meshopt_fallback.gltf").string());
    for (const auto& b : doc["buffers"])
        if (b.contains("uri"))
            fs::copy_file(meshopt_corpus() / b["uri"].get<std::string>(),
                          dir / b["uri"].get<std::string>(), fs::copy_options::overwrite_existing);
    int broken = -1;
    for (std::size_t v = 0; v < doc["bufferViews"].size() && broken < 0; ++v)
        if (auto& view = doc["bufferViews"][v]; view.contains("extensions")) {
            auto& e = view["extensions"]["EXT_meshopt_compression"];
            e["byteLength"] = e["byteLength"].get<int>() / 3;
            broken = int(v);
        }
    ASSERT_GE(broken, 0) << "gltfpack -cf wrote no compressed view";
    std::ofstream(dir / "cut.gltf") << doc.dump();
    const sherpa::scene::LoadResult whole =
        sherpa::scene::load_scene((meshopt_corpus() / "Duck.meshopt_fallback.gltf").string());
    const sherpa::scene::LoadResult cut = sherpa::scene::load_scene((dir / "cut.gltf").string());
    ASSERT_TRUE(whole) << whole.error;
    ASSERT_TRUE(cut) << cut.error;
    ASSERT_EQ(cut.scene->primitives.size(), whole.scene->primitives.size());
    for (const auto& p : cut.scene->primitives)
        EXPECT_TRUE(p.skipped_reason.empty()) << p.skipped_reason;
    bool said = false;
    for (const auto& w : cut.scene->warnings)
        said |= w.find("bufferViews[" + std::to_string(broken) +
                       "].extensions.EXT_meshopt_compression: the") != std::string::npos &&
                w.find("fallback bytes") != std::string::npos;
    EXPECT_TRUE(said) << "no warning names the view and the fallback";
    // The fallback holds what the stream decodes to (gltfpack writes the decoded bytes).
    ASSERT_EQ(cut.scene->meshes.size(), whole.scene->meshes.size());
    for (std::size_t m = 0; m < cut.scene->meshes.size(); ++m) {
        const auto &a = cut.scene->meshes[m].vertices, &b = whole.scene->meshes[m].vertices;
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i].position, b[i].position) << i;
    }
}

TEST(BrokenMeshopt, StreamPastItsBufferIsNamed) {
    const std::string path =
        broken_copy("past_buffer.gltf", [](nlohmann::json& e) { e["byteOffset"] = 1 << 30; });
    test::expect_clear_load_error(path, "exceeds buffers[0]");
}

TEST(BrokenMeshopt, CorruptHeaderSkipsItsPrimitiveByName) {
    const std::string path = broken_copy("bad_mode.gltf", [](nlohmann::json& e) {
        e["mode"] = "TRIANGLES"; // an ATTRIBUTES stream read as indices: wrong header byte
        e["byteStride"] = 2;
        e["count"] = 3;
        e.erase("filter");
    });
    test::expect_primitive_skipped(path, 0, 0, kFirstViewPointer,
                                   "is not a meshopt TRIANGLES stream");
}

TEST(BrokenMeshopt, CountBeyondTheViewIsNamed) {
    const std::string path =
        broken_copy("big_count.gltf", [](nlohmann::json& e) { e["count"] = 1u << 30; });
    test::expect_clear_load_error(path, "exceeds the view's byteLength");
}

// A view that only animation data reads (gltfpack's QUATERNION-filtered rotations):
// its stream, cut short, is named in a warning, the channel reading it is skipped,
// and the rest of the file loads.
TEST(BrokenMeshopt, AnimationStreamThatDoesNotDecodeIsNamed) {
    const std::vector<unsigned char> glb =
        test::read_bytes(meshopt_corpus() / "BoxAnimated.meshopt.glb");
    ASSERT_GT(glb.size(), 20u);
    std::uint32_t json_length = 0;
    std::memcpy(&json_length, glb.data() + 12, 4);
    nlohmann::json doc = nlohmann::json::parse(glb.begin() + 20, glb.begin() + 20 + json_length);
    int broken = -1;
    for (std::size_t v = 0; v < doc["bufferViews"].size() && broken < 0; ++v) {
        auto& view = doc["bufferViews"][v];
        if (view.contains("extensions") &&
            view["extensions"]["EXT_meshopt_compression"].value("filter", "") == "QUATERNION") {
            auto& e = view["extensions"]["EXT_meshopt_compression"];
            e["byteLength"] = e["byteLength"].get<int>() / 2;
            broken = int(v);
        }
    }
    ASSERT_GE(broken, 0) << "gltfpack no longer filters rotations";
    std::string text = doc.dump();
    text.resize((text.size() + 3) / 4 * 4, ' ');
    std::vector<unsigned char> out(glb.begin(), glb.begin() + 12);
    const auto put32 = [&](std::uint32_t v) {
        for (int b = 0; b < 4; ++b) out.push_back(static_cast<unsigned char>(v >> (8 * b)));
    };
    put32(std::uint32_t(text.size()));
    put32(0x4E4F534A); // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    out.insert(out.end(), glb.begin() + 20 + json_length, glb.end());
    const std::uint32_t total = std::uint32_t(out.size());
    std::memcpy(out.data() + 8, &total, 4);
    const fs::path path =
        fs::temp_directory_path() / ("sherpa_meshopt_anim_" + std::to_string(::getpid()) + ".glb");
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path.string());
    fs::remove(path);
    ASSERT_TRUE(r) << r.error;
    bool named = false, skipped = false;
    for (const std::string& w : r.scene->warnings) {
        named |= w.rfind("bufferViews[" + std::to_string(broken) +
                             "].extensions.EXT_meshopt_compression: the ATTRIBUTES stream",
                         0) == 0;
        skipped |= w.find("channels[0] skipped") != std::string::npos;
    }
    EXPECT_TRUE(named) << "no warning names the view's stream";
    EXPECT_TRUE(skipped) << "the channel reading the view is not skipped by name";
    for (const auto& p : r.scene->primitives) EXPECT_TRUE(p.skipped_reason.empty());
}

} // namespace
