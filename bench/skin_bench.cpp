// sherpa-bench-skin [--frames N] [--width W --height H] [--rounds R] [--rt]
// GPU skinning and morphing cost (issue #16): the lit frame of a moving model posed on
// the GPU (FrameRequest::pose: the MOTION pipelines skin and morph in the vertex
// stage) against the same model frozen in that pose on the CPU (freeze_pose(): a
// static scene, no motion streams), in the same run, alternating R rounds. Models: a
// generated skinned tube (100k vertices, 64 joints, two influences per vertex, bent)
// and the moving sample models with skins or morph targets. Prints medians and the
// ratio (goal: skinning <= 1.3x the static frame). Animation evaluation per frame
// (BrainStem-sized and 1,000-joint rigs) is sherpa-bench-anim's.
// --rt: the ray tracer's posed frames (issue #17) instead: every frame a new pose
// (the tube bends 0..8 degrees per joint, the sample models sweep their animation),
// so each one poses the moving vertices, refits (or rebuilds) their BLAS and the
// TLAS, then traces; GPU ms per part, medians, refit against rebuild in one run.
#include "process_cpu.h"

#include <sherpa/core/heap_tuning.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/animation.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

using namespace sherpa;

namespace {

struct Times {
    std::vector<double> wall, cpu; // per round: median wall ms, mean CPU ms per frame
};

void measure(render::Renderer& r, const render::FrameRequest& s, int frames, Times& out) {
    std::vector<double> ms;
    r.render(s); // warm: pipelines, shadows
    const double cpu0 = bench::process_cpu_ms();
    for (int f = 0; f < frames; ++f) {
        const auto t0 = std::chrono::steady_clock::now();
        r.render(s);
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
    }
    std::sort(ms.begin(), ms.end());
    out.wall.push_back(ms[ms.size() / 2]);
    out.cpu.push_back((bench::process_cpu_ms() - cpu0) / frames);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// A tube along +Y of `rings` x `segments` vertices on a chain of `joints` joints one
// unit apart, each vertex weighted between its two nearest joints; the default pose
// bends every joint by 4 degrees about Z.
scene::Scene skinned_tube(std::uint32_t joints, std::uint32_t rings, std::uint32_t segments) {
    scene::Scene s;
    s.materials.push_back(scene::MaterialInstance{});
    s.nodes.resize(joints + 1);
    scene::Skin skin;
    for (std::uint32_t j = 0; j < joints; ++j) {
        scene::Node& n = s.nodes[j];
        n.translation = {0.0f, j ? 1.0f : 0.0f, 0.0f};
        n.rotation = glm::angleAxis(glm::radians(4.0f), glm::vec3(0, 0, 1));
        if (j > 0) {
            n.parent = static_cast<std::int32_t>(j - 1);
            s.nodes[j - 1].children.push_back(j);
        }
        skin.joints.push_back(j);
        skin.inverse_bind.push_back(glm::translate(glm::mat4(1.0f), glm::vec3(0, -float(j), 0)));
    }
    s.skins.push_back(std::move(skin));
    scene::Node& holder = s.nodes[joints];
    holder.mesh = 0;
    holder.skin = 0;
    scene::Mesh mesh;
    scene::PrimitiveMotion m;
    m.influences = 4;
    m.max_joint = joints - 1;
    m.boxes.resize(joints);
    for (std::uint32_t j = 0; j < joints; ++j) m.boxes[j].joint = static_cast<std::int32_t>(j);
    const float height = float(joints - 1);
    for (std::uint32_t r = 0; r < rings; ++r)
        for (std::uint32_t g = 0; g < segments; ++g) {
            const float a = 6.2831853f * float(g) / float(segments);
            const float y = height * float(r) / float(rings - 1);
            scene::Vertex v;
            v.position = {0.3f * std::cos(a), y, 0.3f * std::sin(a)};
            v.normal = {std::cos(a), 0.0f, std::sin(a)};
            v.uv0 = {float(g) / float(segments), float(r) / float(rings)};
            mesh.vertices.push_back(v);
            m.base_positions.push_back(v.position);
            const auto j0 = std::min<std::uint32_t>(std::uint32_t(y), joints - 1);
            const auto j1 = std::min(j0 + 1, joints - 1);
            const float f = y - float(j0);
            const std::uint16_t js[4] = {std::uint16_t(j0), std::uint16_t(j1), 0, 0};
            const float ws[4] = {1.0f - f, f, 0.0f, 0.0f};
            for (int k = 0; k < 4; ++k) {
                m.joints.push_back(js[k]);
                m.weights.push_back(ws[k]);
                if (ws[k] > 0.0f) m.boxes[js[k]].base.expand(v.position);
            }
        }
    for (std::uint32_t r = 0; r + 1 < rings; ++r)
        for (std::uint32_t g = 0; g < segments; ++g) {
            const std::uint32_t a = r * segments + g, b = r * segments + (g + 1) % segments;
            for (std::uint32_t i : {a, a + segments, b, b, a + segments, b + segments})
                mesh.indices.push_back(i);
        }
    m.boxes.erase(std::remove_if(m.boxes.begin(), m.boxes.end(),
                                 [](const scene::InfluenceBox& b) { return !b.base.valid(); }),
                  m.boxes.end());
    for (const scene::Vertex& v : mesh.vertices) mesh.local_bounds.expand(v.position);
    mesh.provenance[std::size_t(scene::VertexAttribute::Normal)] = scene::Provenance::Authored;
    mesh.provenance[std::size_t(scene::VertexAttribute::TexCoord0)] = scene::Provenance::Authored;
    mesh.source_vertex_count = static_cast<std::uint32_t>(mesh.vertices.size());
    scene::PrimitiveInfo p;
    p.engine_mesh = 0;
    p.motion = 0;
    p.vertices = mesh.source_vertex_count;
    s.primitives.push_back(p);
    s.motions.push_back(std::move(m));
    scene::MeshInstance inst;
    inst.node_id = joints;
    inst.world_bounds = mesh.local_bounds;
    s.instances.push_back(inst);
    s.meshes.push_back(std::move(mesh));
    s.displayed_nodes.push_back(joints);
    s.node_world.assign(s.nodes.size(), glm::mat4(1.0f));
    // The scene bounds of the pose drawn (framing, shadows).
    s.bounds = scene::posed_scene_bounds(s, scene::evaluate_pose(s, -1, 0.0)).exact;
    return s;
}

// The tube's pose with every joint bent by `degrees` about Z.
scene::Pose bent(const scene::Scene& tube, float degrees) {
    scene::Scene copy;
    copy.nodes = tube.nodes;
    copy.skins = tube.skins;
    for (scene::Node& n : copy.nodes)
        if (n.mesh < 0) n.rotation = glm::angleAxis(glm::radians(degrees), glm::vec3(0, 0, 1));
    return scene::evaluate_pose(copy, -1, 0.0);
}

double pass_ms(const render::FrameStats& f, std::string_view name) {
    for (const render::PassTiming& p : f.passes)
        if (p.name == name) return p.ms;
    return 0.0;
}

// Posed ray-traced frames of `s` through `poses` (cycled), refit and rebuild.
void measure_rt(gpu::Context& context, const std::string& name, const scene::Scene& s,
                const std::vector<std::shared_ptr<const scene::Pose>>& poses, int frames,
                std::uint32_t width, std::uint32_t height) {
    for (bool refit : {true, false}) {
        render::RendererOptions options;
        options.ray_tracing = true;
        options.acceleration.refit_posed = refit;
        render::Renderer renderer(context, options);
        renderer.load(s);
        render::FrameRequest settings;
        settings.width = width;
        settings.height = height;
        settings.shadows = false;
        settings.view = render::DebugView::Normal;
        settings.renderer = render::RendererKind::RayTraced;
        std::vector<double> pose, blas, tlas, rays;
        for (int f = 0; f < frames; ++f) {
            settings.pose = poses[std::size_t(f) % poses.size()];
            const render::FrameStats st = renderer.render(settings);
            pose.push_back(pass_ms(st, "pose_vertices"));
            blas.push_back(pass_ms(st, "posed_blas"));
            tlas.push_back(pass_ms(st, "tlas"));
            rays.push_back(pass_ms(st, "rays"));
        }
        std::printf("%-22s %-8s %10.3f %10.3f %10.3f %10.3f\n", name.c_str(),
                    refit ? "refit" : "rebuild", median(pose), median(blas), median(tlas),
                    median(rays));
    }
}

} // namespace

int main(int argc, char** argv) {
    core::keep_freed_memory_mapped();
    int frames = 20, rounds = 3;
    std::uint32_t width = 1280, height = 720;
    bool rt = false;
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--rt") rt = true;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--rt") {
            --i;
            continue;
        }
        const int v = std::atoi(argv[i + 1]);
        if (a == "--frames") frames = std::max(1, v);
        if (a == "--rounds") rounds = std::max(1, v);
        if (a == "--width") width = std::uint32_t(std::max(16, v));
        if (a == "--height") height = std::uint32_t(std::max(16, v));
    }
    gpu::Context context(gpu::ContextOptions{});
    render::Renderer renderer(context);
    std::printf("device: %s, %ux%u lit, %d frames x %d alternating rounds\n",
                context.info().name.c_str(), width, height, frames, rounds);
    std::printf("%-22s %9s %12s %12s %12s %12s %7s %7s\n", "model", "vertices", "skinned ms",
                "static ms", "skinned cpu", "static cpu", "wall x", "cpu x");
    struct Model {
        std::string name;
        scene::Scene scene;
    };
    std::vector<Model> models;
    models.push_back({"tube 100k v, 64 joints", skinned_tube(64, 800, 128)});
    for (const char* name : {"RiggedSimple", "AnimatedMorphSphere", "SimpleMorph"}) {
        scene::LoadResult r = scene::load_scene(std::string(SHERPA_ASSETS_DIR) + "/gltf/" + name +
                                                "/glTF/" + name + ".gltf");
        if (!r) {
            std::fprintf(stderr, "%s: %s\n", name, r.error.c_str());
            continue;
        }
        models.push_back({name, std::move(*r.scene)});
    }
    if (rt) {
        std::printf("ray traced, normal view; GPU ms per frame (medians), a new pose each frame\n");
        std::printf("%-22s %-8s %10s %10s %10s %10s\n", "model", "BLAS", "pose", "posed BLAS",
                    "TLAS", "rays");
        for (const Model& m : models) {
            std::vector<std::shared_ptr<const scene::Pose>> poses;
            for (int k = 0; k < 8; ++k) {
                const double f = (k + 0.5) / 8.0;
                if (m.scene.animations.empty()) {
                    poses.push_back(
                        std::make_shared<const scene::Pose>(bent(m.scene, 8.0f * float(f))));
                } else {
                    const scene::Animation& a = m.scene.animations[0];
                    poses.push_back(std::make_shared<const scene::Pose>(
                        scene::evaluate_pose(m.scene, 0, a.start + f * (a.end - a.start))));
                }
            }
            measure_rt(context, m.name, m.scene, poses, frames, width, height);
        }
        return 0;
    }
    for (const Model& m : models) {
        const scene::Scene& s = m.scene;
        const double t =
            s.animations.empty()
                ? 0.0
                : s.animations[0].start + 0.37 * (s.animations[0].end - s.animations[0].start);
        const auto pose = std::make_shared<const scene::Pose>(
            scene::evaluate_pose(s, s.animations.empty() ? -1 : 0, t));
        const scene::Scene frozen = scene::freeze_pose(s, *pose);
        render::FrameRequest settings;
        settings.width = width;
        settings.height = height;
        settings.pose = pose;
        // One camera for both, on the posed geometry (auto framing would frame each
        // scene's bounds as loaded: the moving one's are the bind pose's).
        const core::Aabb posed = scene::posed_scene_bounds(s, *pose).exact;
        const glm::vec3 c = posed.center();
        const float r = std::max(0.5f * glm::length(posed.extent()), 1e-3f);
        const glm::vec3 eye = c + glm::normalize(glm::vec3(0.35f, 0.3f, 1.0f)) * (2.2f * r);
        char camera[256];
        std::snprintf(camera, sizeof(camera), "eye=%g,%g,%g:target=%g,%g,%g:near=%g", eye.x, eye.y,
                      eye.z, c.x, c.y, c.z, 0.01f * r);
        std::string error;
        if (!render::parse_camera_spec(camera, settings.camera, error)) {
            std::fprintf(stderr, "%s: %s\n", m.name.c_str(), error.c_str());
            return 1;
        }
        Times skinned, still;
        std::uint64_t vertices = 0;
        for (const scene::Mesh& mesh : s.meshes) vertices += mesh.vertices.size();
        for (int round = 0; round < rounds; ++round) {
            renderer.load(s);
            measure(renderer, settings, frames, skinned);
            renderer.load(frozen);
            measure(renderer, settings, frames, still);
        }
        const double sw = median(skinned.wall), fw = median(still.wall);
        const double sc = median(skinned.cpu), fc = median(still.cpu);
        std::printf("%-22s %9llu %12.2f %12.2f %12.2f %12.2f %7.2f %7.2f\n", m.name.c_str(),
                    (unsigned long long)vertices, sw, fw, sc, fc, sw / fw, sc / fc);
    }
    return 0;
}
