#include <sherpa/scene/visibility.h>

namespace sherpa::scene {

std::vector<bool> hidden_subtrees(std::span<const Node> nodes, const std::vector<bool>& hidden) {
    std::vector<bool> out(nodes.size(), false);
    if (hidden.empty()) return out;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        // At most nodes.size() steps up: a cycle of parents cannot loop forever.
        std::size_t steps = 0;
        for (std::int64_t a = static_cast<std::int64_t>(n);
             a >= 0 && static_cast<std::size_t>(a) < nodes.size() && steps <= nodes.size();
             a = nodes[static_cast<std::size_t>(a)].parent, ++steps)
            if (static_cast<std::size_t>(a) < hidden.size() &&
                hidden[static_cast<std::size_t>(a)]) {
                out[n] = true;
                break;
            }
    }
    return out;
}

} // namespace sherpa::scene
