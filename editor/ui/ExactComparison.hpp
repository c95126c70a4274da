#pragma once

#include "editor/ui/ComparisonLevels.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/image/Image.hpp"

#include <QImage>
#include <QObject>
#include <QString>
#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace speculum::scene {
class Scene;
} // namespace speculum::scene

namespace speculum::ui {

class Viewport;

// What "Compare with exact" found for one view.
struct ComparisonResult {
    int width = 0;
    int height = 0;
    double rmse = 0.0;                   // sRGB 0..1, all pixels
    double psnr = 0.0;                   // dB
    std::optional<double> psnrMirrors;   // none when no pixel shows a planar mirror
    std::optional<double> psnrReflector; // none when no pixel shows the curved reflector
    double psnrLow = 0.0;                // the 95 % interval the exact image's own noise leaves on the PSNR
    double psnrHigh = 0.0;
    double mae = 0.0;     // mean absolute error of the sRGB values
    double ssim = 1.0;    // mean SSIM, 1 for identical images
    double flip = 0.0;    // mean LDR-FLIP, 0 … 1
    double hdrFlip = 0.0; // mean HDR-FLIP on the linear images
    double rasterCpuMs = 0.0;
    double rasterGpuMs = -1.0; // -1: no GPU timer on this context
    double traceMs = 0.0;      // of the level shown (the levels before it not counted)
    // The exact image's own Monte Carlo noise: paths per rough pixel, and their RMS standard error (linear
    // radiance; 0: exact, no rough pixel on screen). It halves from one level to the next.
    int paths = 0;
    double noiseRms = 0.0;
    int roughPixels = 0;
    bool final = true; // false: a level the refinement goes on from
    QImage errorMap;   // the error ramp (render::metrics), sRGB, width × height
    QImage flipMap;    // the FLIP map in magma, sRGB, width × height
    QImage reference;  // the exact tracer's image, sRGB, width × height
    QImage raster;     // the rasterizer's image that was measured, sRGB, width × height
    QStringList warnings;
    render::FrameInput input; // what was compared (for the parallax proxy the sweep derives)
};

// Renders the current view with the rasterizer (on the viewport's context, synchronously: a small frame
// takes milliseconds) and with the exact tracer on a worker thread, then measures the raster frame's error
// against the exact one with the bench's own functions (accuracy::measureFrames, traceReference,
// compareWithReference): sRGB RMSE and PSNR overall and on the pixels showing mirrors and the reflector,
// against the bench's scene reference (shadows traced with each light's PCF footprint, so that PCF does
// not count as error here).
//
// The exact image is refined progressively (ComparisonLevels): a quick probe first, which gives the time
// estimate, then levels of 4, 16, 64… paths per rough pixel, each measured and shown as it is done, with
// the noise it has left and the time left for the rest.
class ExactComparison : public QObject {
    Q_OBJECT

public:
    ExactComparison(scene::Scene& scene, Viewport& viewport, QObject* parent = nullptr);
    ~ExactComparison() override; // cancels and waits for a running trace

    // Starts a comparison of the current view at `quality.width` pixels wide (kComparisonAspect). Returns
    // false with the reason in failed() when it cannot start (no GL context yet, already running).
    bool start(const ComparisonQuality& quality, double time);
    void cancel();
    bool running() const { return m_thread.joinable(); }

signals:
    // Before the first level is traced: the levels planned and the time they should take in all.
    void estimated(double seconds, int paths);
    // While tracing: the fraction done (0..1, by estimated time), the level being traced and the seconds
    // left for it and the levels after it.
    void progress(double fraction, int paths, double secondsLeft);
    void refined(const speculum::ui::ComparisonResult& result); // a level done, more to come
    void finished(const speculum::ui::ComparisonResult& result);
    void failed(const QString& message, bool cancelled);

private:
    struct Job;
    // What the worker tells the GUI thread, in order (poll() hands it on as signals).
    struct Event {
        enum class Kind { Estimate, Progress, Level, Failed } kind = Kind::Progress;
        double seconds = 0.0;
        double fraction = 0.0;
        int paths = 0;
        std::unique_ptr<ComparisonResult> result; // Level
        QString error;                            // Failed
        bool cancelled = false;
    };
    void work(std::unique_ptr<Job> job);
    void post(Event event);
    void poll();
    void join();

    scene::Scene& m_scene;
    Viewport& m_viewport;
    std::thread m_thread;
    std::atomic<bool> m_cancel{false};
    std::atomic<bool> m_done{false};
    std::mutex m_mutex;
    std::deque<Event> m_events;                 // under m_mutex
    std::unique_ptr<ComparisonResult> m_latest; // GUI thread: the last level shown, kept for a cancel
};

// The linear error map of render::metrics as an 8-bit sRGB QImage.
QImage toQImage(const render::Image& linear);

} // namespace speculum::ui
