#pragma once

#include "render/frame/FrameInput.hpp"

#include <QColor>
#include <QLineF>
#include <QSizeF>
#include <glm/mat4x4.hpp>
#include <optional>
#include <vector>

class QPainter;

namespace speculum::ui {

// Projects world segments to widget pixels with the renderer's matrices (as ScreenProjection does for
// points), cutting them at the near plane first, in double: a grid line that runs past the camera is
// drawn up to where it leaves the view, not flipped through the eye.
class ClipProjection {
public:
    ClipProjection(const render::Camera& camera, QSizeF size);
    // The visible part of a segment, or nothing when it lies wholly in front of the near plane's eye side.
    std::optional<QLineF> segment(const glm::dvec3& a, const glm::dvec3& b) const;
    std::optional<QPointF> point(const glm::dvec3& p) const;

private:
    QPointF toWidget(const glm::dvec4& clip) const;
    glm::dmat4 m_viewProjection{1.0};
    double m_near = 0.1;
    QSizeF m_size;
};

// The ground grid on y = 0, as pieces of lines with their colour (alpha included), ready to draw. Lines
// lie every `spacing` units (a power of ten picked from the view's distance to its target, so about the
// same number of cells is on screen at any zoom), every tenth brighter, the X axis (z = 0) red and the Z
// axis (x = 0) blue. It fades with distance from the camera and where it is seen at a grazing angle, so it
// never turns into a moiré near the horizon. It is an overlay drawn over the frame, so it is kept faint:
// enough to see where the ground is and which way is which, without hiding what stands on it.
struct GridPiece {
    QLineF line;
    QColor color;
};
struct GroundGrid {
    double spacing = 1.0;
    std::vector<GridPiece> pieces;
};
GroundGrid groundGrid(const render::Camera& camera, QSizeF size);

void paintGroundGrid(QPainter& painter, const render::Camera& camera, QSizeF size);

} // namespace speculum::ui
