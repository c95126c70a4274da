#pragma once

#include "base/Result.hpp"
#include "render/math/Projection.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"

#include <QString>
#include <glm/vec3.hpp>
#include <vector>

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

scene::NodeTree makeNode(NewNodeKind kind, const glm::dvec3& at = glm::dvec3(0.0));

// A node showing a model file (any format Assimp reads), named after the file. An imported reflector
// uses the file as the reflector's surface.
scene::NodeTree makeModelNode(const QString& absolutePath, const glm::dvec3& at = glm::dvec3(0.0),
                              bool asReflector = false);

// Where an imported model goes: its box `model` (in the coordinates it will be placed in) is moved so that
// it stands on the ground, centred on `focus` in x and z, and then along +X past every box of `occupied`
// it would overlap (with a small gap), so it does not land inside what is already there. The ground is the
// top of the highest flat box of `occupied` (a floor, a table top, a floor mirror: height at most a tenth
// of its width) under the focus and not above it, else y = 0; boxes wholly at or below the ground do not
// count as in the way. Returns the translation to add to the model's root.
glm::dvec3 placeOnGround(const render::math::Box& model, const glm::dvec3& focus,
                         const std::vector<render::math::Box>& occupied);

// The world boxes of the scene's meshes and mirrors at an animation time, one per node (what an import
// must not land in). Meshes come from `meshes` (already cached ones cost nothing); missing ones are
// skipped.
std::vector<render::math::Box> occupiedBoxes(const scene::Scene& scene, double timeSeconds,
                                             scene::MeshLibrary& meshes);

// Scales a node about the origin of its parent's space by `factor` (translation and scale alike): what
// fitting an imported model into a unit box does to its root.
void scaleAboutParentOrigin(scene::NodeData& node, double factor);

// `base` if no node of the scene has that name, else "base 2", "base 3", ...
std::string uniqueName(const scene::Scene& scene, const std::string& base);

// Copy of a node's subtree for "Duplicate": the copy's name is made unique; a reflector stays one (each
// has a map of its own).
scene::NodeTree duplicateTree(const scene::Scene& scene, scene::NodeId id);

} // namespace speculum::document
