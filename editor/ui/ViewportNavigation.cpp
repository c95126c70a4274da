// Viewport: navigation. The view's camera (reset, presets, a saved view, Frame Selection), the mouse and
// keys that move it or hand a press to picking and the handles, and the edit of the scene camera when
// the view looks through it.
#include "editor/document/Commands.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/ui/ViewportModels.hpp"
#include "editor/ui/ViewportOverlay.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/math/Projection.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/evaluate/Picking.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/model/Scene.hpp"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QUndoStack>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>

namespace speculum::ui {

namespace {

constexpr double kClickSlopPixels = 4.0; // a press that moves less than this is a click, not a drag

// What a node draws (its mesh, its mirror), without its children, added to `box`; false when it draws
// nothing.
bool addOwnBounds(render::math::Box& box, const scene::NodeData& d, const glm::dmat4& world,
                  scene::MeshLibrary& meshes) {
    std::vector<std::string> ignored;
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

void Viewport::setLookThroughSceneCamera(bool on) {
    m_sceneCameraMode = on;
    if (on) {
        resetView();
    }
}

void Viewport::resetView() {
    m_view.reset(m_scene.camera());
    update();
}

render::Camera Viewport::sceneCamera() const {
    return m_scene.camera();
}

void Viewport::setViewCamera(const render::Camera& camera) {
    ++m_gestureSerial; // a step of its own when it edits the scene camera
    m_view.place(camera.position, camera.target, camera.up);
    navigated();
}

std::pair<glm::dvec3, glm::dvec3> Viewport::viewPositionTarget() const {
    return {m_view.camera().position, m_view.camera().target};
}

void Viewport::placeView(const glm::dvec3& position, const glm::dvec3& target) {
    m_view.place(position, target);
    update();
}

void Viewport::frameSelected() {
    m_models->prepare(m_scene);
    const render::math::Box box = framedBox(m_scene, m_selection, m_meshes, m_clock.time());
    if (box.empty()) {
        return;
    }
    const double radius = std::max(glm::length(box.max - box.min) * 0.5, 1e-3);
    m_view.frame(box.center(), radius, double(width()) / std::max(height(), 1));
    navigated();
}

void Viewport::navigated() {
    if (m_sceneCameraMode && m_undoStack) {
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
    update();
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    const QPointF pos = event->position();
    const bool pan = event->button() == Qt::MiddleButton ||
                     (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
    ++m_gestureSerial;
    if (pan) {
        m_drag = Drag::Pan;
    } else if (event->button() == Qt::LeftButton) {
        updateGizmo();
        // Ctrl+click always picks (to add or remove), even over a handle.
        const bool ctrl = event->modifiers() & Qt::ControlModifier;
        const int axis = m_selection && m_undoStack && !ctrl ? m_gizmo.hitTest(pos) : -1;
        if (axis >= 0 && m_handleDrag->press(m_gizmo, axis, pos, m_selection->node(), m_selection->roots(),
                                             m_lastFrameTime)) {
            m_drag = Drag::Handle;
        } else {
            m_drag = Drag::PendingClick;
        }
        m_pressPosition = pos;
        m_pressAlt = event->modifiers() & Qt::AltModifier;
        m_pressCtrl = event->modifiers() & Qt::ControlModifier;
    } else {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    m_lastMouse = pos.toPoint();
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPointF posF = event->position();
    if (m_drag == Drag::None) {
        if (m_selection && m_undoStack) {
            updateGizmo();
            const int hover = m_gizmo.hitTest(posF);
            if (hover != m_hoverAxis) {
                m_hoverAxis = hover;
                setCursor(hover >= 0 ? Qt::PointingHandCursor : Qt::ArrowCursor);
                m_overlay->update();
            }
        }
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    if (m_drag == Drag::Handle) {
        interacted();
        m_handleDrag->move(posF);
        event->accept();
        return;
    }
    if (m_drag == Drag::PendingClick) {
        if (std::hypot(posF.x() - m_pressPosition.x(), posF.y() - m_pressPosition.y()) < kClickSlopPixels) {
            event->accept();
            return;
        }
        m_drag = Drag::Orbit;
    }
    const QPoint pos = posF.toPoint();
    const QPoint delta = pos - m_lastMouse;
    m_lastMouse = pos;
    if (m_drag == Drag::Orbit) {
        // The scene follows the mouse (Blender, three.js), unless View ▸ Invert Vertical Orbit is on.
        m_view.orbitByDrag(delta.x(), delta.y(), double(height()));
    } else {
        const double perPixel = 1.0 / std::max(height(), 1);
        m_view.pan(-delta.x() * perPixel, delta.y() * perPixel);
    }
    interacted();
    navigated();
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseReleaseEvent(event);
        return;
    }
    if (m_drag == Drag::PendingClick && m_selection) {
        const std::uint64_t id = pickAt(m_pressPosition, m_pressAlt);
        if (m_pressCtrl) {
            // Ctrl+click adds or removes; Ctrl+click on nothing keeps the selection.
            m_selection->toggleNode(scene::NodeId(id));
        } else if (id) {
            m_selection->selectNode(scene::NodeId(id));
        } else {
            m_selection->clear();
        }
    }
    if (m_drag == Drag::Handle) {
        m_handleDrag->release();
    }
    m_drag = Drag::None;
    m_overlay->update();
    event->accept();
}

void Viewport::mouseDoubleClickEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) {
        resetView();
        event->accept();
    }
}

void Viewport::wheelEvent(QWheelEvent* event) {
    // One notch (120 units) moves 15% closer or farther.
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0.0) {
        m_view.zoom(std::pow(0.85, notches));
        interacted();
        navigated();
    }
    event->accept();
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && m_drag == Drag::Handle) {
        // Cancel the drag: every node back as it was, and no undo step left behind.
        m_handleDrag->cancel();
        m_drag = Drag::None;
        m_overlay->update();
        event->accept();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

} // namespace speculum::ui
