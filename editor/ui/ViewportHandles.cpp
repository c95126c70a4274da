// ViewportHandles: what is under the cursor, the handles of the current node as they lie on screen, and
// the left button's press, click and handle drag.
#include "editor/ui/ViewportHandles.hpp"

#include "editor/view/Selection.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/evaluate/Picking.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/model/Scene.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::ui {

namespace {

constexpr double kLightPickPixels = 12.0;
constexpr double kClickSlopPixels = 4.0; // a press that moves less than this is a click, not a drag

} // namespace

ViewportHandles::ViewportHandles(scene::Scene& scene, std::function<scene::MeshLibrary&()> meshes)
    : m_scene(scene)
    , m_meshes(std::move(meshes)) {}

ViewportHandles::~ViewportHandles() = default;

void ViewportHandles::setEditing(view::Selection* selection, QUndoStack* undoStack) {
    m_selection = selection;
    m_undoStack = undoStack;
    m_handleDrag = undoStack ? std::make_unique<HandleDrag>(m_scene, *undoStack) : nullptr;
}

bool ViewportHandles::setMode(HandleMode mode) {
    if (mode == m_mode) {
        return false;
    }
    m_mode = mode;
    m_hoverAxis = -1;
    return true;
}

bool ViewportHandles::hover(QPointF position, const ViewOnScreen& view) {
    if (!isEditing()) {
        return false;
    }
    setUpGizmo(view);
    const int axis = m_gizmo.hitTest(position);
    if (axis == m_hoverAxis) {
        return false;
    }
    m_hoverAxis = axis;
    return true;
}

void ViewportHandles::press(QPointF position, Qt::KeyboardModifiers modifiers, const ViewOnScreen& view) {
    setUpGizmo(view);
    // Ctrl+click always picks (to add or remove), even over a handle.
    const bool ctrl = modifiers & Qt::ControlModifier;
    const int axis = isEditing() && !ctrl ? m_gizmo.hitTest(position) : -1;
    if (axis >= 0 &&
        m_handleDrag->press(m_gizmo, axis, position, m_selection->node(), m_selection->roots(), view.time)) {
        m_press = Press::Handle;
    } else {
        m_press = Press::PendingClick;
    }
    m_pressPosition = position;
    m_pressAlt = modifiers & Qt::AltModifier;
    m_pressCtrl = ctrl;
}

bool ViewportHandles::leavesClick(QPointF position) {
    if (std::hypot(position.x() - m_pressPosition.x(), position.y() - m_pressPosition.y()) <
        kClickSlopPixels) {
        return false;
    }
    m_press = Press::None;
    return true;
}

void ViewportHandles::dragHandle(QPointF position, const std::optional<SnapSteps>& snap) {
    m_handleDrag->move(position, snap);
}

// What a click on the mesh of node `hit` selects: the top of its hierarchy first (an imported model's
// root, as Blender, Godot and Unity select the object, not its deepest part); a click again goes one level
// deeper, down to the part itself. Ctrl+click (`deeper` false) always means the top.
scene::NodeId ViewportHandles::clickTarget(scene::NodeId hit, bool deeper) const {
    std::vector<scene::NodeId> chain{hit}; // hit, its parent, …, the top-level node
    for (scene::NodeId up = m_scene.parentOf(hit); up != scene::kNoNode; up = m_scene.parentOf(up)) {
        chain.push_back(up);
    }
    if (deeper && m_selection && m_selection->nodes().size() == 1) {
        const auto selected = std::find(chain.begin(), chain.end(), m_selection->node());
        if (selected != chain.end()) {
            return selected == chain.begin() ? hit : *(selected - 1); // the part itself stays selected
        }
    }
    return chain.back();
}

bool ViewportHandles::release(const ViewOnScreen& view) {
    const Press press = m_press;
    m_press = Press::None;
    if (press == Press::PendingClick && m_selection) {
        const std::uint64_t id = pickAt(m_pressPosition, m_pressAlt, view);
        if (m_pressCtrl) {
            // Ctrl+click adds or removes; Ctrl+click on nothing keeps the selection.
            m_selection->toggleNode(clickTarget(scene::NodeId(id), false));
        } else if (id) {
            m_selection->selectNode(clickTarget(scene::NodeId(id), true));
        } else {
            m_selection->clear();
        }
    }
    if (press == Press::Handle) {
        m_handleDrag->release();
    }
    return press != Press::None;
}

bool ViewportHandles::cancelHandleDrag() {
    if (m_press != Press::Handle) {
        return false;
    }
    // Every node back as it was, and no undo step left behind.
    m_handleDrag->cancel();
    m_press = Press::None;
    return true;
}

void ViewportHandles::setUpGizmo(const ViewOnScreen& view) {
    const scene::Node* node = m_selection ? m_selection->selectedNode() : nullptr;
    if (!node || !m_undoStack) {
        m_gizmo = Gizmo{};
        return;
    }
    const double t = view.time;
    const glm::dmat4 parent = scene::parentWorldMatrix(m_scene, node->id(), t);
    const glm::dmat4 world = parent * scene::animatedLocalMatrix(node->data(), t);
    m_gizmo.setUp(m_mode, view.screen, parent, world);
}

const Gizmo* ViewportHandles::shownGizmo(const ViewOnScreen& view, int& activeAxis) {
    setUpGizmo(view);
    const bool dragging = m_press == Press::Handle && m_handleDrag;
    const Gizmo& gizmo = dragging ? m_handleDrag->gizmo() : m_gizmo;
    activeAxis = dragging ? m_handleDrag->axis() : m_hoverAxis;
    return gizmo.isValid() ? &gizmo : nullptr;
}

std::optional<QPointF> ViewportHandles::handlePoint(int axis, const ViewOnScreen& view) {
    setUpGizmo(view);
    if (!m_gizmo.isValid() || axis < 0 || axis > 2) {
        return std::nullopt;
    }
    const auto& line = m_gizmo.axes()[std::size_t(axis)].line;
    if (line.empty()) {
        return std::nullopt;
    }
    // The tip of a segment, or the ring point nearest the bottom of the screen (least likely hidden).
    if (m_mode != HandleMode::Rotate) {
        const QPointF tip = line.back();
        return line.front() + (tip - line.front()) * 0.9;
    }
    return *std::max_element(line.begin(), line.end(), [](QPointF a, QPointF b) { return a.y() < b.y(); });
}

std::uint64_t ViewportHandles::pickAt(QPointF position, bool mirrorItself, const ViewOnScreen& view) {
    const double t = view.time;
    const ScreenProjection& screen = view.screen;
    // Lights have no surface: they are picked by their marker.
    std::uint64_t light = 0;
    double nearest = kLightPickPixels;
    const auto worlds = scene::worldMatrices(m_scene, t);
    m_scene.forEachNode([&](const scene::Node& node) {
        if (!node.data().light) {
            return;
        }
        if (auto p = screen.project(glm::dvec3(worlds.at(node.id())[3]))) {
            const double d = std::hypot(p->x() - position.x(), p->y() - position.y());
            if (d < nearest) {
                nearest = d;
                light = node.id();
            }
        }
    });
    if (light) {
        return light;
    }
    scene::PickScene pickScene = scene::buildPickScene(m_scene, t, m_meshes());
    if (mirrorItself) {
        pickScene.mirrorDepth = 0;
    }
    const double w = std::max(screen.size().width(), 1.0), h = std::max(screen.size().height(), 1.0);
    const scene::Ray ray =
        scene::cameraRay(screen.camera(), w / h, position.x() / w * 2.0 - 1.0, 1.0 - position.y() / h * 2.0);
    const auto hit = scene::pick(pickScene, ray);
    return hit ? hit->id : 0;
}

} // namespace speculum::ui
