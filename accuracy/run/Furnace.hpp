#pragma once

#include "accuracy/Results.hpp"
#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/renderer/Renderer.hpp"

#include <functional>
#include <string>
#include <vector>

namespace speculum::accuracy {

// The white furnace: a rough mirror (or the curved reflector) alone under a uniform white sky, no light,
// no ambient. What it shows is exactly the energy the GGX lobe keeps after masking and shadowing, its
// directional albedo E(μ_v, α): 1 for a perfect mirror, less as roughness grows. Every raster glossy path
// should show E; one that shows more or less creates or loses energy, an error no blur setting fixes.

// The rough floor mirror under the white sky, seen `viewDegrees` from its normal by a narrow camera, so
// that every pixel of a small image sees about that angle.
render::FrameInput planarFurnace(double roughness, double viewDegrees);
// A rough chrome ball under the white sky, seen from +Z; its centre pixel faces the camera (μ_v = 1).
render::FrameInput reflectorFurnace(double roughness);

// The roughnesses measured: 0 (the perfect mirror), then 0.1 to 1, the glossy sweep's among them.
const std::vector<double>& furnaceRoughnesses();

// Renders and traces each surface at each roughness with each raster glossy path (green channel: the sky
// is white). `stop`, asked between rows, ends it with the error "stopped". Needs the renderer's GL context
// current.
base::Result<std::vector<FurnaceRow>> runFurnace(render::Renderer& renderer,
                                                 const std::function<bool()>& stop = {});

} // namespace speculum::accuracy
