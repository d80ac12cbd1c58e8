// glTF lights, cameras, nodes and scenes -> engine records; hierarchy validation.
#include "import_context.h"
#include "import_error.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

namespace sherpa::scene::detail {

namespace {

// Why a light cannot be shown, or "" when it can (KHR_lights_punctual's rules).
std::string light_problem(const tinygltf::Light& src, const Light& l) {
    if (src.type != "directional" && src.type != "point" && src.type != "spot")
        return ".type: \"" + src.type + "\" is not directional, point or spot";
    if (!std::isfinite(l.intensity) || l.intensity < 0.0f)
        return ".intensity: " + number_text(src.intensity) + " is negative or not finite";
    if (!core::is_finite(l.color) || l.color.x < 0.0f || l.color.y < 0.0f || l.color.z < 0.0f)
        return ".color: has negative or non-finite components";
    if (l.type == LightType::Spot &&
        !(l.inner_cone >= 0.0f && l.inner_cone < l.outer_cone && l.outer_cone <= 1.5707964f))
        return ".spot: innerConeAngle " + number_text(src.spot.innerConeAngle) +
               " and outerConeAngle " + number_text(src.spot.outerConeAngle) +
               " break 0 <= inner < outer <= pi/2";
    return {};
}

// Why a camera cannot be shown, or "" when it can. tinygltf reads an absent
// aspectRatio or zfar as 0: those mean "viewport aspect" and "infinite far plane".
std::string camera_problem(const tinygltf::Camera& src, const Camera& c) {
    if (c.type == CameraType::Perspective) {
        if (!(c.yfov > 0.0f && c.yfov < 3.14159f))
            return ".perspective.yfov: " + number_text(src.perspective.yfov) + " is not in (0, pi)";
        if (!(c.znear > 0.0f && std::isfinite(c.znear)))
            return ".perspective.znear: " + number_text(src.perspective.znear) + " is not > 0";
        if (c.zfar != 0.0f && !(c.zfar > c.znear))
            return ".perspective: zfar " + number_text(src.perspective.zfar) +
                   " is not greater than znear " + number_text(src.perspective.znear);
        if (!(c.aspect >= 0.0f) || !std::isfinite(c.aspect))
            return ".perspective.aspectRatio: " + number_text(src.perspective.aspectRatio) +
                   " is not > 0";
        return {};
    }
    if (!(c.xmag > 0.0f && c.ymag > 0.0f && std::isfinite(c.xmag) && std::isfinite(c.ymag)))
        return ".orthographic: xmag " + number_text(src.orthographic.xmag) + " and ymag " +
               number_text(src.orthographic.ymag) + " must be > 0";
    if (!(c.znear >= 0.0f && c.zfar > c.znear && std::isfinite(c.zfar)))
        return ".orthographic: zfar " + number_text(src.orthographic.zfar) +
               " is not greater than znear " + number_text(src.orthographic.znear);
    return {};
}

} // namespace

void import_lights_cameras(ImportContext& ctx) {
    const auto& model = ctx.model;
    Scene& scene = ctx.scene;
    ctx.light_skipped.assign(model.lights.size(), 0);
    for (std::size_t i = 0; i < model.lights.size(); ++i) {
        const auto& src = model.lights[i];
        Light l;
        l.name = src.name;
        l.type = src.type == "point"  ? LightType::Point
                 : src.type == "spot" ? LightType::Spot
                                      : LightType::Directional;
        if (src.color.size() == 3) l.color = {src.color[0], src.color[1], src.color[2]};
        l.intensity = static_cast<float>(src.intensity);
        l.range = static_cast<float>(src.range);
        l.inner_cone = static_cast<float>(src.spot.innerConeAngle);
        l.outer_cone = static_cast<float>(src.spot.outerConeAngle);
        if (const std::string problem = light_problem(src, l); !problem.empty()) {
            ctx.warn("extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]" + problem +
                     "; light skipped (not placed), the rest of the file is kept");
            ctx.light_skipped[i] = 1;
        }
        scene.lights.push_back(l);
    }
    ctx.camera_skipped.assign(model.cameras.size(), 0);
    for (std::size_t i = 0; i < model.cameras.size(); ++i) {
        const auto& src = model.cameras[i];
        const std::string where = "cameras[" + std::to_string(i) + "]";
        Camera c;
        c.name = src.name;
        std::string problem;
        if (src.type == "perspective") {
            c.type = CameraType::Perspective;
            c.yfov = static_cast<float>(src.perspective.yfov);
            c.aspect = static_cast<float>(src.perspective.aspectRatio);
            c.znear = static_cast<float>(src.perspective.znear);
            c.zfar = static_cast<float>(src.perspective.zfar);
            problem = camera_problem(src, c);
        } else if (src.type == "orthographic") {
            c.type = CameraType::Orthographic;
            c.xmag = static_cast<float>(src.orthographic.xmag);
            c.ymag = static_cast<float>(src.orthographic.ymag);
            c.znear = static_cast<float>(src.orthographic.znear);
            c.zfar = static_cast<float>(src.orthographic.zfar);
            problem = camera_problem(src, c);
        } else {
            problem = ".type: \"" + src.type + "\" is not perspective or orthographic";
        }
        if (!problem.empty()) {
            ctx.warn(where + problem +
                     "; camera skipped (not placed), the rest of the file is kept");
            ctx.camera_skipped[i] = 1;
        }
        scene.cameras.push_back(c);
    }
    scene.counts.lights = model.lights.size();
    scene.counts.cameras = model.cameras.size();
}

namespace {

void check_index(int index, std::size_t size, const std::string& where, const char* what) {
    if (index < -1 || index >= static_cast<int>(size))
        fail(where + ": " + what + " index " + std::to_string(index) + " out of range (file has " +
             std::to_string(size) + ")");
}

} // namespace

void import_nodes_and_scenes(ImportContext& ctx) {
    const auto& model = ctx.model;
    Scene& scene = ctx.scene;
    const std::size_t n = model.nodes.size();
    scene.nodes.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& src = model.nodes[i];
        const std::string where = "nodes[" + std::to_string(i) + "]";
        Node& node = scene.nodes[i];
        node.name = src.name;
        check_index(src.mesh, model.meshes.size(), where + ".mesh", "mesh");
        check_index(src.camera, model.cameras.size(), where + ".camera", "camera");
        check_index(src.skin, model.skins.size(), where + ".skin", "skin");
        node.mesh = src.mesh;
        node.camera = src.camera >= 0 && ctx.camera_skipped[static_cast<std::size_t>(src.camera)]
                          ? -1
                          : src.camera;
        node.skin = src.skin;
        if (const auto it = src.extensions.find("KHR_node_visibility");
            it != src.extensions.end() && it->second.Has("visible")) {
            const tinygltf::Value& v = it->second.Get("visible");
            if (v.IsBool())
                node.visible = v.Get<bool>();
            else
                ctx.warn(where + ".extensions.KHR_node_visibility.visible: not a boolean; the "
                                 "node is shown");
        }
        if (const auto it = src.extensions.find("KHR_lights_punctual");
            it != src.extensions.end()) {
            const auto& v = it->second;
            if (!v.IsObject() || !v.Has("light") || !v.Get("light").IsNumber())
                fail(where + ".extensions.KHR_lights_punctual: missing \"light\" index");
            const int light = v.Get("light").GetNumberAsInt();
            check_index(light, model.lights.size(), where + ".extensions.KHR_lights_punctual.light",
                        "light");
            if (light >= 0 && !ctx.light_skipped[static_cast<std::size_t>(light)])
                node.light = light;
        }
        if (src.matrix.size() == 16) {
            node.has_matrix = true;
            for (int k = 0; k < 16; ++k)
                glm::value_ptr(node.matrix)[k] =
                    static_cast<float>(src.matrix[static_cast<std::size_t>(k)]);
            if (!core::is_finite(node.matrix)) fail(where + ".matrix: not finite");
        } else if (!src.matrix.empty()) {
            fail(where + ".matrix: has " + std::to_string(src.matrix.size()) + " elements, not 16");
        }
        if (src.translation.size() == 3)
            node.translation = {src.translation[0], src.translation[1], src.translation[2]};
        if (src.scale.size() == 3) node.scale = {src.scale[0], src.scale[1], src.scale[2]};
        if (src.rotation.size() ==
            4) // glTF stores (x, y, z, w); glm::quat's constructor takes w first.
            node.rotation =
                glm::quat(static_cast<float>(src.rotation[3]), static_cast<float>(src.rotation[0]),
                          static_cast<float>(src.rotation[1]), static_cast<float>(src.rotation[2]));
        if (!core::is_finite(node.local_transform()))
            fail(where + ": translation/rotation/scale not finite");
        for (int child : src.children) {
            if (child < 0 || static_cast<std::size_t>(child) >= n)
                fail(where + ".children: node " + std::to_string(child) +
                     " out of range (file has " + std::to_string(n) + " nodes)");
            Node& c = scene.nodes[static_cast<std::size_t>(child)];
            if (static_cast<std::size_t>(child) == i)
                fail(where + ".children: node " + std::to_string(i) + " is its own child (cycle)");
            if (c.parent >= 0)
                fail("nodes[" + std::to_string(child) + "] is a child of both nodes[" +
                     std::to_string(c.parent) + "] and nodes[" + std::to_string(i) +
                     "]: glTF nodes must form disjoint trees");
            c.parent = static_cast<std::int32_t>(i);
            node.children.push_back(static_cast<std::uint32_t>(child));
        }
    }
    // With at most one parent per node, a cycle is a parent chain that never ends.
    std::vector<std::uint8_t> state(n, 0); // 0 unvisited, 1 on current chain, 2 reaches a root
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t cur = i;
        std::vector<std::size_t> chain;
        while (state[cur] == 0) {
            state[cur] = 1;
            chain.push_back(cur);
            if (scene.nodes[cur].parent < 0) break;
            cur = static_cast<std::size_t>(scene.nodes[cur].parent);
            if (state[cur] == 1)
                fail("nodes[" + std::to_string(cur) +
                     "]: the node hierarchy has a cycle through this node");
        }
        for (std::size_t c : chain) state[c] = 2;
    }
    scene.counts.nodes = n;

    for (std::size_t s = 0; s < model.scenes.size(); ++s) {
        SceneDef def;
        def.name = model.scenes[s].name;
        std::size_t repeated = 0;
        for (int root : model.scenes[s].nodes) {
            if (std::find(def.roots.begin(), def.roots.end(), static_cast<std::uint32_t>(root)) !=
                def.roots.end()) {
                ++repeated; // glTF: scene.nodes are unique; a repeat would draw twice
                continue;
            }
            if (root < 0 || static_cast<std::size_t>(root) >= n)
                fail("scenes[" + std::to_string(s) + "].nodes: node " + std::to_string(root) +
                     " out of range");
            if (scene.nodes[static_cast<std::size_t>(root)].parent >= 0)
                fail("scenes[" + std::to_string(s) + "].nodes: node " + std::to_string(root) +
                     " is not a root node");
            def.roots.push_back(static_cast<std::uint32_t>(root));
        }
        if (repeated)
            ctx.warn("scenes[" + std::to_string(s) + "].nodes: " + std::to_string(repeated) +
                     " repeated root node(s) ignored; each root is shown once");
        scene.scenes.push_back(std::move(def));
    }
    scene.counts.scenes = model.scenes.size();
    if (scene.scenes.empty() && n > 0) {
        // No scene at all: show every root node rather than nothing, and say so.
        SceneDef def;
        def.name = "(all root nodes)";
        for (std::size_t i = 0; i < n; ++i)
            if (scene.nodes[i].parent < 0) def.roots.push_back(static_cast<std::uint32_t>(i));
        scene.scenes.push_back(std::move(def));
        ctx.warn("the file defines no scenes; showing all root nodes");
    }
}

} // namespace sherpa::scene::detail
