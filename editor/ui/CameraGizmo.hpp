#pragma once

#include "editor/ui/ViewGrid.hpp"

#include <QLineF>
#include <vector>

class QPainter;

namespace speculum::ui {

// The scene camera (what `speculum render` draws) as a wireframe pyramid seen from the view: its eye, the
// four edges to a rectangle a little way along its view (in the view's aspect), and a triangle over the
// rectangle's top edge showing its up side. Its size follows the scene camera's distance to its target,
// within limits, so it reads as a camera at any scale. Nothing when the view sits where the scene camera
// does (looking through it).
std::vector<QLineF> cameraGizmoLines(const render::Camera& sceneCamera, const ClipProjection& view,
                                     const render::Camera& viewCamera, double aspect);
void paintCameraGizmo(QPainter& painter, const render::Camera& sceneCamera, const render::Camera& viewCamera,
                      QSizeF size);

} // namespace speculum::ui
