#pragma once
// Which nodes of the open scene are shown (the scene tree's check boxes): hiding a
// node hides its subtree, as in every DCC tool and the renderer. Part of
// EditorContext: the scene tree and the viewport read it and listen to changed().
#include <QObject>

#include <cstddef>
#include <memory>
#include <vector>

namespace sherpa::editor {

class EditorContext;

class NodeVisibility : public QObject {
    Q_OBJECT
public:
    // The nodes of `context`'s scene.
    explicit NodeVisibility(const EditorContext& context);

    bool nodeVisible(int node) const;
    // Instances whose node and every ancestor are visible (hidden_subtrees(), the
    // renderer's rule).
    bool instanceVisible(std::size_t instance) const;
    // Per node, true where unchecked; null while every node is shown. A new mask per
    // change (never modified once handed out): what the viewport's frames carry to
    // the renderer.
    std::shared_ptr<const std::vector<bool>> hidden() const { return hidden_; }
    void setNodeVisible(int node, bool visible);
    // Every node shown, without changed(): a new scene (EditorContext::setSession).
    void clear();

Q_SIGNALS:
    void changed();

private:
    const EditorContext& context_;
    std::shared_ptr<const std::vector<bool>> hidden_;
    std::vector<bool> hidden_subtrees_; // hidden_ with the subtree rule applied
};

} // namespace sherpa::editor
