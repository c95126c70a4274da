// MainWindow: model import on a worker thread (progress and Cancel in the status bar); the document layer
// places the imported model (placeImportedModel) and adds it as one undo step (addNodeTree).
#include "base/FileKind.hpp"
#include "editor/document/EditOperations.hpp"
#include "editor/ui/Gizmo.hpp"
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/ModelImportJob.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"
#include "scene/import/ModelImport.hpp"
#include "scene/model/Scene.hpp"

#include <QAction>
#include <QEventLoop>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QToolButton>
#include <algorithm>

namespace speculum::ui {

namespace {

const QString kFitImportsKey = QStringLiteral("import/fitToUnitBox");

} // namespace

bool MainWindow::fitImportsToUnitBox() const {
    return QSettings().value(kFitImportsKey, false).toBool();
}

void MainWindow::setFitImportsToUnitBox(bool on) {
    QSettings().setValue(kFitImportsKey, on);
    if (m_fitImportsAction && m_fitImportsAction->isChecked() != on) {
        m_fitImportsAction->setChecked(on);
    }
}

bool MainWindow::isImporting() const {
    return m_importJob != nullptr || !m_importQueue.empty();
}

void MainWindow::createImportStatus() {
    m_importStatus = new QWidget(this);
    m_importStatus->setObjectName(QStringLiteral("importStatus"));
    auto* layout = new QHBoxLayout(m_importStatus);
    layout->setContentsMargins(0, 0, 0, 0);
    m_importLabel = new QLabel(m_importStatus);
    m_importProgress = new QProgressBar(m_importStatus);
    m_importProgress->setObjectName(QStringLiteral("importProgress"));
    m_importProgress->setRange(0, 1000);
    m_importProgress->setMaximumWidth(160);
    m_importProgress->setTextVisible(false);
    m_importCancel = new QToolButton(m_importStatus);
    m_importCancel->setObjectName(QStringLiteral("importCancel"));
    m_importCancel->setText(tr("Cancel"));
    m_importCancel->setToolTip(tr("Stop importing; the document stays as it is"));
    connect(m_importCancel, &QToolButton::clicked, this, &MainWindow::cancelImports);
    layout->addWidget(m_importLabel);
    layout->addWidget(m_importProgress);
    layout->addWidget(m_importCancel);
    statusBar()->addPermanentWidget(m_importStatus);
    m_importStatus->hide();
}

base::Status MainWindow::startModelImport(const QString& path, bool asReflector, bool interactive) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    // Only a stat here, on the GUI thread (it cannot block on a FIFO); the worker reads the file, and the
    // reader checks the opened descriptor again. The cause is named: a FIFO is not "no such file".
    if (auto regular = base::requireRegularFile(absolute.toStdString()); !regular) {
        return base::Error{shown(absolute, kShownPathChars).toStdString() + ": " + regular.error()};
    }
    m_importQueue.push_back(ImportRequest{absolute, asReflector, interactive, ++m_importSerial});
    if (!m_importJob) {
        startNextImport();
    }
    return base::Done{};
}

base::Status MainWindow::importModelFile(const QString& path, bool asReflector) {
    if (auto started = startModelImport(path, asReflector, false); !started) {
        logMessage(tr("Could not import: %1").arg(QString::fromStdString(started.error())));
        return started;
    }
    const int serial = m_importSerial;
    base::Status outcome = base::Error{"the import did not finish"};
    QEventLoop loop;
    const auto connection = connect(
        this, &MainWindow::importFinished, &loop, [&](const QString&, bool ok, const QString& message) {
            if (m_doneSerial == serial) {
                outcome = ok ? base::Status(base::Done{}) : base::Status(base::Error{message.toStdString()});
                loop.quit();
            }
        });
    if (m_doneSerial < serial) {
        loop.exec(); // the window keeps painting and taking input meanwhile
    }
    disconnect(connection);
    return outcome;
}

void MainWindow::cancelImports() {
    while (!m_importQueue.empty()) {
        const ImportRequest request = m_importQueue.front();
        m_importQueue.pop_front();
        m_doneSerial = request.serial;
        emit importFinished(request.path, false, tr("cancelled"));
    }
    if (m_importJob) {
        m_importJob->cancel(); // it ends at its next check and reports "cancelled" (onImportDone)
        m_importLabel->setText(tr("Cancelling %1…").arg(shown(QFileInfo(m_importing.path).fileName())));
    }
}

void MainWindow::startNextImport() {
    if (m_importJob || m_importQueue.empty()) {
        return;
    }
    m_importing = m_importQueue.front();
    m_importQueue.pop_front();
    m_importJob = new ModelImportJob(m_importing.path, this);
    if (m_importHook) {
        m_importJob->setWorkerHook(m_importHook);
    }
    connect(m_importJob, &ModelImportJob::progress, this, &MainWindow::showImportProgress);
    connect(m_importJob, &ModelImportJob::finished, this, &MainWindow::onImportDone);
    m_importLabel->setText(tr("Importing %1…").arg(shown(QFileInfo(m_importing.path).fileName())));
    m_importProgress->setValue(0);
    m_importStatus->show();
    logMessage(tr("Importing %1…").arg(shown(m_importing.path, kShownPathChars)));
    m_importJob->start();
}

void MainWindow::showImportProgress(double fraction, const QString& phase) {
    if (!m_importJob || m_importJob->isCancelled()) {
        return;
    }
    m_importProgress->setValue(int(std::clamp(fraction, 0.0, 1.0) * 1000.0));
    m_importLabel->setText(
        tr("Importing %1 (%2)…").arg(shown(QFileInfo(m_importing.path).fileName()), phase));
}

void MainWindow::onImportDone() {
    ModelImportJob* job = m_importJob;
    if (!job) {
        return;
    }
    m_importJob = nullptr;
    const ImportRequest request = m_importing;
    const bool cancelled = job->isCancelled();
    ModelImportJob::Output out = job->takeOutput();
    job->deleteLater();
    m_importStatus->hide();

    auto finish = [&](bool ok, const QString& message) {
        m_doneSerial = request.serial;
        emit importFinished(request.path, ok, message);
        startNextImport();
    };
    const QString fileName = shown(QFileInfo(request.path).fileName());
    if (cancelled) {
        logMessage(tr("Import of %1 cancelled").arg(request.path));
        statusBar()->showMessage(tr("Import of %1 cancelled; the document is unchanged.").arg(fileName),
                                 5000);
        finish(false, tr("cancelled"));
        return;
    }
    // Warnings like the viewport's: every one in the log, the first in the status bar.
    for (const auto& w : out.warnings) {
        logMessage(tr("Import: %1").arg(QString::fromStdString(w)));
    }
    if (!out.model) {
        const QString error = QString::fromStdString(out.model.error());
        logMessage(tr("Could not import %1: %2").arg(shown(request.path, kShownPathChars), error));
        statusBar()->showMessage(tr("Could not import %1: %2").arg(fileName, error), 8000);
        if (request.interactive) {
            QMessageBox::critical(this, tr("Import Model"),
                                  tr("Could not import %1:\n\n%2").arg(fileName, error));
        }
        finish(false, error);
        return;
    }
    scene::ImportedModel& model = out.model.value();

    document::ImportPlacement placement;
    placement.asReflector = request.asReflector;
    placement.fitToUnitBox = fitImportsToUnitBox();
    placement.focus = m_viewport->lookAtPoint();
    placement.timeSeconds = m_clock->time();
    document::PlacedModel placed = document::placeImportedModel(scene(), m_viewport->meshes(), model,
                                                                request.path.toStdString(), placement);
    if (!placement.fitToUnitBox && placed.timesTheScene >= document::kMuchLargerThanScene &&
        offerFitToScene(request, fileName, placed)) {
        placement.fitToSize = placed.sceneSize;
        placed = document::placeImportedModel(scene(), m_viewport->meshes(), model,
                                              request.path.toStdString(), placement);
    }
    for (const auto& w : placed.warnings) {
        logMessage(tr("Import: %1").arg(QString::fromStdString(w)));
    }
    out.warnings.insert(out.warnings.end(), placed.warnings.begin(), placed.warnings.end());

    std::size_t triangles = 0;
    for (const auto& part : model.parts) {
        triangles += part.mesh ? part.mesh->triangleCount() : 0;
    }
    const std::size_t parts = model.parts.size(), materials = model.materials.size();
    // The document's mesh library gets the model now (through the viewport, which tracks the reads of its
    // files), so the first frame does not read the file again (on the GUI thread).
    m_viewport->adoptModel(request.path.toStdString(),
                           std::make_shared<const scene::ImportedModel>(std::move(model)));

    if (auto added = addTree(std::move(placed.tree)); !added) {
        logMessage(tr("Could not import %1: %2").arg(request.path, QString::fromStdString(added.error())));
        if (request.interactive) {
            QMessageBox::critical(this, tr("Import Model"), QString::fromStdString(added.error()));
        }
        finish(false, QString::fromStdString(added.error()));
        return;
    }
    const glm::dvec3 size = placed.size;
    logMessage(tr("Imported %1: %2 part(s), %3 material(s), %4 triangles, %5 × %6 × %7 units%8")
                   .arg(shown(request.path, kShownPathChars))
                   .arg(parts)
                   .arg(materials)
                   .arg(triangles)
                   .arg(size.x, 0, 'g', 3)
                   .arg(size.y, 0, 'g', 3)
                   .arg(size.z, 0, 'g', 3)
                   .arg(placed.fit != 1.0 ? tr(" (fitted to a unit box)") : QString()));
    reportImported(fileName, placed, out.warnings);
    finish(true, QString());
}

// After an import: the view frames the model where it landed outside it, and the status bar says so, or
// names the first warning.
void MainWindow::reportImported(const QString& fileName, const document::PlacedModel& placed,
                                const std::vector<std::string>& warnings) {
    const bool framed = frameIfOutOfView(placed.box);
    if (framed) {
        logMessage(tr("%1 landed outside the view: the view now frames it (Shift+F goes back to the scene "
                      "camera).")
                       .arg(fileName));
    }
    if (warnings.empty()) {
        statusBar()->showMessage(framed ? tr("Imported %1; the view frames it").arg(fileName)
                                        : tr("Imported %1").arg(fileName),
                                 5000);
    } else {
        statusBar()->showMessage(tr("Imported %1 with %2 warning(s): %3")
                                     .arg(fileName)
                                     .arg(warnings.size())
                                     .arg(QString::fromStdString(warnings.front())),
                                 8000);
    }
}

// A model far larger than the scene (kMuchLargerThanScene): asked, when the import is the user's own,
// whether to scale it to the scene's size; a drop or a scripted import keeps its real size and says so.
bool MainWindow::offerFitToScene(const ImportRequest& request, const QString& fileName,
                                 const document::PlacedModel& placed) {
    const QString sizes = tr("%1 is %2 times as large as the scene (%3 units against %4).")
                              .arg(fileName)
                              .arg(placed.timesTheScene, 0, 'f', 0)
                              .arg(std::max({placed.size.x, placed.size.y, placed.size.z}), 0, 'g', 3)
                              .arg(placed.sceneSize, 0, 'g', 3);
    if (!request.interactive) {
        logMessage(sizes + QLatin1Char(' ') + tr("Imported at its real size."));
        return false;
    }
    QMessageBox question(QMessageBox::Question, tr("Import Model"),
                         sizes + QStringLiteral("\n\n") + tr("Scale it to the scene's size?"),
                         QMessageBox::NoButton, this);
    question.setObjectName(QStringLiteral("fitToSceneQuestion"));
    QPushButton* fit = question.addButton(tr("Fit to the Scene"), QMessageBox::AcceptRole);
    question.addButton(tr("Keep Real Size"), QMessageBox::RejectRole);
    question.setDefaultButton(fit);
    question.exec();
    const bool fitted = question.clickedButton() == fit;
    logMessage(sizes + QLatin1Char(' ') +
               (fitted ? tr("Scaled to the scene's size.") : tr("Kept at its real size.")));
    return fitted;
}

// Frames the newly imported model (selected) when any part of its box lies outside the view or behind
// the eye; true when it did.
bool MainWindow::frameIfOutOfView(const render::math::Box& box) {
    if (box.empty()) {
        return false;
    }
    const ScreenProjection screen(m_viewport->viewCamera(), QSizeF(m_viewport->size()));
    const QRectF view(QPointF(0.0, 0.0), QSizeF(m_viewport->size()));
    for (const glm::dvec3& corner : box.corners()) {
        const auto at = screen.project(corner);
        if (!at || !view.contains(*at)) {
            m_viewport->frameSelected();
            return true;
        }
    }
    return false;
}

} // namespace speculum::ui
