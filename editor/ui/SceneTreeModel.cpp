#include "editor/ui/SceneTreeModel.hpp"

#include "editor/document/EditOperations.hpp"
#include "editor/ui/Icons.hpp"

#include <QDataStream>
#include <QIODevice>
#include <QMimeData>
#include <QPalette>
#include <QUndoStack>
#include <algorithm>
#include <utility>

namespace speculum::ui {

using scene::kNoNode;
using scene::NodeId;

SceneTreeModel::SceneTreeModel(scene::Scene& scene, QUndoStack& undoStack, QObject* parent)
    : QAbstractItemModel(parent)
    , m_scene(scene)
    , m_undoStack(undoStack) {
    using scene::Scene;
    connect(&scene, &Scene::aboutToReset, this, [this] { beginResetModel(); });
    connect(&scene, &Scene::sceneReset, this, [this] { endResetModel(); });
    connect(&scene, &Scene::nodeAboutToBeAdded, this, [this](NodeId parent, int index) {
        const int row = rowOf(parent, index);
        beginInsertRows(parentIndexOf(parent), row, row);
    });
    connect(&scene, &Scene::nodeAdded, this, [this] { endInsertRows(); });
    connect(&scene, &Scene::nodeAboutToBeRemoved, this, [this](NodeId, NodeId parent, int index) {
        const int row = rowOf(parent, index);
        m_removing = true;
        beginRemoveRows(parentIndexOf(parent), row, row);
    });
    connect(&scene, &Scene::nodeRemoved, this, [this] {
        endRemoveRows();
        m_removing = false;
    });
    connect(&scene, &Scene::nodeChanged, this, [this](NodeId id) {
        const QModelIndex i = indexOf(id);
        emit dataChanged(i, i);
    });
}

QModelIndex SceneTreeModel::parentIndexOf(NodeId parent) const {
    return parent == kNoNode ? QModelIndex() : indexOf(parent);
}

QModelIndex SceneTreeModel::indexOf(NodeId id) const {
    const int sceneIndex = m_scene.indexOf(id);
    if (sceneIndex < 0) {
        return {};
    }
    return createIndex(rowOf(m_scene.parentOf(id), sceneIndex), 0, quintptr(id));
}

QModelIndex SceneTreeModel::cameraIndex() const {
    return createIndex(0, 0, kCameraId);
}

NodeId SceneTreeModel::nodeId(const QModelIndex& index) const {
    if (!index.isValid() || index.internalId() == kCameraId) {
        return kNoNode;
    }
    return NodeId(index.internalId());
}

bool SceneTreeModel::isCamera(const QModelIndex& index) const {
    return index.isValid() && index.internalId() == kCameraId;
}

QModelIndex SceneTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (column != 0 || row < 0) {
        return {};
    }
    if (!parent.isValid()) {
        if (row == 0) {
            return cameraIndex();
        }
        const auto& nodes = m_scene.topLevelNodes();
        if (row - 1 >= int(nodes.size())) {
            return {};
        }
        return createIndex(row, 0, quintptr(nodes[std::size_t(row - 1)]->id()));
    }
    const scene::Node* node = m_scene.findNode(nodeId(parent));
    if (!node || row >= node->childCount()) {
        return {};
    }
    return createIndex(row, 0, quintptr(node->child(row)->id()));
}

QModelIndex SceneTreeModel::parent(const QModelIndex& index) const {
    const NodeId id = nodeId(index);
    if (id == kNoNode) {
        return {};
    }
    const NodeId parent = m_scene.parentOf(id);
    return parent == kNoNode ? QModelIndex() : indexOf(parent);
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid()) {
        return m_scene.childCount(kNoNode) + 1;
    }
    if (parent.column() != 0 || isCamera(parent)) {
        return 0;
    }
    return m_scene.childCount(nodeId(parent));
}

int SceneTreeModel::columnCount(const QModelIndex&) const {
    return 1;
}

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const {
    if (isCamera(index)) {
        switch (role) {
        case Qt::DisplayRole:
            return tr("Camera");
        case Qt::DecorationRole:
            return kindIcon(NodeKind::Camera);
        case Qt::ToolTipRole:
            return tr("The scene camera (stills and the CLI render through it)");
        default:
            return {};
        }
    }
    const scene::Node* node = m_scene.findNode(nodeId(index));
    if (!node) {
        return {};
    }
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        return QString::fromStdString(node->name());
    case Qt::DecorationRole:
        return kindIcon(nodeKind(node->data()));
    case Qt::ToolTipRole:
        return tr("%1 — %2%3")
            .arg(QString::fromStdString(node->name()), kindName(nodeKind(node->data())),
                 m_scene.isHidden(node->id()) ? tr(" (hidden: in no picture; tick it to show it)")
                                              : QString());
    case Qt::CheckStateRole: // the row's eye: ticked while the node is in the pictures
        return node->data().hidden ? Qt::Unchecked : Qt::Checked;
    case Qt::ForegroundRole: // hidden, or under a hidden node: greyed
        return m_scene.isHidden(node->id()) ? QVariant(QPalette().brush(QPalette::Disabled, QPalette::Text))
                                            : QVariant();
    default:
        return {};
    }
}

bool SceneTreeModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    const NodeId id = nodeId(index);
    const scene::Node* node = m_scene.findNode(id);
    if (role == Qt::CheckStateRole && node) {
        const bool hidden = Qt::CheckState(value.toInt()) != Qt::Checked;
        return bool(document::setNodesHidden(m_scene, m_undoStack, {id}, hidden));
    }
    if (role != Qt::EditRole || !node) {
        return false;
    }
    // An empty name is refused; the old one stays.
    return bool(document::renameNode(m_scene, m_undoStack, id, value.toString().toStdString()));
}

Qt::ItemFlags SceneTreeModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) {
        return Qt::ItemIsDropEnabled; // the top level accepts drops
    }
    if (isCamera(index)) {
        return Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    }
    return Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsEditable | Qt::ItemIsDragEnabled |
           Qt::ItemIsDropEnabled | Qt::ItemIsUserCheckable;
}

QStringList SceneTreeModel::mimeTypes() const {
    return {QString::fromLatin1(kMimeType)};
}

QMimeData* SceneTreeModel::mimeData(const QModelIndexList& indexes) const {
    QByteArray bytes;
    QDataStream stream(&bytes, QIODevice::WriteOnly);
    for (const QModelIndex& index : indexes) {
        if (const NodeId id = nodeId(index); id != kNoNode) {
            stream << quint64(id);
        }
    }
    auto* data = new QMimeData;
    data->setData(QString::fromLatin1(kMimeType), bytes);
    return data;
}

std::vector<NodeId> SceneTreeModel::decode(const QMimeData* data) const {
    std::vector<NodeId> ids;
    if (!data || !data->hasFormat(QString::fromLatin1(kMimeType))) {
        return ids;
    }
    QDataStream stream(data->data(QString::fromLatin1(kMimeType)));
    while (!stream.atEnd()) {
        quint64 id = 0;
        stream >> id;
        if (m_scene.findNode(NodeId(id))) {
            ids.push_back(NodeId(id));
        }
    }
    return ids;
}

bool SceneTreeModel::canDropMimeData(const QMimeData* data, Qt::DropAction action, int, int,
                                     const QModelIndex& parent) const {
    if (action != Qt::MoveAction || isCamera(parent)) {
        return false;
    }
    const NodeId newParent = nodeId(parent);
    const auto ids = decode(data);
    if (ids.empty()) {
        return false;
    }
    // Not onto a dragged node nor into one's subtree: that would be a cycle.
    return std::none_of(ids.begin(), ids.end(), [&](NodeId id) { return m_scene.isAncestor(id, newParent); });
}

bool SceneTreeModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                  const QModelIndex& parent) {
    if (!canDropMimeData(data, action, row, column, parent)) {
        return false;
    }
    const NodeId newParent = nodeId(parent);
    const int sceneIndex = row < 0 ? -1 : (newParent == kNoNode ? std::max(row - 1, 0) : row);
    // The rows need no removing by the view afterwards (the default removeRows() refuses): the commands
    // moved the nodes already.
    return moveNodes(decode(data), newParent, sceneIndex);
}

bool SceneTreeModel::moveNodes(const std::vector<NodeId>& ids, NodeId newParent, int index) {
    return bool(document::moveNodes(m_scene, m_undoStack, ids, newParent, index));
}

} // namespace speculum::ui
