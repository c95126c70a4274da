#pragma once

#include "scene/export/AnimationExport.hpp"

#include <QObject>
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace speculum::ui {

// File ▸ Export Animation's frames (scene::exportAnimation) on a worker thread, so the editor keeps
// drawing, playing and answering while they are drawn. Raster frames are drawn on a GL context of the
// worker's own (EGL surfaceless, as `speculum render --frames` draws, and as SweepRunJob does), with a
// renderer of its own: the viewport keeps its context, and its drawing never moves the export's shadow and
// environment maps. Exact frames need no context.
//
// The scene is the document's, which only the GUI thread may read: for each frame the worker asks the GUI
// thread to evaluate it (`evaluate`, called there) and waits for the answer. Progress and the result come
// back through queued calls, on the thread that owns this object.
class AnimationExportJob : public QObject {
    Q_OBJECT

public:
    using Evaluate = std::function<render::FrameInput(double time)>; // called on the GUI thread

    explicit AnimationExportJob(Evaluate evaluate, QObject* parent = nullptr);
    ~AnimationExportJob() override; // cancels a running export and waits for it

    // Starts the export; false when one is running already. The settings are checked by the engine first
    // (a refusal arrives as finished() with the error).
    bool start(const std::string& projectPath, const scene::AnimationSettings& settings,
               const scene::AnimationOutput& output);
    // Asks the export to stop; it does within a frame's sample, then finished() arrives with `cancelled`.
    void cancel();
    bool running() const { return m_thread.joinable(); }

signals:
    void progress(const speculum::scene::AnimationProgress& p);
    void finished(const speculum::scene::AnimationResult& result);

private:
    void post(std::function<void()> onGuiThread);
    void work(std::string projectPath, scene::AnimationSettings settings, scene::AnimationOutput output);
    scene::AnimationResult draw(const std::string& projectPath, const scene::AnimationSettings& settings,
                                const scene::AnimationOutput& output);
    bool reportProgress(const scene::AnimationProgress& p);
    render::FrameInput frameFromGuiThread(double time); // worker side
    void evaluateRequestedFrame();                      // GUI side

    Evaluate m_evaluate;
    std::thread m_thread;
    std::atomic<bool> m_cancel{false};
    int m_lastReportedDone = -1;      // worker only: progress is posted when a frame ends,
    double m_lastReportedSeconds = 0; // or every kProgressInterval within one

    // The frame the worker waits for.
    std::mutex m_frameMutex;
    std::condition_variable m_frameReady;
    std::optional<double> m_requestedTime;
    std::optional<render::FrameInput> m_frame;
    bool m_abandoned = false; // this object is going: the worker gets no more frames
};

} // namespace speculum::ui
