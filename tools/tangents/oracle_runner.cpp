#include "oracle_runner.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace sherpa::tools {
namespace {

void write_u32(std::ofstream& out, std::uint32_t v) {
    out.write(reinterpret_cast<char*>(&v), 4);
}

template <class T>
void write_corners(std::ofstream& out, std::span<const T> values,
                   std::span<const std::uint32_t> indices) {
    for (std::uint32_t i : indices) out.write(reinterpret_cast<const char*>(&values[i]), sizeof(T));
}

} // namespace

OracleResult run_oracle(const OracleSetup& setup, const std::vector<scene::TangentInput>& meshes,
                        int time_repeats) {
    const std::string in_path = setup.work_dir + "/mikktspace_oracle_in.bin";
    const std::string out_path = setup.work_dir + "/mikktspace_oracle_out.bin";
    const std::string log_path = setup.work_dir + "/mikktspace_oracle.log";
    {
        std::ofstream in(in_path, std::ios::binary);
        write_u32(in, static_cast<std::uint32_t>(meshes.size()));
        for (const scene::TangentInput& m : meshes) {
            write_u32(in, static_cast<std::uint32_t>(m.indices.size()));
            write_corners(in, m.positions, m.indices);
            write_corners(in, m.normals, m.indices);
            write_corners(in, m.uvs, m.indices);
        }
        if (!in) throw std::runtime_error("cannot write " + in_path);
    }
    std::string command = "\"" + setup.node + "\" \"" + setup.script + "\" \"" + setup.cache_dir +
                          "\" \"" + in_path + "\" \"" + out_path + "\"";
    if (time_repeats > 0) command += " --time " + std::to_string(time_repeats);
    command += " > \"" + log_path + "\" 2>&1";
    if (std::system(command.c_str()) != 0) {
        std::ifstream log(log_path);
        const std::string text((std::istreambuf_iterator<char>(log)),
                               std::istreambuf_iterator<char>());
        throw std::runtime_error("oracle failed (" + command + "): " + text);
    }
    OracleResult result;
    if (time_repeats > 0) {
        std::ifstream log(log_path);
        std::string word;
        while (log >> word)
            if (word == "oracle_seconds")
                log >> result.seconds;
            else if (word == "oracle_cpu_seconds")
                log >> result.cpu_seconds;
    }
    std::ifstream out(out_path, std::ios::binary);
    for (const scene::TangentInput& m : meshes) {
        std::vector<glm::vec4> tangents(m.indices.size());
        out.read(reinterpret_cast<char*>(tangents.data()),
                 std::streamsize(tangents.size() * sizeof(glm::vec4)));
        if (!out) throw std::runtime_error("oracle output too short: " + out_path);
        for (glm::vec4& t : tangents) t.w = -t.w; // reference's v-up sign to glTF's v-down
        result.tangents.push_back(std::move(tangents));
    }
    std::remove(in_path.c_str());
    std::remove(out_path.c_str());
    std::remove(log_path.c_str());
    return result;
}

bool oracle_unusable(const glm::vec4& t) {
    const bool finite = std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z);
    return !finite || (t.x == 0.0f && t.y == 0.0f && t.z == 0.0f);
}

bool oracle_agrees_with_fallback(const glm::vec4& t, scene::TangentFallback cause) {
    if (oracle_unusable(t)) return true;
    // The reference's untouched default (+x, sign -1 before the flip to glTF's +1) is a
    // plausible tangent too, so it only counts where the input itself is degenerate.
    const bool is_default = t.x == 1.0f && t.y == 0.0f && t.z == 0.0f && t.w == 1.0f;
    return is_default && (cause == scene::TangentFallback::DegenerateUv ||
                          cause == scene::TangentFallback::DegeneratePosition ||
                          cause == scene::TangentFallback::NonFiniteInput);
}

} // namespace sherpa::tools
