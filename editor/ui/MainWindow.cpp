#include "editor/ui/MainWindow.hpp"

#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "editor/document/NewScene.hpp"
#include "editor/ui/AccuracyPanel.hpp"
#include "editor/ui/AnimationExportJob.hpp"
#include "editor/ui/InspectPanel.hpp"
#include "editor/ui/Inspector.hpp"
#include "editor/ui/RenderPassesPanel.hpp"
#include "editor/ui/SceneTreeModel.hpp"
#include "editor/ui/SceneTreePanel.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/import/ModelFormats.hpp"
#include "scene/model/Scene.hpp"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QUndoView>
#include <algorithm>

namespace speculum::ui {

namespace {

const QString kLastFolderKey = QStringLiteral("files/lastFolder");
const QString kRecentKey = QStringLiteral("files/recent");
const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");
constexpr int kMaxRecent = 8;
constexpr int kAutosaveSeconds = 30;

// Every 30 s, or every SPECULUM_AUTOSAVE_SECONDS (1..3600) when that is set: more often for a user who
// wants less to lose, and the only way a test can see an autosave without waiting half a minute.
int autosaveSeconds(QString& problem) {
    const QByteArray text = qgetenv("SPECULUM_AUTOSAVE_SECONDS");
    if (text.isEmpty()) {
        return kAutosaveSeconds;
    }
    bool ok = false;
    const int seconds = text.toInt(&ok);
    if (!ok || seconds < 1 || seconds > 3600) {
        problem =
            QStringLiteral("SPECULUM_AUTOSAVE_SECONDS=%1 is not a number of seconds in 1..3600; autosaving "
                           "every %2 s")
                .arg(QString::fromLocal8Bit(text))
                .arg(kAutosaveSeconds);
        return kAutosaveSeconds;
    }
    return seconds;
}

} // namespace

QString shown(const QString& text, std::size_t maxChars) {
    return QString::fromStdString(base::printable(text.toStdString(), maxChars));
}

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , m_session(new document::DocumentSession(this))
    , m_clock(new view::AnimationClock(this))
    , m_recovery(std::make_unique<scene::RecoveryStore>(scene::RecoveryStore::forThisProcess())) {
    m_selection = new view::Selection(scene(), this);
    m_viewport = new Viewport(scene(), m_session->meshes(), *m_clock, this);
    m_viewport->setEditing(m_selection, &undoStack());
    setCentralWidget(m_viewport);
    setAcceptDrops(true);
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks |
                   QMainWindow::AllowNestedDocks);

    createActions();
    createDocks();
    createViewportMenu();
    createStatusBar();
    createTimeline();
    createViewPlacement();

    connect(&undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(&scene(), &scene::Scene::projectPathChanged, this, &MainWindow::updateTitle);
    connect(m_selection, &view::Selection::changed, this, &MainWindow::updateEditActions);
    connect(m_viewport, &Viewport::frameRendered, this, &MainWindow::onFrameRendered);
    connect(m_viewport, &Viewport::warningsChanged, this, &MainWindow::onWarningsChanged);
    connect(m_viewport, &Viewport::rendererFailed, this, &MainWindow::logMessage);
    connect(&m_session->fileWatch(), &document::ProjectFileWatch::changedOnDisk, this,
            &MainWindow::onProjectChangedOnDisk);
    connect(m_inspector, &Inspector::message, this,
            [this](const QString& text) { statusBar()->showMessage(text, 8000); });

    QString autosaveProblem;
    m_autosave.setInterval(autosaveSeconds(autosaveProblem) * 1000);
    if (!autosaveProblem.isEmpty()) {
        logMessage(autosaveProblem);
    }
    connect(&m_autosave, &QTimer::timeout, this, [this] { autosaveNow(); });
    m_autosave.start();

    newProject();
}

MainWindow::~MainWindow() {
    // Before the document goes with the other children: a running export stops and waits for its worker,
    // which asks the GUI thread for the document's frames.
    delete m_animationJob;
}

QAction* MainWindow::action(const QString& objectName) const {
    return findChild<QAction*>(objectName);
}

bool MainWindow::isModified() const {
    return m_session->isModified();
}

// ---- document operations without dialogs ----

base::Status MainWindow::openProjectFile(const QString& path) {
    std::vector<std::string> warnings;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    // The project is read here, on the GUI thread: a FIFO, a device or /dev/stdin would block it (and the
    // autosave with it) for good, so anything but a regular file is refused before it is opened. The
    // reader checks the opened descriptor again.
    base::Status status = base::requireRegularFile(absolute.toStdString());
    if (status) {
        status = m_session->open(absolute, warnings);
    }
    if (!status) {
        logMessage(tr("Could not open %1: %2")
                       .arg(shown(absolute, kShownPathChars), QString::fromStdString(status.error())));
        return status;
    }
    // A running import's result was meant for the old document.
    cancelImports();
    m_recovery->discard();
    m_restoredEdits.clear();
    for (const auto& w : warnings) {
        logMessage(QString::fromStdString(w));
    }
    QSettings().setValue(kLastFolderKey, QFileInfo(absolute).absolutePath());
    addRecentFile(absolute);
    logMessage(tr("Opened %1").arg(absolute));
    statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(absolute).fileName()), 5000);
    updateTitle();
    return status;
}

base::Status MainWindow::saveProjectFile(const QString& path, bool overwriteDiskChanges) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    rememberEditorView(); // the file reopens where the editor looks now
    using DiskChanges = document::DocumentSession::DiskChanges;
    base::Status status =
        m_session->save(absolute, overwriteDiskChanges ? DiskChanges::Overwrite : DiskChanges::Refuse);
    if (!status) {
        logMessage(tr("Could not save %1: %2").arg(absolute, QString::fromStdString(status.error())));
        return status;
    }
    m_recovery->discard(); // saved: nothing left to recover
    m_restoredEdits.clear();
    QSettings().setValue(kLastFolderKey, QFileInfo(absolute).absolutePath());
    addRecentFile(absolute);
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(absolute).fileName()), 5000);
    updateTitle();
    return status;
}

void MainWindow::newProject() {
    cancelImports();                                         // what they bring was meant for the old document
    m_session->replace(document::newSceneData(), QString()); // a floor, a sun, a raised camera
    m_recovery->discard();
    m_restoredEdits.clear();
    updateTitle(); // the clock starts over on the scene's reset (createTimeline)
}

void MainWindow::logMessage(const QString& message) {
    m_logLines << message;
    if (m_log) {
        m_log->appendPlainText(message);
    }
    qInfo("%s", qPrintable(message));
}

// ---- layout and recent files ----

void MainWindow::restoreLayout() {
    QSettings settings;
    restoreGeometry(settings.value(kGeometryKey).toByteArray());
    restoreState(settings.value(kStateKey).toByteArray());
}

QStringList MainWindow::recentFiles() const {
    return QSettings().value(kRecentKey).toStringList();
}

void MainWindow::addRecentFile(const QString& path) {
    QStringList files = recentFiles();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecent) {
        files.removeLast();
    }
    QSettings().setValue(kRecentKey, files);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    if (!m_recentMenu) {
        return;
    }
    m_recentMenu->clear();
    const QStringList files = recentFiles();
    int n = 0;
    for (const QString& file : files) {
        QAction* a =
            m_recentMenu->addAction(QStringLiteral("&%1 %2").arg(++n).arg(QFileInfo(file).fileName()));
        a->setToolTip(file);
        a->setStatusTip(file);
        connect(a, &QAction::triggered, this, [this, file] {
            if (!maybeSave()) {
                return;
            }
            if (auto status = openProjectFile(file); !status) {
                QMessageBox::critical(
                    this, tr("Open Project"),
                    tr("Could not open %1:\n\n%2").arg(shown(file), QString::fromStdString(status.error())));
            }
        });
    }
    if (!files.isEmpty()) {
        m_recentMenu->addSeparator();
        m_recentMenu->addAction(tr("Clear Recent Files"), this, [this] {
            QSettings().remove(kRecentKey);
            rebuildRecentMenu();
        });
    }
    m_recentMenu->setEnabled(!files.isEmpty());
}

// ---- closing, drag and drop ----

bool MainWindow::maybeSave() {
    if (!isModified()) {
        return true;
    }
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved Changes"), tr("The document has been modified.\nDo you want to save your changes?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    switch (answer) {
    case QMessageBox::Save:
        return onSave();
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (maybeSave()) {
        QSettings settings;
        settings.setValue(kGeometryKey, saveGeometry());
        settings.setValue(kStateKey, saveState());
        m_recovery->discard(); // a clean exit: nothing to recover next time
        event->accept();
    } else {
        event->ignore();
    }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const QMimeData* mime = event->mimeData();
    if (!mime->hasUrls()) {
        return;
    }
    for (const QUrl& url : mime->urls()) {
        const QString path = url.toLocalFile();
        if (path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive) || scene::isImportableModel(path)) {
            event->acceptProposedAction();
            return;
        }
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
    QStringList failures;
    for (const QUrl& url : event->mimeData()->urls()) {
        const QString path = url.toLocalFile();
        if (path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) {
            if (maybeSave()) {
                if (auto status = openProjectFile(path); !status) {
                    failures << tr("Could not open %1: %2")
                                    .arg(shown(QFileInfo(path).fileName()),
                                         QString::fromStdString(status.error()));
                }
            }
        } else if (scene::isImportableModel(path)) {
            // On the worker, one file after the other; a file that fails there shows its own box.
            if (auto status = startModelImport(path, false, true); !status) {
                failures << QString::fromStdString(status.error());
            }
        }
    }
    event->acceptProposedAction();
    if (!failures.isEmpty()) {
        QMessageBox::critical(this, tr("Open or Import"), failures.join(QLatin1Char('\n')));
    }
}

QString MainWindow::dialogFolder() const {
    if (!scene().projectPath().isEmpty()) {
        return QFileInfo(scene().projectPath()).absolutePath();
    }
    const QString last = QSettings().value(kLastFolderKey).toString();
    return last.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) : last;
}

void MainWindow::updateTitle() {
    const QString name =
        scene().projectPath().isEmpty() ? tr("Untitled") : QFileInfo(scene().projectPath()).fileName();
    // "[*]" is where Qt shows the modified marker.
    setWindowTitle(tr("%1[*] — speculum").arg(name));
    setWindowModified(isModified());
}

// ---- status bar and log ----

void MainWindow::onFrameRendered(const render::FrameReport& report, double animationTime) {
    QString text = tr("CPU %1 ms").arg(report.cpuMs, 0, 'f', 2);
    if (report.gpuMs >= 0.0) {
        text += tr(" · GPU %1 ms").arg(report.gpuMs, 0, 'f', 2);
    }
    if (m_viewport->framesPerSecond() > 0.0) {
        text += tr(" · %1 fps").arg(m_viewport->framesPerSecond(), 0, 'f', 1);
    }
    m_frameLabel->setText(text);
    Q_UNUSED(animationTime); // the timeline's readout shows the clock (MainWindowTime.cpp)
    m_passesPanel->showReport(report);
}

void MainWindow::onWarningsChanged(const QStringList& warnings) {
    for (const QString& w : warnings) {
        logMessage(tr("Viewport: %1").arg(w));
    }
    if (!warnings.isEmpty()) {
        statusBar()->showMessage(warnings.front(), 8000);
        m_shownViewportWarning = warnings.front();
    } else if (!m_shownViewportWarning.isEmpty() && statusBar()->currentMessage() == m_shownViewportWarning) {
        statusBar()->clearMessage(); // no longer true ("mesh loading" once the model is in)
    }
}

void MainWindow::createStatusBar() {
    m_frameLabel = new QLabel(this);
    m_frameLabel->setObjectName(QStringLiteral("frameLabel"));
    m_frameLabel->setMinimumWidth(260);
    statusBar()->addPermanentWidget(m_frameLabel);
    createImportStatus();
}

// The docks around the viewport: Scene and Render Passes on the left, Properties and Accuracy on the right,
// the Log below; each can be shown from the View menu.
void MainWindow::createDocks() {
    QDockWidget* treeDock = createSceneDock();
    QDockWidget* inspectorDock = createInspectorDock();
    QDockWidget* passesDock = createPassesDock(treeDock);
    QDockWidget* accuracyDock = createAccuracyDock(inspectorDock);
    QDockWidget* logDock = createLogDock();
    QDockWidget* historyDock = createHistoryDock(treeDock);
    QDockWidget* inspectDock = createInspectDock(inspectorDock);

    resizeDocks({treeDock, inspectorDock}, {240, 320}, Qt::Horizontal);
    resizeDocks({treeDock, passesDock}, {300, 200}, Qt::Vertical);

    m_viewMenu->addSeparator();
    for (QDockWidget* dock :
         {treeDock, inspectorDock, passesDock, accuracyDock, inspectDock, historyDock, logDock}) {
        m_viewMenu->addAction(dock->toggleViewAction());
    }
    logDock->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
}

// Hidden at first, tabbed with the Properties: View ▸ Inspect Pixel turns the viewport's inspect tool on
// and brings it up; a step that touched a node selects that node.
QDockWidget* MainWindow::createInspectDock(QDockWidget* inspectorDock) {
    auto* panel = new InspectPanel(this);
    auto* dock = new QDockWidget(tr("Pixel Inspector"), this);
    dock->setObjectName(QStringLiteral("inspectDock"));
    dock->setWidget(panel);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    dock->hide();
    auto* tool = new QAction(tr("Inspect &Pixel"), this);
    tool->setObjectName(QStringLiteral("inspectPixelAction"));
    tool->setCheckable(true);
    tool->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_I));
    tool->setStatusTip(tr("Click a pixel of the view: its exact path beside the raster's recipe"));
    m_viewMenu->addAction(tool);
    connect(tool, &QAction::toggled, this, [this, dock, inspectorDock](bool on) {
        m_viewport->setInspecting(on);
        if (!on)
            return;
        // Tabbed with the Properties the first time it shows (hidden, it is tabbed with nothing, so that
        // the Accuracy panel's placement beside the Properties is unchanged).
        if (!dock->isVisible() && !dock->isFloating() && !tabifiedDockWidgets(inspectorDock).contains(dock))
            tabifyDockWidget(inspectorDock, dock);
        dock->show();
        dock->raise();
    });
    connect(m_viewport, &Viewport::pixelInspected, panel, &InspectPanel::show);
    connect(panel, &InspectPanel::pathStepChosen, m_viewport, &Viewport::highlightInspectedStep);
    connect(m_viewport, &Viewport::inspectionFailed, panel, [panel](const QString& message) {
        panel->showMessage(tr("The pixel could not be explained: %1").arg(message));
    });
    connect(panel, &InspectPanel::nodeChosen, this, [this](const QString& name) {
        const std::string wanted = name.toStdString();
        scene::NodeId found = scene::kNoNode;
        scene().forEachNode([&](const scene::Node& node) {
            if (found == scene::kNoNode && node.data().name == wanted)
                found = node.id();
        });
        if (found != scene::kNoNode)
            m_selection->selectNode(found);
    });
    return dock;
}

QDockWidget* MainWindow::createSceneDock() {
    m_treeModel = new SceneTreeModel(scene(), undoStack(), this);
    m_treePanel = new SceneTreePanel(*m_treeModel, *m_selection, this);
    auto* treeDock = new QDockWidget(tr("Scene"), this);
    treeDock->setObjectName(QStringLiteral("sceneDock"));
    treeDock->setWidget(m_treePanel);
    addDockWidget(Qt::LeftDockWidgetArea, treeDock);
    m_treePanel->setContextActions({m_renameAction, m_duplicateAction, m_cutAction, m_copyAction,
                                    action(QStringLiteral("actionPaste")), m_deleteAction, nullptr,
                                    action(QStringLiteral("actionFrameSelected"))},
                                   m_addMenu);
    // Ctrl+A in the tree selects the nodes (the view on its own would select the camera row too).
    m_treePanel->addAction(action(QStringLiteral("actionSelectAll")));
    return treeDock;
}

QDockWidget* MainWindow::createInspectorDock() {
    m_inspector = new Inspector(scene(), undoStack(), *m_selection, this);
    auto* inspectorDock = new QDockWidget(tr("Properties"), this);
    inspectorDock->setObjectName(QStringLiteral("inspectorDock"));
    inspectorDock->setWidget(m_inspector);
    addDockWidget(Qt::RightDockWidgetArea, inspectorDock);
    return inspectorDock;
}

// Under the Scene dock.
QDockWidget* MainWindow::createPassesDock(QDockWidget* treeDock) {
    m_passesPanel = new RenderPassesPanel(this);
    auto* passesDock = new QDockWidget(tr("Render Passes"), this);
    passesDock->setObjectName(QStringLiteral("passesDock"));
    passesDock->setWidget(m_passesPanel);
    addDockWidget(Qt::LeftDockWidgetArea, passesDock);
    splitDockWidget(treeDock, passesDock, Qt::Vertical);
    return passesDock;
}

// Hidden at first: it is for the moments a user asks what an approximation costs, not for editing.
QDockWidget* MainWindow::createAccuracyDock(QDockWidget* inspectorDock) {
    m_accuracyPanel = new AccuracyPanel(scene(), undoStack(), *m_viewport, *m_clock, this);
    auto* accuracyDock = new QDockWidget(tr("Accuracy"), this);
    accuracyDock->setObjectName(QStringLiteral("accuracyDock"));
    accuracyDock->setWidget(m_accuracyPanel);
    // Beside the Properties where there is room (placeAccuracyDock): comparing and then editing a setting
    // wants both in sight. View ▸ Accuracy brings it to the front even where it is tabbed.
    addDockWidget(Qt::RightDockWidgetArea, accuracyDock);
    splitDockWidget(inspectorDock, accuracyDock, Qt::Horizontal);
    accuracyDock->hide();
    connect(accuracyDock->toggleViewAction(), &QAction::toggled, accuracyDock,
            [this, accuracyDock, inspectorDock](bool shown) {
                if (shown) {
                    placeAccuracyDock(accuracyDock, inspectorDock);
                } else if (m_propertiesWidth > 0 && inspectorDock->isVisible()) {
                    // Its room goes back to the viewport: the Properties return to the width they had
                    // before it opened (after the layout has taken the dock out).
                    QTimer::singleShot(0, this, [this, inspectorDock] {
                        resizeDocks({inspectorDock}, {m_propertiesWidth}, Qt::Horizontal);
                    });
                }
            });
    connect(m_accuracyPanel, &AccuracyPanel::message, this, [this](const QString& text) {
        logMessage(text);
        statusBar()->showMessage(text, 8000);
    });
    return accuracyDock;
}

namespace {
constexpr int kMinViewportWidth = 480; // the least the viewport keeps for the Accuracy panel beside it
constexpr int kAccuracyWidth = 400;    // the Accuracy panel's width beside the Properties, at least
} // namespace

// Beside the Properties where the window has room for both and a viewport of kMinViewportWidth, else
// tabbed with them (a window as wide as a laptop's screen would otherwise grow past it, or squeeze the
// Properties' fields). Only while the two share a dock area: a layout the user made stays theirs.
void MainWindow::placeAccuracyDock(QDockWidget* accuracyDock, QDockWidget* inspectorDock) {
    m_propertiesWidth = inspectorDock->width();
    const bool together = !accuracyDock->isFloating() && !inspectorDock->isFloating() &&
                          dockWidgetArea(accuracyDock) == dockWidgetArea(inspectorDock);
    if (together) {
        const int room = inspectorDock->width() + m_viewport->width();
        const int besideNeeds = m_propertiesWidth +
                                std::max(kAccuracyWidth, accuracyDock->minimumSizeHint().width()) +
                                kMinViewportWidth;
        if (besideNeeds > room) {
            tabifyDockWidget(inspectorDock, accuracyDock);
        } else if (tabifiedDockWidgets(inspectorDock).contains(accuracyDock)) {
            splitDockWidget(inspectorDock, accuracyDock, Qt::Horizontal);
        }
    }
    accuracyDock->raise();
    if (!together || tabifiedDockWidgets(inspectorDock).contains(accuracyDock))
        return;
    // Room for both: the Properties keep their width, the images get theirs, taken from the viewport.
    // After the dock is laid out (a resize before that is undone by its first layout).
    QTimer::singleShot(0, this, [this, accuracyDock, inspectorDock] {
        const int spare = std::max(m_viewport->width() - kMinViewportWidth, 0);
        const int accuracy = std::clamp(accuracyDock->width() + spare, kAccuracyWidth, 480);
        resizeDocks({inspectorDock, accuracyDock}, {m_propertiesWidth, accuracy}, Qt::Horizontal);
    });
}

// Every step of the undo stack by name, the current one marked; clicking a step goes back (or forward) to
// it, as Blender's Undo History does. Hidden at first.
QDockWidget* MainWindow::createHistoryDock(QDockWidget* treeDock) {
    auto* historyDock = new QDockWidget(tr("Undo History"), this);
    historyDock->setObjectName(QStringLiteral("historyDock"));
    auto* history = new QUndoView(&undoStack(), historyDock);
    history->setObjectName(QStringLiteral("undoHistory"));
    history->setEmptyLabel(tr("Opened"));
    historyDock->setWidget(history);
    addDockWidget(Qt::LeftDockWidgetArea, historyDock);
    historyDock->hide();
    // Tabbed with the Scene tree once shown (a hidden dock in the tree's tab group would still widen it).
    connect(historyDock->toggleViewAction(), &QAction::toggled, historyDock,
            [this, treeDock, historyDock](bool shown) {
                if (shown && !historyDock->isFloating() &&
                    dockWidgetArea(historyDock) == dockWidgetArea(treeDock) &&
                    !tabifiedDockWidgets(treeDock).contains(historyDock)) {
                    tabifyDockWidget(treeDock, historyDock);
                    historyDock->raise();
                }
            });
    historyDock->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_Z));
    return historyDock;
}

QDockWidget* MainWindow::createLogDock() {
    auto* logDock = new QDockWidget(tr("Log"), this);
    logDock->setObjectName(QStringLiteral("logDock"));
    m_log = new QPlainTextEdit(logDock);
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(2000);
    for (const QString& line : m_logLines) {
        m_log->appendPlainText(line);
    }
    logDock->setWidget(m_log);
    addDockWidget(Qt::BottomDockWidgetArea, logDock);
    logDock->hide();
    return logDock;
}

} // namespace speculum::ui
