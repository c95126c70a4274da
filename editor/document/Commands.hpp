#pragma once

#include "scene/model/Scene.hpp"

#include <QUndoCommand>
#include <memory>
#include <vector>

class QUndoStack;

namespace speculum::document {

// Undoable edits of a Scene. Push them on a QUndoStack (push() runs redo() once), preferably through
// pushEdit() below. Commands refer to nodes by NodeId, which survives remove/undo cycles, so a stack of
// commands stays valid in any order of undo/redo.
//
// Exact undo: a command whose net effect is nothing is obsolete (QUndoCommand::isObsolete) and never stays
// on a stack. Each command knows at construction whether it changes anything (a property set to the value
// it has, a rename to the same name, a move to where the node is); a merge that brings a mergeable command
// back to where it started (a drag that returns, a drag cancelled with Esc) makes it obsolete, and
// QUndoStack then removes the step and restores the clean state it had.

// Pushes `command` (taking ownership) unless it is obsolete from the start. QUndoStack::push drops an
// obsolete command too, but only after it has thrown away the redo steps, and a clean state among them;
// this leaves the stack exactly as it was. Returns whether the command ran (as a step of its own or merged
// into the previous one).
bool pushEdit(QUndoStack& stack, QUndoCommand* command);

// Replaces the data of several nodes at once, as one undo step: a handle drag on a multiple selection.
// Consecutive commands with the same non-empty mergeKey over the same nodes (same ids, same order) merge,
// so a whole drag stays one step however many mouse moves it takes.
class SetNodesDataCommand : public QUndoCommand {
public:
    struct Change {
        scene::NodeId id = scene::kNoNode;
        scene::NodeData data;
    };
    SetNodesDataCommand(scene::Scene& scene, std::vector<Change> changes, const QString& text = {},
                        const QString& mergeKey = {}, QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    scene::Scene& m_scene;
    std::vector<scene::NodeId> m_nodes;
    std::vector<scene::NodeData> m_before;
    std::vector<scene::NodeData> m_after;
    QString m_mergeKey;
};

// Replaces one node's whole data: a SetNodesDataCommand of one node. Consecutive commands on the same node
// with the same non-empty mergeKey merge into one undo step (a slider drag: use e.g. "material.specular";
// start a new key, e.g. with a drag serial number, when a new drag begins). It has a merge id of its own, so
// an inspector edit never merges into a handle drag over the same node.
class SetNodeDataCommand : public SetNodesDataCommand {
public:
    SetNodeDataCommand(scene::Scene& scene, scene::NodeId id, scene::NodeData data, const QString& text = {},
                       const QString& mergeKey = {}, QUndoCommand* parent = nullptr);
    int id() const override;
};

// Changes only the name (a separate command so the undo text reads "Rename").
class RenameNodeCommand : public QUndoCommand {
public:
    RenameNodeCommand(scene::Scene& scene, scene::NodeId id, std::string name,
                      QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;

private:
    scene::Scene& m_scene;
    scene::NodeId m_node;
    std::string m_before;
    std::string m_after;
};

// Adds a subtree under parent (kNoNode = top level) at index (-1 = append). The new node's id is known after
// the first redo() (i.e. after push) and stays the same over undo/redo.
class AddNodeCommand : public QUndoCommand {
public:
    AddNodeCommand(scene::Scene& scene, scene::NodeTree tree, scene::NodeId parent = scene::kNoNode,
                   int index = -1, QUndoCommand* parent_ = nullptr);
    void undo() override;
    void redo() override;
    scene::NodeId nodeId() const { return m_node; }

private:
    scene::Scene& m_scene;
    scene::NodeTree m_tree;
    scene::NodeId m_parent;
    int m_index;
    scene::NodeId m_node = scene::kNoNode;
    std::unique_ptr<scene::Node> m_detached; // held while undone
};

// Removes a node and its subtree; undo puts the same nodes (same ids) back at the same place.
class RemoveNodeCommand : public QUndoCommand {
public:
    RemoveNodeCommand(scene::Scene& scene, scene::NodeId id, QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;

private:
    scene::Scene& m_scene;
    scene::NodeId m_node;
    scene::NodeId m_parent = scene::kNoNode;
    int m_index = -1;
    std::unique_ptr<scene::Node> m_detached; // held while done
};

// Moves a node (with its subtree) under another parent / to another position. newIndex counts positions in
// the new parent's child list after the node has been taken out. Moving a node into its own subtree is a
// programmer error (check Scene::isAncestor first).
class MoveNodeCommand : public QUndoCommand {
public:
    MoveNodeCommand(scene::Scene& scene, scene::NodeId id, scene::NodeId newParent, int newIndex,
                    QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;

private:
    void move(scene::NodeId parent, int index);
    bool movesNothing() const;
    scene::Scene& m_scene;
    scene::NodeId m_node;
    scene::NodeId m_oldParent;
    int m_oldIndex;
    scene::NodeId m_newParent;
    int m_newIndex;
};

// Scene settings; consecutive commands merge (one undo step per slider drag) when mergeable is true.
class SetSettingsCommand : public QUndoCommand {
public:
    SetSettingsCommand(scene::Scene& scene, scene::SceneSettings settings, bool mergeable = false,
                       QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;
    // Mergeable commands merge only with the next one of the same key (empty by default): the inspector
    // uses "property#gesture" so that one slider drag is one step but two different edits are two.
    void setMergeKey(const QString& key) { m_mergeKey = key; }

private:
    scene::Scene& m_scene;
    scene::SceneSettings m_before;
    scene::SceneSettings m_after;
    bool m_mergeable;
    QString m_mergeKey;
};

// Camera; consecutive mergeable commands merge (one undo step per orbit/pan drag).
class SetCameraCommand : public QUndoCommand {
public:
    SetCameraCommand(scene::Scene& scene, scene::CameraData camera, bool mergeable = false,
                     QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;
    // Mergeable commands merge only with the next one of the same key (empty by default): the inspector
    // uses "property#gesture" so that one slider drag is one step but two different edits are two.
    void setMergeKey(const QString& key) { m_mergeKey = key; }

private:
    scene::Scene& m_scene;
    scene::CameraData m_before;
    scene::CameraData m_after;
    bool m_mergeable;
    QString m_mergeKey;
};

} // namespace speculum::document
