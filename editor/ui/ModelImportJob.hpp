#pragma once

#include "base/Result.hpp"
#include "render/mesh/MeshData.hpp"
#include "scene/import/ModelImport.hpp"

#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

class QThread;

namespace speculum::ui {

// One model file read on a worker thread: scene::importModelFile with progress and cancel, then the
// pick hierarchies of its parts (so the first click on a big model does not build them on the GUI thread).
// The worker touches no document and no widget: it only fills the result, which the GUI thread takes after
// finished(). Progress reaches the GUI thread through queued signals. Destroying a running job cancels it and
// waits for the worker.
class ModelImportJob : public QObject {
    Q_OBJECT

public:
    struct Output {
        base::Result<scene::ImportedModel> model = base::Error{"not run"};
        std::vector<std::string> warnings;
    };

    explicit ModelImportJob(QString absolutePath, QObject* parent = nullptr);
    ~ModelImportJob() override;

    // Called on the worker thread at every progress report, before it is posted (tests use it to hold an
    // import in flight). Set before start().
    void setWorkerHook(std::function<void(double fraction)> hook) { m_hook = std::move(hook); }

    void start();
    // Asks the worker to stop at its next check; finished() still comes, with the error "cancelled".
    void cancel() { m_cancel = true; }
    bool isCancelled() const { return m_cancel; }
    bool isRunning() const;
    const QString& path() const { return m_path; }

    // After finished(): what the worker produced (moved out; call once).
    Output takeOutput() { return std::move(m_output); }

signals:
    void progress(double fraction, const QString& phase);
    void finished();

private:
    void run(); // on the worker

    QString m_path;
    std::atomic<bool> m_cancel{false};
    std::function<void(double)> m_hook;
    QThread* m_thread = nullptr;
    Output m_output;
    // Throttling of progress posts (worker side only).
    double m_lastPosted = -1.0;
    std::string m_lastPhase;
};

} // namespace speculum::ui
