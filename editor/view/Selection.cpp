#include "editor/view/Selection.hpp"

#include <algorithm>

namespace speculum::view {

Selection::Selection(scene::Scene& scene, QObject* parent)
    : QObject(parent)
    , m_scene(scene) {
    // Queued: a move takes the node out and puts it back within one command; only a node still gone
    // after the command is deselected.
    connect(
        &scene, &scene::Scene::nodeRemoved, this,
        [this] {
            std::vector<scene::NodeId> kept;
            std::copy_if(m_nodes.begin(), m_nodes.end(), std::back_inserter(kept),
                         [this](scene::NodeId id) { return m_scene.findNode(id) != nullptr; });
            assign(std::move(kept), m_camera);
        },
        Qt::QueuedConnection);
    connect(&scene, &scene::Scene::sceneReset, this, &Selection::clear);
}

bool Selection::contains(scene::NodeId id) const {
    return std::find(m_nodes.begin(), m_nodes.end(), id) != m_nodes.end();
}

std::vector<scene::NodeId> Selection::roots() const {
    std::vector<scene::NodeId> roots;
    for (scene::NodeId id : m_nodes) {
        if (!m_scene.findNode(id)) {
            continue;
        }
        const bool underAnother = std::any_of(m_nodes.begin(), m_nodes.end(), [&](scene::NodeId other) {
            return other != id && m_scene.isAncestor(other, id);
        });
        if (!underAnother) {
            roots.push_back(id);
        }
    }
    return roots;
}

void Selection::assign(std::vector<scene::NodeId> nodes, bool camera) {
    if (nodes == m_nodes && camera == m_camera) {
        return;
    }
    m_nodes = std::move(nodes);
    m_camera = camera;
    emit changed();
}

void Selection::selectNode(scene::NodeId id) {
    if (id == scene::kNoNode || !m_scene.findNode(id)) {
        assign({}, false);
    } else {
        assign({id}, false);
    }
}

void Selection::toggleNode(scene::NodeId id) {
    if (id == scene::kNoNode || !m_scene.findNode(id)) {
        return;
    }
    std::vector<scene::NodeId> nodes = m_nodes;
    if (const auto it = std::find(nodes.begin(), nodes.end(), id); it != nodes.end()) {
        nodes.erase(it);
    } else {
        nodes.push_back(id);
    }
    assign(std::move(nodes), false);
}

void Selection::setNodes(const std::vector<scene::NodeId>& ids, scene::NodeId current) {
    std::vector<scene::NodeId> nodes;
    bool hasCurrent = false;
    for (scene::NodeId id : ids) {
        if (id == scene::kNoNode || !m_scene.findNode(id) ||
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
