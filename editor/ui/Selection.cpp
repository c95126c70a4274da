#include "editor/ui/Selection.hpp"

namespace speculum::ui {

Selection::Selection(document::Scene& scene, QObject* parent)
    : QObject(parent)
    , m_scene(scene) {
    // Queued: a move takes the node out and puts it back within one command; only a node still gone
    // after the command is deselected.
    connect(
        &scene, &document::Scene::nodeRemoved, this,
        [this] {
            if (m_node != document::kNoNode && !m_scene.findNode(m_node)) {
                clear();
            }
        },
        Qt::QueuedConnection);
    connect(&scene, &document::Scene::sceneReset, this, &Selection::clear);
}

void Selection::selectNode(document::NodeId id) {
    if (id != document::kNoNode && !m_scene.findNode(id)) {
        id = document::kNoNode;
    }
    if (id == m_node && !m_camera) {
        return;
    }
    m_node = id;
    m_camera = false;
    emit changed();
}

void Selection::selectCamera() {
    if (m_camera) {
        return;
    }
    m_node = document::kNoNode;
    m_camera = true;
    emit changed();
}

void Selection::clear() {
    if (isEmpty()) {
        return;
    }
    m_node = document::kNoNode;
    m_camera = false;
    emit changed();
}

} // namespace speculum::ui
