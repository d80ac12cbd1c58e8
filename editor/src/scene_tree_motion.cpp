// SceneTreeModel's motion rows (issue 16): after the scenes, each skin with its
// joints (selecting one selects the joint's node) and each animation with its
// channels (target node and path, sampler) and samplers (interpolation, key count,
// time range). Node rows of joints say "joint" in the Type column.
#include "scene_tree_model.h"

#include <QStringList>

#include "format_values.h"
#include "motion_playback.h"

namespace sherpa::editor {

namespace {
QString path_name(scene::AnimationPath p) {
    return QString::fromLatin1(to_string(p).data(), static_cast<qsizetype>(to_string(p).size()));
}
QString interpolation_name(scene::Interpolation i) {
    return QString::fromLatin1(to_string(i).data(), static_cast<qsizetype>(to_string(i).size()));
}
QString node_name(const scene::Scene& s, std::uint32_t n) {
    if (n >= s.nodes.size() || s.nodes[n].name.empty()) return SceneTreeModel::tr("Node %1").arg(n);
    return QString::fromStdString(s.nodes[n].name);
}
} // namespace

void SceneTreeModel::addMotion(const scene::Scene& scene) {
    joint_.assign(scene.nodes.size(), 0);
    for (std::size_t k = 0; k < scene.skins.size(); ++k) {
        const int skin = addItem(Kind::Skin, static_cast<int>(k), -1, -1);
        for (const std::uint32_t j : scene.skins[k].joints) {
            if (j >= scene.nodes.size()) continue;
            joint_[j] = 1;
            addItem(Kind::Joint, static_cast<int>(j), static_cast<int>(j), skin);
        }
    }
    for (std::size_t a = 0; a < scene.animations.size(); ++a) {
        const scene::Animation& anim = scene.animations[a];
        const int item = addItem(Kind::Animation, static_cast<int>(a), -1, -1);
        for (std::size_t c = 0; c < anim.channels.size(); ++c)
            addItem(Kind::Channel, static_cast<int>(c), static_cast<int>(anim.channels[c].node),
                    item);
        for (std::size_t s = 0; s < anim.samplers.size(); ++s)
            addItem(Kind::Sampler, static_cast<int>(s), -1, item);
    }
}

QString SceneTreeModel::motionName(const Item& it) const {
    const scene::Scene& s = *context_.scene();
    const auto idx = static_cast<std::size_t>(it.index);
    switch (it.kind) {
    case Kind::Skin: {
        const QString n = QString::fromStdString(s.skins[idx].name);
        return n.isEmpty() ? tr("Skin %1").arg(it.index) : tr("Skin %1: %2").arg(it.index).arg(n);
    }
    case Kind::Joint:
        return node_name(s, static_cast<std::uint32_t>(it.index));
    case Kind::Animation: {
        const QString n = QString::fromStdString(s.animations[idx].name);
        return n.isEmpty() ? tr("Animation %1").arg(it.index)
                           : tr("Animation %1: %2").arg(it.index).arg(n);
    }
    case Kind::Channel:
        return tr("Channel %1").arg(it.index);
    case Kind::Sampler:
        return tr("Sampler %1").arg(it.index);
    default:
        return {};
    }
}

QString SceneTreeModel::motionType(const Item& it) const {
    switch (it.kind) {
    case Kind::Skin:
        return tr("skin");
    case Kind::Joint:
        return tr("joint");
    case Kind::Animation:
        return tr("animation");
    case Kind::Channel:
        return tr("channel");
    case Kind::Sampler:
        return tr("sampler");
    default:
        return {};
    }
}

QString SceneTreeModel::motionDetail(const Item& it, bool full) const {
    const scene::Scene& s = *context_.scene();
    const auto idx = static_cast<std::size_t>(it.index);
    switch (it.kind) {
    case Kind::Skin: {
        const scene::Skin& skin = s.skins[idx];
        const QString joints = tr("%1 joints").arg(skin.joints.size());
        if (skin.skeleton < 0) return joints;
        return tr("%1, skeleton %2")
            .arg(joints, node_name(s, static_cast<std::uint32_t>(skin.skeleton)));
    }
    case Kind::Joint:
        return tr("node %1").arg(it.index);
    case Kind::Animation: {
        const scene::Animation& a = s.animations[idx];
        const QString text =
            tr("%1 s, %2 channels").arg(a.end - a.start, 0, 'f', 3).arg(a.channels.size());
        if (!full) return text;
        return tr("%1, %2 samplers, %3 keys, %4 to %5 s")
            .arg(text)
            .arg(a.samplers.size())
            .arg(key_times(a).size())
            .arg(a.start, 0, 'f', 3)
            .arg(a.end, 0, 'f', 3);
    }
    case Kind::Channel: {
        const scene::Animation& a = s.animations[static_cast<std::size_t>(
            items_[static_cast<std::size_t>(it.parent)].index)];
        const scene::AnimationChannel& c = a.channels[idx];
        return tr("%1 %2, sampler %3").arg(node_name(s, c.node), path_name(c.path)).arg(c.sampler);
    }
    case Kind::Sampler: {
        const scene::Animation& a = s.animations[static_cast<std::size_t>(
            items_[static_cast<std::size_t>(it.parent)].index)];
        const scene::AnimationSampler& sm = a.samplers[idx];
        const QString text =
            tr("%1, %2 keys").arg(interpolation_name(sm.interpolation)).arg(sm.times.size());
        if (!full || sm.times.empty()) return text;
        return tr("%1, %2 to %3 s")
            .arg(text)
            .arg(sm.times.front(), 0, 'f', 3)
            .arg(sm.times.back(), 0, 'f', 3);
    }
    default:
        return {};
    }
}

} // namespace sherpa::editor
