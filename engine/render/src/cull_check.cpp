#include <sherpa/gpu/context.h>
#include <sherpa/render/cull_check.h>
#include <sherpa/render/gpu_culling.h>
#include <sherpa/scene/mesh_pass.h>

#include <exception>

namespace sherpa::render {

GpuCullChecker::GpuCullChecker(gpu::Context& context, gpu::ResourceManager& resources,
                               const scene::Scene& scene)
    : context_(context), resources_(resources), scene_(scene),
      pipeline_(std::make_shared<const GpuCullPipeline>(context)) {
    culler(false);
}

GpuCullChecker::~GpuCullChecker() = default;

GpuCuller& GpuCullChecker::culler(bool casters) {
    std::unique_ptr<GpuCuller>& c = casters ? casters_ : camera_;
    if (c) return *c;
    c = std::make_unique<GpuCuller>(context_, resources_, 1, pipeline_);
    if (casters) {
        c->build(scene::build_mesh_passes(scene_).shadow, scene_);
    } else {
        // The camera sees every instance.
        scene::MeshPass pass(scene::MeshPassKind::Forward);
        for (std::uint32_t i = 0; i < scene_.instances.size(); ++i)
            pass.add(i, scene_.instances[i].mesh_id, scene::instance_pipeline_key(scene_, i));
        pass.update();
        c->build(pass, scene_);
    }
    return *c;
}

GpuCullComparison GpuCullChecker::compare(const scene::Frustum& frustum, scene::CullMethod method,
                                          std::span<const std::uint8_t> cpu_visible, bool casters) {
    GpuCuller& c = culler(casters);
    const GpuCullReadback r = c.run(frustum, method);
    GpuCullComparison out;
    out.gpu_ms = r.gpu_ms;
    out.objects = c.object_count();
    out.batches = c.batch_count();
    const std::vector<std::uint32_t>& instances = c.object_instances();
    for (std::size_t k = 0; k < r.visible.size() && k < instances.size(); ++k) {
        const bool gpu = r.visible[k] != 0;
        const bool cpu = instances[k] < cpu_visible.size() && cpu_visible[instances[k]] != 0;
        if (gpu) out.visible.push_back(instances[k]);
        out.differences += gpu != cpu ? 1 : 0;
    }
    return out;
}

bool gpu_cull_passes(const scene::Scene& scene,
                     const std::vector<std::pair<std::string, scene::Frustum>>& frusta,
                     const std::vector<scene::PassResult>& cpu, std::vector<scene::PassResult>& out,
                     std::string& error) {
    try {
        gpu::Context context;
        gpu::ResourceManager resources(context);
        GpuCullChecker check(context, resources, scene);
        // Lavapipe compiles the pipeline at its first dispatch (171 ms for the camera
        // pass of a 10k grid): one untimed run keeps that out of `gpu ms`.
        if (!frusta.empty()) check.compare(frusta.front().second, scene::CullMethod::PVertex, {});
        for (std::size_t p = 0; p < frusta.size(); ++p) {
            // Objects the CPU path sees in this pass (casters only for cascades).
            std::vector<std::uint8_t> cpu_visible(scene.instances.size(), 0);
            for (std::uint32_t i : cpu[p].visible_opaque) cpu_visible[i] = 1;
            for (std::uint32_t i : cpu[p].visible_transparent) cpu_visible[i] = 1;
            const GpuCullComparison r =
                check.compare(frusta[p].second, scene::CullMethod::PVertex, cpu_visible, p > 0);
            scene::PassResult res;
            scene::CullStats& st = res.stats;
            st.pass = frusta[p].first;
            st.method = scene::CullMethod::PVertex;
            st.gpu = true;
            st.gpu_ms = r.gpu_ms;
            st.total = r.objects; // casters only for cascades
            st.tested = r.objects;
            for (std::uint32_t inst : r.visible) {
                ++st.visible;
                st.triangles += scene.meshes[scene.instances[inst].mesh_id].triangle_count();
                if (scene.materials[scene.instances[inst].material_id].alpha_mode ==
                    scene::AlphaMode::Blend)
                    res.visible_transparent.push_back(inst);
                else
                    res.visible_opaque.push_back(inst);
            }
            st.culled = st.tested - st.visible;
            st.draw_calls = r.batches; // one vkCmdDrawIndexedIndirectCount per batch
            st.cpu_gpu_differences = r.differences;
            out.push_back(std::move(res));
        }
        return true;
    } catch (const std::exception& e) {
        error = std::string("GPU culling: ") + e.what();
        return false;
    }
}

} // namespace sherpa::render
