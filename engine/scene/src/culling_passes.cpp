#include <sherpa/scene/culling_passes.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

namespace sherpa::scene {

BoxesSoA instance_boxes(const Scene& scene) {
    std::vector<core::Aabb> boxes(scene.instances.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = scene.instances[i].world_bounds;
    BoxesSoA soa;
    soa.assign(boxes);
    return soa;
}

CullInput prepare_cull_input(const Scene& scene) {
    CullInput in;
    in.boxes = instance_boxes(scene);
    const std::size_t n = scene.instances.size();
    in.group_of.resize(n);
    in.transparent.resize(n);
    // Dense group ids in (mesh, alpha mode, double sided) order, so that bucketing
    // by id yields the renderer's sorted draw order.
    std::vector<std::tuple<std::uint32_t, std::uint32_t, bool, std::uint32_t>> keyed(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const MeshInstance& inst = scene.instances[i];
        const MaterialInstance& m = scene.materials[inst.material_id];
        keyed[i] = {inst.mesh_id, static_cast<std::uint32_t>(m.alpha_mode), m.double_sided, i};
        in.transparent[i] = m.alpha_mode == AlphaMode::Blend ? 1 : 0;
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < n; ++k) {
        const auto& [mesh, alpha, two_sided, i] = keyed[k];
        if (k == 0 || std::get<0>(keyed[k - 1]) != mesh || std::get<1>(keyed[k - 1]) != alpha ||
            std::get<2>(keyed[k - 1]) != two_sided) {
            in.group_keys.push_back(
                DrawGroup{mesh, static_cast<AlphaMode>(alpha), two_sided, 0, 0});
            in.group_triangles.push_back(scene.meshes[mesh].triangle_count());
        }
        in.group_of[i] = static_cast<std::uint32_t>(in.group_keys.size() - 1);
    }
    return in;
}

PassResult cull_pass(const CullInput& input, const Frustum& frustum, glm::vec3 eye,
                     const CullOptions& options, std::string pass_name) {
    PassResult r;
    const auto t0 = std::chrono::steady_clock::now();
    const BoxesSoA& boxes = input.boxes;
    std::vector<std::uint8_t> visible(boxes.size());
    CullCounts counts =
        cull_boxes(frustum, boxes, options.method, options.simd, visible, options.threads);
    if (options.casters_only) { // blended instances are not in a shadow pass
        for (std::uint32_t i : boxes.invalid) counts.invalid -= input.transparent[i];
        for (std::uint32_t i = 0; i < visible.size(); ++i) {
            if (!input.transparent[i]) continue;
            --counts.tested;
            --(visible[i] ? counts.visible : counts.culled);
            visible[i] = 0;
        }
    }
    // Counting sort of visible opaque instances by group id: linear time.
    const std::size_t groups = input.group_keys.size();
    std::vector<std::uint32_t> offset(groups + 1, 0);
    for (std::uint32_t i = 0; i < visible.size(); ++i) {
        if (!visible[i]) continue;
        if (input.transparent[i])
            r.visible_transparent.push_back(i);
        else
            ++offset[input.group_of[i] + 1];
    }
    for (std::size_t g = 0; g < groups; ++g) offset[g + 1] += offset[g];
    r.draw_order.resize(offset[groups]);
    std::vector<std::uint32_t> cursor(offset.begin(), offset.end() - 1);
    for (std::uint32_t i = 0; i < visible.size(); ++i)
        if (visible[i] && !input.transparent[i]) r.draw_order[cursor[input.group_of[i]]++] = i;
    r.visible_opaque = r.draw_order;
    std::uint64_t triangles = 0;
    for (std::size_t g = 0; g < groups; ++g) {
        const std::uint32_t count = offset[g + 1] - offset[g];
        if (count == 0) continue;
        DrawGroup d = input.group_keys[g];
        d.first = offset[g];
        d.count = count;
        r.groups.push_back(d);
        triangles += std::uint64_t{count} * input.group_triangles[g];
    }
    // Transparents back to front by distance from the eye to the box centre; each
    // is its own draw, in that order.
    std::vector<std::pair<float, std::uint32_t>> by_depth;
    by_depth.reserve(r.visible_transparent.size());
    for (std::uint32_t i : r.visible_transparent) {
        const glm::vec3 d = boxes.box(i).center() - eye;
        by_depth.emplace_back(-glm::dot(d, d), i);
    }
    std::sort(by_depth.begin(), by_depth.end());
    for (std::size_t k = 0; k < by_depth.size(); ++k) {
        const std::uint32_t i = by_depth[k].second;
        r.visible_transparent[k] = i;
        DrawGroup d = input.group_keys[input.group_of[i]];
        d.first = i;
        d.count = 1;
        r.groups.push_back(d);
        triangles += input.group_triangles[input.group_of[i]];
    }
    CullStats& s = r.stats;
    s.cpu_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    s.pass = std::move(pass_name);
    s.method = options.method;
    s.simd = std::min(options.simd, core::best_simd_level());
    s.total = counts.tested; // every instance of the pass (casters only for cascades)
    s.tested = counts.tested;
    s.visible = counts.visible;
    s.culled = counts.culled;
    s.invalid = counts.invalid;
    s.draw_calls = r.groups.size();
    s.triangles = triangles;
    if (options.count_false_positives) {
        std::vector<std::uint8_t> exact(boxes.size());
        cull_boxes(frustum, boxes, CullMethod::Exact, options.simd, exact, options.threads);
        std::int64_t fp = 0;
        for (std::size_t i = 0; i < exact.size(); ++i) fp += (visible[i] && !exact[i]) ? 1 : 0;
        s.false_positives = fp;
    }
    return r;
}

} // namespace sherpa::scene
