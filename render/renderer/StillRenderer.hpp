#pragma once

#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/image/Image.hpp"
#include "render/plan/StillSize.hpp"
#include "render/renderer/Renderer.hpp"

#include <functional>
#include <optional>
#include <string>

namespace speculum::render {

// Stills larger than this (either side) render in tiles of at most this size, so the GPU memory a still
// takes stays bounded whatever its size.
inline constexpr int kDefaultTileSize = 2048;

struct StillSettings {
    int width = 1280;
    int height = 720;
    int ssaa = 1; // N: N×N samples per pixel on an ordered sub-pixel grid
    // Largest tile side in pixels; 0: kDefaultTileSize. Never more than maxStillSize(). Tests set small
    // tiles to compare tiled and untiled stills.
    int tileSize = 0;
    bool reuseMaps = true;          // RenderOptions::reuseMaps for the first sample (later ones always reuse)
    bool lightingVariants = true;   // RenderOptions::lightingVariants for every sample
    bool boundShadowLookups = true; // RenderOptions::boundShadowLookups for every sample
    bool cullHiddenBackFaces = true;     // RenderOptions::cullHiddenBackFaces for every sample
    bool showScreenSpaceSources = false; // RenderOptions::showScreenSpaceSources for every sample
    // RenderOptions::preview for every sample (`speculum explain --preview` shows what a preview gives up);
    // ignored where the still is drawn in tiles.
    PreviewPolicy preview;
    // RenderOptions::probePixel for the first sample, whose report is StillResult::firstSample (pixel
    // (x, y) of the image, y from the top); ignored where the still is drawn in tiles.
    std::optional<glm::ivec2> probePixel;
};

// Reports progress in 0..1 with a short stage name; returning false cancels the render.
using ProgressCallback = std::function<bool(double fraction, const std::string& stage)>;

struct StillResult {
    Image image; // linear RGBA, row 0 at the top
    // The report of the first sample of the first tile (the one that renders shadows and the environment
    // map): its plan, the passes that ran with their timings, and the skips. A tile's plan holds only the
    // passes that draw in that tile.
    FrameReport firstSample;
    double totalMs = 0.0;
    int samples = 1;
    int tiles = 1;
};

// Largest still the current context can render in one piece.
int maxStillSize();

// Renders a still offscreen with the given renderer (the CLI's and the editor's export share this),
// supersampling by averaging N×N frames each shifted by a sub-pixel offset: the same result as
// rendering N times larger and box-filtering, without the N²-times larger buffers. Stills larger than a
// tile render tile by tile, each tile a window of the whole image's view (see RenderOptions::tile), so
// the pixels are those of an untiled render. A frame that had to leave out a map whose planned size did not
// fit (FrameReport::drawAgain) is drawn again, planned with the size that does.
base::Result<StillResult> renderStill(Renderer& renderer, const FrameInput& input,
                                      const StillSettings& settings, const ProgressCallback& progress = {});

// Explaining a pixel of a scene with screen-space reflections: the colour pixel (x, y from the top) shows in
// a still drawn with StillSettings::showScreenSpaceSources (green, met in the image; blue, the reflector's
// map; red, the background; blended by the trace's confidence). None where the scene traces nothing in
// the image.
base::Result<std::optional<glm::dvec3>> screenSpaceSourceAt(Renderer& renderer, const FrameInput& input,
                                                            StillSettings settings, glm::ivec2 pixel);

} // namespace speculum::render
