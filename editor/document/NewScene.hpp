#pragma once

#include "scene/model/SceneData.hpp"

namespace speculum::document {

// What File ▸ New (and the editor at start-up) opens: a 10 × 10 floor at y = 0, a sun that casts shadows,
// and a camera raised above the floor looking down at its middle, so the first things added stand on
// something and are seen from above, never edge-on at eye level y = 0. A project file without a camera
// still reads with CameraData's own defaults; only new documents start like this.
scene::SceneData newSceneData();

} // namespace speculum::document
