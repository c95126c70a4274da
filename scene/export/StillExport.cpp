#include "scene/export/StillExport.hpp"

#include "base/Printable.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/reference/Tracer.hpp"
#include "scene/evaluate/Snapshot.hpp"

#include <QFileInfo>
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <thread>

namespace speculum::scene {

namespace {

std::string plural(int n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The tracer on the CPU (no GL), on the calling thread, which the progress callback keeps responsive and
// can stop.
base::Result<StillExportResult> traceStill(const render::FrameInput& input,
                                           const StillExportSettings& settings,
                                           const render::ProgressCallback& progress) {
    auto tracer = render::reference::Tracer::create(input);
    if (!tracer)
        return base::Error{tracer.error()};
    render::reference::TraceSettings trace;
    trace.width = settings.width;
    trace.height = settings.height;
    trace.ssaa = settings.ssaa;
    trace.samples = settings.samples;
    auto traced = tracer->render(trace, [&](double fraction) {
        return !progress || progress(fraction, "exact reference, ray tracing");
    });
    if (!traced)
        return base::Error{traced.error()};
    StillExportResult result;
    result.still.image = std::move(traced->image);
    result.still.totalMs = traced->totalMs;
    result.still.samples = traced->samples;
    result.warnings = std::move(traced->warnings);
    result.trace = TraceFigures{traced->paths, traced->glossyPixels, traced->noiseRms};
    result.renderer = "reference ray tracer (Embree 3, " +
                      plural(int(std::max(1u, std::thread::hardware_concurrency())), "thread", "threads") +
                      ")";
    return result;
}

base::Result<StillExportResult> rasterStill(render::Renderer& renderer, const render::FrameInput& input,
                                            const StillExportSettings& settings,
                                            const render::ProgressCallback& progress) {
    render::StillSettings still{settings.width, settings.height, settings.ssaa};
    still.showScreenSpaceSources = settings.screenSpaceSources;
    auto rendered = render::renderStill(renderer, input, still, progress);
    if (!rendered)
        return base::Error{rendered.error()};
    StillExportResult result;
    result.still = std::move(*rendered);
    result.warnings = result.still.firstSample.warnings;
    return result;
}

} // namespace

base::Status validateStillExport(const StillExportSettings& settings, const std::string& path) {
    if (settings.width < 1 || settings.height < 1)
        return base::Error{"the image size must be at least 1×1"};
    if (auto size = render::checkStillSize(settings.width, settings.height); !size)
        return size;
    if (settings.ssaa < render::kMinSsaa || settings.ssaa > render::kMaxSsaa)
        return base::Error{"supersampling must be in " + std::to_string(render::kMinSsaa) + ".." +
                           std::to_string(render::kMaxSsaa) + ", got " + std::to_string(settings.ssaa)};
    if (settings.reference && (settings.samples < render::reference::kMinTraceSamples ||
                               settings.samples > render::reference::kMaxTraceSamples))
        return base::Error{"samples must be in " + std::to_string(render::reference::kMinTraceSamples) +
                           ".." + std::to_string(render::reference::kMaxTraceSamples) + ", got " +
                           std::to_string(settings.samples)};
    if (!render::isSupportedImagePath(path))
        return base::Error{base::printable(path, 200) +
                           ": unsupported image format (supported: " + render::supportedImageFormats() + ")"};
    const std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
    if (!std::filesystem::is_directory(folder))
        return base::Error{base::printable(path, 200) + ": folder " + base::quoted(folder.string(), 200) +
                           " does not exist"};
    return render::checkImageTarget(path, settings.width, settings.height);
}

render::ImageMetadata stillMetadata(const std::string& projectPath, const StillExportSettings& settings,
                                    const StillExportResult& result) {
    std::ostringstream text;
    text << "size " << settings.width << "x" << settings.height << ", ssaa " << settings.ssaa << ", time "
         << settings.time << " s";
    if (settings.screenSpaceSources)
        text << ", screen-space sources";
    if (result.trace)
        text << ", reference, " << plural(result.trace->paths, "path", "paths") << " per glossy sample";
    const std::string name = projectPath.empty() ? std::string("an untitled scene")
                                                 : std::filesystem::path(projectPath).filename().string();
    render::ImageMetadata metadata;
    metadata.attributes = {
        {"Software", std::string("speculum ") + SPECULUM_VERSION},
        {"ImageDescription",
         std::string(result.trace ? "speculum reference render of " : "speculum render of ") + name + " (" +
             text.str() + ")"},
    };
    if (!projectPath.empty())
        metadata.attributes.emplace_back("speculum:scene", std::filesystem::absolute(projectPath).string());
    metadata.attributes.emplace_back("speculum:settings", text.str());
    metadata.attributes.emplace_back("speculum:renderTimeMs", std::to_string(result.still.totalMs));
    if (result.trace) {
        std::ostringstream noise; // full precision, for scripts comparing renders
        noise << std::setprecision(17) << result.trace->noiseRms;
        metadata.attributes.emplace_back("speculum:noiseRms", noise.str());
        metadata.attributes.emplace_back("speculum:glossyPixels", std::to_string(result.trace->glossyPixels));
    }
    if (!result.renderer.empty())
        metadata.attributes.emplace_back("speculum:renderer", result.renderer);
    return metadata;
}

base::Result<StillExportResult> renderStillImage(render::Renderer* renderer, const render::FrameInput& input,
                                                 const StillExportSettings& settings,
                                                 const render::ProgressCallback& progress,
                                                 const std::string& rendererDescription) {
    if (!settings.reference && !renderer)
        return base::Error{"no renderer to draw the still with"};
    auto result = settings.reference ? traceStill(input, settings, progress)
                                     : rasterStill(*renderer, input, settings, progress);
    if (result && !settings.reference)
        result->renderer = rendererDescription;
    return result;
}

base::Result<StillExportResult> writeStill(render::Renderer* renderer, const render::FrameInput& input,
                                           const std::string& projectPath,
                                           const StillExportSettings& settings, const std::string& outputPath,
                                           const render::ProgressCallback& progress,
                                           const std::string& rendererDescription) {
    if (auto valid = validateStillExport(settings, outputPath); !valid)
        return base::Error{valid.error()};
    auto result = renderStillImage(renderer, input, settings, progress, rendererDescription);
    if (!result)
        return result;
    if (auto written = render::writeImage(outputPath, result->still.image,
                                          stillMetadata(projectPath, settings, *result));
        !written)
        return base::Error{written.error()};
    return result;
}

base::Result<StillExportResult> exportStill(render::Renderer* renderer, const Scene& scene,
                                            MeshLibrary& meshes, const StillExportSettings& settings,
                                            const QString& outputPath,
                                            const render::ProgressCallback& progress,
                                            const std::string& rendererDescription) {
    const std::string path = outputPath.toStdString();
    if (auto valid = validateStillExport(settings, path); !valid)
        return base::Error{valid.error()};
    std::vector<Warning> warnings;
    render::FrameInput input = snapshot(scene, settings.time, meshes, warnings);
    if (settings.camera)
        input.camera = *settings.camera;
    auto result = writeStill(renderer, input, scene.projectPath().toStdString(), settings, path, progress,
                             rendererDescription);
    if (result)
        result->sceneWarnings = std::move(warnings);
    return result;
}

} // namespace speculum::scene
