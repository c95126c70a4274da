#pragma once

#include "render/frame/FrameInput.hpp"

#include <QPointF>
#include <QSizeF>
#include <array>

class QPainter;

namespace speculum::ui {

// The axis gizmo in the viewport's top-right corner: the world's X (red), Y (green) and Z (blue) as the
// view sees them, the positive ends labelled and the negative ones as dim dots, nearer ones drawn over
// farther ones. It turns with the view and ignores its position and zoom.
struct AxisGizmoEnd {
    int axis = 0; // 0 x, 1 y, 2 z
    bool positive = true;
    QPointF tip;        // widget pixels
    double depth = 0.0; // toward the viewer is negative: drawn last
};
struct AxisGizmoLayout {
    QPointF center;
    std::array<AxisGizmoEnd, 6> ends; // in drawing order (farthest first)
};
constexpr double kAxisGizmoRadius = 34.0;
AxisGizmoLayout axisGizmoLayout(const render::Camera& camera, QSizeF size);
void paintAxisGizmo(QPainter& painter, const render::Camera& camera, QSizeF size);

// The pivot the view orbits about (its target): a small ring with a dot, so a drag's centre is visible.
void paintPivot(QPainter& painter, QPointF at);

} // namespace speculum::ui
