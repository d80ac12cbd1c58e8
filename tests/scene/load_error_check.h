#pragma once
// Shared load checks of the scene suites: a file that must load, and the malformed-input
// suites' (bad_input_test, hostile_input_test) files that must fail or warn.
#include <sherpa/scene/scene_loader.h>

#include <cstdint>
#include <memory>
#include <string>

#include <gtest/gtest.h>

namespace sherpa::test {

// The scene of a file that must load; a test failure with the error and null where not.
inline std::unique_ptr<scene::Scene> load_scene_or_fail(const std::string& path) {
    scene::LoadResult r = scene::load_scene(path);
    EXPECT_TRUE(r) << r.error;
    return std::move(r.scene);
}

// A file that must fail to load, and a fragment its error must contain.
struct BadCase {
    const char* file;
    const char* message;
};

// The load fails with one readable line that starts with "PATH: ", contains
// `fragment`, holds only printable ASCII (no raw bytes of the file), and no scene.
inline void expect_clear_load_error(const std::string& path, const std::string& fragment) {
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
    EXPECT_FALSE(r);
    EXPECT_EQ(r.scene, nullptr);
    EXPECT_EQ(r.error.rfind(path + ": ", 0), 0u) << "error must start with the file: " << r.error;
    EXPECT_NE(r.error.find(fragment), std::string::npos) << r.error;
    EXPECT_LT(r.error.size(), 400u) << "one readable line";
    for (const char c : r.error)
        EXPECT_TRUE(c >= 0x20 && c < 0x7F) << "no raw bytes in a message: " << r.error;
}

// A file with a broken part that loads anyway: the part is skipped or defaulted and a
// validation message (a SHERPA_ code, or the validator's own) contains `fragment`.
inline void expect_loads_naming(const std::string& path, const std::string& fragment) {
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
    ASSERT_TRUE(r) << r.error;
    bool named = false;
    for (const auto& m : r.scene->validation.messages)
        named |= m.message.find(fragment) != std::string::npos;
    EXPECT_TRUE(named) << path << " has no message containing: " << fragment;
    EXPECT_GT(r.scene->validation.count(sherpa::scene::Severity::Error), 0u) << path;
}

// A file whose primitive `mesh`/`primitive` cannot be read: the file loads, the
// primitive is listed as skipped with a reason containing `fragment`, and the report
// has a SHERPA_PRIMITIVE_SKIPPED error at `pointer` or below it.
inline void expect_primitive_skipped(const std::string& path, std::uint32_t mesh,
                                     std::uint32_t primitive, const std::string& pointer,
                                     const std::string& fragment) {
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
    ASSERT_TRUE(r) << r.error;
    bool listed = false;
    for (const auto& p : r.scene->primitives)
        if (p.mesh == mesh && p.primitive == primitive) {
            listed = true;
            EXPECT_NE(p.skipped_reason.find(fragment), std::string::npos) << p.skipped_reason;
        }
    EXPECT_TRUE(listed) << path << ": primitive not listed";
    bool named = false;
    for (const auto& m : r.scene->validation.messages)
        named |= m.code == "SHERPA_PRIMITIVE_SKIPPED" && m.pointer.rfind(pointer, 0) == 0 &&
                 m.severity == sherpa::scene::Severity::Error;
    EXPECT_TRUE(named) << path << ": no SHERPA_PRIMITIVE_SKIPPED at " << pointer;
}

// gtest parameter names from file names ("a.gltf" -> "a_gltf").
inline std::string case_name(const ::testing::TestParamInfo<BadCase>& info) {
    std::string n = info.param.file;
    for (char& c : n)
        if (c == '.') c = '_';
    return n;
}

} // namespace sherpa::test
