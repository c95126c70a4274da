// ViewportNavigation: the view's camera and how it moves, and the edit of the scene camera while the view
// looks through it.
#include "editor/ui/ViewportNavigation.hpp"

#include "editor/document/Commands.hpp"
#include "editor/view/Selection.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/math/Projection.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/evaluate/Picking.hpp"
#include "scene/model/Scene.hpp"

#include <QUndoStack>
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>

namespace speculum::ui {

namespace {

// What a node draws (its mesh, its mirror), without its children, added to `box`; false when it draws
// nothing.
bool addOwnBounds(render::math::Box& box, const scene::NodeData& d, const glm::dmat4& world,
                  scene::MeshLibrary& meshes) {
    std::vector<scene::Warning> ignored;
    bool added = false;
    if (d.mesh) {
        if (auto mesh = meshes.get(*d.mesh, ignored)) {
            box.add(render::math::worldBounds(scene::meshBounds(*mesh), world));
            added = true;
        }
    }
    if (d.mirror) {
        const glm::vec2 h = glm::vec2(d.mirror->size * 0.5);
        box.add(render::math::worldBounds(render::Bounds{{-h.x, 0.0f, -h.y}, {h.x, 0.0f, h.y}}, world));
        added = true;
    }
    return added;
}

// What Frame Selection fits into the view: the selected nodes with everything under them, or every node
// when nothing is selected. A node with nothing drawn under it counts as a unit cube at its origin.
render::math::Box framedBox(const scene::Scene& scene, const view::Selection* selection,
                            scene::MeshLibrary& meshes, double t) {
    const auto worlds = scene::worldMatrices(scene, t);
    render::math::Box box;
    // A selected group (an imported model's root) frames everything under it.
    std::function<bool(const scene::Node&)> addSubtree = [&](const scene::Node& node) {
        const auto it = worlds.find(node.id());
        bool added = it != worlds.end() && addOwnBounds(box, node.data(), it->second, meshes);
        for (const auto& child : node.children()) {
            added = addSubtree(*child) || added;
        }
        return added;
    };
    auto addNode = [&](const scene::Node& node) {
        if (!addSubtree(node)) {
            const auto it = worlds.find(node.id());
            if (it == worlds.end()) {
                return;
            }
            const glm::dvec3 p(it->second[3]);
            box.add(p - glm::dvec3(0.5));
            box.add(p + glm::dvec3(0.5));
        }
    };
    bool any = false;
    if (selection) {
        for (scene::NodeId id : selection->nodes()) {
            if (const scene::Node* node = scene.findNode(id)) {
                addNode(*node);
                any = true;
            }
        }
    }
    if (!any) {
        for (const auto& node : scene.topLevelNodes()) {
            addNode(*node);
        }
    }
    return box;
}

} // namespace

ViewportNavigation::ViewportNavigation(scene::Scene& scene)
    : m_scene(scene) {
    m_view.reset(m_scene.camera());
}

std::pair<glm::dvec3, glm::dvec3> ViewportNavigation::positionTarget() const {
    return {m_view.camera().position, m_view.camera().target};
}

void ViewportNavigation::setLookThroughSceneCamera(bool on) {
    m_looksThroughSceneCamera = on;
    if (on) {
        reset();
    }
}

void ViewportNavigation::reset() {
    m_view.reset(m_scene.camera());
}

void ViewportNavigation::place(const glm::dvec3& position, const glm::dvec3& target) {
    m_view.place(position, target);
}

void ViewportNavigation::setCamera(const render::Camera& camera) {
    ++m_gestureSerial; // a step of its own when it edits the scene camera
    m_view.place(camera.position, camera.target, camera.up);
    moved();
}

bool ViewportNavigation::frameSelected(const view::Selection* selection, scene::MeshLibrary& meshes,
                                       double time, QSize size) {
    const render::math::Box box = framedBox(m_scene, selection, meshes, time);
    if (box.empty()) {
        return false;
    }
    const double radius = std::max(glm::length(box.max - box.min) * 0.5, 1e-3);
    m_view.frame(box.center(), radius, double(size.width()) / std::max(size.height(), 1));
    moved();
    return true;
}

void ViewportNavigation::beginDrag(Drag drag, QPoint position) {
    m_drag = drag;
    m_lastMouse = position;
}

void ViewportNavigation::dragTo(QPoint position, int widgetHeight) {
    const QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    if (m_drag == Drag::Orbit) {
        // The scene follows the mouse (Blender, three.js), unless View ▸ Invert Vertical Orbit is on.
        m_view.orbitByDrag(delta.x(), delta.y(), double(widgetHeight));
    } else if (m_drag == Drag::Pan) {
        const double perPixel = 1.0 / std::max(widgetHeight, 1);
        m_view.pan(-delta.x() * perPixel, delta.y() * perPixel);
    }
    moved();
}

bool ViewportNavigation::endDrag() {
    const bool was = m_drag != Drag::None;
    m_drag = Drag::None;
    return was;
}

void ViewportNavigation::zoom(double notches) {
    m_view.zoom(std::pow(0.85, notches));
    moved();
}

void ViewportNavigation::orbitStep(double yawDegrees, double pitchDegrees) {
    ++m_gestureSerial;
    m_view.orbit(yawDegrees, pitchDegrees);
    moved();
}

void ViewportNavigation::zoomStep(double notches) {
    ++m_gestureSerial;
    zoom(notches);
}

void ViewportNavigation::moved() {
    if (!m_looksThroughSceneCamera || !m_undoStack) {
        return;
    }
    // Looking through the scene camera: the navigation is an edit of the document's camera.
    scene::CameraData camera = m_scene.camera();
    const render::Camera& v = m_view.camera();
    camera.position = v.position;
    camera.target = v.target;
    camera.up = v.up;
    camera.far = std::min(std::max(camera.far, v.far), camera.near * render::kMaxFarNearRatio);
    auto* command = new document::SetCameraCommand(m_scene, camera, true);
    command->setMergeKey(QStringLiteral("navigate#%1").arg(m_gestureSerial));
    document::pushEdit(*m_undoStack, command); // an orbit that ends where it began is no step
}

} // namespace speculum::ui
