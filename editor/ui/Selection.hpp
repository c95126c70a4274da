#pragma once

#include "editor/document/Scene.hpp"

#include <QObject>

namespace speculum::ui {

// What is selected in the editor: one node, the scene camera, or nothing. Shared by the scene tree, the
// inspector and the viewport; a node that leaves the scene (deleted, or undone) is deselected.
class Selection : public QObject {
    Q_OBJECT

public:
    explicit Selection(document::Scene& scene, QObject* parent = nullptr);

    document::NodeId node() const { return m_node; }
    bool isCamera() const { return m_camera; }
    bool isEmpty() const { return m_node == document::kNoNode && !m_camera; }
    const document::Node* selectedNode() const { return m_scene.findNode(m_node); }

public slots:
    void selectNode(speculum::document::NodeId id);
    void selectCamera();
    void clear();

signals:
    void changed();

private:
    document::Scene& m_scene;
    document::NodeId m_node = document::kNoNode;
    bool m_camera = false;
};

} // namespace speculum::ui
