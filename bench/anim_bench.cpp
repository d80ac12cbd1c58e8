// sherpa-bench-anim [--repeat N]
// Animation evaluation per frame on one core (issue #16): evaluate_pose (every channel
// sampled, node locals, world and joint matrices, morph weights), then the per-joint
// culling bounds and the exact CPU posing of the skinned primitives. Rigs: the heaviest
// skinned sample model in shared/assets (RiggedSimple) and generated skins of 64, 256
// and 1,000 joints (a binary joint tree, LINEAR T/R/S channels with 60 keys on every
// joint, 8 vertices per joint with 4 influences each). Median over frames at times
// spread across the animation. Goal: <= 50 us per frame for a BrainStem-sized rig.
#include <sherpa/scene/animation.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace sherpa;

namespace {

using Clock = std::chrono::steady_clock;

// Median microseconds of `frame(t)` over `repeat` times spread across [0, duration].
double median_us(int repeat, double duration, const std::function<void(double)>& frame) {
    std::vector<double> us;
    frame(0.0); // warm caches
    for (int r = 0; r < repeat; ++r) {
        const double t = duration * (r + 0.5) / repeat;
        const auto t0 = Clock::now();
        frame(t);
        us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
    }
    std::sort(us.begin(), us.end());
    return us[us.size() / 2];
}

scene::AnimationSampler keys(std::uint32_t width, int count, std::uint32_t seed) {
    scene::AnimationSampler s;
    s.width = width;
    for (int k = 0; k < count; ++k) {
        s.times.push_back(static_cast<float>(k) / 30.0f);
        for (std::uint32_t c = 0; c < width; ++c)
            s.values.push_back(std::sin(0.1f * static_cast<float>(k * 7 + c * 3 + seed)));
    }
    return s;
}

// A binary tree of `joints` nodes skinned by one skin, animated on T/R/S, with one
// primitive of 8 vertices per joint (each vertex on 4 neighbouring joints).
scene::Scene generated_rig(std::uint32_t joints) {
    scene::Scene s;
    s.nodes.resize(joints + 1);
    scene::Skin skin;
    scene::Animation anim;
    anim.name = "generated";
    for (std::uint32_t j = 0; j < joints; ++j) {
        scene::Node& n = s.nodes[j];
        n.translation = {0.0f, 0.1f, 0.0f};
        if (j > 0) {
            n.parent = static_cast<std::int32_t>((j - 1) / 2);
            s.nodes[(j - 1) / 2].children.push_back(j);
        }
        skin.joints.push_back(j);
        skin.inverse_bind.push_back(glm::mat4(1.0f));
        for (scene::AnimationPath p :
             {scene::AnimationPath::Translation, scene::AnimationPath::Rotation,
              scene::AnimationPath::Scale}) {
            anim.samplers.push_back(keys(p == scene::AnimationPath::Rotation ? 4 : 3, 60, j));
            anim.channels.push_back({static_cast<std::uint32_t>(anim.samplers.size() - 1), j, p});
        }
    }
    anim.end = 59.0f / 30.0f;
    s.skins.push_back(std::move(skin));
    s.animations.push_back(std::move(anim));
    scene::Node& holder = s.nodes[joints];
    holder.mesh = 0;
    holder.skin = 0;
    scene::PrimitiveMotion m;
    m.influences = 4;
    for (std::uint32_t v = 0; v < joints * 8; ++v) {
        m.base_positions.push_back({std::sin(float(v)), std::cos(float(v)), 0.01f * float(v)});
        for (std::uint32_t k = 0; k < 4; ++k) {
            m.joints.push_back(static_cast<std::uint16_t>((v / 8 + k) % joints));
            m.weights.push_back(0.25f);
        }
    }
    m.max_joint = joints - 1;
    // Per-joint boxes as the importer makes them (every vertex in its joints' boxes).
    m.boxes.resize(joints);
    for (std::uint32_t j = 0; j < joints; ++j) m.boxes[j].joint = static_cast<std::int32_t>(j);
    for (std::uint32_t v = 0; v < joints * 8; ++v)
        for (std::uint32_t k = 0; k < 4; ++k)
            m.boxes[m.joints[v * 4 + k]].base.expand(m.base_positions[v]);
    s.motions.push_back(std::move(m));
    scene::PrimitiveInfo p;
    p.engine_mesh = 0; // posed from the motion data only
    p.motion = 0;
    p.vertices = joints * 8;
    s.primitives.push_back(p);
    s.meshes.resize(1);
    s.displayed_nodes.push_back(joints);
    return s;
}

void report(const char* name, const scene::Scene& s, int repeat) {
    const double d = s.animations.empty() ? 0.0 : s.animations[0].end;
    std::size_t joints = 0, channels = 0, vertices = 0;
    for (const auto& sk : s.skins) joints += sk.joints.size();
    for (const auto& a : s.animations) channels += a.channels.size();
    for (const auto& m : s.motions) vertices += m.base_positions.size();
    const double eval =
        median_us(repeat, d, [&](double t) { (void)scene::evaluate_pose(s, 0, t); });
    scene::Pose pose = scene::evaluate_pose(s, 0, 0.5 * d);
    double sink = 0.0;
    auto each_instance =
        [&](const std::function<void(std::uint32_t, const scene::PrimitiveInfo&)>& f) {
            for (std::uint32_t n : s.displayed_nodes)
                for (const auto& p : s.primitives)
                    if (s.nodes[n].mesh >= 0 &&
                        p.mesh == static_cast<std::uint32_t>(s.nodes[n].mesh) && p.motion >= 0)
                        f(n, p);
        };
    const double cull = median_us(repeat, d, [&](double) {
        each_instance([&](std::uint32_t n, const scene::PrimitiveInfo& p) {
            sink += scene::culling_bounds(s, pose, n, p).max.x;
        });
    });
    const double posing = median_us(repeat, d, [&](double) {
        each_instance([&](std::uint32_t n, const scene::PrimitiveInfo& p) {
            sink += scene::posed_positions(s, pose, n, p).size();
        });
    });
    std::printf("%-22s %6zu joints %6zu channels %7zu vertices | evaluate_pose %8.2f us | "
                "culling bounds %8.2f us | CPU skinning %9.1f us%s\n",
                name, joints, channels, vertices, eval, cull, posing, sink < 0 ? " " : "");
}

} // namespace

int main(int argc, char** argv) {
    int repeat = 501;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--repeat") == 0) repeat = std::max(3, std::atoi(argv[++i]));
    std::printf("sherpa-bench-anim: median per frame over %d times, one core\n", repeat);
    const std::string rigged =
        std::string(SHERPA_ASSETS_DIR) + "/gltf/RiggedSimple/glTF/RiggedSimple.gltf";
    if (auto r = scene::load_scene(rigged))
        report("RiggedSimple", *r.scene, repeat);
    else
        std::printf("RiggedSimple: %s\n", r.error.c_str());
    for (std::uint32_t j : {64u, 256u, 1000u}) {
        const scene::Scene s = generated_rig(j);
        report(("generated " + std::to_string(j)).c_str(), s, repeat);
    }
    return 0;
}
