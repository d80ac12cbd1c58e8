#include "node_visibility.h"

#include <sherpa/scene/visibility.h>

#include <algorithm>

#include "editor_context.h"

namespace sherpa::editor {

NodeVisibility::NodeVisibility(const EditorContext& context) : context_(context) {}

bool NodeVisibility::nodeVisible(int node) const {
    return node < 0 || !hidden_ || static_cast<std::size_t>(node) >= hidden_->size() ||
           !(*hidden_)[static_cast<std::size_t>(node)];
}

bool NodeVisibility::instanceVisible(std::size_t instance) const {
    const scene::Scene* scene = context_.scene();
    if (!scene || instance >= scene->instances.size()) return false;
    // Hiding a node hides its subtree, as in every DCC tool.
    const std::uint32_t node = scene->instances[instance].node_id;
    return node >= hidden_subtrees_.size() || !hidden_subtrees_[node];
}

void NodeVisibility::setNodeVisible(int node, bool visible) {
    const scene::Scene* scene = context_.scene();
    if (!scene || node < 0 || static_cast<std::size_t>(node) >= scene->nodes.size()) return;
    if (nodeVisible(node) == visible) return;
    auto mask = hidden_ ? std::make_shared<std::vector<bool>>(*hidden_)
                        : std::make_shared<std::vector<bool>>(scene->nodes.size(), false);
    (*mask)[static_cast<std::size_t>(node)] = !visible;
    hidden_subtrees_ = scene::hidden_subtrees(scene->nodes, *mask);
    if (std::find(mask->begin(), mask->end(), true) == mask->end())
        hidden_.reset(); // every node shown again
    else
        hidden_ = std::move(mask);
    Q_EMIT changed();
}

void NodeVisibility::clear() {
    hidden_.reset();
    hidden_subtrees_.clear();
}

} // namespace sherpa::editor
