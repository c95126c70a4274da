#pragma once

// The small scene the command, undo and edit-operation tests share: A, B (with children B1, B2), C.
#include "scene/model/Scene.hpp"

#include <string>
#include <utility>
#include <vector>

namespace speculum::document::test {

inline scene::NodeTree named(const std::string& name, std::vector<scene::NodeTree> children = {}) {
    scene::NodeTree node;
    node.data.name = name;
    node.children = std::move(children);
    return node;
}

inline scene::SceneData threeNodeScene() {
    scene::SceneData data;
    data.nodes = {named("A"), named("B", {named("B1"), named("B2")}), named("C")};
    return data;
}

// The id of the node called `name`, or kNoNode.
inline scene::NodeId nodeIdByName(const scene::Scene& scene, const std::string& name) {
    scene::NodeId found = scene::kNoNode;
    scene.forEachNode([&](const scene::Node& node) {
        if (node.name() == name) {
            found = node.id();
        }
    });
    return found;
}

} // namespace speculum::document::test
