// sherpa-tangent-report OUT_DIR [--repeat N] [--no-oracle]
// Writes the data behind docs/tangents: methods.csv (per method and model: time, angle
// error against authored tangents and against exact MikkTSpace, handedness flips,
// fallbacks, vertex splits) and sweep.csv (per generated failure case and method:
// fallbacks by cause, non-finite values before the guard, NaNs in the output, error
// against the known tangent). docs/tangents/regenerate.sh turns them into charts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include <sherpa/scene/mesh_tangents.h>
#include <sherpa/scene/tangent_compare.h>
#include <sherpa/scene/tangents.h>

#include "oracle_runner.h"
#include "tangent_meshes.h"
#include "tangent_sweep.h"

using namespace sherpa;

namespace {

double thread_cpu_seconds() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

struct Run {
    std::vector<glm::vec4> tangents;
    std::vector<scene::TangentFallback> fallbacks;
    scene::TangentStats stats;
    double cpu_seconds = 1e30; // best of the repeats
};

Run run_method(const bench::BenchMesh& m, scene::TangentMethod method, int repeat) {
    Run r;
    r.tangents.resize(m.indices.size());
    r.fallbacks.resize(m.indices.size());
    scene::TangentWorkspace workspace;
    for (int i = 0; i < repeat; ++i) {
        const double t0 = thread_cpu_seconds();
        r.stats =
            scene::generate_corner_tangents(m.input(), method, r.tangents, r.fallbacks, &workspace);
        r.cpu_seconds = std::min(r.cpu_seconds, thread_cpu_seconds() - t0);
    }
    return r;
}

// Vertices apply_corner_tangents would add for these tangents.
std::uint32_t split_count(const bench::BenchMesh& m, const std::vector<glm::vec4>& tangents) {
    scene::Mesh mesh;
    mesh.vertices.resize(m.positions.size());
    mesh.indices = m.indices;
    return scene::apply_corner_tangents(mesh, tangents);
}

std::string stats_columns(const scene::TangentComparison& c) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.6g,%.6g,%.6g,%llu", c.mean, c.p99, c.max,
                  (unsigned long long)c.flips);
    return buf;
}

void write_methods(const std::string& path, int repeat, bool with_oracle) {
    std::vector<bench::BenchMesh> meshes = bench::load_sample_meshes(SHERPA_ASSETS_DIR);
    meshes.push_back(bench::make_torus(500, 250));
    std::ofstream csv(path);
    csv << "model,method,triangles,ms_per_mtri,authored_mean_deg,authored_p99_deg,authored_max_deg,"
           "authored_flips,exact_mean_deg,exact_p99_deg,exact_max_deg,exact_flips,fallback_corners,"
           "split_vertices\n";
    const std::string empty_stats = ",,,";
    for (const bench::BenchMesh& m : meshes) {
        std::vector<glm::vec4> authored;
        for (std::uint32_t i : m.indices)
            if (!m.authored.empty()) authored.push_back(m.authored[i]);
        const Run exact = run_method(m, scene::TangentMethod::MikkTSpace, repeat);
        std::vector<std::pair<std::string, Run>> runs;
        for (scene::TangentMethod method : scene::kAllTangentMethods)
            runs.emplace_back(
                std::string(to_string(method)),
                method == scene::TangentMethod::MikkTSpace ? exact : run_method(m, method, repeat));
        if (with_oracle) {
            Run oracle;
            const tools::OracleResult result = tools::run_oracle(
                {SHERPA_NODE, SHERPA_ORACLE_SCRIPT, SHERPA_ORACLE_CACHE, "."}, {m.input()}, repeat);
            oracle.tangents = result.tangents[0];
            oracle.cpu_seconds = result.cpu_seconds;
            // The reference reports no fallbacks; count what it leaves NaN or zero.
            for (const glm::vec4& t : oracle.tangents)
                oracle.stats.corners[tools::oracle_unusable(t) ? 5 : 0]++;
            runs.emplace_back("reference-wasm", std::move(oracle));
        }
        for (const auto& [name, run] : runs) {
            // Corners where exact MikkTSpace fell back carry no exact value to compare.
            std::vector<std::uint8_t> skip(exact.fallbacks.size());
            for (std::size_t c = 0; c < skip.size(); ++c)
                skip[c] = exact.fallbacks[c] != scene::TangentFallback::None;
            const double ms = 1e3 * run.cpu_seconds / (double(m.triangles()) / 1e6);
            csv << m.name << "," << name << "," << m.triangles() << "," << ms << ","
                << (authored.empty()
                        ? empty_stats
                        : stats_columns(scene::compare_tangents(run.tangents, authored)))
                << "," << stats_columns(scene::compare_tangents(run.tangents, exact.tangents, skip))
                << "," << run.stats.fallbacks() << "," << split_count(m, run.tangents) << "\n";
        }
        std::printf("methods: %s done\n", m.name.c_str());
    }
}

void write_sweep(const std::string& path) {
    std::ofstream csv(path);
    csv << "case,method,corners,fallback_corners";
    for (std::size_t c = 1; c < scene::kTangentFallbackCauses; ++c)
        csv << "," << to_string(scene::TangentFallback(c));
    csv << ",nonfinite_before_guard,nan_in_output,max_error_deg,flips\n";
    for (const bench::SweepCase& s : bench::make_sweep()) {
        for (scene::TangentMethod method : scene::kAllTangentMethods) {
            const Run r = run_method(s.mesh, method, 1);
            std::uint64_t nan_out = 0;
            for (const glm::vec4& t : r.tangents)
                nan_out += !(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) &&
                             std::isfinite(t.w));
            std::vector<std::uint8_t> skip(r.fallbacks.size());
            for (std::size_t c = 0; c < skip.size(); ++c)
                skip[c] = r.fallbacks[c] != scene::TangentFallback::None;
            const scene::TangentComparison err =
                scene::compare_tangents(r.tangents, s.expected, skip);
            csv << s.mesh.name << "," << to_string(method) << "," << r.tangents.size() << ","
                << r.stats.fallbacks();
            for (std::size_t c = 1; c < scene::kTangentFallbackCauses; ++c)
                csv << "," << r.stats.corners[c];
            csv << "," << r.stats.nonfinite_before_guard << "," << nan_out << "," << err.max << ","
                << err.flips << "\n";
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') {
        std::fprintf(stderr, "usage: sherpa-tangent-report OUT_DIR [--repeat N] [--no-oracle]\n");
        return 2;
    }
    const std::string out = argv[1];
    int repeat = 3;
    bool with_oracle = true;
    for (int i = 2; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--no-oracle"))
            with_oracle = false;
    }
    try {
        write_sweep(out + "/sweep.csv");
        write_methods(out + "/methods.csv", repeat, with_oracle);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    std::printf("wrote %s/methods.csv and %s/sweep.csv\n", out.c_str(), out.c_str());
    return 0;
}
