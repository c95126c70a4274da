#pragma once

#include "render/image/Image.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/renderer/Renderer.hpp"
#include "render/renderer/StillRenderer.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"
#include "scene/model/Warning.hpp"

#include <QString>
#include <optional>
#include <string>
#include <vector>

namespace speculum::scene {

// A still image of a scene: the one path `speculum render` (raster or --reference) and the editor's Export
// Still both take, so the two give the same pixels and write the same metadata for the same settings (the
// scene camera, animations at `time`, render::renderStill's supersampling or the tracer's paths,
// render::writeImage's encoding).
struct StillExportSettings {
    int width = 1280;
    int height = 720;
    int ssaa = 1;
    double time = 0.0;
    // The exact ray-traced reference (`speculum render --reference`): the CPU tracer, no GL; no renderer
    // is needed.
    bool reference = false;
    int samples = 16; // the reference's paths per sub-sample that meets a rough surface (--samples)
    // Screen-space mirrors drawn in the colour of where their reflection comes from (render
    // --screen-space-sources; render::StillSettings::showScreenSpaceSources). Raster stills only.
    bool screenSpaceSources = false;
    // Render through this camera instead of the scene's (the editor's "current view" option).
    std::optional<render::Camera> camera;
};

// Checks settings and output path before any work ("foo.bmp: unsupported image format ...").
base::Status validateStillExport(const StillExportSettings& settings, const std::string& outputPath);

// What the tracer's Monte Carlo part left, for a reference still.
struct TraceFigures {
    int paths = 1;        // per sub-sample of a pixel that meets a rough surface
    int glossyPixels = 0; // pixels that needed several paths
    double noiseRms = 0; // the root mean square of the pixels' standard errors (linear radiance); NaN: 1 path
};

struct StillExportResult {
    render::StillResult still;
    std::vector<Warning> sceneWarnings; // exportStill's snapshot, shown before the renderer's
    std::vector<std::string> warnings;  // renderer or tracer
    std::optional<TraceFigures> trace;  // a reference still's noise
    std::string renderer;               // what drew it: the GL description, or the tracer's
};

// The attributes stored in the file: software, a description with the settings, the project path, the
// render time, what drew it, and for a reference its paths and noise.
render::ImageMetadata stillMetadata(const std::string& projectPath, const StillExportSettings& settings,
                                    const StillExportResult& result);

// Renders `input` as writeStill() does, without writing it: for the frames of an animation.
base::Result<StillExportResult> renderStillImage(render::Renderer* renderer, const render::FrameInput& input,
                                                 const StillExportSettings& settings,
                                                 const render::ProgressCallback& progress = {},
                                                 const std::string& rendererDescription = {});

// Renders `input` (a scene evaluated at settings.time) with `renderer` (its context current), or traces it
// for a reference still, and writes `outputPath`. A cancel through `progress` returns an error "cancelled"
// and writes nothing; so does any failure.
base::Result<StillExportResult> writeStill(render::Renderer* renderer, const render::FrameInput& input,
                                           const std::string& projectPath,
                                           const StillExportSettings& settings, const std::string& outputPath,
                                           const render::ProgressCallback& progress = {},
                                           const std::string& rendererDescription = {});

// The document's still: the scene evaluated at settings.time (through settings.camera when set), then
// writeStill. The snapshot's warnings are the result's sceneWarnings.
base::Result<StillExportResult> exportStill(render::Renderer* renderer, const Scene& scene,
                                            MeshLibrary& meshes, const StillExportSettings& settings,
                                            const QString& outputPath,
                                            const render::ProgressCallback& progress = {},
                                            const std::string& rendererDescription = {});

} // namespace speculum::scene
