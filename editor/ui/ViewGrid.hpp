#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/frame/Guides.hpp"

#include <QPointF>
#include <QSizeF>
#include <glm/mat4x4.hpp>
#include <optional>
#include <vector>

namespace speculum::ui {

// Projects world points to widget pixels with the renderer's matrices, in double: nothing for a point at or
// behind the near plane.
class ClipProjection {
public:
    ClipProjection(const render::Camera& camera, QSizeF size);
    std::optional<QPointF> point(const glm::dvec3& p) const;

private:
    QPointF toWidget(const glm::dvec4& clip) const;
    glm::dmat4 m_viewProjection{1.0};
    double m_near = 0.1;
    QSizeF m_size;
};

// The ground grid on y = 0, as pieces of world-space lines with their colour (alpha included), for the
// renderer to draw over the view, hidden where the scene stands in front of it (render::GuideLine). Lines
// lie every `spacing` units (a power of ten picked from the view's distance to its target, so about the same
// number of cells is on screen at any zoom), every tenth brighter, the X axis (z = 0) red and the Z axis
// (x = 0) blue. It fades with distance from the camera and where it is seen at a grazing angle, so it never
// turns into a moiré near the horizon. It is kept faint: enough to see where the ground is and which way is
// which, without hiding what stands on it.
struct GroundGrid {
    double spacing = 1.0;
    std::vector<render::GuideLine> lines;
};
GroundGrid groundGrid(const render::Camera& camera);
// Its spacing alone (what Ctrl snaps a moved node to).
double groundGridSpacing(const render::Camera& camera);

} // namespace speculum::ui
