#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/image/Image.hpp"

#include <QImage>
#include <QObject>
#include <QString>
#include <atomic>
#include <memory>
#include <optional>
#include <thread>

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
    double rasterCpuMs = 0.0;
    double rasterGpuMs = -1.0; // -1: no GPU timer on this context
    double traceMs = 0.0;
    QImage errorMap;  // the error ramp (render::metrics), sRGB, width × height
    QImage reference; // the exact tracer's image, sRGB, width × height
    QImage raster;    // the rasterizer's image that was measured, sRGB, width × height
    QStringList warnings;
    render::FrameInput input; // what was compared (for the parallax proxy the sweep derives)
};

// Renders the current view with the rasterizer (on the viewport's context, synchronously: a small frame
// takes milliseconds) and with the exact tracer on a worker thread (seconds on llvmpipe machines), then
// measures the raster frame's error against the exact one with the bench's own functions
// (accuracy::measureFrames, traceReference, compareWithReference): sRGB RMSE and PSNR overall and on the
// pixels showing mirrors and the reflector, against the bench's scene reference (shadows traced with each
// light's PCF footprint, so that PCF does not count as error here).
class ExactComparison : public QObject {
    Q_OBJECT

public:
    ExactComparison(scene::Scene& scene, Viewport& viewport, QObject* parent = nullptr);
    ~ExactComparison() override; // cancels and waits for a running trace

    // Starts a comparison of the current view at `width` pixels wide (the viewport's aspect). Returns false
    // with the reason in failed() when it cannot start (no GL context yet, already running).
    bool start(int width, double time);
    void cancel();
    bool running() const { return m_thread.joinable(); }

signals:
    void progress(double fraction); // 0..1 of the trace
    void finished(const speculum::ui::ComparisonResult& result);
    void failed(const QString& message, bool cancelled);

private:
    void poll();
    void join();

    scene::Scene& m_scene;
    Viewport& m_viewport;
    std::thread m_thread;
    std::atomic<double> m_fraction{0.0};
    std::atomic<bool> m_cancel{false};
    std::atomic<bool> m_done{false};
    // Written by the worker before m_done; read on the GUI thread after it.
    std::unique_ptr<ComparisonResult> m_result;
    QString m_error;
    bool m_cancelled = false; // the worker stopped because cancel() asked it to
};

// The linear error map of render::metrics as an 8-bit sRGB QImage.
QImage toQImage(const render::Image& linear);

} // namespace speculum::ui
