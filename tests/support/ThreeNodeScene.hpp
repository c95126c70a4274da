#pragma once

// The small scene the command, undo and edit-operation tests share: A, B (with children B1, B2), C.
#include "scene/model/Scene.hpp"

#include <string>
#include <utility>
#include <vector>

namespace speculum::document::test {

inline NodeTree named(const std::string& name, std::vector<NodeTree> children = {}) {
    NodeTree node;
    node.data.name = name;
    node.children = std::move(children);
    return node;
}

inline SceneData threeNodeScene() {
    SceneData data;
    data.nodes = {named("A"), named("B", {named("B1"), named("B2")}), named("C")};
    return data;
}

// The id of the node called `name`, or kNoNode.
inline NodeId nodeIdByName(const Scene& scene, const std::string& name) {
    NodeId found = kNoNode;
    scene.forEachNode([&](const Node& node) {
        if (node.name() == name) {
            found = node.id();
        }
    });
    return found;
}

} // namespace speculum::document::test
