// Viewport: the marks painted over the frame by its overlay widget (ViewportOverlay), with QPainter in
// widget coordinates, projected with the view's camera: light markers, the selection's outlines and the
// current node's handles (as ViewportHandles shows them). They are not part of the frame (grabFramebuffer()
// shows the scene only).
#include "editor/ui/Viewport.hpp"
#include "editor/ui/ViewportModels.hpp"
#include "editor/view/Selection.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/model/Scene.hpp"

#include <QPainter>
#include <cmath>
#include <unordered_map>
#include <utility>
#include <vector>

namespace speculum::ui {

namespace {

const QColor kAxisColors[3] = {QColor(230, 70, 70), QColor(90, 200, 80), QColor(70, 130, 240)};
const QColor kActiveColor(255, 220, 60);
const QColor kSelectionColor(255, 150, 40);     // the current node's outline
const QColor kSelectedColor(190, 105, 35, 210); // the other selected nodes' outlines

using WorldMatrices = std::unordered_map<scene::NodeId, glm::dmat4>;
using Edge = std::pair<glm::dvec3, glm::dvec3>;

// Light markers: lights have no surface in the frame, so show where they are.
void paintLightMarkers(QPainter& painter, const scene::Scene& scene, const ScreenProjection& screen,
                       const WorldMatrices& worlds) {
    scene.forEachNode([&](const scene::Node& node) {
        if (!node.data().light) {
            return;
        }
        if (auto p = screen.project(glm::dvec3(worlds.at(node.id())[3]))) {
            const glm::dvec3 c = glm::clamp(node.data().light->color, 0.0, 1.0);
            painter.setPen(QPen(QColor(30, 30, 30, 200), 1.0));
            painter.setBrush(QColor::fromRgbF(float(c.r), float(c.g), float(c.b)));
            painter.drawEllipse(*p, 5.0, 5.0);
            painter.setPen(QPen(QColor(255, 210, 60), 1.5));
            for (int i = 0; i < 8; ++i) {
                const double a = i * 3.14159265358979 / 4.0;
                painter.drawLine(*p + QPointF(std::cos(a), std::sin(a)) * 7.0,
                                 *p + QPointF(std::cos(a), std::sin(a)) * 11.0);
            }
        }
    });
}

// A node's outline in world space: the edges of its local box (mesh bounds, or the mirror rectangle).
std::vector<Edge> outlineEdges(const scene::NodeData& d, const glm::dmat4& world,
                               scene::MeshLibrary& meshes) {
    std::vector<Edge> edges;
    auto addBox = [&](glm::dvec3 lo, glm::dvec3 hi) {
        glm::dvec3 c[8];
        for (int i = 0; i < 8; ++i) {
            c[i] = glm::dvec3(
                world * glm::dvec4((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z, 1.0));
        }
        static const int pairs[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                         {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
        for (const auto& p : pairs) {
            edges.emplace_back(c[p[0]], c[p[1]]);
        }
    };
    std::vector<scene::Warning> ignored;
    if (d.mesh) {
        if (auto mesh = meshes.get(*d.mesh, ignored)) {
            const render::Bounds b = scene::meshBounds(*mesh);
            addBox(glm::dvec3(b.min), glm::dvec3(b.max));
        }
    }
    if (d.mirror) {
        const glm::dvec2 h = d.mirror->size * 0.5;
        addBox({-h.x, 0.0, -h.y}, {h.x, 0.0, h.y});
    }
    return edges;
}

// Selection outlines, dashed: the current node's brighter and drawn last, on top.
void paintSelectionOutlines(QPainter& painter, const scene::Scene& scene, const view::Selection& selection,
                            scene::MeshLibrary& meshes, const ScreenProjection& screen,
                            const WorldMatrices& worlds) {
    for (scene::NodeId id : selection.nodes()) {
        const scene::Node* node = scene.findNode(id);
        const auto found = worlds.find(id);
        if (!node || found == worlds.end()) {
            continue;
        }
        const std::vector<Edge> edges = outlineEdges(node->data(), found->second, meshes);
        const bool current = id == selection.node();
        painter.setPen(QPen(current ? kSelectionColor : kSelectedColor, current ? 1.5 : 1.0, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        for (const auto& [a, b] : edges) {
            const auto pa = screen.project(a), pb = screen.project(b);
            if (pa && pb) {
                painter.drawLine(*pa, *pb);
            }
        }
    }
}

// The handles: an axis each (arrow heads when moving, squares when scaling, rings when rotating), the one
// at `active` (hovered or dragged, -1: none) highlighted, and a dot at the origin.
void paintGizmo(QPainter& painter, const Gizmo& gizmo, int active) {
    for (const auto& axis : gizmo.axes()) {
        const QColor color = axis.index == active ? kActiveColor : kAxisColors[axis.index];
        painter.setPen(QPen(color, axis.index == active ? 3.5 : 2.5, Qt::SolidLine, Qt::RoundCap));
        painter.setBrush(Qt::NoBrush);
        if (axis.line.size() < 2) {
            continue;
        }
        painter.drawPolyline(axis.line.data(), int(axis.line.size()));
        if (gizmo.mode() == HandleMode::Move || gizmo.mode() == HandleMode::Scale) {
            const QPointF tip = axis.line.back();
            painter.setBrush(color);
            if (gizmo.mode() == HandleMode::Scale) {
                painter.drawRect(QRectF(tip - QPointF(4.5, 4.5), QSizeF(9, 9)));
            } else {
                const QPointF dir = tip - axis.line.front();
                const double len = std::hypot(dir.x(), dir.y());
                if (len > 1.0) {
                    const QPointF u = dir / len, n(-u.y(), u.x());
                    const QPointF head[3] = {tip + u * 10.0, tip + n * 5.0, tip - n * 5.0};
                    painter.drawPolygon(head, 3);
                }
            }
        }
    }
    if (gizmo.mode() == HandleMode::Scale) {
        // The uniform-scale handle: a square around the origin.
        const bool hot = active == Gizmo::kUniformAxis;
        painter.setPen(QPen(hot ? kActiveColor : QColor(235, 235, 235), hot ? 2.5 : 1.5));
        painter.setBrush(Qt::NoBrush);
        const double r = Gizmo::kCentrePixels - 1.5;
        painter.drawRect(QRectF(gizmo.origin() - QPointF(r, r), QSizeF(2 * r, 2 * r)));
    }
    painter.setPen(QPen(Qt::white, 1.5));
    painter.setBrush(QColor(40, 40, 40));
    painter.drawEllipse(gizmo.origin(), 3.5, 3.5);
}

} // namespace

void Viewport::paintOverlay(QPainter& painter) {
    m_models->prepare(m_scene);
    if (!m_renderer) {
        return;
    }
    const ScreenProjection screen = projection();
    const WorldMatrices worlds = scene::worldMatrices(m_scene, m_lastFrameTime);
    paintLightMarkers(painter, m_scene, screen, worlds);
    if (!m_selection) {
        return;
    }
    paintSelectionOutlines(painter, m_scene, *m_selection, m_meshes, screen, worlds);

    // Handles: on the current node only (a drag carries over to the rest of the selection).
    if (!m_undoStack) {
        return;
    }
    int activeAxis = -1;
    if (const Gizmo* gizmo = m_handles.shownGizmo(viewOnScreen(), activeAxis)) {
        paintGizmo(painter, *gizmo, activeAxis);
    }
}

} // namespace speculum::ui
