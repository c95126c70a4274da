#include "editor/view/Selection.hpp"

#include <algorithm>

namespace speculum::view {

Selection::Selection(document::Scene& scene, QObject* parent)
    : QObject(parent)
    , m_scene(scene) {
    // Queued: a move takes the node out and puts it back within one command; only a node still gone
    // after the command is deselected.
    connect(
        &scene, &document::Scene::nodeRemoved, this,
        [this] {
            std::vector<document::NodeId> kept;
            std::copy_if(m_nodes.begin(), m_nodes.end(), std::back_inserter(kept),
                         [this](document::NodeId id) { return m_scene.findNode(id) != nullptr; });
            assign(std::move(kept), m_camera);
        },
        Qt::QueuedConnection);
    connect(&scene, &document::Scene::sceneReset, this, &Selection::clear);
}

bool Selection::contains(document::NodeId id) const {
    return std::find(m_nodes.begin(), m_nodes.end(), id) != m_nodes.end();
}

std::vector<document::NodeId> Selection::roots() const {
    std::vector<document::NodeId> roots;
    for (document::NodeId id : m_nodes) {
        if (!m_scene.findNode(id)) {
            continue;
        }
        const bool underAnother = std::any_of(m_nodes.begin(), m_nodes.end(), [&](document::NodeId other) {
            return other != id && m_scene.isAncestor(other, id);
        });
        if (!underAnother) {
            roots.push_back(id);
        }
    }
    return roots;
}

void Selection::assign(std::vector<document::NodeId> nodes, bool camera) {
    if (nodes == m_nodes && camera == m_camera) {
        return;
    }
    m_nodes = std::move(nodes);
    m_camera = camera;
    emit changed();
}

void Selection::selectNode(document::NodeId id) {
    if (id == document::kNoNode || !m_scene.findNode(id)) {
        assign({}, false);
    } else {
        assign({id}, false);
    }
}

void Selection::toggleNode(document::NodeId id) {
    if (id == document::kNoNode || !m_scene.findNode(id)) {
        return;
    }
    std::vector<document::NodeId> nodes = m_nodes;
    if (const auto it = std::find(nodes.begin(), nodes.end(), id); it != nodes.end()) {
        nodes.erase(it);
    } else {
        nodes.push_back(id);
    }
    assign(std::move(nodes), false);
}

void Selection::setNodes(const std::vector<document::NodeId>& ids, document::NodeId current) {
    std::vector<document::NodeId> nodes;
    bool hasCurrent = false;
    for (document::NodeId id : ids) {
        if (id == document::kNoNode || !m_scene.findNode(id) ||
            std::find(nodes.begin(), nodes.end(), id) != nodes.end()) {
            continue;
        }
        if (id == current) {
            hasCurrent = true;
        } else {
            nodes.push_back(id);
        }
    }
    if (hasCurrent) {
        nodes.push_back(current);
    }
    assign(std::move(nodes), false);
}

void Selection::selectCamera() {
    assign({}, true);
}

void Selection::clear() {
    assign({}, false);
}

} // namespace speculum::view
