#pragma once
// Paths to the shared real assets and the hand-made malformed files.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

namespace sherpa::test {

inline std::filesystem::path assets_dir() {
    return SHERPA_ASSETS_DIR;
}
inline std::filesystem::path data_dir() {
    return SHERPA_TEST_DATA_DIR;
}

// A file name in the temporary directory of this process alone (ctest -j runs suites
// side by side): PREFIX_PID_NAME.
inline std::string temp_path(const std::string& prefix, const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            (prefix + "_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

inline std::string gltf_asset(const std::string& name) {
    return (assets_dir() / "gltf" / name / "glTF" / (name + ".gltf")).string();
}

// Every sample model in shared/assets/gltf (name of its folder), sorted.
inline std::vector<std::string> all_gltf_models() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(assets_dir() / "gltf", ec))
        if (std::filesystem::exists(e.path() / "glTF" / (e.path().filename().string() + ".gltf")))
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

inline nlohmann::json read_json(const std::string& path) {
    std::ifstream f(path);
    return nlohmann::json::parse(f);
}

inline std::vector<unsigned char> read_bytes(const std::filesystem::path& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

} // namespace sherpa::test
