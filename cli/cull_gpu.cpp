#include "cull_gpu.h"

#include <sherpa/gpu/context.h>
#include <sherpa/render/gpu_culling.h>

#include <exception>

namespace sherpa::cli {

bool gpu_cull_passes(const Scene& scene, const std::vector<std::pair<std::string, Frustum>>& frusta,
                     const std::vector<PassResult>& cpu, std::vector<PassResult>& out,
                     std::string& error) {
    try {
        gpu::Context context;
        gpu::ResourceManager resources(context);
        // The camera sees every instance; cascades see the shadow casters.
        MeshPass camera_pass(MeshPassKind::Forward);
        for (std::uint32_t i = 0; i < scene.instances.size(); ++i)
            camera_pass.add(i, scene.instances[i].mesh_id, instance_pipeline_key(scene, i));
        camera_pass.update();
        const ScenePasses passes = build_mesh_passes(scene);
        const auto pipeline = std::make_shared<const gpu::GpuCullPipeline>(context);
        gpu::GpuCuller camera_culler(context, resources, 1, pipeline),
            shadow_culler(context, resources, 1, pipeline);
        camera_culler.build(camera_pass, scene);
        shadow_culler.build(passes.shadow, scene);
        // Lavapipe compiles the (shared) pipeline at its first dispatch (171 ms for
        // the camera pass of a 10k grid): one untimed run keeps that out of `gpu ms`.
        if (!frusta.empty()) camera_culler.run(frusta.front().second, CullMethod::PVertex);
        for (std::size_t p = 0; p < frusta.size(); ++p) {
            gpu::GpuCuller& culler = p == 0 ? camera_culler : shadow_culler;
            const gpu::GpuCullReadback r = culler.run(frusta[p].second, CullMethod::PVertex);
            // Objects the CPU path sees in this pass (casters only for cascades).
            std::vector<std::uint8_t> cpu_visible(scene.instances.size(), 0);
            for (std::uint32_t i : cpu[p].visible_opaque) cpu_visible[i] = 1;
            for (std::uint32_t i : cpu[p].visible_transparent) cpu_visible[i] = 1;
            PassResult res;
            CullStats& st = res.stats;
            st.pass = frusta[p].first;
            st.method = CullMethod::PVertex;
            st.gpu = true;
            st.gpu_ms = r.gpu_ms;
            st.total = culler.object_count(); // casters only for cascades
            st.tested = culler.object_count();
            std::int64_t differences = 0;
            for (std::size_t k = 0; k < r.visible.size(); ++k) {
                const std::uint32_t inst = culler.object_instances()[k];
                differences += (r.visible[k] != 0) != (cpu_visible[inst] != 0) ? 1 : 0;
                if (!r.visible[k]) continue;
                ++st.visible;
                st.triangles += scene.meshes[scene.instances[inst].mesh_id].triangle_count();
                if (scene.materials[scene.instances[inst].material_id].alpha_mode ==
                    AlphaMode::Blend)
                    res.visible_transparent.push_back(inst);
                else
                    res.visible_opaque.push_back(inst);
            }
            st.culled = st.tested - st.visible;
            st.draw_calls = culler.batch_count(); // one vkCmdDrawIndexedIndirectCount per batch
            st.cpu_gpu_differences = differences;
            out.push_back(std::move(res));
        }
        return true;
    } catch (const std::exception& e) {
        error = std::string("GPU culling: ") + e.what();
        return false;
    }
}

} // namespace sherpa::cli
