// Culling while moving, at the scene layer: at every key time of every animation of
// the sample models that move, each instance's conservative culling bounds
// (instance_culling_bounds(), what the renderer and `cull --time` test) hold every
// one of its exactly posed vertices (posed_positions(), checked against three.js), so
// no frustum that sees a vertex of it can cull it.
#include <gtest/gtest.h>

#include <set>

#include <sherpa/scene/animation.h>
#include <sherpa/scene/scene_loader.h>

#include "test_support.h"

namespace sherpa::test {
namespace {

TEST(MotionCulling, BoundsHoldEveryPosedVertexAtEveryKeyTime) {
    std::size_t checked = 0;
    for (const char* name : {"RiggedSimple", "SimpleMorph", "AnimatedMorphSphere", "AnimatedCube",
                             "BoxAnimated", "AnimatedTriangle", "VC"}) {
        SCOPED_TRACE(name);
        const scene::LoadResult r = scene::load_scene(gltf_asset(name));
        ASSERT_TRUE(r) << r.error;
        const scene::Scene& s = *r.scene;
        ASSERT_FALSE(s.animations.empty());
        for (std::size_t a = 0; a < s.animations.size(); ++a) {
            std::set<float> times; // every sampled time of the animation
            for (const scene::AnimationSampler& sampler : s.animations[a].samplers)
                times.insert(sampler.times.begin(), sampler.times.end());
            for (float t : times) {
                const scene::Pose pose = scene::evaluate_pose(s, static_cast<std::int32_t>(a), t);
                const std::vector<core::Aabb> bounds = scene::instance_culling_bounds(s, pose);
                ASSERT_EQ(bounds.size(), s.instances.size());
                for (std::size_t i = 0; i < s.instances.size(); ++i) {
                    const scene::MeshInstance& inst = s.instances[i];
                    for (const scene::PrimitiveInfo& p : s.primitives) {
                        if (p.engine_mesh != static_cast<std::int32_t>(inst.mesh_id)) continue;
                        for (const glm::vec3& v :
                             scene::posed_positions(s, pose, inst.node_id, p)) {
                            ++checked;
                            const core::Aabb& b = bounds[i];
                            ASSERT_TRUE(b.valid() && glm::all(glm::lessThanEqual(b.min, v)) &&
                                        glm::all(glm::lessThanEqual(v, b.max)))
                                << "animation " << a << " t=" << t << " instance " << i;
                        }
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 10000u);
}

} // namespace
} // namespace sherpa::test
