#pragma once

#include "base/Result.hpp"
#include "editor/document/NodeFactory.hpp"
#include "render/frame/FrameInput.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/import/ModelImport.hpp"
#include "scene/model/Scene.hpp"

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

class QUndoStack;

namespace speculum::document {

// The editor's editing operations (Edit, Add and Import, a rename or a drag in the scene tree, Set Scene
// Camera from View): each checks what it is asked, changes the scene through commands inside one
// EditTransaction and so leaves exactly one undo step with the label the Undo menu shows, or, when it is
// refused or would change nothing, no step and the scene as it was. The widgets call these and build no
// commands of their own.

// Adds `tree` at the top level, its name made unique ("Sphere 2"): "Add “Sphere 2”". Refused when the scene
// would get a second curved reflector (the message names the node that has it). Returns the new node.
base::Result<scene::NodeId> addNodeTree(scene::Scene& scene, QUndoStack& undo, scene::NodeTree tree);

// Deletes the nodes with their subtrees: "Delete “Box”", or "Delete 3 nodes". `roots` are outermost nodes
// (view::Selection::roots()): none under another. Unknown ids are skipped; none left is an error.
base::Status deleteNodes(scene::Scene& scene, QUndoStack& undo, const std::vector<scene::NodeId>& roots);

// Hides the nodes (and so what is under them) or shows them again: "Hide “A”", "Show 3 nodes", one undo
// step; nodes already so change nothing (no step when none changes). showAllNodes shows every hidden node.
base::Status setNodesHidden(scene::Scene& scene, QUndoStack& undo, const std::vector<scene::NodeId>& ids,
                            bool hidden);
base::Status showAllNodes(scene::Scene& scene, QUndoStack& undo);

struct Duplicates {
    std::vector<scene::NodeId> copies;          // one per root, in the same order
    scene::NodeId currentCopy = scene::kNoNode; // the copy of `current`, or of the root it lies under
};
// Copies each root (with its subtree) right after itself under the same parent, each copy's name unique
// against the copies made before it: "Duplicate “Box”", or "Duplicate 3 nodes". Each copy is moved along
// world +X past its original (its width and a gap) and past whatever else is there at that height, so it
// never lands exactly on the original. `meshes` gives the boxes of model files (without it only built-in
// shapes and mirrors are measured: a file is never read here); `timeSeconds` is the animation time at
// which they are measured.
base::Result<Duplicates> duplicateNodes(scene::Scene& scene, QUndoStack& undo,
                                        const std::vector<scene::NodeId>& roots,
                                        scene::NodeId current = scene::kNoNode,
                                        scene::MeshLibrary* meshes = nullptr, double timeSeconds = 0.0);

// "Rename “A” to “B”". The name is trimmed; an empty or unchanged name is refused.
base::Status renameNode(scene::Scene& scene, QUndoStack& undo, scene::NodeId id, const std::string& name);

// Moves the nodes under newParent (kNoNode: the top level) before scene position `index` of its current
// children (-1: at the end), one after the other in tree order; a node under another of them goes with
// that one. "Move “A”", or "Move 3 nodes". Refused when a node would go into its own subtree; a move that
// changes no position leaves no step (and is an error).
base::Status moveNodes(scene::Scene& scene, QUndoStack& undo, const std::vector<scene::NodeId>& ids,
                       scene::NodeId newParent, int index);
// Of `ids`, those that exist and lie under no other of them, sorted in tree order (repeats dropped).
std::vector<scene::NodeId> outermostInTreeOrder(const scene::Scene& scene,
                                                const std::vector<scene::NodeId>& ids);

// Makes the scene camera look like `view` (position, target, up; far kept within the depth range the
// renderer allows): "Set scene camera from view". A view that already is the scene camera leaves no step.
base::Status setCameraFromView(scene::Scene& scene, QUndoStack& undo, const render::Camera& view);

// How an imported model lands in the scene.
struct ImportPlacement {
    bool asReflector = false;  // the whole file is the curved reflector's surface
    bool fitToUnitBox = false; // scaled to fit a 1-unit box instead of its real size
    double fitToSize = 0.0;    // > 0: scaled so its largest side is this long (the scene's, when asked)
    glm::dvec3 focus{0.0};     // where the view looks: the model stands on the ground there, moved along +X
                               // past what is already there
    double timeSeconds = 0.0;  // the animation time at which "what is already there" is measured
};
struct PlacedModel {
    scene::NodeTree tree;  // ready for addNodeTree
    double fit = 1.0;      // the scale fitting applied (1: real size)
    glm::dvec3 size{0.0};  // of the placed model, scene units
    render::math::Box box; // where it lands, in the top level's coordinates
    // The largest side of what the scene already holds (0: nothing yet), and how many times the model's
    // largest side is that: what an import far too big for the scene is judged by (kMuchLargerThanScene).
    double sceneSize = 0.0;
    double timesTheScene = 0.0;
    std::vector<std::string> warnings; // about the node tree (transforms that had to be approximated)
};
// A model this many times the scene's size is offered a fit to it: at its real size the scene would vanish
// under it, or the view would have to leave the scene to see it.
inline constexpr double kMuchLargerThanScene = 100.0;

// The nodes for an imported model, placed (nothing changes yet): a node tree like the file's, or one
// reflector node for the whole file. `meshes` gives the boxes of the nodes already in the scene.
PlacedModel placeImportedModel(const scene::Scene& scene, scene::MeshLibrary& meshes,
                               const scene::ImportedModel& model, const std::string& absolutePath,
                               const ImportPlacement& placement);

// Where Add ▸ … puts a new node: on the ground at the view's focus, moved along +X past what is there
// (placeOnGround, as an import). A new mirror stands upright facing the view (turned about Y toward the
// camera), or lies flat facing up when the view looks down steeply (more than 60°), so the first mirror is
// never edge-on; flat things (a plane, a lying mirror) sit a hair above the ground so they do not fight a
// floor for depth. Lights go 2 units above the ground there.
struct NewNodePlacement {
    glm::dvec3 focus{0.0};                  // the point the view looks at
    glm::dvec3 viewPosition{0.0, 0.0, 1.0}; // the view's camera: a new mirror faces it
    double timeSeconds = 0.0;               // when "what is already there" is measured
};
scene::NodeTree placeNewNode(const scene::Scene& scene, scene::MeshLibrary& meshes, NewNodeKind kind,
                             const NewNodePlacement& placement);

} // namespace speculum::document
