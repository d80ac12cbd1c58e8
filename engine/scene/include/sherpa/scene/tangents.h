#pragma once
// Tangent-space generation: exact MikkTSpace and two cheaper alternatives, computed per
// face corner over plain spans. mesh_tangents.h writes the results into meshes.
//
// Conventions: uvs are glTF texture coordinates (origin top-left, v down). The returned
// tangents follow glTF: xyz tangent (direction of increasing u), w = +1/-1 such that
// bitangent = cross(normal, tangent.xyz) * w points towards decreasing v ("up" in the image).
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

#include <glm/glm.hpp>

namespace sherpa::scene {

enum class TangentMethod : std::uint8_t {
    MikkTSpace,       // exact MikkTSpace, one tangent per corner (vertices split where needed)
    MikkTSpaceWelded, // MikkTSpace, then each vertex keeps the last corner written (Himalaya)
    Lengyel,          // per-triangle dP/du summed per vertex, Gram-Schmidt (nvpro's loader)
};
inline constexpr std::array<TangentMethod, 3> kAllTangentMethods{
    TangentMethod::MikkTSpace, TangentMethod::MikkTSpaceWelded, TangentMethod::Lengyel};
std::string_view to_string(TangentMethod m);
// Accepts the names to_string returns ("mikktspace", "mikktspace-welded", "lengyel").
bool parse_tangent_method(std::string_view name, TangentMethod& out);

// Why a corner's tangent could not come from the method, so that a fallback tangent
// (unit, orthogonal to the normal, w = +1) stands in. The cause is read from the corner's
// own triangle, most fundamental first.
enum class TangentFallback : std::uint8_t {
    None = 0,
    NonFiniteInput,     // NaN/Inf in the triangle's positions or uvs, or in the corner's normal
    InvalidNormal,      // the corner's normal has zero length
    DegeneratePosition, // zero-area triangle: coincident or collinear corners
    DegenerateUv,       // zero-area triangle in uv space
    ZeroResult,         // inputs were fine but the contributions cancelled out
};
inline constexpr std::size_t kTangentFallbackCauses = 6;
std::string_view to_string(TangentFallback f);

struct TangentStats {
    // Corners per fallback cause; index by TangentFallback ([None] counts the corners the
    // method computed itself).
    std::array<std::uint64_t, kTangentFallbackCauses> corners{};
    // Corners whose value, before the fallback guard, was NaN/Inf: what the method
    // yields unguarded. The returned tangents are always finite.
    std::uint64_t nonfinite_before_guard = 0;
    // Vertices whose normal is further than kNormalUnitTolerance from unit length and
    // was rescaled before use.
    std::uint64_t rescaled_normals = 0;

    std::uint64_t fallbacks() const;
    std::uint64_t count(TangentFallback f) const { return corners[static_cast<std::size_t>(f)]; }
    TangentStats& operator+=(const TangentStats& o);
};

// A normal counts as unit (and is used as is, exactly like the reference) when
// | |n|^2 - 1 | <= this; beyond it, it is rescaled before projecting onto its plane.
inline constexpr float kNormalUnitTolerance = 2e-3f;

// One triangle list over one vertex set.
// Contract: positions, normals and uvs have the same size; indices.size() is a multiple
// of 3 and every index is below positions.size(). Broken contracts throw
// std::invalid_argument; any float values (NaN, Inf, zero normals) are accepted.
struct TangentInput {
    std::span<const glm::vec3> positions;
    std::span<const glm::vec3> normals;
    std::span<const glm::vec2> uvs; // the set the normal texture samples, glTF orientation
    std::span<const std::uint32_t> indices;
};

// Scratch memory that calls may share to avoid reallocating (and re-faulting) their
// buffers: results never depend on what a workspace held before. Not thread-safe: one
// per thread.
class TangentWorkspace {
public:
    TangentWorkspace();
    ~TangentWorkspace();
    TangentWorkspace(TangentWorkspace&&) noexcept;
    TangentWorkspace& operator=(TangentWorkspace&&) noexcept;
    struct Buffers;
    Buffers& buffers() { return *buffers_; }

private:
    std::unique_ptr<Buffers> buffers_;
};

// Computes one tangent per corner (out.size() == indices.size()). `fallbacks`, when not
// empty, must have the same size and receives each corner's TangentFallback. Without a
// workspace the call allocates its own scratch, proportional to the input.
TangentStats generate_corner_tangents(const TangentInput& input, TangentMethod method,
                                      std::span<glm::vec4> out,
                                      std::span<TangentFallback> fallbacks = {},
                                      TangentWorkspace* workspace = nullptr);

} // namespace sherpa::scene
