#include "scene_tree_model.h"

#include <QFont>
#include <QStringList>
#include <map>

#include "format_values.h"
#include "validation_model.h"

namespace sherpa::editor {

namespace {
// glTF allows DAGs only through multiple scenes; a guard against malformed cycles anyway.
constexpr int kMaxDepth = 256;

QString from_std(const std::string& s) {
    return QString::fromStdString(s);
}
} // namespace

SceneTreeModel::SceneTreeModel(const EditorContext& context, QObject* parent)
    : QAbstractItemModel(parent), context_(context) {
    connect(&context_, &EditorContext::sceneReady, this, [this] {
        beginResetModel();
        rebuild();
        endResetModel();
    });
    connect(&context_.visibility(), &NodeVisibility::changed, this, [this] {
        // Checkboxes of every node row may change (a hidden parent greys its subtree).
        for (int n = 0; n < static_cast<int>(node_item_.size()); ++n) {
            const QModelIndex i = indexOfNode(n);
            if (i.isValid()) Q_EMIT dataChanged(i, i.siblingAtColumn(DetailColumn));
        }
    });
    rebuild();
}

int SceneTreeModel::addItem(Kind kind, int index, int node, int parent) {
    const int id = static_cast<int>(items_.size());
    std::vector<int>& siblings =
        parent < 0 ? top_ : items_[static_cast<std::size_t>(parent)].children;
    items_.push_back({kind, index, node, parent, static_cast<int>(siblings.size()), {}});
    // `siblings` may dangle after push_back when it lives in items_: look it up again.
    (parent < 0 ? top_ : items_[static_cast<std::size_t>(parent)].children).push_back(id);
    return id;
}

void SceneTreeModel::rebuild() {
    items_.clear();
    top_.clear();
    node_item_.clear();
    rebuildMarks();
    const scene::Scene* scene = context_.scene();
    if (!scene) return;
    node_item_.assign(scene->nodes.size(), -1);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> primitive_info;
    for (std::size_t i = 0; i < scene->primitives.size(); ++i)
        primitive_info[{scene->primitives[i].mesh, scene->primitives[i].primitive}] =
            static_cast<int>(i);

    // Recursion over the node graph; primitives, lights and cameras hang under their node.
    struct Walker {
        SceneTreeModel& m;
        const scene::Scene& s;
        const std::map<std::pair<std::uint32_t, std::uint32_t>, int>& info;
        bool displayed;
        void node(int n, int parent, int depth) {
            if (depth > kMaxDepth) return;
            const int item = m.addItem(Kind::Node, n, n, parent);
            if (displayed && m.node_item_[static_cast<std::size_t>(n)] < 0)
                m.node_item_[static_cast<std::size_t>(n)] = item;
            const scene::Node& nd = s.nodes[static_cast<std::size_t>(n)];
            if (nd.mesh >= 0 && static_cast<std::size_t>(nd.mesh) < s.mesh_primitives.size()) {
                const auto& prims = s.mesh_primitives[static_cast<std::size_t>(nd.mesh)];
                for (std::size_t p = 0; p < prims.size(); ++p) {
                    const auto it = info.find(
                        {static_cast<std::uint32_t>(nd.mesh), static_cast<std::uint32_t>(p)});
                    if (it == info.end()) continue;
                    const int pi = m.addItem(Kind::Primitive, it->second, n, item);
                    if (prims[p] >= 0)
                        m.addItem(Kind::Material,
                                  static_cast<int>(
                                      s.meshes[static_cast<std::size_t>(prims[p])].material_id),
                                  n, pi);
                }
            }
            if (nd.light >= 0) m.addItem(Kind::Light, nd.light, n, item);
            if (nd.camera >= 0) m.addItem(Kind::Camera, nd.camera, n, item);
            for (std::uint32_t c : nd.children) node(static_cast<int>(c), item, depth + 1);
        }
    };
    for (std::size_t si = 0; si < scene->scenes.size(); ++si) {
        const int root = addItem(Kind::SceneRoot, static_cast<int>(si), -1, -1);
        Walker w{*this, *scene, primitive_info, static_cast<int>(si) == scene->displayed_scene};
        for (std::uint32_t r : scene->scenes[si].roots) w.node(static_cast<int>(r), root, 0);
    }
    addMotion(*scene);
}

QModelIndex SceneTreeModel::index(int row, int column, const QModelIndex& parent) const {
    const std::vector<int>& rows = parent.isValid() ? items_[parent.internalId()].children : top_;
    if (row < 0 || row >= static_cast<int>(rows.size()) || column < 0 || column >= ColumnCount)
        return {};
    return createIndex(row, column, static_cast<quintptr>(rows[static_cast<std::size_t>(row)]));
}

QModelIndex SceneTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid()) return {};
    const int p = items_[child.internalId()].parent;
    if (p < 0) return {};
    return createIndex(items_[static_cast<std::size_t>(p)].row, 0, static_cast<quintptr>(p));
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const {
    if (parent.isValid() && parent.column() != 0) return 0;
    return static_cast<int>(parent.isValid() ? items_[parent.internalId()].children.size()
                                             : top_.size());
}

int SceneTreeModel::columnCount(const QModelIndex&) const {
    return ColumnCount;
}

QString SceneTreeModel::name(const Item& it) const {
    const scene::Scene& s = *context_.scene();
    const auto idx = static_cast<std::size_t>(it.index);
    switch (it.kind) {
    case Kind::SceneRoot: {
        // The authored name is data (often Blender's default "Scene"): shown after a
        // translated label, so the root reads as a scene in every language.
        const QString n = from_std(s.scenes[idx].name);
        return n.isEmpty() ? tr("Scene %1").arg(it.index) : tr("Scene %1: %2").arg(it.index).arg(n);
    }
    case Kind::Node: {
        const QString n = from_std(s.nodes[idx].name);
        return n.isEmpty() ? tr("Node %1").arg(it.index) : n;
    }
    case Kind::Primitive:
        return tr("Primitive %1").arg(s.primitives[idx].primitive);
    case Kind::Material: {
        const QString n = from_std(s.materials[idx].name);
        return n.isEmpty() ? tr("Material %1").arg(it.index) : n;
    }
    case Kind::Light: {
        const QString n = from_std(s.lights[idx].name);
        return n.isEmpty() ? tr("Light %1").arg(it.index) : n;
    }
    case Kind::Camera: {
        const QString n = from_std(s.cameras[idx].name);
        return n.isEmpty() ? tr("Camera %1").arg(it.index) : n;
    }
    case Kind::Skin:
    case Kind::Joint:
    case Kind::Animation:
    case Kind::Channel:
    case Kind::Sampler:
        return motionName(it);
    }
    return {};
}

// A node's own transform: what differs from identity, or (full) the whole TRS.
QString SceneTreeModel::nodeTransform(const scene::Node& n, bool full) const {
    if (n.has_matrix) return tr("matrix");
    if (!full) {
        QStringList parts;
        if (n.translation != glm::vec3(0.0f)) parts << tr("T %1").arg(format::vec(n.translation));
        if (n.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) parts << tr("rotated");
        if (n.scale != glm::vec3(1.0f)) parts << tr("S %1").arg(format::vec(n.scale));
        return parts.isEmpty() ? tr("identity") : parts.join(QStringLiteral("  "));
    }
    return tr("T %1  R %2  S %3")
        .arg(format::vec(n.translation))
        .arg(format::vec(glm::vec4(n.rotation.x, n.rotation.y, n.rotation.z, n.rotation.w)))
        .arg(format::vec(n.scale));
}

QString SceneTreeModel::detail(const Item& it, bool full) const {
    const scene::Scene& s = *context_.scene();
    const auto idx = static_cast<std::size_t>(it.index);
    switch (it.kind) {
    case Kind::SceneRoot:
        return it.index == s.displayed_scene ? tr("displayed") : QString();
    case Kind::Node: {
        const scene::Node& n = s.nodes[idx];
        // EXT_mesh_gpu_instancing: the node's mesh is drawn once per row, not at the node.
        QString instances;
        if (n.instancing)
            instances = n.instancing->rows.size() == n.instancing->file_rows
                            ? tr("×%1 GPU instances").arg(n.instancing->rows.size())
                            : tr("×%1 GPU instances (of %2 rows)")
                                  .arg(n.instancing->rows.size())
                                  .arg(n.instancing->file_rows);
        const QString transform = nodeTransform(n, full);
        return instances.isEmpty() ? transform : instances + QStringLiteral("  ") + transform;
    }
    case Kind::Primitive: {
        const scene::PrimitiveInfo& p = s.primitives[idx];
        if (p.engine_mesh < 0) return tr("skipped: %1").arg(from_std(p.skipped_reason));
        if (!full && p.mode == scene::PrimitiveMode::Triangles)
            return tr("%1 vertices, %2 triangles").arg(p.vertices).arg(p.triangles);
        return tr("%1, %2 vertices, %3 triangles")
            .arg(format::primitiveMode(p.mode))
            .arg(p.vertices)
            .arg(p.triangles);
    }
    case Kind::Material:
        return format::alphaMode(s.materials[idx].alpha_mode);
    case Kind::Light: {
        const scene::Light& l = s.lights[idx];
        return l.type == scene::LightType::Directional ? tr("directional")
               : l.type == scene::LightType::Point     ? tr("point")
                                                       : tr("spot");
    }
    case Kind::Camera:
        return s.cameras[idx].type == scene::CameraType::Perspective ? tr("perspective")
                                                                     : tr("orthographic");
    case Kind::Skin:
    case Kind::Joint:
    case Kind::Animation:
    case Kind::Channel:
    case Kind::Sampler:
        return motionDetail(it, full);
    }
    return {};
}

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !context_.scene()) return {};
    const Item& it = items_[index.internalId()];
    switch (role) {
    case Qt::ToolTipRole:
        if (index.column() == NameColumn && mark(it) >= 0)
            return tr("Validation messages name this (see the Validation dock).");
        return index.column() == DetailColumn ? detail(it, true) : QVariant();
    case Qt::DecorationRole:
        return index.column() == NameColumn && mark(it) >= 0 ? severity_icon(mark(it)) : QVariant();
    case Qt::DisplayRole:
        if (index.column() == NameColumn) return name(it);
        if (index.column() == DetailColumn) return detail(it);
        switch (it.kind) {
        case Kind::SceneRoot:
            return tr("scene");
        case Kind::Node:
            return static_cast<std::size_t>(it.index) < joint_.size() &&
                           joint_[static_cast<std::size_t>(it.index)]
                       ? tr("joint")
                       : tr("node");
        case Kind::Primitive:
            return tr("primitive");
        case Kind::Material:
            return tr("material");
        case Kind::Light:
            return tr("light");
        case Kind::Camera:
            return tr("camera");
        case Kind::Skin:
        case Kind::Joint:
        case Kind::Animation:
        case Kind::Channel:
        case Kind::Sampler:
            return motionType(it);
        }
        return {};
    case Qt::CheckStateRole:
        if (index.column() == NameColumn && it.kind == Kind::Node)
            return context_.visibility().nodeVisible(it.index) ? Qt::Checked : Qt::Unchecked;
        return {};
    case Qt::FontRole:
        if (it.kind == Kind::Node && context_.selection().current().node == it.index) {
            QFont f;
            f.setBold(true);
            return f;
        }
        return {};
    case KindRole:
        return static_cast<int>(it.kind);
    case IndexRole:
        return it.index;
    case NodeRole:
        return it.node;
    default:
        return {};
    }
}

bool SceneTreeModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::CheckStateRole) return false;
    const Item& it = items_[index.internalId()];
    if (it.kind != Kind::Node) return false;
    // Action out; the view updates when the context says the visibility changed.
    Q_EMIT visibilityRequested(it.index, value.toInt() == Qt::Checked);
    return true;
}

Qt::ItemFlags SceneTreeModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == NameColumn && items_[index.internalId()].kind == Kind::Node)
        f |= Qt::ItemIsUserCheckable;
    return f;
}

QVariant SceneTreeModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case NameColumn:
        return tr("Name");
    case TypeColumn:
        return tr("Type");
    case DetailColumn:
        return tr("Details");
    default:
        return {};
    }
}

QModelIndex SceneTreeModel::indexOfNode(int node) const {
    if (node < 0 || static_cast<std::size_t>(node) >= node_item_.size()) return {};
    const int item = node_item_[static_cast<std::size_t>(node)];
    if (item < 0) return {};
    return createIndex(items_[static_cast<std::size_t>(item)].row, 0, static_cast<quintptr>(item));
}

QModelIndex SceneTreeModel::indexOfPrimitive(int node, int mesh) const {
    const QModelIndex n = indexOfNode(node);
    if (!n.isValid() || !context_.scene()) return n;
    for (int child : items_[n.internalId()].children) {
        const Item& it = items_[static_cast<std::size_t>(child)];
        if (it.kind == Kind::Primitive &&
            context_.scene()->primitives[static_cast<std::size_t>(it.index)].engine_mesh == mesh)
            return createIndex(it.row, 0, static_cast<quintptr>(child));
    }
    return n;
}

} // namespace sherpa::editor
