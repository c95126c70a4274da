#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/frame/Guides.hpp"

#include <utility>
#include <vector>

namespace speculum::ui {

// The scene camera (what `speculum render` draws) as a wireframe pyramid seen from the view: its eye, the
// four edges to a rectangle a little way along its view (in the view's aspect), and a triangle over the
// rectangle's top edge showing its up side. Its size follows the scene camera's distance to its target,
// within limits, so it reads as a camera at any scale. Nothing when the view sits where the scene camera
// does (looking through it).
std::vector<std::pair<glm::dvec3, glm::dvec3>>
cameraGizmoSegments(const render::Camera& sceneCamera, const render::Camera& viewCamera, double aspect);
// The same as guide lines for the renderer (a dark halo under a light line), faint where the scene hides
// them.
void addCameraGizmoGuides(const render::Camera& sceneCamera, const render::Camera& viewCamera, double aspect,
                          std::vector<render::GuideLine>& guides);

} // namespace speculum::ui
