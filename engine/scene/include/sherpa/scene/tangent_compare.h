#pragma once
// Angle errors between two sets of per-corner tangents: what `sherpa-cli tangents
// --compare`, the oracle tests and the accuracy report print.
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace sherpa::scene {

// Angle in degrees between the xyz parts (computed in double with atan2, so that tiny
// angles are exact). Non-finite inputs give NaN.
double tangent_angle_degrees(const glm::vec4& a, const glm::vec4& b);

struct TangentComparison {
    std::uint64_t corners = 0;         // corners compared
    double mean = 0, p99 = 0, max = 0; // angle error, degrees
    std::uint64_t flips = 0;           // corners whose handedness (sign of w) differs
    std::uint64_t nonfinite = 0;       // corners where either side is NaN/Inf (not in the stats)
};

// Compares corner by corner; `skip`, when not empty, marks corners to leave out.
// Contract: a.size() == b.size() and skip empty or of that size (else invalid_argument).
TangentComparison compare_tangents(std::span<const glm::vec4> a, std::span<const glm::vec4> b,
                                   std::span<const std::uint8_t> skip = {});

} // namespace sherpa::scene
