#pragma once

#include "render/frame/FrameInput.hpp"

#include <optional>
#include <string_view>

namespace speculum::view {

// Blender's numpad views, in speculum's Y-up world (Blender's Z-up front is −Y there, which is +Z here):
// Front looks along −Z (from +Z), Right along −X (from +X), Top straight down; Back, Left and Bottom are
// the opposite sides (Ctrl+numpad in Blender).
enum class ViewPreset { Front, Back, Right, Left, Top, Bottom };

// The view `current` turned to look at its own target from the preset's side, at the same distance (the
// field of view and the depth range kept). Top and Bottom stop a hair short of the pole, where the orbit
// stops too, so the up vector stays +Y and orbiting on from there turns the way it always does; on screen
// +X is to the right and −Z up (Top), as in Blender.
render::Camera presetView(const render::Camera& current, ViewPreset preset);

// The unit direction a preset looks along (exact, without the hair off the pole).
glm::dvec3 presetDirection(ViewPreset preset);

// "front", "back", "right", "left", "top", "bottom": action names and labels.
std::string_view presetName(ViewPreset preset);

} // namespace speculum::view
