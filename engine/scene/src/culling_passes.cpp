#include <sherpa/scene/culling_passes.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

namespace sherpa {

BoxesSoA instance_boxes(const Scene& scene) {
    std::vector<Aabb> boxes(scene.instances.size());
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

PassResult cull_pass(const Scene& scene, const CullInput& input, const Frustum& frustum,
                     glm::vec3 eye, const CullOptions& options, std::string pass_name) {
    PassResult r;
    const auto t0 = std::chrono::steady_clock::now();
    const BoxesSoA& boxes = input.boxes;
    std::vector<std::uint8_t> visible(boxes.size());
    const CullCounts counts =
        cull_boxes(frustum, boxes, options.method, options.simd, visible, options.threads);
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
    s.simd = std::min(options.simd, best_simd_level());
    s.total = scene.instances.size();
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

std::vector<glm::mat4> cascade_view_projections(const CameraSpec& camera, glm::vec3 light_direction,
                                                const Aabb& scene_bounds,
                                                const CascadeSetup& setup) {
    std::vector<glm::mat4> out;
    if (setup.count == 0 || !scene_bounds.valid() || glm::length(light_direction) == 0.0f)
        return out;
    const glm::vec3 dir = glm::normalize(light_direction);
    // Far end: the camera's far plane, else the farthest scene corner.
    float far_d = camera.far_plane > 0.0f ? camera.far_plane : 0.0f;
    if (far_d == 0.0f)
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 p{(c & 1) ? scene_bounds.max.x : scene_bounds.min.x,
                              (c & 2) ? scene_bounds.max.y : scene_bounds.min.y,
                              (c & 4) ? scene_bounds.max.z : scene_bounds.min.z};
            far_d = std::max(far_d, glm::length(p - camera.eye));
        }
    if (setup.max_distance > 0.0f) far_d = std::min(far_d, setup.max_distance);
    const float near_d = camera.near_plane;
    far_d = std::max(far_d, near_d * 2.0f);
    // Camera basis and the slice corners at distance d along the view direction.
    const glm::vec3 fwd = glm::normalize(camera.target - camera.eye);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, camera.up));
    const glm::vec3 up = glm::cross(right, fwd);
    const float ty = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f), tx = ty * camera.aspect;
    const glm::vec3 light_up = std::abs(dir.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::mat4 light_view = glm::lookAt(glm::vec3(0.0f), dir, light_up);
    float scene_max_z = -INFINITY; // toward the light is +Z in light view space
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 p{(c & 1) ? scene_bounds.max.x : scene_bounds.min.x,
                          (c & 2) ? scene_bounds.max.y : scene_bounds.min.y,
                          (c & 4) ? scene_bounds.max.z : scene_bounds.min.z};
        scene_max_z = std::max(scene_max_z, (light_view * glm::vec4(p, 1.0f)).z);
    }
    float prev = near_d;
    for (std::uint32_t i = 1; i <= setup.count; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(setup.count);
        const float split = setup.lambda * near_d * std::pow(far_d / near_d, t) +
                            (1.0f - setup.lambda) * (near_d + (far_d - near_d) * t);
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        for (float d : {prev, split})
            for (int c = 0; c < 4; ++c) {
                const glm::vec3 p = camera.eye + fwd * d +
                                    right * (((c & 1) ? 1.0f : -1.0f) * tx * d) +
                                    up * (((c & 2) ? 1.0f : -1.0f) * ty * d);
                const glm::vec3 q = glm::vec3(light_view * glm::vec4(p, 1.0f));
                lo = glm::min(lo, q);
                hi = glm::max(hi, q);
            }
        hi.z = std::max(hi.z, scene_max_z); // extend toward the light: off-screen casters
        const glm::vec2 c = 0.5f * (glm::vec2(lo) + glm::vec2(hi));
        const glm::vec2 half = glm::max(0.5f * (glm::vec2(hi) - glm::vec2(lo)), glm::vec2(1e-4f));
        // View-space depth runs along -Z: near = -hi.z, far = -lo.z.
        const glm::mat4 proj =
            orthographic_reverse_z(half.x, half.y, -hi.z, std::max(-lo.z, -hi.z + 1e-4f));
        out.push_back(proj * glm::translate(glm::mat4(1.0f), glm::vec3(-c, 0.0f)) * light_view);
        prev = split;
    }
    return out;
}

} // namespace sherpa
