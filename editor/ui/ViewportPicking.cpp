// Viewport: what is under the cursor and the handles. Picking (lights by their marker, everything else
// through the mirrors with scene::pick), and the handles of the current node as they lie on screen.
#include "editor/ui/Viewport.hpp"
#include "editor/ui/ViewportModels.hpp"
#include "editor/ui/ViewportOverlay.hpp"
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

} // namespace

void Viewport::setHandleMode(HandleMode mode) {
    if (mode == m_handleMode) {
        return;
    }
    m_handleMode = mode;
    m_hoverAxis = -1;
    m_overlay->update();
    emit handleModeChanged(mode);
}

ScreenProjection Viewport::projection() const {
    return ScreenProjection(m_view.camera(), QSizeF(width(), height()));
}

void Viewport::updateGizmo() {
    const scene::Node* node = m_selection ? m_selection->selectedNode() : nullptr;
    if (!node || !m_undoStack) {
        m_gizmo = Gizmo{};
        return;
    }
    const double t = m_lastFrameTime;
    const glm::dmat4 parent = scene::parentWorldMatrix(m_scene, node->id(), t);
    const glm::dmat4 world = parent * scene::animatedLocalMatrix(node->data(), t);
    m_gizmo.setUp(m_handleMode, projection(), parent, world);
}

std::optional<QPointF> Viewport::handlePoint(int axis) {
    updateGizmo();
    if (!m_gizmo.isValid() || axis < 0 || axis > 2) {
        return std::nullopt;
    }
    const auto& line = m_gizmo.axes()[std::size_t(axis)].line;
    if (line.empty()) {
        return std::nullopt;
    }
    // The tip of a segment, or the ring point nearest the bottom of the screen (least likely hidden).
    if (m_handleMode != HandleMode::Rotate) {
        const QPointF tip = line.back();
        return line.front() + (tip - line.front()) * 0.9;
    }
    return *std::max_element(line.begin(), line.end(), [](QPointF a, QPointF b) { return a.y() < b.y(); });
}

std::uint64_t Viewport::pickAt(QPointF position, bool mirrorItself) {
    const double t = m_lastFrameTime;
    const ScreenProjection screen = projection();
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
    m_models->prepare(m_scene);
    scene::PickScene pickScene = scene::buildPickScene(m_scene, t, m_meshes);
    if (mirrorItself) {
        pickScene.mirrorDepth = 0;
    }
    const double w = std::max(width(), 1), h = std::max(height(), 1);
    const scene::Ray ray =
        scene::cameraRay(m_view.camera(), w / h, position.x() / w * 2.0 - 1.0, 1.0 - position.y() / h * 2.0);
    const auto hit = scene::pick(pickScene, ray);
    return hit ? hit->id : 0;
}

} // namespace speculum::ui
