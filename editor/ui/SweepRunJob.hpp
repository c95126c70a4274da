#pragma once

#include "accuracy/run/SweepRun.hpp"
#include "scene/model/Warning.hpp"

#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <thread>
#include <vector>

namespace speculum::scene {
class MeshLibrary;
class Scene;
} // namespace speculum::scene

namespace speculum::ui {

// The bench's sweep (accuracy::runSweep) on a worker thread with a GL context of its own (EGL surfaceless,
// as `speculum bench` draws), so the editor stays responsive and its viewport keeps its context. The
// worker reads only its own copy of the scene's frame: nothing the document holds is touched while it
// runs. Results come back through queued signals, on the thread that owns this object.
class SweepRunJob : public QObject {
    Q_OBJECT

public:
    explicit SweepRunJob(QObject* parent = nullptr);
    ~SweepRunJob() override; // stops and waits for a running sweep

    // The frame `speculum bench` measures: the scene at t = 0 through its own camera. `meshes` is the
    // library the snapshot's meshes came from (its built-in teapots are swapped by identity).
    static accuracy::SweepInput inputFor(const scene::Scene& scene, scene::MeshLibrary& meshes,
                                         const QString& sceneName, bool quick,
                                         std::vector<scene::Warning>& warnings);

    // Starts the sweep; false (and failed()) when one is already running.
    bool start(accuracy::SweepInput input);
    // Asks the sweep to stop; it does within a frame, then failed(..., true) arrives.
    void cancel();
    bool running() const { return m_thread.joinable(); }

signals:
    // `done` of `total` steps (references, configurations, timing rounds); `line` says what runs now.
    void progress(int done, int total, const QString& line);
    // Every record measured so far (times provisional until the timing rounds are done).
    void recordsChanged(const std::vector<speculum::accuracy::Record>& records);
    void finished(const speculum::accuracy::ResultsFile& results);
    void failed(const QString& message, bool cancelled);

private:
    void post(std::function<void()> onGuiThread);
    void work(accuracy::SweepInput input);

    std::thread m_thread;
    std::atomic<bool> m_cancel{false};
};

} // namespace speculum::ui
