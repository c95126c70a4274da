#pragma once

#include "scene/model/Scene.hpp"

#include <QObject>
#include <vector>

namespace speculum::view {

// What is selected in the editor: a set of nodes, the scene camera, or nothing. Shared by the scene tree,
// the inspector and the viewport. The nodes are kept in the order they were selected; the last one is the
// current (active) node: the inspector shows it, the handles sit on it, Rename acts on it. The camera is
// never selected together with nodes. A node that leaves the scene (deleted, or undone) is deselected.
class Selection : public QObject {
    Q_OBJECT

public:
    explicit Selection(scene::Scene& scene, QObject* parent = nullptr);

    // The current node (the last one selected), kNoNode when no node is selected.
    scene::NodeId node() const { return m_nodes.empty() ? scene::kNoNode : m_nodes.back(); }
    // All selected nodes in the order they were selected: the current node is last.
    const std::vector<scene::NodeId>& nodes() const { return m_nodes; }
    bool contains(scene::NodeId id) const;
    // The selected nodes that have no selected ancestor, in selection order: what an action on the whole
    // selection acts on (a node under a selected ancestor goes with it; acting on both would act twice).
    std::vector<scene::NodeId> roots() const;
    bool isCamera() const { return m_camera; }
    bool isEmpty() const { return m_nodes.empty() && !m_camera; }
    const scene::Node* selectedNode() const { return m_scene.findNode(node()); }

public slots:
    // Selects only this node (kNoNode, or a node not in the scene: nothing).
    void selectNode(scene::NodeId id);
    // Ctrl+click: adds the node (it becomes the current one) or takes it out of the selection.
    void toggleNode(scene::NodeId id);
    // Selects these nodes (unknown ids and repeats are skipped); `current` becomes the current node when it
    // is among them, otherwise the last one is.
    void setNodes(const std::vector<scene::NodeId>& ids, scene::NodeId current = scene::kNoNode);
    void selectCamera();
    void clear();

signals:
    void changed();

private:
    void assign(std::vector<scene::NodeId> nodes, bool camera);

    scene::Scene& m_scene;
    std::vector<scene::NodeId> m_nodes;
    bool m_camera = false;
};

} // namespace speculum::view
