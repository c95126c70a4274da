#pragma once

#include "render/frame/FrameInput.hpp"

#include <string>
#include <vector>

namespace speculum::render::passes {

// The `#define` lines that build the lit shaders (shaders/lighting.glsl) for this frame's lights: their
// count, and per light its shadow slot (-1: none) and whether the map is a cube (point lights). Frames with
// the same lights and shadow slots share one variant.
std::string lightingVariant(const FrameInput& input, const std::vector<int>& shadowedLights);

} // namespace speculum::render::passes
