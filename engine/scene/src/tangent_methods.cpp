// Method dispatch, the cheaper alternatives to exact MikkTSpace, and the guard that turns
// every corner a method could not compute into a finite tangent orthogonal to the normal.
#include <stdexcept>
#include <string>

#include "tangent_internal.h"

namespace sherpa::scene {

std::string_view to_string(TangentMethod m) {
    switch (m) {
    case TangentMethod::MikkTSpace:
        return "mikktspace";
    case TangentMethod::MikkTSpaceWelded:
        return "mikktspace-welded";
    case TangentMethod::Lengyel:
        return "lengyel";
    }
    return "unknown";
}

bool parse_tangent_method(std::string_view name, TangentMethod& out) {
    for (TangentMethod m : kAllTangentMethods)
        if (to_string(m) == name) {
            out = m;
            return true;
        }
    return false;
}

std::string_view to_string(TangentFallback f) {
    switch (f) {
    case TangentFallback::None:
        return "none";
    case TangentFallback::NonFiniteInput:
        return "nonfinite_input";
    case TangentFallback::InvalidNormal:
        return "invalid_normal";
    case TangentFallback::DegeneratePosition:
        return "degenerate_position";
    case TangentFallback::DegenerateUv:
        return "degenerate_uv";
    case TangentFallback::ZeroResult:
        return "zero_result";
    }
    return "unknown";
}

std::uint64_t TangentStats::fallbacks() const {
    std::uint64_t total = 0;
    for (std::size_t i = 1; i < corners.size(); ++i) total += corners[i];
    return total;
}

TangentWorkspace::TangentWorkspace() : buffers_(std::make_unique<Buffers>()) {}
TangentWorkspace::~TangentWorkspace() = default;
TangentWorkspace::TangentWorkspace(TangentWorkspace&&) noexcept = default;
TangentWorkspace& TangentWorkspace::operator=(TangentWorkspace&&) noexcept = default;

TangentStats& TangentStats::operator+=(const TangentStats& o) {
    for (std::size_t i = 0; i < corners.size(); ++i) corners[i] += o.corners[i];
    nonfinite_before_guard += o.nonfinite_before_guard;
    rescaled_normals += o.rescaled_normals;
    return *this;
}

namespace tangent_detail {

void lengyel_corners(const TangentInput& in, std::span<glm::vec4> out,
                     std::span<std::uint8_t> assigned, std::uint64_t& rescaled_normals,
                     std::uint64_t& nonfinite_unguarded, MethodScratch& scratch) {
    // Per indexed vertex: the plain sum of its triangles' dP/du and dP/dv (no angle
    // weights, no welding by value, no handedness groups: the textbook method). A
    // triangle whose uv area is zero makes the textbook formula divide by zero; it is
    // left out here, and the corners it would have poisoned are counted.
    const std::size_t vertex_count = in.positions.size();
    auto& sdir_sum = scratch.sdir_sum;
    auto& tdir_sum = scratch.tdir_sum;
    // Per vertex: bit 0 poisoned by a non-finite triangle, bit 1 already counted.
    auto& state = scratch.flags;
    sdir_sum.assign(vertex_count, glm::vec3(0.0f));
    tdir_sum.assign(vertex_count, glm::vec3(0.0f));
    state.assign(vertex_count, 0);
    for (std::size_t c = 0; c < in.indices.size(); c += 3) {
        const std::uint32_t i0 = in.indices[c], i1 = in.indices[c + 1], i2 = in.indices[c + 2];
        const glm::vec3 e1 = in.positions[i1] - in.positions[i0];
        const glm::vec3 e2 = in.positions[i2] - in.positions[i0];
        const glm::vec2 duv1 = in.uvs[i1] - in.uvs[i0], duv2 = in.uvs[i2] - in.uvs[i0];
        const float r = 1.0f / (duv1.x * duv2.y - duv2.x * duv1.y);
        const glm::vec3 sdir = (e1 * duv2.y - e2 * duv1.y) * r;
        const glm::vec3 tdir = (e2 * duv1.x - e1 * duv2.x) * r;
        if (!finite(sdir) || !finite(tdir)) {
            state[i0] |= 1;
            state[i1] |= 1;
            state[i2] |= 1;
            continue;
        }
        for (std::uint32_t v : {i0, i1, i2}) {
            sdir_sum[v] += sdir;
            tdir_sum[v] += tdir;
        }
    }
    for (std::size_t c = 0; c < in.indices.size(); ++c) {
        const std::uint32_t v = in.indices[c];
        bool rescaled = false;
        const glm::vec3 n = projection_normal(in.normals[v], rescaled);
        if (!(state[v] & 2)) {
            state[v] |= 2;
            rescaled_normals += rescaled ? 1 : 0;
        }
        nonfinite_unguarded += state[v] & 1;
        const glm::vec3 t = sdir_sum[v] - n * dot3(n, sdir_sum[v]);
        if (!not_zero(t) || !finite(t) || !usable_normal(n)) {
            out[c] = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
            assigned[c] = 0;
            continue;
        }
        // Handedness in uv space with v up is negated for glTF's v down.
        const float w = dot3(glm::cross(n, t), tdir_sum[v]) < 0.0f ? 1.0f : -1.0f;
        out[c] = glm::vec4(normalized(t), w);
        assigned[c] = 1;
    }
}

namespace {

// Cause of a corner's failure, read from its own triangle (see TangentFallback).
TangentFallback classify(const TangentInput& in, std::size_t corner) {
    const std::size_t base = corner - corner % 3;
    const std::uint32_t i0 = in.indices[base], i1 = in.indices[base + 1], i2 = in.indices[base + 2];
    const glm::vec3 n = in.normals[in.indices[corner]];
    if (!finite(in.positions[i0]) || !finite(in.positions[i1]) || !finite(in.positions[i2]) ||
        !finite(in.uvs[i0]) || !finite(in.uvs[i1]) || !finite(in.uvs[i2]) || !finite(n))
        return TangentFallback::NonFiniteInput;
    if (dot3(n, n) == 0.0f) return TangentFallback::InvalidNormal;
    if (zero_area(in.positions[i0], in.positions[i1], in.positions[i2]))
        return TangentFallback::DegeneratePosition;
    const glm::vec2 t1 = in.uvs[i1] - in.uvs[i0], t2 = in.uvs[i2] - in.uvs[i0];
    if (!tangent_detail::not_zero(t1.x * t2.y - t1.y * t2.x)) return TangentFallback::DegenerateUv;
    return TangentFallback::ZeroResult;
}

// A unit vector orthogonal to `n` (unit), from Duff et al., "Building an Orthonormal
// Basis, Revisited" (JCGT 2017): continuous except at n.z == 0 flips, never degenerate.
glm::vec3 any_perpendicular(const glm::vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    return glm::vec3(1.0f + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x);
}

// The fallback tangent: the first usable candidate (the method's own value, the
// triangle's dP/du, the edge leaving the corner) made orthogonal to the normal, or any
// perpendicular. The normal is the corner's, else the triangle's geometric one.
glm::vec4 fallback_tangent(const TangentInput& in, std::size_t corner, const glm::vec4& computed,
                           bool use_computed) {
    const std::size_t base = corner - corner % 3;
    const std::uint32_t i0 = in.indices[base], i1 = in.indices[base + 1], i2 = in.indices[base + 2];
    const glm::vec3 d1 = in.positions[i1] - in.positions[i0];
    const glm::vec3 d2 = in.positions[i2] - in.positions[i0];
    glm::vec3 n = in.normals[in.indices[corner]];
    if (!finite(n) || !not_zero(n)) n = glm::cross(d1, d2);
    const bool has_normal = finite(n) && not_zero(n);
    if (has_normal) n = normalized(n);

    const glm::vec2 t1 = in.uvs[i1] - in.uvs[i0], t2 = in.uvs[i2] - in.uvs[i0];
    const glm::vec3 candidates[3] = {
        use_computed ? glm::vec3(computed) : glm::vec3(0.0f), t2.y * d1 - t1.y * d2,
        in.positions[in.indices[base + (corner + 1) % 3]] - in.positions[in.indices[corner]]};
    for (const glm::vec3& candidate : candidates) {
        if (!finite(candidate)) continue;
        const glm::vec3 t = has_normal ? candidate - n * dot3(n, candidate) : candidate;
        if (!not_zero(t)) continue;
        const glm::vec3 unit = normalized(t);
        if (finite(unit) && dot3(unit, unit) > 0.5f) return glm::vec4(unit, 1.0f);
    }
    return glm::vec4(has_normal ? any_perpendicular(n) : glm::vec3(1.0f, 0.0f, 0.0f), 1.0f);
}

} // namespace
} // namespace tangent_detail

TangentStats generate_corner_tangents(const TangentInput& in, TangentMethod method,
                                      std::span<glm::vec4> out,
                                      std::span<TangentFallback> fallbacks,
                                      TangentWorkspace* workspace) {
    using namespace tangent_detail;
    if (in.normals.size() != in.positions.size() || in.uvs.size() != in.positions.size())
        throw std::invalid_argument("tangents: positions, normals and uvs differ in size");
    if (in.indices.size() % 3 != 0)
        throw std::invalid_argument("tangents: index count is not a multiple of 3");
    if (out.size() != in.indices.size() || (!fallbacks.empty() && fallbacks.size() != out.size()))
        throw std::invalid_argument("tangents: output size differs from the index count");
    if (in.indices.size() >= (std::size_t(1) << 31))
        throw std::invalid_argument("tangents: more than 2^31 corners in one call");
    for (std::uint32_t i : in.indices)
        if (i >= in.positions.size())
            throw std::invalid_argument("tangents: index " + std::to_string(i) +
                                        " is out of range");

    TangentWorkspace local;
    TangentWorkspace::Buffers& buffers = (workspace ? *workspace : local).buffers();
    TangentStats stats;
    auto& assigned = buffers.method.assigned;
    assigned.resize(out.size());
    if (method == TangentMethod::Lengyel) {
        lengyel_corners(in, out, assigned, stats.rescaled_normals, stats.nonfinite_before_guard,
                        buffers.method);
    } else {
        mikktspace_corners(in, out, assigned, stats.rescaled_normals, buffers);
        if (method == TangentMethod::MikkTSpaceWelded) {
            // One tangent per indexed vertex: the last corner written wins.
            auto& last_corner = buffers.method.last_corner;
            last_corner.resize(in.positions.size());
            for (std::size_t c = 0; c < out.size(); ++c)
                last_corner[in.indices[c]] = static_cast<std::uint32_t>(c);
            for (std::size_t c = 0; c < out.size(); ++c) {
                const std::uint32_t winner = last_corner[in.indices[c]];
                out[c] = out[winner];
                assigned[c] = assigned[winner];
            }
        }
    }

    // The methods mark every corner they could not compute (see tangent_internal.h), so
    // the guard only visits those.
    for (std::size_t c = 0; c < out.size(); ++c) {
        TangentFallback cause = TangentFallback::None;
        if (!assigned[c]) {
            const glm::vec4 t = out[c];
            const bool t_finite = finite(t);
            if (!t_finite && method != TangentMethod::Lengyel) ++stats.nonfinite_before_guard;
            cause = classify(in, c);
            out[c] = fallback_tangent(in, c, t, t_finite && not_zero(glm::vec3(t)));
        }
        ++stats.corners[static_cast<std::size_t>(cause)];
        if (!fallbacks.empty()) fallbacks[c] = cause;
    }
    return stats;
}

} // namespace sherpa::scene
