#pragma once
// JSON views of engine data, shared by CLI subcommands.
#include <nlohmann/json.hpp>

#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/scene.h>
#include <sherpa/scene/usage_report.h>

namespace sherpa::cli {

nlohmann::json aabb_json(const core::Aabb& box);
nlohmann::json usage_json(const scene::Scene& scene, const scene::UsageReport& report);
// EXT_mesh_gpu_instancing: per instanced node its rows (in the file, drawn) and
// accessors; totals, and the drawn instances (of the displayed scene) they make.
nlohmann::json gpu_instancing_json(const scene::Scene& scene);
// The `sherpa-cli info --json` object.
nlohmann::json scene_info_json(const scene::Scene& scene);
// A culling pass's statistics and the matrix it culled against
// ("cull_view_projection", column-major), for `cull --json` and `render --report`.
nlohmann::json cull_stats_json(const scene::CullStats& stats);

} // namespace sherpa::cli
