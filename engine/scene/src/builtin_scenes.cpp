// builtin:default and builtin:grid?n=N, generated in code (no files).
#include "builtin_shapes.h"

#include <sherpa/scene/scene_loader.h>

#include <charconv>
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

namespace sherpa::scene {
namespace {

using detail::make_box;
using detail::make_plane;
using detail::make_torus;
using detail::make_uv_sphere;

// Incremental builder that keeps the source counts consistent with what it adds.
struct SceneBuilder {
    Scene& s;

    std::int32_t add_mesh(Mesh geometry, std::uint32_t material, std::string name) {
        const auto group = static_cast<std::uint32_t>(s.mesh_primitives.size());
        geometry.group_id = group;
        geometry.primitive_index = 0;
        geometry.name = name + "#0";
        geometry.material_id = material;
        PrimitiveInfo info;
        info.mesh = group;
        info.vertices = geometry.source_vertex_count;
        info.indices = static_cast<std::uint32_t>(geometry.indices.size());
        info.triangles = geometry.source_triangle_count;
        info.material = static_cast<std::int32_t>(material);
        info.engine_mesh = static_cast<std::int32_t>(s.meshes.size());
        for (VertexAttribute a : kAllVertexAttributes) // what the generator wrote
            if (geometry.provenance_of(a) == Provenance::Authored)
                info.file_attributes.emplace_back(gltf_name(a));
        s.counts.vertices += info.vertices;
        s.counts.triangles += info.triangles;
        s.mesh_primitives.push_back({info.engine_mesh});
        s.primitives.push_back(std::move(info));
        s.meshes.push_back(std::move(geometry));
        return static_cast<std::int32_t>(group);
    }
    std::uint32_t add_node(std::string name, std::int32_t parent, glm::vec3 t,
                           glm::quat r = {1, 0, 0, 0}, glm::vec3 sc = glm::vec3(1.0f)) {
        Node n;
        n.name = std::move(name);
        n.parent = parent;
        n.translation = t;
        n.rotation = r;
        n.scale = sc;
        const auto id = static_cast<std::uint32_t>(s.nodes.size());
        s.nodes.push_back(std::move(n));
        if (parent >= 0) s.nodes[static_cast<std::size_t>(parent)].children.push_back(id);
        return id;
    }
    std::int32_t add_texture(ImageRecord image, std::uint8_t role) {
        s.images.push_back(std::move(image));
        TextureRecord t;
        t.name = s.images.back().name;
        t.image = static_cast<std::int32_t>(s.images.size() - 1);
        t.sampler = 0;
        t.roles = role;
        s.textures.push_back(t);
        return static_cast<std::int32_t>(s.textures.size() - 1);
    }
    std::uint32_t add_material(MaterialInstance m) {
        m.gltf_index = static_cast<std::int32_t>(s.materials.size());
        s.materials.push_back(std::move(m));
        return static_cast<std::uint32_t>(s.materials.size() - 1);
    }
    void finish() {
        s.counts.scenes = s.scenes.size();
        s.counts.nodes = s.nodes.size();
        s.counts.meshes = s.mesh_primitives.size();
        s.counts.primitives = s.primitives.size();
        s.counts.materials = s.materials.size();
        s.counts.textures = s.textures.size();
        s.counts.images = s.images.size();
        s.counts.samplers = s.samplers.size();
        s.counts.lights = s.lights.size();
        s.counts.cameras = s.cameras.size();
    }
};

struct Materials {
    std::uint32_t ground, bumpy, metal, glass, mask;
};

Materials add_materials(SceneBuilder& b) {
    b.s.samplers.push_back(SamplerDesc{});
    const std::int32_t checker = b.add_texture(detail::make_checker(256, 8), kRoleColor);
    const std::int32_t bumps = b.add_texture(detail::make_bump_normal_map(256), kRoleNormal);
    const std::int32_t discs = b.add_texture(detail::make_disc_mask(256, 4), kRoleColor);
    Materials ids{};
    MaterialInstance m;
    m.name = "ground";
    m.base_color.texture = checker;
    m.metallic_factor = 0.0f;
    m.roughness_factor = 0.9f;
    ids.ground = b.add_material(m);
    m = {};
    m.name = "bumpy";
    m.base_color_factor = {0.9f, 0.45f, 0.2f, 1.0f};
    m.normal.texture = bumps;
    m.metallic_factor = 0.1f;
    m.roughness_factor = 0.45f;
    ids.bumpy = b.add_material(m);
    m = {};
    m.name = "metal";
    m.base_color_factor = {0.95f, 0.8f, 0.45f, 1.0f};
    m.metallic_factor = 1.0f;
    m.roughness_factor = 0.3f;
    ids.metal = b.add_material(m);
    m = {};
    m.name = "glass (alpha blend)";
    m.base_color_factor = {0.3f, 0.6f, 1.0f, 0.35f};
    m.alpha_mode = AlphaMode::Blend;
    m.double_sided = true;
    m.metallic_factor = 0.0f;
    m.roughness_factor = 0.1f;
    ids.glass = b.add_material(m);
    m = {};
    m.name = "perforated (alpha mask)";
    m.base_color.texture = discs;
    m.alpha_mode = AlphaMode::Mask;
    m.alpha_cutoff = 0.5f;
    m.double_sided = true;
    m.metallic_factor = 0.0f;
    m.roughness_factor = 0.6f;
    ids.mask = b.add_material(m);
    return ids;
}

void add_sun_and_camera(SceneBuilder& b, std::uint32_t root, glm::vec3 eye, glm::vec3 target) {
    Light sun;
    sun.name = "sun";
    sun.intensity = 3.0f;
    b.s.lights.push_back(sun);
    const glm::vec3 sun_dir = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    const std::uint32_t sun_node =
        b.add_node("sun", static_cast<std::int32_t>(root), glm::vec3(0.0f),
                   glm::rotation(glm::vec3(0, 0, -1), sun_dir));
    b.s.nodes[sun_node].light = 0;
    Camera cam;
    cam.name = "overview";
    cam.yfov = glm::radians(50.0f);
    b.s.cameras.push_back(cam);
    const glm::mat4 look = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
    const std::uint32_t cam_node =
        b.add_node("camera", static_cast<std::int32_t>(root), eye, glm::quat_cast(look));
    b.s.nodes[cam_node].camera = 0;
}

void build_default(SceneBuilder& b) {
    const Materials mat = add_materials(b);
    const std::int32_t ground = b.add_mesh(make_plane(40.0f, 8, 10.0f), mat.ground, "ground");
    const std::int32_t sphere =
        b.add_mesh(make_uv_sphere(1.0f, 48, 24), mat.bumpy, "sphere (UV seam)");
    const std::int32_t torus =
        b.add_mesh(make_torus(0.9f, 0.35f, 64, 24), mat.bumpy, "torus (mirrored UVs)");
    const std::int32_t box =
        b.add_mesh(make_box(glm::vec3(0.8f)), mat.bumpy, "box (mirrored faces)");
    const std::int32_t glass = b.add_mesh(make_uv_sphere(1.0f, 32, 16), mat.glass, "glass sphere");
    const std::int32_t perforated =
        b.add_mesh(make_box(glm::vec3(0.9f)), mat.mask, "perforated box");
    const std::int32_t small_sphere =
        b.add_mesh(make_uv_sphere(0.35f, 16, 8), mat.metal, "small sphere");
    const std::int32_t small_torus =
        b.add_mesh(make_torus(0.3f, 0.12f, 16, 8), mat.metal, "small torus");
    const std::int32_t small_box = b.add_mesh(make_box(glm::vec3(0.3f)), mat.metal, "small box");

    b.s.scenes.push_back({"builtin:default", {}});
    const std::uint32_t root = b.add_node("builtin:default", -1, glm::vec3(0.0f));
    b.s.scenes[0].roots.push_back(root);
    const auto r = static_cast<std::int32_t>(root);
    const std::uint32_t ground_node = b.add_node("ground", r, glm::vec3(0.0f));
    b.s.nodes[ground_node].mesh = ground;
    b.s.backdrop_nodes.push_back(ground_node); // 40 m wide: framing it hides the objects
    b.s.nodes[b.add_node("sphere", r, {-3.0f, 1.0f, 0.0f})].mesh = sphere;
    b.s.nodes[b.add_node("torus", r, {0.0f, 1.0f, 0.0f},
                         glm::angleAxis(glm::radians(60.0f), glm::vec3(1, 0, 0)))]
        .mesh = torus;
    b.s.nodes[b.add_node("box", r, {3.0f, 0.8f, 0.0f},
                         glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0)))]
        .mesh = box;
    b.s.nodes[b.add_node("glass sphere", r, {-1.5f, 1.0f, 2.8f})].mesh = glass;
    b.s.nodes[b.add_node("perforated box", r, {1.8f, 0.9f, 2.8f})].mesh = perforated;
    const std::uint32_t grid = b.add_node("instance grid", r, {0.0f, 0.0f, -5.0f});
    const std::int32_t shapes[3] = {small_sphere, small_torus, small_box};
    for (int z = 0; z < 6; ++z)
        for (int x = 0; x < 8; ++x) {
            const int k = z * 8 + x;
            const std::uint32_t n =
                b.add_node("grid " + std::to_string(k), static_cast<std::int32_t>(grid),
                           {(x - 3.5f) * 1.2f, 0.4f, -z * 1.2f});
            b.s.nodes[n].mesh = shapes[k % 3];
        }
    add_sun_and_camera(b, root, {7.0f, 5.0f, 9.0f}, {0.0f, 0.5f, -1.0f});
}

void build_grid(SceneBuilder& b, std::uint64_t n) {
    const Materials mat = add_materials(b);
    const std::int32_t shapes[3] = {b.add_mesh(make_uv_sphere(0.4f, 12, 6), mat.metal, "sphere"),
                                    b.add_mesh(make_torus(0.3f, 0.12f, 12, 6), mat.bumpy, "torus"),
                                    b.add_mesh(make_box(glm::vec3(0.35f)), mat.metal, "box")};
    b.s.scenes.push_back({"builtin:grid", {}});
    const std::uint32_t root = b.add_node("grid", -1, glm::vec3(0.0f));
    b.s.scenes[0].roots.push_back(root);
    const auto side = static_cast<std::uint64_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    constexpr float spacing = 1.5f;
    b.s.nodes.reserve(n + 3);
    b.s.nodes[root].children.reserve(n);
    for (std::uint64_t i = 0; i < n; ++i) {
        const float x =
            (static_cast<float>(i % side) - 0.5f * static_cast<float>(side - 1)) * spacing;
        const float z =
            (static_cast<float>(i / side) - 0.5f * static_cast<float>(side - 1)) * spacing;
        // Small per-instance rotation so instances are not all axis-aligned boxes.
        const glm::quat rot = glm::angleAxis(static_cast<float>(i % 7) * 0.4f, glm::vec3(0, 1, 0));
        const std::uint32_t id =
            b.add_node("i" + std::to_string(i), static_cast<std::int32_t>(root), {x, 0.5f, z}, rot);
        b.s.nodes[id].mesh = shapes[i % 3];
    }
    const float half = 0.5f * static_cast<float>(side) * spacing;
    add_sun_and_camera(b, root, {half * 0.8f, half * 0.6f + 4.0f, half * 1.2f + 4.0f},
                       glm::vec3(0.0f));
}

} // namespace

LoadResult make_builtin_scene(std::string_view spec) {
    const auto t0 = std::chrono::steady_clock::now();
    auto scene = std::make_unique<Scene>();
    scene->source = std::string(spec);
    SceneBuilder b{*scene};
    const std::string_view name = spec.substr(8); // after "builtin:"
    if (name == "default") {
        build_default(b);
    } else if (name.rfind("grid?n=", 0) == 0) {
        const std::string_view num = name.substr(7);
        std::uint64_t n = 0;
        const auto [end, ec] = std::from_chars(num.data(), num.data() + num.size(), n);
        constexpr std::uint64_t kMaxInstances = 4'000'000;
        if (ec != std::errc{} || end != num.data() + num.size() || n == 0 || n > kMaxInstances)
            return {nullptr, std::string(spec) + ": n must be an integer in [1, " +
                                 std::to_string(kMaxInstances) + "]"};
        build_grid(b, n);
    } else {
        return {nullptr, std::string(spec) +
                             ": unknown built-in scene (have builtin:default, builtin:grid?n=N)"};
    }
    b.finish();
    std::string error;
    if (!select_scene(*scene, 0, error)) return {nullptr, std::string(spec) + ": " + error};
    scene->process_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return {std::move(scene), {}};
}

} // namespace sherpa::scene
