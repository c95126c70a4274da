#include "editor/document/EditOperations.hpp"

#include "editor/document/Commands.hpp"
#include "editor/document/EditTransaction.hpp"
#include "editor/document/NodeFactory.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/math/Projection.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/evaluate/Picking.hpp"
#include "scene/model/NodeMath.hpp"

#include <QFileInfo>
#include <QString>
#include <QUndoStack>
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <unordered_map>

namespace speculum::document {

namespace {

QString quoted(const std::string& name) {
    return QStringLiteral("\u201c%1\u201d").arg(QString::fromStdString(name));
}

std::vector<scene::NodeId> existing(const scene::Scene& scene, const std::vector<scene::NodeId>& ids) {
    std::vector<scene::NodeId> kept;
    std::copy_if(ids.begin(), ids.end(), std::back_inserter(kept),
                 [&](scene::NodeId id) { return scene.findNode(id) != nullptr; });
    return kept;
}

// The scene index `id` gets when moved under newParent before scene position `index` (-1: at the end),
// counted as MoveNodeCommand wants it (after the node has been taken out); nothing when that changes
// nothing.
std::optional<int> moveTarget(const scene::Scene& scene, scene::NodeId id, scene::NodeId newParent,
                              int index) {
    const scene::NodeId oldParent = scene.parentOf(id);
    const int oldIndex = scene.indexOf(id);
    int newIndex = index;
    if (newIndex >= 0 && oldParent == newParent && oldIndex < newIndex) {
        --newIndex;
    }
    const int count = scene.childCount(newParent) - (oldParent == newParent ? 1 : 0);
    if (newIndex < 0 || newIndex > count) {
        newIndex = count;
    }
    if (oldParent == newParent && oldIndex == newIndex) {
        return std::nullopt;
    }
    return newIndex;
}

// What a node draws itself (its mesh, its mirror), in world space; empty when it draws nothing or its
// mesh is a model file and `files` is null (a duplicate must not read files on the GUI thread).
render::math::Box ownWorldBox(const scene::NodeData& d, const glm::dmat4& world, scene::MeshLibrary& builtins,
                              scene::MeshLibrary* files) {
    render::math::Box box;
    std::vector<scene::Warning> ignored;
    if (d.mesh) {
        scene::MeshLibrary* library = d.mesh->builtin ? (files ? files : &builtins) : files;
        if (library) {
            if (auto mesh = library->get(*d.mesh, ignored); mesh && *mesh) {
                box.add(render::math::worldBounds(scene::meshBounds(*mesh), world));
            }
        }
    }
    if (d.mirror) {
        const glm::vec2 h = glm::vec2(d.mirror->size * 0.5);
        box.add(render::math::worldBounds(render::Bounds{{-h.x, 0.0f, -h.y}, {h.x, 0.0f, h.y}}, world));
    }
    return box;
}

// A node's subtree as a world box: what it draws, or a half-unit box around its origin when it draws
// nothing measurable (an empty, a light, a model not read yet), so that even those step aside.
render::math::Box subtreeWorldBox(const scene::Node& node,
                                  const std::unordered_map<scene::NodeId, glm::dmat4>& worlds,
                                  scene::MeshLibrary& builtins, scene::MeshLibrary* files) {
    render::math::Box box;
    std::function<void(const scene::Node&)> add = [&](const scene::Node& n) {
        if (const auto it = worlds.find(n.id()); it != worlds.end()) {
            box.add(ownWorldBox(n.data(), it->second, builtins, files));
        }
        for (const auto& child : n.children()) {
            add(*child);
        }
    };
    add(node);
    if (box.empty()) {
        if (const auto it = worlds.find(node.id()); it != worlds.end()) {
            const glm::dvec3 p(it->second[3]);
            box.add(p - glm::dvec3(0.25));
            box.add(p + glm::dvec3(0.25));
        }
    }
    return box;
}

bool boxesOverlap(const render::math::Box& a, const render::math::Box& b, double eps) {
    for (int i = 0; i < 3; ++i) {
        if (!(a.min[i] < b.max[i] - eps && b.min[i] < a.max[i] - eps)) {
            return false;
        }
    }
    return true;
}

// How far along world +X a copy of `box` goes: past the original by its width and a gap, then on past
// every box of `occupied` it would overlap there.
double duplicateShift(const render::math::Box& box, const std::vector<render::math::Box>& occupied) {
    const glm::dvec3 size = box.max - box.min;
    const double scale = std::max({size.x, size.y, size.z, 1e-6});
    const double gap = std::max(0.1 * size.x, 0.05 * scale);
    const double eps = 1e-6 * scale;
    double shift = size.x + gap;
    for (std::size_t step = 0; step <= occupied.size(); ++step) {
        render::math::Box moved = box;
        moved.min.x += shift;
        moved.max.x += shift;
        double past = -1e300;
        for (const auto& other : occupied) {
            if (!other.empty() && boxesOverlap(moved, other, eps)) {
                past = std::max(past, other.max.x);
            }
        }
        if (past == -1e300) {
            break;
        }
        shift = past + gap - box.min.x;
    }
    return shift;
}

} // namespace

base::Result<scene::NodeId> addNodeTree(scene::Scene& scene, QUndoStack& undo, scene::NodeTree tree) {
    tree.data.name = uniqueName(scene, tree.data.name);
    EditTransaction edit(undo);
    auto* command = new AddNodeCommand(scene, std::move(tree));
    edit.push(command);
    const scene::NodeId id = command->nodeId();
    edit.commit();
    return id;
}

base::Status deleteNodes(scene::Scene& scene, QUndoStack& undo, const std::vector<scene::NodeId>& roots) {
    const std::vector<scene::NodeId> nodes = existing(scene, roots);
    if (nodes.empty()) {
        return base::Error{"nothing is selected"};
    }
    EditTransaction edit(undo,
                         nodes.size() > 1 ? QStringLiteral("Delete %1 nodes").arg(nodes.size()) : QString());
    for (scene::NodeId id : nodes) {
        edit.push(new RemoveNodeCommand(scene, id));
    }
    edit.commit();
    return base::Done{};
}

base::Result<Duplicates> duplicateNodes(scene::Scene& scene, QUndoStack& undo,
                                        const std::vector<scene::NodeId>& roots, scene::NodeId current,
                                        scene::MeshLibrary* meshes, double timeSeconds) {
    const std::vector<scene::NodeId> nodes = existing(scene, roots);
    if (nodes.empty()) {
        return base::Error{"nothing is selected"};
    }
    EditTransaction edit(undo, nodes.size() > 1 ? QStringLiteral("Duplicate %1 nodes").arg(nodes.size())
                                                : QString());
    Duplicates result;
    // What is already there, measured once; each copy placed joins it, so copies do not land in each other.
    scene::MeshLibrary builtins; // built-in shapes only: cheap, and never a file read
    const auto worlds = scene::worldMatrices(scene, timeSeconds);
    std::vector<render::math::Box> occupied;
    scene.forEachNode([&](const scene::Node& n) {
        if (const auto it = worlds.find(n.id()); it != worlds.end()) {
            if (auto box = ownWorldBox(n.data(), it->second, builtins, meshes); !box.empty()) {
                occupied.push_back(box);
            }
        }
    });
    for (scene::NodeId id : nodes) {
        // One at a time: each copy's name is made unique against the copies made before it.
        scene::NodeTree copy = duplicateTree(scene, id);
        const render::math::Box box = subtreeWorldBox(*scene.findNode(id), worlds, builtins, meshes);
        if (!box.empty()) {
            const double shift = duplicateShift(box, occupied);
            // The world +X shift in the parent's space (its rotation and scale undone).
            const glm::dmat4 parent = scene::parentWorldMatrix(scene, id, timeSeconds);
            const glm::dvec3 local = glm::dvec3(glm::inverse(parent) * glm::dvec4(shift, 0.0, 0.0, 0.0));
            if (std::isfinite(local.x) && std::isfinite(local.y) && std::isfinite(local.z)) {
                copy.data.transform.translate += local;
                render::math::Box placed = box;
                placed.min.x += shift;
                placed.max.x += shift;
                occupied.push_back(placed);
            }
        }
        auto* command = new AddNodeCommand(scene, std::move(copy), scene.parentOf(id), scene.indexOf(id) + 1);
        command->setText(QStringLiteral("Duplicate %1").arg(quoted(scene.findNode(id)->name())));
        edit.push(command);
        result.copies.push_back(command->nodeId());
        if (scene.isAncestor(id, current)) { // the current node or one under it
            result.currentCopy = command->nodeId();
        }
    }
    edit.commit();
    return result;
}

base::Status renameNode(scene::Scene& scene, QUndoStack& undo, scene::NodeId id, const std::string& name) {
    const scene::Node* node = scene.findNode(id);
    if (!node) {
        return base::Error{"no such node"};
    }
    const std::string trimmed = QString::fromStdString(name).trimmed().toStdString();
    if (trimmed.empty()) {
        return base::Error{"a name cannot be empty"};
    }
    if (trimmed == node->name()) {
        return base::Error{"the name is unchanged"};
    }
    EditTransaction edit(undo);
    edit.push(new RenameNodeCommand(scene, id, trimmed));
    edit.commit();
    return base::Done{};
}

std::vector<scene::NodeId> outermostInTreeOrder(const scene::Scene& scene,
                                                const std::vector<scene::NodeId>& ids) {
    // A node's tree position as the scene indexes from the top level down: these compare in tree order,
    // whatever order the ids came in.
    auto path = [&scene](scene::NodeId id) {
        std::vector<int> indexes;
        for (scene::NodeId n = id; n != scene::kNoNode; n = scene.parentOf(n)) {
            indexes.push_back(scene.indexOf(n));
        }
        std::reverse(indexes.begin(), indexes.end());
        return indexes;
    };
    std::vector<std::pair<std::vector<int>, scene::NodeId>> sorted;
    for (scene::NodeId id : ids) {
        if (scene.findNode(id)) {
            sorted.emplace_back(path(id), id);
        }
    }
    std::sort(sorted.begin(), sorted.end());
    // Ancestors sort before their descendants, so each node need only be checked against those kept.
    std::vector<scene::NodeId> outermost;
    for (const auto& entry : sorted) {
        const scene::NodeId id = entry.second;
        const bool underKept = std::any_of(outermost.begin(), outermost.end(),
                                           [&](scene::NodeId kept) { return scene.isAncestor(kept, id); });
        if (!underKept) {
            outermost.push_back(id); // also drops repeats: isAncestor() holds for the node itself
        }
    }
    return outermost;
}

base::Status moveNodes(scene::Scene& scene, QUndoStack& undo, const std::vector<scene::NodeId>& ids,
                       scene::NodeId newParent, int index) {
    if (newParent != scene::kNoNode && !scene.findNode(newParent)) {
        return base::Error{"no such parent node"};
    }
    if (std::any_of(ids.begin(), ids.end(),
                    [&](scene::NodeId id) { return scene.isAncestor(id, newParent); })) {
        return base::Error{"a node cannot go into its own subtree"};
    }
    const std::vector<scene::NodeId> nodes = outermostInTreeOrder(scene, ids);
    if (nodes.empty()) {
        return base::Error{"nothing to move"};
    }
    // One at a time, each right after the one before, with the scene's indexes as they are after the
    // previous moves: taking a node out from above the drop position shifts the positions after it.
    // One node keeps its own "Move “name”" text.
    EditTransaction edit(undo,
                         nodes.size() > 1 ? QStringLiteral("Move %1 nodes").arg(nodes.size()) : QString());
    int next = index;
    for (scene::NodeId id : nodes) {
        if (const std::optional<int> newIndex = moveTarget(scene, id, newParent, next)) {
            edit.push(new MoveNodeCommand(scene, id, newParent, *newIndex));
        }
        next = scene.indexOf(id) + 1;
    }
    if (edit.empty()) {
        return base::Error{"the nodes are there already"};
    }
    edit.commit();
    return base::Done{};
}

base::Status setCameraFromView(scene::Scene& scene, QUndoStack& undo, const render::Camera& view) {
    scene::CameraData camera = scene.camera();
    camera.position = view.position;
    camera.target = view.target;
    camera.up = view.up;
    camera.far = std::min(std::max(camera.far, view.far), camera.near * render::kMaxFarNearRatio);
    if (camera == scene.camera()) {
        return base::Done{}; // already so: no step
    }
    EditTransaction edit(undo, QStringLiteral("Set scene camera from view"));
    edit.push(new SetCameraCommand(scene, camera));
    edit.commit();
    return base::Done{};
}

namespace {

double largestSide(const render::math::Box& box) {
    const glm::dvec3 extent = box.max - box.min;
    return std::max({extent.x, extent.y, extent.z});
}

} // namespace

PlacedModel placeImportedModel(const scene::Scene& scene, scene::MeshLibrary& meshes,
                               const scene::ImportedModel& model, const std::string& absolutePath,
                               const ImportPlacement& placement) {
    PlacedModel placed;
    const QString path = QString::fromStdString(absolutePath);
    // The box the nodes fill in the coordinates they are added in (the top level). A reflector draws the
    // whole file flattened, which fills the same box as the node tree.
    render::math::Box box = render::math::worldBounds(model.bounds, glm::dmat4(1.0));
    if (placement.asReflector) {
        placed.tree = makeModelNode(path, glm::dvec3(0.0), true);
    } else {
        placed.tree = scene::modelNodeTree(
            model, absolutePath, QFileInfo(path).completeBaseName().toStdString(), &placed.warnings);
    }
    const std::vector<render::math::Box> occupied = occupiedBoxes(scene, placement.timeSeconds, meshes);
    const double size = largestSide(box);
    render::math::Box around;
    for (const render::math::Box& b : occupied)
        around.add(b);
    placed.sceneSize = around.empty() ? 0.0 : largestSide(around);
    placed.timesTheScene = placed.sceneSize > 0.0 ? size / placed.sceneSize : 0.0;
    const double fitTo = placement.fitToUnitBox ? 1.0 : placement.fitToSize;
    if (fitTo > 0.0 && size > 0.0 && std::isfinite(size)) {
        placed.fit = fitTo / size;
        scaleAboutParentOrigin(placed.tree.data, placed.fit);
        box.min *= placed.fit;
        box.max *= placed.fit;
    }
    const glm::dvec3 offset = placeOnGround(box, placement.focus, occupied);
    placed.tree.data.transform.translate += offset;
    placed.size = box.max - box.min;
    placed.box = box;
    placed.box.min += offset;
    placed.box.max += offset;
    return placed;
}

// A new reflector's parallax proxy: the box around everything already in the scene, when that box
// surrounds the reflector (what the bench's "parallax on" gives a reflector without a proxy of its own,
// and finds closer to the exact reflection wherever the scene is not far away); none when nothing
// surrounds it, where a proxy would say nothing true.
namespace {

std::optional<scene::ReflectorParallax> surroundingProxy(const render::math::Box& reflector,
                                                         const std::vector<render::math::Box>& occupied) {
    render::math::Box around;
    for (const render::math::Box& b : occupied) {
        around.add(b);
    }
    if (around.empty() || reflector.empty())
        return std::nullopt;
    if (!glm::all(glm::lessThanEqual(around.min, reflector.min)) ||
        !glm::all(glm::greaterThanEqual(around.max, reflector.max)))
        return std::nullopt;
    scene::ReflectorParallax proxy;
    proxy.shape = render::ParallaxShape::Box;
    proxy.min = around.min - reflector.center();
    proxy.max = around.max - reflector.center();
    return proxy;
}

} // namespace

scene::NodeTree placeNewNode(const scene::Scene& scene, scene::MeshLibrary& meshes, NewNodeKind kind,
                             const NewNodePlacement& placement) {
    const bool light = kind == NewNodeKind::PointLight || kind == NewNodeKind::DirectionalLight ||
                       kind == NewNodeKind::SpotLight;
    scene::NodeTree tree = makeNode(kind, glm::dvec3(0.0));
    scene::NodeData& d = tree.data;
    bool flat = kind == NewNodeKind::Plane;
    if (d.mirror) {
        const glm::dvec3 toView = placement.viewPosition - placement.focus;
        const double horizontal = std::hypot(toView.x, toView.z);
        // Looking down by more than 60°: a mirror lying on the ground faces the camera better than a
        // standing one, which the view would see almost edge-on from above.
        if (horizontal > 1e-9 && std::atan2(toView.y, horizontal) < glm::radians(60.0)) {
            // Rotate X by 90° turns the mirror's +Y normal to +Z; the yaw then points it at the view.
            d.transform.rotate = {90.0, glm::degrees(std::atan2(toView.x, toView.z)), 0.0};
        } else {
            flat = true;
        }
    }
    const glm::dmat4 local = scene::localMatrix(d.transform);
    render::math::Box box;
    if (light) {
        box.add(glm::dvec3(-0.1));
        box.add(glm::dvec3(0.1));
    } else {
        box = ownWorldBox(d, local, meshes, &meshes);
        if (box.empty()) { // an empty: a small box, so that empties added in a row step aside
            box.add(glm::dvec3(-0.25));
            box.add(glm::dvec3(0.25));
        }
    }
    const std::vector<render::math::Box> occupied = occupiedBoxes(scene, placement.timeSeconds, meshes);
    glm::dvec3 offset = placeOnGround(box, placement.focus, occupied);
    if (light) {
        // makeNode put it 2 units up: over the ground under the focus, whatever stands there.
        offset = {placement.focus.x, offset.y + box.min.y, placement.focus.z};
    }
    if (flat) {
        const glm::dvec3 size = box.max - box.min;
        offset.y += 0.005 * std::max({size.x, size.z, 1e-3});
    }
    d.transform.translate += offset;
    if (d.reflector) {
        box.min += offset;
        box.max += offset;
        d.reflector->parallax = surroundingProxy(box, occupied);
    }
    return tree;
}

base::Status setNodesHidden(scene::Scene& scene, QUndoStack& undo, const std::vector<scene::NodeId>& ids,
                            bool hidden) {
    std::vector<SetNodesDataCommand::Change> changes;
    for (scene::NodeId id : existing(scene, ids)) {
        scene::NodeData data = scene.findNode(id)->data();
        if (data.hidden != hidden) {
            data.hidden = hidden;
            changes.push_back({id, std::move(data)});
        }
    }
    if (changes.empty()) {
        return base::Error{hidden ? "nothing to hide" : "nothing to show"};
    }
    const QString verb = hidden ? QStringLiteral("Hide") : QStringLiteral("Show");
    const QString text =
        changes.size() == 1
            ? QStringLiteral("%1 \u201c%2\u201d").arg(verb, QString::fromStdString(changes.front().data.name))
            : QStringLiteral("%1 %2 nodes").arg(verb).arg(changes.size());
    undo.push(new SetNodesDataCommand(scene, std::move(changes), text));
    return base::Done{};
}

base::Status showAllNodes(scene::Scene& scene, QUndoStack& undo) {
    std::vector<scene::NodeId> hidden;
    scene.forEachNode([&](const scene::Node& node) {
        if (node.data().hidden) {
            hidden.push_back(node.id());
        }
    });
    return setNodesHidden(scene, undo, hidden, false);
}

} // namespace speculum::document
