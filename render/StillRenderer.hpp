#pragma once

#include "render/FrameInput.hpp"
#include "render/Renderer.hpp"
#include "render/Result.hpp"
#include "render/image/Image.hpp"

#include <functional>
#include <string>

namespace speculum::render {

struct StillSettings {
    int width = 1280;
    int height = 720;
    int ssaa = 1;          // N: N×N samples per pixel on an ordered sub-pixel grid
    bool reuseMaps = true; // RenderOptions::reuseMaps for the first sample (later ones always reuse)
};

// Reports progress in 0..1 with a short stage name; returning false cancels the render.
using ProgressCallback = std::function<bool(double fraction, const std::string& stage)>;

struct StillResult {
    Image image;             // linear RGBA, row 0 at the top
    FrameReport firstSample; // the plan and timings of the first sample (the one that renders shadows)
    double totalMs = 0.0;
    int samples = 1;
};

// Largest still the current context can render in one piece.
int maxStillSize();

// Renders a still offscreen with the given renderer (the CLI's and the editor's export share this),
// supersampling by averaging N×N frames each shifted by a sub-pixel offset: the same result as
// rendering N times larger and box-filtering, without the N²-times larger buffers.
Result<StillResult> renderStill(Renderer& renderer, const FrameInput& input, const StillSettings& settings,
                                const ProgressCallback& progress = {});

} // namespace speculum::render
