#include <sherpa/scene/tangent_compare.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace sherpa::scene {

double tangent_angle_degrees(const glm::vec4& a, const glm::vec4& b) {
    const glm::dvec3 x(a), y(b);
    return glm::degrees(std::atan2(glm::length(glm::cross(x, y)), glm::dot(x, y)));
}

TangentComparison compare_tangents(std::span<const glm::vec4> a, std::span<const glm::vec4> b,
                                   std::span<const std::uint8_t> skip) {
    if (a.size() != b.size() || (!skip.empty() && skip.size() != a.size()))
        throw std::invalid_argument("compare_tangents: sizes differ");
    TangentComparison out;
    std::vector<double> angles;
    angles.reserve(a.size());
    double sum = 0.0;
    for (std::size_t c = 0; c < a.size(); ++c) {
        if (!skip.empty() && skip[c]) continue;
        const double angle = tangent_angle_degrees(a[c], b[c]);
        if (!std::isfinite(angle) || !std::isfinite(a[c].w) || !std::isfinite(b[c].w)) {
            ++out.nonfinite;
            continue;
        }
        angles.push_back(angle);
        sum += angle;
        out.flips += (a[c].w < 0.0f) != (b[c].w < 0.0f) ? 1 : 0;
    }
    out.corners = angles.size();
    if (angles.empty()) return out;
    out.mean = sum / static_cast<double>(angles.size());
    out.max = *std::max_element(angles.begin(), angles.end());
    // p99: the smallest value at or above 99% of the corners.
    const std::size_t rank = static_cast<std::size_t>(std::ceil(0.99 * double(angles.size()))) - 1;
    std::nth_element(angles.begin(), angles.begin() + static_cast<std::ptrdiff_t>(rank),
                     angles.end());
    out.p99 = angles[rank];
    return out;
}

} // namespace sherpa::scene
