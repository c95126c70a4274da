#pragma once

#include "scene/model/Scene.hpp"

#include <QAbstractItemModel>
#include <vector>

class QUndoStack;

namespace speculum::ui {

// The document as a tree for QTreeView: the scene camera as the first top-level row, then the nodes in file
// order. It follows the Scene's signals, so every change from anywhere (inspector, viewport, undo) shows.
// Edits made in the view are the document's operations (document/EditOperations.hpp): renaming in place is
// renameNode, dragging nodes onto another (or between rows) moveNodes, each one undo step.
class SceneTreeModel : public QAbstractItemModel {
    Q_OBJECT

public:
    static constexpr quintptr kCameraId = ~quintptr(0);
    static constexpr const char* kMimeType = "application/x-speculum-node-ids";

    SceneTreeModel(scene::Scene& scene, QUndoStack& undoStack, QObject* parent = nullptr);

    QModelIndex indexOf(scene::NodeId id) const;
    QModelIndex cameraIndex() const;
    // kNoNode for the camera row and invalid indexes.
    scene::NodeId nodeId(const QModelIndex& index) const;
    bool isCamera(const QModelIndex& index) const;
    // True while rows are being removed: views move their current index then, which is no user's choice.
    bool isRemovingRows() const { return m_removing; }

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& index) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction; }
    Qt::DropActions supportedDragActions() const override { return Qt::MoveAction; }
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;

    // Moves nodes under newParent (kNoNode = top level) before scene position `index` of the new parent's
    // current children (-1 = at the end), one after the other in tree order, as one undo step
    // (document::moveNodes). False when a move is impossible (a target in one of their subtrees) or
    // nothing changes.
    bool moveNodes(const std::vector<scene::NodeId>& ids, scene::NodeId newParent, int index);

private:
    // Top-level scene index <-> model row (the camera row comes first).
    static int rowOf(scene::NodeId parent, int sceneIndex) {
        return parent == scene::kNoNode ? sceneIndex + 1 : sceneIndex;
    }
    QModelIndex parentIndexOf(scene::NodeId parent) const;
    std::vector<scene::NodeId> decode(const QMimeData* data) const;

    scene::Scene& m_scene;
    QUndoStack& m_undoStack;
    bool m_removing = false;
};

} // namespace speculum::ui
