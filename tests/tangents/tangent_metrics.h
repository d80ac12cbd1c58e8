#pragma once
// Angle errors between tangents and their summary statistics, shared by tangent tests,
// the benchmark and the accuracy report.
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sherpa::test {

// Angle in degrees between the xyz parts, in double and via atan2 so tiny angles are exact.
inline double angle_degrees(const glm::vec4& a, const glm::vec4& b) {
    const glm::dvec3 x(a), y(b);
    return glm::degrees(std::atan2(glm::length(glm::cross(x, y)), glm::dot(x, y)));
}

struct ErrorStats {
    double mean = 0.0, p99 = 0.0, max = 0.0;
    std::size_t count = 0;
};

inline ErrorStats summarize(std::vector<double> values) {
    ErrorStats s;
    s.count = values.size();
    if (values.empty()) return s;
    double sum = 0.0;
    for (double v : values) sum += v;
    s.mean = sum / static_cast<double>(values.size());
    const std::size_t k =
        std::min(values.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * values.size())) - 1);
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    s.p99 = values[k];
    s.max = *std::max_element(values.begin(), values.end());
    return s;
}

} // namespace sherpa::test
