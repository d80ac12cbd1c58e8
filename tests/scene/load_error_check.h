#pragma once
// Shared checks of the malformed-input suites (bad_input_test, hostile_input_test).
#include <sherpa/scene/scene_loader.h>

#include <string>

#include <gtest/gtest.h>

namespace sherpa::test {

// A file that must fail to load, and a fragment its error must contain.
struct BadCase {
    const char* file;
    const char* message;
};

// The load fails with one readable line that starts with "PATH: ", contains
// `fragment`, holds only printable ASCII (no raw bytes of the file), and no scene.
inline void expect_clear_load_error(const std::string& path, const std::string& fragment) {
    const sherpa::LoadResult r = sherpa::load_scene(path);
    EXPECT_FALSE(r);
    EXPECT_EQ(r.scene, nullptr);
    EXPECT_EQ(r.error.rfind(path + ": ", 0), 0u) << "error must start with the file: " << r.error;
    EXPECT_NE(r.error.find(fragment), std::string::npos) << r.error;
    EXPECT_LT(r.error.size(), 400u) << "one readable line";
    for (const char c : r.error)
        EXPECT_TRUE(c >= 0x20 && c < 0x7F) << "no raw bytes in a message: " << r.error;
}

// gtest parameter names from file names ("a.gltf" -> "a_gltf").
inline std::string case_name(const ::testing::TestParamInfo<BadCase>& info) {
    std::string n = info.param.file;
    for (char& c : n)
        if (c == '.') c = '_';
    return n;
}

} // namespace sherpa::test
