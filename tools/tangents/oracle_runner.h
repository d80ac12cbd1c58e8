#pragma once
// Runs the MikkTSpace oracle (npm `mikktspace`, the reference compiled to WebAssembly)
// through Node.js on indexed meshes, for the oracle tests, the benchmark and the
// accuracy report.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/scene/tangents.h>

namespace sherpa::tools {

struct OracleSetup {
    std::string node = "node";
    std::string script;         // mikktspace_oracle.js
    std::string cache_dir;      // where install_oracle.sh put node_modules/mikktspace
    std::string work_dir = "."; // where the exchange files go
};

struct OracleResult {
    // Per mesh, per corner, in glTF's convention (the package's w negated).
    std::vector<std::vector<glm::vec4>> tangents;
    double seconds = 0.0;     // best wall time inside generateTangents over all meshes, if timed
    double cpu_seconds = 0.0; // best CPU time of the same
};

// Unindexes each mesh, runs the oracle (timing `time_repeats` runs when > 0) and reads
// its tangents back. Throws std::runtime_error with the oracle's failure.
OracleResult run_oracle(const OracleSetup& setup, const std::vector<scene::TangentInput>& meshes,
                        int time_repeats = 0);

// Whether the oracle's tangent is no tangent at all: NaN/Inf or zero.
bool oracle_unusable(const glm::vec4& t);

// Whether the oracle itself marks a corner degenerate where we report `cause`: it gave no
// usable tangent, or it left the corner at the reference's default (+x, glTF sign +1),
// which it does for corners of degenerate triangles that no group reached, and our
// cause confirms the corner's triangle is degenerate.
bool oracle_agrees_with_fallback(const glm::vec4& t, scene::TangentFallback cause);

} // namespace sherpa::tools
