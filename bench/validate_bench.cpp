// sherpa-bench-validate --node-path CACHE/node_modules [--repeat N] [--nodes N] [--passes]
// The validator's cost against the importer's (goal: validation adds <= 10% to parse +
// process) and against the Khronos glTF-Validator (npm gltf-validator, goal >= 20x
// faster), all in one run: DamagedHelmet, 2CylinderEngine and a generated file of N
// nodes (default 100000). The fastest of N warm runs each, column by column (on a
// shared machine the fastest run is the one least disturbed; a median still moved by
// several times between runs). The JavaScript time is the
// validator's own (validateBytes, JSON parse included, Node start-up excluded); Sherpa's
// is shown alone and with the JSON parse the importer shares with it. --passes adds the
// validator's passes one by one per file (validate_passes.cpp).
#include "validate_passes.h"

#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

double fastest(const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}

// N nodes in a tree (each node's parent is node (i-1)/8), every 4th with a mesh: one
// triangle shared by all, data in a data URI.
fs::path write_many_nodes(std::size_t n) {
    nlohmann::json doc;
    doc["asset"] = {{"version", "2.0"}};
    doc["scene"] = 0;
    doc["scenes"] = {{{"nodes", {0}}}};
    nlohmann::json nodes = nlohmann::json::array();
    for (std::size_t i = 0; i < n; ++i) {
        nlohmann::json node = {{"translation", {double(i % 17), double(i % 5), 0.5}}};
        if (i % 4 == 0) node["mesh"] = 0;
        nlohmann::json children = nlohmann::json::array();
        for (std::size_t c = 8 * i + 1; c <= 8 * i + 8 && c < n; ++c) children.push_back(c);
        if (!children.empty()) node["children"] = children;
        nodes.push_back(node);
    }
    doc["nodes"] = nodes;
    doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}};
    doc["accessors"] = {{{"bufferView", 0},
                         {"componentType", 5126},
                         {"count", 3},
                         {"type", "VEC3"},
                         {"min", {0, 0, 0}},
                         {"max", {1, 1, 0}}}};
    doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", 36}, {"target", 34962}}};
    // 0,0,0  1,0,0  0,1,0 as little-endian floats
    doc["buffers"] = {
        {{"byteLength", 36},
         {"uri", "data:application/"
                 "octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}}};
    const fs::path path =
        fs::temp_directory_path() / ("sherpa_validate_bench_" + std::to_string(n) + ".gltf");
    std::ofstream(path) << doc.dump();
    return path;
}

// The Khronos validator's own time on `path`, or a negative number when it failed.
double khronos_ms(const std::string& node_path, const fs::path& script, const fs::path& path) {
    const std::string cmd =
        "NODE_PATH='" + node_path + "' node '" + script.string() + "' '" + path.string() + "'";
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return -1;
    std::string out;
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof(buf), p)) out.append(buf, n);
    pclose(p);
    try {
        return nlohmann::json::parse(out.substr(0, out.find('\n'))).value("ms", -1.0);
    } catch (...) {
        return -1;
    }
}

} // namespace

int main(int argc, char** argv) {
    int repeat = 5;
    std::size_t many = 100000;
    std::string node_path;
    bool passes = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--nodes") && i + 1 < argc)
            many = static_cast<std::size_t>(std::max(1, std::atoi(argv[++i])));
        else if (!std::strcmp(argv[i], "--node-path") && i + 1 < argc)
            node_path = argv[++i];
        else if (!std::strcmp(argv[i], "--passes"))
            passes = true;
    }
    const fs::path assets = fs::path(SHERPA_ASSETS_DIR) / "gltf";
    const fs::path script =
        fs::path(SHERPA_SOURCE_DIR) / "tools/gltf_validator/khronos_validate.js";
    const std::vector<fs::path> files = {assets / "DamagedHelmet/glTF/DamagedHelmet.gltf",
                                         assets / "2CylinderEngine/glTF/2CylinderEngine.gltf",
                                         write_many_nodes(many)};
    std::printf("%-28s %9s %9s %9s %8s %10s %9s %9s\n", "file", "parse ms", "process", "validate",
                "share", "khronos ms", "x faster", "x (+json)");
    for (const fs::path& f : files) {
        std::vector<double> parse, process, validate, json_ms, js;
        for (int r = 0; r < repeat; ++r) {
            const auto result = sherpa::scene::load_scene(f.string());
            if (!result) {
                std::printf("%s: %s\n", f.string().c_str(), result.error.c_str());
                return 1;
            }
            parse.push_back(result.scene->parse_ms);
            process.push_back(result.scene->process_ms);
            validate.push_back(result.scene->validation.ms);
            // The JSON parse the validator shares with the importer, timed alone.
            std::ifstream in(f, std::ios::binary);
            const std::string text{std::istreambuf_iterator<char>(in),
                                   std::istreambuf_iterator<char>()};
            const auto t0 = std::chrono::steady_clock::now();
            const auto doc = nlohmann::json::parse(text);
            json_ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count());
            if (!node_path.empty()) js.push_back(khronos_ms(node_path, script, f));
        }
        const double p = fastest(parse), q = fastest(process), v = fastest(validate),
                     j = fastest(json_ms);
        const double k = fastest(js);
        std::printf("%-28s %9.2f %9.2f %9.2f %7.1f%% %10.2f %9.1f %9.1f\n",
                    f.filename().string().substr(0, 28).c_str(), p, q, v, 100.0 * v / (p + q),
                    node_path.empty() ? 0.0 : k, k > 0 ? k / v : 0.0, k > 0 ? k / (v + j) : 0.0);
    }
    std::printf("fastest of %d runs per column; share: validate / (parse + process), goal <= "
                "10%%; x faster: Khronos (JS) time / Sherpa's, goal >= 20x\n",
                repeat);
    if (passes)
        for (const fs::path& f : files)
            if (!sherpa::bench::print_passes(f, std::max(repeat, 20))) return 1;
    return 0;
}
