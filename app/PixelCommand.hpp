#pragma once

#include "app/CliOptions.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/renderer/StillRenderer.hpp"

#include <optional>
#include <string>

namespace speculum::app {

// `explain --pixel X,Y`: traces the pixel exactly, puts its path beside the raster recipe the still's
// first sample recorded (StillSettings::probePixel), and prints both with their difference, as a table or
// (--json) as JSON. Returns the exit status.
// `screenSpaceSource`: the pixel in the screen-space sources view (render::screenSpaceSourceAt).
int printPixelExplanation(const CliOptions& options, const render::FrameInput& input,
                          const render::StillResult& still,
                          const std::optional<glm::dvec3>& screenSpaceSource, const std::string& renderer);

} // namespace speculum::app
