// Node visibility inside the renderer (SceneSetup::hidden_nodes): a changed mask
// is expanded to subtrees once (hidden_subtrees(), the editor's rule too), mapped to
// GPU instances for the culling pass (whose GPU cullers, shown-id lists and
// statistics leave hidden instances out), redraws the cached shadow cascades, and
// reaches the TLAS before the next ray-traced frame. An unchanged mask costs one
// comparison.
#include "renderer_impl.h"

#include <sherpa/scene/visibility.h>

namespace sherpa::gpu {

void Renderer::Impl::load_visibility(const Scene& source) {
    nodes_ = source.nodes;
    instance_node_.clear();
    for (const std::uint32_t si : scene->scene_instances())
        instance_node_.push_back(si < source.instances.size() ? source.instances[si].node_id : ~0u);
    hidden_given_.clear();
    hidden_nodes_.clear();
    // The TLAS was built with RendererOptions::acceleration's mask; ours replaces it.
    tlas_visibility_ = options.acceleration.hidden_nodes.empty();
}

void Renderer::Impl::apply_visibility(bool rt) {
    if (!scene) return;
    static const std::vector<bool> kNone;
    const std::vector<bool>& given = setup.hidden_nodes ? *setup.hidden_nodes : kNone;
    if (given != hidden_given_) {
        // Frames in flight index the GPU cullers being replaced: wait for them and
        // keep their statistics in the history now.
        for (auto& s : slots_) {
            wait_slot(*s);
            if (s->has_results && !s->history_pushed) {
                FrameStats unused;
                culling.read_stats(*s, scene.get(), unused);
            }
            s->culling.count = 0;
        }
        hidden_given_ = given;
        hidden_nodes_ = hidden_subtrees(nodes_, given);
        std::vector<std::uint8_t> hidden(instance_node_.size(), 0);
        for (std::size_t i = 0; i < hidden.size(); ++i)
            hidden[i] =
                instance_node_[i] < hidden_nodes_.size() && hidden_nodes_[instance_node_[i]];
        culling.set_hidden(std::move(hidden), *scene);
        shadows_.invalidate(); // the casters changed
        tlas_visibility_ = false;
    }
    if (rt && acceleration && !tlas_visibility_) {
        for (auto& s : slots_) wait_slot(*s);
        acceleration->set_hidden_nodes(hidden_nodes_);
        // The rebuilt TLAS holds the loaded transforms: the frame's pose goes in again.
        rt_pose_generation_ = 0;
        tlas_visibility_ = true;
    }
}

} // namespace sherpa::gpu
