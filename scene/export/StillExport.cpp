#include "scene/export/StillExport.hpp"

#include "base/Printable.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/reference/Tracer.hpp"
#include "scene/evaluate/Snapshot.hpp"

#include <QDir>
#include <QFileInfo>
#include <sstream>

namespace speculum::scene {

base::Status validateStillExport(const StillExportSettings& settings, const QString& outputPath) {
    const std::string path = outputPath.toStdString();
    if (settings.width < 1 || settings.height < 1) {
        return base::Error{"the image size must be at least 1×1"};
    }
    if (auto size = render::checkStillSize(settings.width, settings.height); !size) {
        return size;
    }
    if (settings.ssaa < render::kMinSsaa || settings.ssaa > render::kMaxSsaa) {
        return base::Error{"supersampling must be in " + std::to_string(render::kMinSsaa) + ".." +
                           std::to_string(render::kMaxSsaa) + ", got " + std::to_string(settings.ssaa)};
    }
    if (!render::isSupportedImagePath(path)) {
        return base::Error{base::printable(path, 200) +
                           ": unsupported image format (supported: " + render::supportedImageFormats() + ")"};
    }
    const QFileInfo info(outputPath);
    if (!info.absoluteDir().exists()) {
        return base::Error{base::printable(path, 200) + ": folder " +
                           base::quoted(info.absolutePath().toStdString(), 200) + " does not exist"};
    }
    return render::checkImageTarget(path, settings.width, settings.height);
}

render::ImageMetadata stillMetadata(const QString& projectPath, const StillExportSettings& settings,
                                    double renderMs, const std::string& rendererDescription) {
    std::ostringstream text;
    text << "size " << settings.width << "x" << settings.height << ", ssaa " << settings.ssaa << ", time "
         << settings.time << " s" << (settings.reference ? ", reference" : "");
    const std::string name = projectPath.isEmpty() ? std::string("an untitled scene")
                                                   : QFileInfo(projectPath).fileName().toStdString();
    render::ImageMetadata metadata;
    metadata.attributes = {
        {"Software", std::string("speculum ") + SPECULUM_VERSION},
        {"ImageDescription", "speculum render of " + name + " (" + text.str() + ")"},
        {"speculum:scene", QFileInfo(projectPath).absoluteFilePath().toStdString()},
        {"speculum:settings", text.str()},
        {"speculum:renderTimeMs", std::to_string(renderMs)},
    };
    if (!rendererDescription.empty()) {
        metadata.attributes.emplace_back("speculum:renderer", rendererDescription);
    }
    return metadata;
}

namespace {

// `speculum render --reference`'s path: the exact tracer on the CPU (no GL), on the calling thread, which
// the progress callback keeps responsive and can stop.
base::Result<render::reference::TraceResult> traceStill(const render::FrameInput& input,
                                                        const StillExportSettings& settings,
                                                        const render::ProgressCallback& progress) {
    auto tracer = render::reference::Tracer::create(input);
    if (!tracer) {
        return base::Error{tracer.error()};
    }
    render::reference::TraceSettings trace;
    trace.width = settings.width;
    trace.height = settings.height;
    trace.ssaa = settings.ssaa;
    return tracer->render(trace, [&](double fraction) {
        return !progress || progress(fraction, "exact reference, ray tracing");
    });
}

} // namespace

base::Result<StillExportResult> exportStill(render::Renderer& renderer, const Scene& scene,
                                            MeshLibrary& meshes, const StillExportSettings& settings,
                                            const QString& outputPath,
                                            const render::ProgressCallback& progress,
                                            const std::string& rendererDescription) {
    if (auto valid = validateStillExport(settings, outputPath); !valid) {
        return base::Error{valid.error()};
    }
    StillExportResult result;
    render::FrameInput input = snapshot(scene, settings.time, meshes, result.warnings);
    if (settings.camera) {
        input.camera = *settings.camera;
    }
    std::string description = rendererDescription;
    if (settings.reference) {
        auto traced = traceStill(input, settings, progress);
        if (!traced) {
            return base::Error{traced.error()};
        }
        result.warnings.insert(result.warnings.end(), traced->warnings.begin(), traced->warnings.end());
        result.still.image = std::move(traced->image);
        result.still.totalMs = traced->totalMs;
        result.still.samples = traced->samples;
        description = "reference ray tracer (Embree 3)";
    } else {
        const render::StillSettings still{settings.width, settings.height, settings.ssaa};
        auto rendered = render::renderStill(renderer, input, still, progress);
        if (!rendered) {
            return base::Error{rendered.error()};
        }
        result.still = std::move(*rendered);
        result.warnings.insert(result.warnings.end(), result.still.firstSample.warnings.begin(),
                               result.still.firstSample.warnings.end());
    }
    const auto metadata = stillMetadata(scene.projectPath(), settings, result.still.totalMs, description);
    if (auto written = render::writeImage(outputPath.toStdString(), result.still.image, metadata); !written) {
        return base::Error{written.error()};
    }
    return result;
}

} // namespace speculum::scene
