#pragma once

#include "editor/document/Scene.hpp"
#include "render/Result.hpp"

#include <QString>
#include <glm/vec3.hpp>

namespace speculum::document {

// The nodes the Add menu creates, with sensible defaults, as values ready for AddNodeCommand. `at` is
// where the new node stands (the editor passes the point the view looks at).

enum class NewNodeKind {
    Empty,
    Teapot,
    Sphere,
    Box,
    Plane,
    Mirror,          // planar mirror: a `mirror` component, 2×2 units, facing +Y
    ReflectorSphere, // curved reflector whose surface is a sphere
    ReflectorTeapot, // ... a teapot
    PointLight,
    DirectionalLight,
    SpotLight,
};

// "Teapot", "Mirror", "Point light", ...: the base of the new node's name and the menu text.
QString displayName(NewNodeKind kind);

NodeTree makeNode(NewNodeKind kind, const glm::dvec3& at = glm::dvec3(0.0));

// A node showing a model file (any format Assimp reads), named after the file. An imported reflector
// uses the file as the reflector's surface.
NodeTree makeModelNode(const QString& absolutePath, const glm::dvec3& at = glm::dvec3(0.0),
                       bool asReflector = false);

// `base` if no node of the scene has that name, else "base 2", "base 3", ...
std::string uniqueName(const Scene& scene, const std::string& base);

// The node that carries the scene's curved reflector (at most one per scene), kNoNode if none.
NodeId reflectorNode(const Scene& scene);

// Whether `tree` may be added: a scene has at most one reflector. The message says which node has it.
render::Status canAdd(const Scene& scene, const NodeTree& tree);

// Copy of a node's subtree for "Duplicate": the copy's name is made unique, and a reflector in the copy is
// dropped (with the returned flag set) since the scene may hold only one.
NodeTree duplicateTree(const Scene& scene, NodeId id, bool* droppedReflector = nullptr);

} // namespace speculum::document
