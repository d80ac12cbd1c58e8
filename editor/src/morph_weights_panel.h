#pragma once
// Per glTF mesh with morph targets: a checkable group ("override") with one slider
// per target. Unchecked, the sliders follow the weights of the pose on screen;
// checked, their values replace the animation's for every node showing the mesh.
#include <QWidget>

#include <vector>

#include "motion_playback.h"

class QGroupBox;
class QLabel;
class QSlider;
class QVBoxLayout;

namespace sherpa::editor {

class MorphWeightsPanel : public QWidget {
    Q_OBJECT
public:
    explicit MorphWeightsPanel(QWidget* parent = nullptr);
    // Rebuilds the groups for `scene` (null: none); every override is dropped.
    void setScene(const scene::Scene* scene);
    // Shows the pose's weights on the groups that are not overridden.
    void showPose(const scene::Pose* pose);
    const MorphOverrides& overrides() const { return overrides_; }
    bool empty() const { return groups_.empty(); }
    // For tests and scripting: overrides mesh `mesh`'s target `target` with `weight`.
    bool setOverride(int mesh, int target, float weight);
    void retranslate();

Q_SIGNALS:
    void overridesChanged();

private:
    struct Group {
        std::uint32_t mesh = 0;
        QString name;  // the glTF mesh's, if any
        int node = -1; // a node showing the mesh (whose pose weights the sliders follow)
        QGroupBox* box = nullptr;
        std::vector<QSlider*> sliders;
        std::vector<QLabel*> names, values;
    };
    void collect(const Group& g);

    const scene::Scene* scene_ = nullptr;
    std::vector<Group> groups_;
    MorphOverrides overrides_;
    QVBoxLayout* layout_;
    QLabel* empty_;
};

} // namespace sherpa::editor
