#include "editor/document/StillExport.hpp"

#include "editor/document/Snapshot.hpp"
#include "render/image/ImageWriter.hpp"
#include "render/io/Printable.hpp"

#include <QDir>
#include <QFileInfo>
#include <sstream>

namespace speculum::document {

render::Status validateStillExport(const StillExportSettings& settings, const QString& outputPath) {
    const std::string path = outputPath.toStdString();
    if (settings.reference) {
        return render::Error{
            "the exact reference needs the ray-traced reference, which this version does not "
            "have yet"};
    }
    if (settings.width < 1 || settings.height < 1) {
        return render::Error{"the image size must be at least 1×1"};
    }
    if (auto size = render::checkStillSize(settings.width, settings.height); !size) {
        return size;
    }
    if (settings.ssaa < 1 || settings.ssaa > 16) {
        return render::Error{"supersampling must be in 1..16, got " + std::to_string(settings.ssaa)};
    }
    if (!render::isSupportedImagePath(path)) {
        return render::Error{render::printable(path, 200) + ": unsupported image format (supported: " +
                             render::supportedImageFormats() + ")"};
    }
    const QFileInfo info(outputPath);
    if (!info.absoluteDir().exists()) {
        return render::Error{render::printable(path, 200) + ": folder " +
                             render::quoted(info.absolutePath().toStdString(), 200) + " does not exist"};
    }
    return render::checkImageTarget(path, settings.width, settings.height);
}

render::ImageMetadata stillMetadata(const QString& projectPath, const StillExportSettings& settings,
                                    double renderMs, const std::string& rendererDescription) {
    std::ostringstream text;
    text << "size " << settings.width << "x" << settings.height << ", ssaa " << settings.ssaa << ", time "
         << settings.time << " s";
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

render::Result<StillExportResult> exportStill(render::Renderer& renderer, const Scene& scene,
                                              MeshLibrary& meshes, const StillExportSettings& settings,
                                              const QString& outputPath,
                                              const render::ProgressCallback& progress,
                                              const std::string& rendererDescription) {
    if (auto valid = validateStillExport(settings, outputPath); !valid) {
        return render::Error{valid.error()};
    }
    StillExportResult result;
    render::FrameInput input = snapshot(scene, settings.time, meshes, result.warnings);
    if (settings.camera) {
        input.camera = *settings.camera;
    }
    const render::StillSettings still{settings.width, settings.height, settings.ssaa};
    auto rendered = render::renderStill(renderer, input, still, progress);
    if (!rendered) {
        return render::Error{rendered.error()};
    }
    result.still = std::move(*rendered);
    result.warnings.insert(result.warnings.end(), result.still.firstSample.warnings.begin(),
                           result.still.firstSample.warnings.end());
    const auto metadata =
        stillMetadata(scene.projectPath(), settings, result.still.totalMs, rendererDescription);
    if (auto written = render::writeImage(outputPath.toStdString(), result.still.image, metadata); !written) {
        return render::Error{written.error()};
    }
    return result;
}

} // namespace speculum::document
