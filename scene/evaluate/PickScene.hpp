#pragma once

#include "scene/evaluate/Picking.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"

#include <glm/mat4x4.hpp>
#include <unordered_map>

namespace speculum::scene {

// The pickable geometry of a scene at an animation time: every node's mesh (the reflector's included) and
// every mirror, with ids = NodeIds, and the scene's mirror depth. Meshes that fail to load are left out.
PickScene buildPickScene(const Scene& scene, double timeSeconds, MeshLibrary& meshes);

// World matrices of all nodes at an animation time (parent world × animated T × R × S).
std::unordered_map<NodeId, glm::dmat4> worldMatrices(const Scene& scene, double timeSeconds);

// The world matrix of a node's parent (identity for top-level nodes) at an animation time.
glm::dmat4 parentWorldMatrix(const Scene& scene, NodeId id, double timeSeconds);

} // namespace speculum::scene
