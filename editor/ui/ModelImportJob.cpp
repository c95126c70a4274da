#include "editor/ui/ModelImportJob.hpp"

#include "scene/evaluate/Picking.hpp"

#include <QMetaObject>
#include <QThread>
#include <cmath>

namespace speculum::ui {

ModelImportJob::ModelImportJob(QString absolutePath, QObject* parent)
    : QObject(parent)
    , m_path(std::move(absolutePath)) {}

ModelImportJob::~ModelImportJob() {
    if (m_thread) {
        m_cancel = true;
        m_thread->wait();
        delete m_thread;
    }
}

bool ModelImportJob::isRunning() const {
    return m_thread && m_thread->isRunning();
}

void ModelImportJob::start() {
    if (m_thread) {
        return;
    }
    m_thread = QThread::create([this] { run(); });
    m_thread->setObjectName(QStringLiteral("model import"));
    // QThread::finished is emitted on the worker; the queued connection delivers it on this object's
    // (the GUI) thread, after run() has filled m_output.
    connect(m_thread, &QThread::finished, this, &ModelImportJob::finished, Qt::QueuedConnection);
    m_thread->start(QThread::LowPriority); // the GUI thread and the renderer come first
}

void ModelImportJob::run() {
    auto report = [this](double fraction, const char* phase) {
        if (m_hook) {
            m_hook(fraction);
        }
        // At most ~200 posts per import: a 4 M-triangle file reports far more often than a bar can show.
        const std::string name = phase ? phase : "";
        if (name == m_lastPhase && std::abs(fraction - m_lastPosted) < 0.005) {
            return;
        }
        m_lastPhase = name;
        m_lastPosted = fraction;
        const QString text = QString::fromStdString(name);
        QMetaObject::invokeMethod(
            this, [this, fraction, text] { emit progress(fraction, text); }, Qt::QueuedConnection);
    };
    scene::ImportControl control{report, &m_cancel};
    report(0.0, "reading");
    Output out;
    out.model = scene::importModelFile(m_path.toStdString(), out.warnings, control);
    if (out.model && !m_cancel) {
        // The pick hierarchies (cached per mesh) now, off the GUI thread.
        const auto& parts = out.model->parts;
        for (std::size_t i = 0; i < parts.size() && !m_cancel; ++i) {
            report(0.95 + 0.04 * double(i) / double(parts.size()), "pick structure");
            if (parts[i].mesh) {
                scene::meshPickAccel(parts[i].mesh);
            }
        }
    }
    if (m_cancel) {
        out.model = base::Error{"cancelled"};
    }
    report(1.0, "done");
    m_output = std::move(out);
}

} // namespace speculum::ui
