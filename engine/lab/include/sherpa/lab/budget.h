#pragma once
// "Model no more than the scene needs", shown: GPU bytes per category as Sherpa stores
// them against the 56-byte unified vertex and against what the materials and views
// need; textures whose level 0 no view of a camera path samples; attributes the file
// has that nothing reads. What `sherpa-cli budget` prints.
#include <cstdint>
#include <string>
#include <vector>

#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/scene.h>

namespace sherpa::lab {

// Bytes of one category three ways: a unified layout (every vertex 56 bytes, textures
// RGBA8 with mips), as Sherpa stores it (used streams only, BC7/BC5 with mips), and
// what is needed (textures at the largest resolution any view samples).
struct BudgetCategory {
    std::string name; // vertex streams, indices, textures, materials, instances
    std::uint64_t unified = 0, stored = 0, needed = 0;
};

// A texture whose level 0 no view samples: with each instance using it seen from the
// closest view of the path that sees it, 95% of their surface (by world area) puts at
// least `texels_per_pixel` (>= 2) texels on a pixel, so the sampler reads level 0 on at
// most 5% of it and a texture `reduce` times smaller per side would look the same there.
struct OversizedTexture {
    std::int32_t image = -1;
    std::string where;
    std::uint32_t width = 0, height = 0;
    double texels_per_pixel = 0.0;
    std::uint32_t reduce = 1; // a power of two
};

// An attribute of a primitive that nothing draws with.
struct UnreadAttribute {
    std::uint32_t mesh = 0, primitive = 0;
    std::string attribute; // glTF semantic
    std::string reason;
};

struct BudgetReport {
    std::vector<BudgetCategory> categories;
    std::vector<OversizedTexture> oversized;
    std::vector<UnreadAttribute> unread;
    std::vector<std::string> notes;
};

struct BudgetOptions {
    // Empty: the 16 views of camera_path(scene.bounds, 32) (families.h) that orbit
    // outside the bounds, each framing the whole scene.
    std::vector<scene::CameraSpec> views;
    std::uint32_t viewport_height = 2160;
};

BudgetReport build_budget(const scene::Scene& scene, const BudgetOptions& options = {});

} // namespace sherpa::lab
