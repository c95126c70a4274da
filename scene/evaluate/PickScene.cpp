#include "scene/evaluate/PickScene.hpp"

#include "scene/model/NodeMath.hpp"

namespace speculum::scene {

namespace {

void collectWorlds(const Node& node, const glm::dmat4& parent, double t,
                   std::unordered_map<NodeId, glm::dmat4>& out) {
    const glm::dmat4 world = parent * animatedLocalMatrix(node.data(), t);
    out[node.id()] = world;
    for (const auto& child : node.children()) {
        collectWorlds(*child, world, t, out);
    }
}

} // namespace

std::unordered_map<NodeId, glm::dmat4> worldMatrices(const Scene& scene, double timeSeconds) {
    std::unordered_map<NodeId, glm::dmat4> out;
    for (const auto& node : scene.topLevelNodes()) {
        collectWorlds(*node, glm::dmat4(1.0), timeSeconds, out);
    }
    return out;
}

glm::dmat4 parentWorldMatrix(const Scene& scene, NodeId id, double timeSeconds) {
    glm::dmat4 world(1.0);
    std::vector<const Node*> chain;
    for (const Node* n = scene.findNode(id); n && n->parent(); n = n->parent()) {
        chain.push_back(n->parent());
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        world = world * animatedLocalMatrix((*it)->data(), timeSeconds);
    }
    return world;
}

PickScene buildPickScene(const Scene& scene, double timeSeconds, MeshLibrary& meshes) {
    PickScene out;
    out.mirrorDepth = scene.settings().mirrorDepth;
    const auto worlds = worldMatrices(scene, timeSeconds);
    std::vector<Warning> ignored; // the viewport reports load problems already
    scene.forEachNode([&](const Node& node) {
        const NodeData& d = node.data();
        if (scene.isHidden(node.id())) {
            return; // not in the picture: nothing to click
        }
        const glm::dmat4& world = worlds.at(node.id());
        if (d.mesh) {
            if (auto mesh = meshes.get(*d.mesh, ignored)) {
                out.meshes.push_back(PickMesh{node.id(), *mesh, world});
            }
        }
        if (d.mirror) {
            out.mirrors.push_back(PickMirror{node.id(), world, d.mirror->size});
        }
    });
    return out;
}

} // namespace speculum::scene
