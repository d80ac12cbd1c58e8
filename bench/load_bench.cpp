// sherpa-bench-load [--repeat N] [--csv] [MODEL_DIR...]
// Per asset: the time to merely read its files (the .gltf and every file beside it:
// buffers and images, which the importer also reads), then tinygltf parse and Sherpa
// processing time, each the median of N warm runs.
#include <sherpa/core/file_io.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

double read_all_ms(const fs::path& dir, std::uint64_t& bytes) {
    const auto t0 = std::chrono::steady_clock::now();
    bytes = 0;
    std::vector<std::uint8_t> buf;
    std::string error;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file() && sherpa::core::read_file(e.path(), buf, error))
            bytes += buf.size();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

int main(int argc, char** argv) {
    int repeat = 9;
    bool csv = false;
    std::vector<fs::path> dirs;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--csv"))
            csv = true;
        else
            dirs.emplace_back(argv[i]);
    }
    if (dirs.empty()) {
        for (const auto& e : fs::directory_iterator(fs::path(SHERPA_ASSETS_DIR) / "gltf"))
            dirs.push_back(e.path());
        std::sort(dirs.begin(), dirs.end());
    }
    if (csv)
        std::printf("asset,bytes,read_ms,parse_ms,process_ms,total_ms,triangles\n");
    else
        std::printf("%-30s %10s %9s %9s %11s %9s %10s\n", "asset", "bytes", "read ms", "parse ms",
                    "process ms", "total ms", "triangles");
    double sum_read = 0, sum_parse = 0, sum_process = 0;
    for (const fs::path& model_dir : dirs) {
        const std::string name = model_dir.filename().string();
        const fs::path gltf = model_dir / "glTF" / (name + ".gltf");
        if (!fs::exists(gltf)) continue;
        std::vector<double> reads, parses, processes;
        std::uint64_t bytes = 0, triangles = 0;
        for (int r = 0; r < repeat; ++r) {
            reads.push_back(read_all_ms(gltf.parent_path(), bytes));
            const sherpa::scene::LoadResult res = sherpa::scene::load_scene(gltf.string());
            if (!res) {
                std::fprintf(stderr, "error: %s\n", res.error.c_str());
                return 1;
            }
            parses.push_back(res.scene->parse_ms);
            processes.push_back(res.scene->process_ms);
            triangles = res.scene->counts.triangles;
        }
        const double rd = median(reads), pa = median(parses), pr = median(processes);
        sum_read += rd, sum_parse += pa, sum_process += pr;
        if (csv)
            std::printf("%s,%llu,%.3f,%.3f,%.3f,%.3f,%llu\n", name.c_str(),
                        (unsigned long long)bytes, rd, pa, pr, pa + pr,
                        (unsigned long long)triangles);
        else
            std::printf("%-30s %10llu %9.3f %9.3f %11.3f %9.3f %10llu\n", name.c_str(),
                        (unsigned long long)bytes, rd, pa, pr, pa + pr,
                        (unsigned long long)triangles);
    }
    if (!csv)
        std::printf("%-30s %10s %9.3f %9.3f %11.3f %9.3f\n", "sum of medians", "", sum_read,
                    sum_parse, sum_process, sum_parse + sum_process);
    return 0;
}
