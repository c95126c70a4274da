#include "editor/ui/ExactComparison.hpp"

#include "accuracy/run/Measure.hpp"
#include "editor/ui/Viewport.hpp"
#include "render/image/ColorSpace.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/Flip.hpp"
#include "scene/evaluate/Snapshot.hpp"

#include <QTimer>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>

namespace speculum::ui {

namespace {

constexpr int kPollMs = 50;

// One level's figures: the raster image against this exact one.
base::Result<std::unique_ptr<ComparisonResult>> measureLevel(const ComparisonResult& frame,
                                                             const render::Image& raster,
                                                             const accuracy::Reference& reference) {
    auto errors = accuracy::compareWithReference(raster, reference);
    if (!errors)
        return base::Error{errors.error()};
    auto result = std::make_unique<ComparisonResult>(frame);
    result->traceMs = reference.traced.totalMs;
    for (const auto& text : reference.traced.warnings)
        result->warnings << QString::fromStdString(text);
    result->paths = reference.traced.paths;
    result->noiseRms = std::isfinite(reference.traced.noiseRms) ? reference.traced.noiseRms : 0.0;
    result->roughPixels = reference.traced.glossyPixels;
    result->rmse = errors->overall.rmse;
    result->psnr = errors->overall.psnr;
    auto psnrOf = [](const std::optional<render::metrics::ErrorStats>& stats) {
        return stats ? std::optional<double>(stats->psnr) : std::nullopt;
    };
    result->psnrMirrors = psnrOf(errors->mirrors);
    result->psnrReflector = psnrOf(errors->reflector);
    result->errorMap = toQImage(render::metrics::errorColorMap(errors->difference));
    result->flipMap = toQImage(render::metrics::flipColorMap(errors->flip));
    result->psnrLow = errors->interval.psnrLow;
    result->psnrHigh = errors->interval.psnrHigh;
    result->mae = errors->overall.mae;
    result->ssim = errors->ssim;
    result->flip = errors->flip.mean;
    result->hdrFlip = errors->hdrFlip;
    result->reference = toQImage(reference.traced.image);
    result->raster = toQImage(raster);
    return result;
}

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

// Everything the worker reads, its own copies: the compared frame as a result to fill, the raster image.
struct ExactComparison::Job {
    ComparisonResult result;
    render::Image raster;
    ComparisonQuality quality;
};

bool ExactComparison::start(const ComparisonQuality& quality, double time) {
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
    auto job = std::make_unique<Job>();
    job->quality = quality;
    job->quality.width = std::clamp(quality.width, 16, 4096);
    ComparisonResult& result = job->result;
    result.width = job->quality.width;
    result.height = comparisonHeight(result.width);
    std::vector<scene::Warning> warnings;
    result.input = scene::snapshot(m_scene, time, m_viewport.meshes(), warnings);
    result.input.camera = m_viewport.viewCamera();

    // The raster frame: the second of two, so shader compilation and first-use costs are not timed; every
    // map is rendered again (as the bench times them), not reused from the viewport's last frame.
    m_viewport.makeCurrent();
    auto raster =
        accuracy::measureFrames(*m_viewport.renderer(), result.input, result.width, result.height, 1, 1);
    m_viewport.doneCurrent();
    m_viewport.update();
    if (!raster) {
        emit failed(QString::fromStdString(raster.error()), false);
        return false;
    }
    result.rasterCpuMs = raster->cpuMs;
    result.rasterGpuMs = raster->gpuMs;
    for (const scene::Warning& w : warnings) {
        result.warnings << QString::fromStdString(w.message);
    }
    job->raster = std::move(raster->image);

    m_cancel = false;
    m_done = false;
    m_latest.reset();
    {
        const std::lock_guard lock(m_mutex);
        m_events.clear();
    }
    // The tracer is thread-safe and needs no GL.
    m_thread = std::thread([this, job = std::move(job)]() mutable { work(std::move(job)); });
    QTimer::singleShot(kPollMs, this, &ExactComparison::poll);
    return true;
}

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// What a trace found about the scene: its cost per path (its own time over the paths it traced), what it
// paid before its first path (the rest of the wall time), and the rough part of the image.
TraceProbe measuredTrace(const accuracy::Reference& reference, double wallSeconds) {
    const render::reference::TraceResult& traced = reference.traced;
    const int pixels = traced.image.width * traced.image.height;
    TraceProbe found;
    found.roughFraction = double(traced.glossyPixels) / double(std::max(pixels, 1));
    const double tracing = traced.totalMs / 1000.0;
    found.secondsPerPath = tracing / tracedPaths(found.roughFraction, pixels, traced.paths);
    found.setupSeconds = std::max(0.0, wallSeconds - tracing);
    return found;
}

// A small trace of the same view (an eighth of the width, the first level's paths): the first figures for
// the estimate.
base::Result<TraceProbe> probeTrace(const render::FrameInput& input, int width,
                                    const std::function<bool(double)>& keepGoing) {
    const int w = std::max(16, width / 8);
    const auto start = Clock::now();
    auto probe = accuracy::traceReference(input, accuracy::ReferenceKind::Scene, w, comparisonHeight(w),
                                          keepGoing, kComparisonPathLevels.front());
    if (!probe)
        return base::Error{probe.error()};
    return measuredTrace(*probe, secondsSince(start));
}

// The estimated time of the levels after one of `paths` paths, as the plan made with `measured` has them.
double secondsAfter(const ComparisonQuality& quality, const TraceProbe& measured, int paths) {
    double seconds = 0.0;
    for (const PlannedLevel& level : planComparisonLevels(quality, measured))
        if (level.paths > paths)
            seconds += level.seconds;
    return seconds;
}

} // namespace

// The worker: the probe and the estimate, then level after level, each traced, measured and posted. The
// levels measure the scene better than the probe: the next level, and on auto whether there is one, is
// decided from the last.
void ExactComparison::work(std::unique_ptr<Job> job) {
    const auto begin = Clock::now();
    auto keepGoing = [this](double) { return !m_cancel.load(); };
    const ComparisonQuality& quality = job->quality;
    auto probe = probeTrace(job->result.input, quality.width, keepGoing);
    if (!probe) {
        post({.kind = Event::Kind::Failed,
              .error = QString::fromStdString(probe.error()),
              .cancelled = m_cancel});
        return;
    }
    const std::vector<PlannedLevel> planned = planComparisonLevels(quality, *probe);
    double plannedSeconds = 0.0;
    for (const PlannedLevel& level : planned)
        plannedSeconds += level.seconds;
    post({.kind = Event::Kind::Estimate, .seconds = plannedSeconds, .paths = planned.back().paths});
    TraceProbe measured = *probe;
    std::optional<PlannedLevel> level = planned.front();
    while (level) {
        const double after = secondsAfter(quality, measured, level->paths);
        const double elapsedBefore = secondsSince(begin);
        const auto start = Clock::now();
        auto reference = accuracy::traceReference(
            job->result.input, accuracy::ReferenceKind::Scene, job->result.width, job->result.height,
            [&](double fraction) {
                const double left = level->seconds * (1.0 - fraction) + after;
                const double done = elapsedBefore + secondsSince(start);
                post({.kind = Event::Kind::Progress,
                      .seconds = left,
                      .fraction = done / std::max(done + left, 1e-9),
                      .paths = level->paths});
                return !m_cancel.load();
            },
            level->paths);
        if (!reference) {
            post({.kind = Event::Kind::Failed,
                  .error = QString::fromStdString(reference.error()),
                  .cancelled = m_cancel});
            return;
        }
        measured = measuredTrace(*reference, secondsSince(start));
        const int done = level->paths;
        level = nextComparisonLevel(quality, done, measured, secondsSince(begin));
        auto result = measureLevel(job->result, job->raster, *reference);
        if (!result) {
            post({.kind = Event::Kind::Failed, .error = QString::fromStdString(result.error())});
            return;
        }
        (*result)->final = !level.has_value();
        post({.kind = Event::Kind::Level, .paths = done, .result = std::move(*result)});
    }
}

void ExactComparison::post(Event event) {
    const std::lock_guard lock(m_mutex);
    if (event.kind == Event::Kind::Progress && !m_events.empty() &&
        m_events.back().kind == Event::Kind::Progress) {
        m_events.back() = std::move(event); // only the latest progress matters
        return;
    }
    const bool last = event.kind == Event::Kind::Failed || (event.result && event.result->final);
    m_events.push_back(std::move(event));
    if (last)
        m_done = true;
}

void ExactComparison::poll() {
    std::deque<Event> events;
    bool done = false;
    {
        // Together: once the worker has said it is done, every event it posted is in this batch.
        const std::lock_guard lock(m_mutex);
        events.swap(m_events);
        done = m_done;
    }
    for (Event& event : events) {
        switch (event.kind) {
        case Event::Kind::Estimate:
            emit estimated(event.seconds, event.paths);
            break;
        case Event::Kind::Progress:
            emit progress(event.fraction, event.paths, event.seconds);
            break;
        case Event::Kind::Level:
            m_latest = std::make_unique<ComparisonResult>(*event.result);
            if (!event.result->final)
                emit refined(*event.result);
            break;
        case Event::Kind::Failed:
            break;
        }
    }
    if (!done) {
        QTimer::singleShot(kPollMs, this, &ExactComparison::poll);
        return;
    }
    join();
    const Event* failure = nullptr;
    for (const Event& event : events)
        if (event.kind == Event::Kind::Failed)
            failure = &event;
    if (!failure && m_latest) {
        emit finished(*m_latest);
    } else if (failure && failure->cancelled && m_latest) {
        // Stopped while refining: the last level done stands as the result.
        m_latest->final = true;
        emit finished(*m_latest);
    } else {
        emit failed(failure ? failure->error : tr("the comparison ended without a result"),
                    failure && failure->cancelled);
    }
}

} // namespace speculum::ui
