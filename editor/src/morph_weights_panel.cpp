#include "morph_weights_panel.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

namespace sherpa::editor {

namespace {
constexpr int kSteps = 1000; // slider units per weight 1.0

QString weight_text(float w) {
    return QString::number(static_cast<double>(w), 'f', 3);
}
} // namespace

MorphWeightsPanel::MorphWeightsPanel(QWidget* parent) : QWidget(parent) {
    layout_ = new QVBoxLayout(this);
    layout_->setContentsMargins(2, 2, 2, 2);
    empty_ = new QLabel(this);
    empty_->setWordWrap(true);
    layout_->addWidget(empty_);
    layout_->addStretch(1);
    retranslate();
}

void MorphWeightsPanel::retranslate() {
    empty_->setText(tr("No morph targets in this scene."));
    for (Group& g : groups_) {
        g.box->setTitle(g.name.isEmpty() ? tr("Override mesh %1").arg(g.mesh)
                                         : tr("Override %1").arg(g.name));
        for (std::size_t k = 0; k < g.names.size(); ++k)
            g.names[k]->setText(tr("target %1").arg(k));
    }
}

void MorphWeightsPanel::setScene(const scene::Scene* scene) {
    for (Group& g : groups_) delete g.box;
    groups_.clear();
    overrides_.clear();
    scene_ = scene;
    if (scene) {
        for (std::size_t m = 0; m < scene->mesh_weights.size(); ++m) {
            const std::size_t targets = scene->mesh_weights[m].size();
            if (targets == 0) continue;
            Group g;
            g.mesh = static_cast<std::uint32_t>(m);
            for (std::size_t n = 0; n < scene->nodes.size() && g.node < 0; ++n)
                if (scene->nodes[n].mesh == static_cast<std::int32_t>(m))
                    g.node = static_cast<int>(n);
            for (const scene::Mesh& mesh : scene->meshes)
                if (mesh.group_id == g.mesh) { // engine meshes are named "mesh#primitive"
                    g.name = QString::fromStdString(mesh.name.substr(0, mesh.name.rfind('#')));
                    break;
                }
            g.box = new QGroupBox(this);
            g.box->setCheckable(true);
            g.box->setChecked(false);
            auto* grid = new QGridLayout(g.box);
            for (std::size_t k = 0; k < targets; ++k) {
                auto* name = new QLabel(g.box);
                auto* slider = new QSlider(Qt::Horizontal, g.box);
                slider->setRange(0, kSteps);
                slider->setMinimumWidth(80);
                auto* value = new QLabel(weight_text(scene->mesh_weights[m][k]), g.box);
                slider->setValue(qRound(scene->mesh_weights[m][k] * kSteps));
                grid->addWidget(name, static_cast<int>(k), 0);
                grid->addWidget(slider, static_cast<int>(k), 1);
                grid->addWidget(value, static_cast<int>(k), 2);
                g.names.push_back(name);
                g.sliders.push_back(slider);
                g.values.push_back(value);
            }
            layout_->insertWidget(layout_->count() - 1, g.box);
            groups_.push_back(std::move(g));
        }
        // Connected after the vector is complete: the lambdas look their group up by index.
        for (std::size_t i = 0; i < groups_.size(); ++i) {
            Group& g = groups_[i];
            connect(g.box, &QGroupBox::toggled, this, [this, i] { collect(groups_[i]); });
            for (QSlider* s : g.sliders)
                connect(s, &QSlider::valueChanged, this, [this, i] { collect(groups_[i]); });
        }
    }
    empty_->setVisible(groups_.empty());
    retranslate();
}

void MorphWeightsPanel::collect(const Group& g) {
    for (std::size_t k = 0; k < g.sliders.size(); ++k)
        g.values[k]->setText(
            weight_text(static_cast<float>(g.sliders[k]->value()) / static_cast<float>(kSteps)));
    if (g.box->isChecked()) {
        std::vector<float>& w = overrides_[g.mesh];
        w.resize(g.sliders.size());
        for (std::size_t k = 0; k < w.size(); ++k)
            w[k] = static_cast<float>(g.sliders[k]->value()) / static_cast<float>(kSteps);
    } else if (overrides_.erase(g.mesh) == 0) {
        return; // a slider following the pose moved: nothing overridden changed
    }
    Q_EMIT overridesChanged();
}

void MorphWeightsPanel::showPose(const scene::Pose* pose) {
    for (Group& g : groups_) {
        if (g.box->isChecked()) continue;
        const std::vector<float>* w = nullptr;
        if (pose && g.node >= 0 && static_cast<std::size_t>(g.node) < pose->weights.size())
            w = &pose->weights[static_cast<std::size_t>(g.node)];
        else if (scene_)
            w = &scene_->mesh_weights[g.mesh];
        if (!w) continue;
        for (std::size_t k = 0; k < g.sliders.size() && k < w->size(); ++k) {
            const QSignalBlocker block(g.sliders[k]);
            g.sliders[k]->setValue(qRound((*w)[k] * kSteps));
            g.values[k]->setText(weight_text((*w)[k]));
        }
    }
}

bool MorphWeightsPanel::setOverride(int mesh, int target, float weight) {
    for (Group& g : groups_) {
        if (static_cast<int>(g.mesh) != mesh) continue;
        if (target < 0 || static_cast<std::size_t>(target) >= g.sliders.size()) return false;
        g.box->setChecked(true);
        g.sliders[static_cast<std::size_t>(target)]->setValue(qRound(weight * kSteps));
        collect(g);
        return true;
    }
    return false;
}

} // namespace sherpa::editor
