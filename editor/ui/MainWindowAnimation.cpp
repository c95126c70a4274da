// MainWindow: File ▸ Export Animation. The frames are drawn on a worker (AnimationExportJob); the GUI
// thread evaluates the document's scene for each of them and shows the progress. Nothing here edits the
// document: an export is no undo step and leaves the document as it was.
#include "editor/ui/AnimationExportJob.hpp"
#include "editor/ui/ExportAnimationDialog.hpp"
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/Viewport.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/model/Scene.hpp"
#include "scene/model/SceneAnimation.hpp"

#include <QDesktopServices>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>
#include <QStatusBar>
#include <QUrl>
#include <algorithm>
#include <cmath>

namespace speculum::ui {

namespace {

// "12 s", "3:05", "1:02:03": the time left, rounded up so that it never reads 0 while a frame draws.
QString durationText(double seconds) {
    const long total = std::lround(std::ceil(std::max(0.0, seconds)));
    if (total < 60) {
        return QObject::tr("%1 s").arg(total);
    }
    const QString minutesAndSeconds =
        QStringLiteral("%1:%2").arg((total / 60) % 60).arg(total % 60, 2, 10, QLatin1Char('0'));
    return total < 3600 ? minutesAndSeconds
                        : QStringLiteral("%1:%2")
                              .arg(total / 3600)
                              .arg(minutesAndSeconds.rightJustified(5, QLatin1Char('0')));
}

QString framesText(const std::vector<int>& frames) {
    if (frames.size() == 1) {
        return QObject::tr("frame %1").arg(frames.front());
    }
    return QObject::tr("frames %1..%2").arg(frames.front()).arg(frames.back());
}

} // namespace

base::Status MainWindow::startAnimationExport(const QString& path, const scene::AnimationSettings& settings) {
    auto output = scene::parseAnimationOutput(path.toStdString());
    if (!output) {
        return base::Error{output.error()};
    }
    if (base::Status valid = scene::validateAnimationExport(settings, *output); !valid) {
        return valid;
    }
    if (animationExportRunning()) {
        return base::Error{"an animation export is running already; cancel it or wait for it to end"};
    }
    // The scene's model files are read on workers: no frame may lack one that is still loading.
    m_viewport->waitForModels();
    if (!m_animationJob) {
        m_animationJob = new AnimationExportJob([this](double time) { return animationFrame(time); }, this);
        connect(m_animationJob, &AnimationExportJob::progress, this, &MainWindow::showAnimationProgress);
        connect(m_animationJob, &AnimationExportJob::finished, this, &MainWindow::animationExportEnded);
    }
    m_animationPath = path;
    m_animationSettings = settings;
    m_animationSceneWarnings.reset();
    m_animationProgress = animationProgressDialog(path);
    m_animationJob->start(scene().projectPath().toStdString(), settings, *output);
    logMessage(
        tr("Exporting %1 frames to %2…").arg(settings.frames.count()).arg(shown(path, kShownPathChars)));
    return base::Done{};
}

bool MainWindow::animationExportRunning() const {
    return m_animationJob && m_animationJob->running();
}

void MainWindow::cancelAnimationExport() {
    if (animationExportRunning()) {
        m_animationJob->cancel();
    }
}

render::FrameInput MainWindow::animationFrame(double time) {
    std::vector<scene::Warning> warnings;
    render::FrameInput input = scene::snapshot(scene(), time, m_viewport->meshes(), warnings);
    if (!m_animationSceneWarnings) { // every frame repeats them
        m_animationSceneWarnings = std::move(warnings);
    }
    return input;
}

// Shown at once and window-modal: the editor keeps drawing, playing and answering, but the document
// cannot change under the frames being drawn (each is evaluated when its turn comes).
QProgressDialog* MainWindow::animationProgressDialog(const QString& path) {
    if (!m_animationProgress) {
        m_animationProgress = new QProgressDialog(this);
        m_animationProgress->setObjectName(QStringLiteral("animationProgress"));
        m_animationProgress->setWindowTitle(tr("Export Animation"));
        m_animationProgress->setWindowModality(Qt::WindowModal);
        m_animationProgress->setRange(0, 1000);
        m_animationProgress->setMinimumDuration(0);
        m_animationProgress->setAutoClose(false);
        m_animationProgress->setAutoReset(false);
        m_animationProgress->setMinimumWidth(420);
        connect(m_animationProgress, &QProgressDialog::canceled, this, &MainWindow::cancelAnimationExport);
    }
    m_animationProgress->reset();
    m_animationProgress->setCancelButtonText(tr("Cancel"));
    m_animationProgress->setLabelText(
        tr("Starting the export to %1…").arg(shown(QFileInfo(path).fileName())));
    m_animationProgress->setValue(0);
    m_animationProgress->show();
    return m_animationProgress;
}

void MainWindow::showAnimationProgress(const scene::AnimationProgress& p) {
    if (!m_animationProgress || !animationExportRunning() || m_animationProgress->wasCanceled()) {
        return;
    }
    const QString left = p.remainingSeconds < 0.0
                             ? tr("Estimating the time left…")
                             : tr("About %1 left (%2 so far)")
                                   .arg(durationText(p.remainingSeconds), durationText(p.elapsedSeconds));
    m_animationProgress->setLabelText(tr("Frame %1 of %2 (number %3) → %4\n%5")
                                          .arg(std::min(p.done + 1, p.total))
                                          .arg(p.total)
                                          .arg(p.frame)
                                          .arg(shown(QFileInfo(m_animationPath).fileName()), left));
    m_animationProgress->setValue(int(std::lround(std::clamp(p.fraction, 0.0, 1.0) * 1000)));
}

void MainWindow::animationExportEnded(const scene::AnimationResult& result) {
    if (m_animationProgress) {
        m_animationProgress->hide();
    }
    m_lastAnimationExport = result;
    logAnimationExport(result);
    const bool sequence = !render::video::videoFormatOf(m_animationPath.toStdString());
    if (result.status) {
        const QString what =
            sequence ? tr("%1 frames to %2").arg(result.files.size()).arg(m_animationPath) : m_animationPath;
        statusBar()->showMessage(tr("Exported %1").arg(shown(what)), 10000);
        if (m_opensExports && !result.files.empty()) {
            // A clip opens in the desktop's player; a sequence's folder in its file manager.
            const QString target =
                sequence ? QFileInfo(QString::fromStdString(result.files.front())).absolutePath()
                         : QString::fromStdString(result.files.front());
            QDesktopServices::openUrl(QUrl::fromLocalFile(target));
        }
    } else if (result.cancelled) {
        statusBar()->showMessage(
            !sequence ? tr("Export cancelled; no clip was written.")
            : result.written.empty()
                ? tr("Export cancelled; no frame was written.")
                : tr("Export cancelled; %1 are kept in %2.")
                      .arg(framesText(result.written),
                           shown(QFileInfo(m_animationPath).absolutePath(), kShownPathChars)),
            10000);
    } else {
        QMessageBox::critical(this, tr("Export Animation"), QString::fromStdString(result.status.error()));
    }
    emit animationExportFinished();
}

void MainWindow::logAnimationExport(const scene::AnimationResult& result) {
    if (m_animationSceneWarnings) {
        for (const scene::Warning& w :
             m_viewport->correctModelWarnings(std::move(*m_animationSceneWarnings))) {
            logMessage(QString::fromStdString(w.message));
        }
        m_animationSceneWarnings.reset();
    }
    for (const std::string& w : result.warnings) {
        logMessage(QString::fromStdString(w));
    }
    if (!result.status) {
        logMessage(tr("Animation export failed: %1").arg(QString::fromStdString(result.status.error())));
        return;
    }
    const scene::StillExportSettings& still = m_animationSettings.still;
    // One arg() call with every value: a sequence's pattern holds a %, which a later arg() would fill.
    logMessage(tr("Exported %1 (%2 at %3 fps, %4×%5, %6; %7 s of drawing)")
                   .arg(shown(m_animationPath, kShownPathChars), framesText(result.written),
                        QString::number(m_animationSettings.fps), QString::number(still.width),
                        QString::number(still.height), QString::fromStdString(result.renderer),
                        QString::number(result.totalMs / 1000.0, 'f', 1)));
}

void MainWindow::onExportAnimation() {
    if (animationExportRunning()) {
        statusBar()->showMessage(tr("An animation export is still running."), 5000);
        return;
    }
    const QString project = scene().projectPath();
    const QString base = project.isEmpty()
                             ? dialogFolder() + QStringLiteral("/animation")
                             : QFileInfo(project).absolutePath() + QLatin1Char('/') +
                                   QFileInfo(project).fileName().section(QLatin1Char('.'), 0, 0);
    const QSize viewSize = m_viewport->size() * m_viewport->devicePixelRatio();
    ExportAnimationDialog dialog(base, scene::animationLoopSeconds(scene()), viewSize, this);
    if (dialog.exec() != QDialog::Accepted) {
        return;
    }
    scene::AnimationSettings settings = dialog.settings();
    if (dialog.useCurrentView()) {
        settings.still.camera = m_viewport->viewCamera();
    }
    if (base::Status started = startAnimationExport(dialog.outputPath(), settings); !started) {
        QMessageBox::critical(this, tr("Export Animation"), QString::fromStdString(started.error()));
    }
}

} // namespace speculum::ui
