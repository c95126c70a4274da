#include "editor/ui/AnimationExportJob.hpp"

#include "render/gl/HeadlessContext.hpp"

#include <QMetaObject>

namespace speculum::ui {

namespace {

// A frame's samples can come thousands of times a second (small frames): the progress dialog needs a few.
constexpr double kProgressInterval = 0.1;

} // namespace

AnimationExportJob::AnimationExportJob(Evaluate evaluate, QObject* parent)
    : QObject(parent)
    , m_evaluate(std::move(evaluate)) {}

AnimationExportJob::~AnimationExportJob() {
    m_cancel = true;
    {
        // The GUI thread no longer answers (it is here, waiting): the worker stops waiting for its frame.
        std::lock_guard lock(m_frameMutex);
        m_abandoned = true;
    }
    m_frameReady.notify_all();
    if (m_thread.joinable()) {
        m_thread.join();
    }
}

bool AnimationExportJob::start(const std::string& projectPath, const scene::AnimationSettings& settings,
                               const scene::AnimationOutput& output) {
    if (running()) {
        return false;
    }
    m_cancel = false;
    m_lastReportedDone = -1;
    m_lastReportedSeconds = 0.0;
    m_thread = std::thread([this, projectPath, settings, output] { work(projectPath, settings, output); });
    return true;
}

void AnimationExportJob::cancel() {
    m_cancel = true;
}

void AnimationExportJob::post(std::function<void()> onGuiThread) {
    QMetaObject::invokeMethod(this, std::move(onGuiThread), Qt::QueuedConnection);
}

void AnimationExportJob::work(std::string projectPath, scene::AnimationSettings settings,
                              scene::AnimationOutput output) {
    scene::AnimationResult result = draw(projectPath, settings, output);
    // Ends the job on the GUI thread: the worker is about to return, so join it first.
    post([this, result = std::move(result)] {
        if (m_thread.joinable()) {
            m_thread.join();
        }
        emit finished(result);
    });
}

scene::AnimationResult AnimationExportJob::draw(const std::string& projectPath,
                                                const scene::AnimationSettings& settings,
                                                const scene::AnimationOutput& output) {
    const scene::FrameSource source = [this](double time) { return frameFromGuiThread(time); };
    const scene::AnimationProgressCallback report = [this](const scene::AnimationProgress& p) {
        return reportProgress(p);
    };
    if (settings.still.reference) {
        return scene::exportAnimation(nullptr, source, projectPath, settings, output, report);
    }
    scene::AnimationResult failed;
    auto context = render::gl::HeadlessContext::create();
    if (!context) {
        failed.status = base::Error{"no OpenGL context for the export: " + context.error()};
        return failed;
    }
    auto renderer = render::Renderer::create();
    if (!renderer) {
        failed.status = base::Error{renderer.error()};
        return failed;
    }
    scene::AnimationResult result = scene::exportAnimation(renderer->get(), source, projectPath, settings,
                                                           output, report, (*context)->description());
    renderer->reset(); // GL objects go before their context
    context->reset();
    return result;
}

bool AnimationExportJob::reportProgress(const scene::AnimationProgress& p) {
    const bool frameEnded = p.done != m_lastReportedDone;
    if (frameEnded || p.elapsedSeconds - m_lastReportedSeconds >= kProgressInterval || p.fraction >= 1.0) {
        m_lastReportedDone = p.done;
        m_lastReportedSeconds = p.elapsedSeconds;
        post([this, p] { emit progress(p); });
    }
    return !m_cancel.load();
}

// Asks the GUI thread for the scene at `time` and waits. When this object is being destroyed the answer
// never comes: the cancel flag is set by then, so the engine stops at its next progress report, before
// the empty frame returned here is drawn.
render::FrameInput AnimationExportJob::frameFromGuiThread(double time) {
    {
        std::lock_guard lock(m_frameMutex);
        m_frame.reset();
        m_requestedTime = time;
    }
    post([this] { evaluateRequestedFrame(); });
    std::unique_lock lock(m_frameMutex);
    m_frameReady.wait(lock, [this] { return m_frame.has_value() || m_abandoned; });
    if (!m_frame) {
        return {};
    }
    render::FrameInput frame = std::move(*m_frame);
    m_frame.reset();
    return frame;
}

void AnimationExportJob::evaluateRequestedFrame() {
    double time = 0.0;
    {
        std::lock_guard lock(m_frameMutex);
        if (!m_requestedTime) {
            return;
        }
        time = *m_requestedTime;
        m_requestedTime.reset();
    }
    render::FrameInput frame = m_evaluate(time);
    {
        std::lock_guard lock(m_frameMutex);
        m_frame = std::move(frame);
    }
    m_frameReady.notify_all();
}

} // namespace speculum::ui
