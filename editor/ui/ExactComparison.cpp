#include "editor/ui/ExactComparison.hpp"

#include "accuracy/run/Measure.hpp"
#include "editor/ui/Viewport.hpp"
#include "render/image/ColorSpace.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "scene/evaluate/Snapshot.hpp"

#include <QTimer>
#include <algorithm>
#include <cmath>

namespace speculum::ui {

namespace {

constexpr int kPollMs = 50;

} // namespace

QImage toQImage(const render::Image& linear) {
    QImage out(linear.width, linear.height, QImage::Format_RGB32);
    for (int y = 0; y < linear.height; ++y) {
        auto* line = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < linear.width; ++x) {
            const auto c = linear.at(x, y);
            line[x] =
                qRgb(render::linearToSrgb8(c.r), render::linearToSrgb8(c.g), render::linearToSrgb8(c.b));
        }
    }
    return out;
}

ExactComparison::ExactComparison(scene::Scene& scene, Viewport& viewport, QObject* parent)
    : QObject(parent)
    , m_scene(scene)
    , m_viewport(viewport) {}

ExactComparison::~ExactComparison() {
    m_cancel = true;
    join();
}

void ExactComparison::join() {
    if (m_thread.joinable()) {
        m_thread.join();
    }
}

void ExactComparison::cancel() {
    m_cancel = true;
}

bool ExactComparison::start(int width, double time) {
    if (running()) {
        emit failed(tr("a comparison is already running"), false);
        return false;
    }
    if (!m_viewport.isValid() || !m_viewport.renderer()) {
        emit failed(m_viewport.rendererError().isEmpty() ? tr("the viewport has no OpenGL context yet")
                                                         : m_viewport.rendererError(),
                    false);
        return false;
    }
    // The viewport's aspect, so the error map lies over the view it was measured on.
    const int w = std::max(16, std::min(width, m_viewport.width()));
    const int h =
        std::max(16, int(std::lround(double(w) * m_viewport.height() / std::max(1, m_viewport.width()))));

    auto result = std::make_unique<ComparisonResult>();
    result->width = w;
    result->height = h;
    std::vector<scene::Warning> warnings;
    result->input = scene::snapshot(m_scene, time, m_viewport.meshes(), warnings);
    result->input.camera = m_viewport.viewCamera();

    // The raster frame: the second of two, so shader compilation and first-use costs are not timed; every
    // map is rendered again (as the bench times them), not reused from the viewport's last frame.
    m_viewport.makeCurrent();
    auto raster = accuracy::measureFrames(*m_viewport.renderer(), result->input, w, h, 1, 1);
    m_viewport.doneCurrent();
    m_viewport.update();
    if (!raster) {
        emit failed(QString::fromStdString(raster.error()), false);
        return false;
    }
    result->rasterCpuMs = raster->cpuMs;
    result->rasterGpuMs = raster->gpuMs;
    for (const scene::Warning& w : warnings) {
        result->warnings << QString::fromStdString(w.message);
    }

    m_cancel = false;
    m_done = false;
    m_fraction = 0.0;
    m_error.clear();
    m_cancelled = false;
    m_result.reset();
    // The tracer is thread-safe and needs no GL; the worker owns copies of everything it reads. The bench's
    // scene reference: shadows traced with each light's PCF footprint.
    m_thread = std::thread([this, result = std::move(result), image = std::move(raster->image)]() mutable {
        auto reference = accuracy::traceReference(result->input, accuracy::ReferenceKind::Scene,
                                                  result->width, result->height, [this](double fraction) {
                                                      m_fraction = fraction;
                                                      return !m_cancel.load();
                                                  });
        if (!reference) {
            m_cancelled = m_cancel;
            m_error = QString::fromStdString(reference.error());
            m_done = true;
            return;
        }
        result->traceMs = reference->traced.totalMs;
        for (const auto& text : reference->traced.warnings) {
            result->warnings << QString::fromStdString(text);
        }
        auto errors = accuracy::compareWithReference(image, *reference);
        if (!errors) {
            m_error = QString::fromStdString(errors.error());
            m_done = true;
            return;
        }
        result->rmse = errors->overall.rmse;
        result->psnr = errors->overall.psnr;
        auto psnrOf = [](const std::optional<render::metrics::ErrorStats>& stats) {
            return stats ? std::optional<double>(stats->psnr) : std::nullopt;
        };
        result->psnrMirrors = psnrOf(errors->mirrors);
        result->psnrReflector = psnrOf(errors->reflector);
        result->errorMap = toQImage(render::metrics::errorColorMap(errors->difference));
        result->reference = toQImage(reference->traced.image);
        result->raster = toQImage(image);
        m_result = std::move(result);
        m_done = true;
    });
    QTimer::singleShot(kPollMs, this, &ExactComparison::poll);
    return true;
}

void ExactComparison::poll() {
    if (!m_done) {
        emit progress(m_fraction);
        QTimer::singleShot(kPollMs, this, &ExactComparison::poll);
        return;
    }
    join();
    if (m_result) {
        const ComparisonResult result = std::move(*m_result);
        m_result.reset();
        emit finished(result);
    } else {
        emit failed(m_error, m_cancelled);
    }
}

} // namespace speculum::ui
