#pragma once

#include "render/image/Image.hpp"
#include "render/renderer/Renderer.hpp"
#include "render/renderer/StillRenderer.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"

#include <QString>
#include <optional>
#include <string>
#include <vector>

namespace speculum::scene {

// A still image of a document: what `speculum render` does and what the editor's Export Still dialog does,
// in one place so the two give the same pixels for the same settings (the scene camera, animations at
// `time`, render::renderStill's supersampling, render::writeImage's encoding).
struct StillExportSettings {
    int width = 1280;
    int height = 720;
    int ssaa = 1;
    double time = 0.0;
    // The exact ray-traced reference (`speculum render --reference`): the CPU tracer, no GL; the renderer
    // passed to exportStill is not used.
    bool reference = false;
    // Render through this camera instead of the scene's (the editor's "current view" option).
    std::optional<render::Camera> camera;
};

// Checks settings and output path before any work ("foo.bmp: unsupported image format ...").
base::Status validateStillExport(const StillExportSettings& settings, const QString& outputPath);

// The attributes stored in the file: software, a description with the settings, the project path.
render::ImageMetadata stillMetadata(const QString& projectPath, const StillExportSettings& settings,
                                    double renderMs, const std::string& rendererDescription);

struct StillExportResult {
    render::StillResult still;
    std::vector<std::string> warnings; // snapshot + renderer
};

// Renders (needs the renderer's context current) and writes `outputPath`. A cancel through `progress`
// returns an error "cancelled" and writes nothing.
base::Result<StillExportResult> exportStill(render::Renderer& renderer, const Scene& scene,
                                            MeshLibrary& meshes, const StillExportSettings& settings,
                                            const QString& outputPath,
                                            const render::ProgressCallback& progress = {},
                                            const std::string& rendererDescription = {});

} // namespace speculum::scene
