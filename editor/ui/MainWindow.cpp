#include "editor/ui/MainWindow.hpp"

#include "editor/document/ProjectFile.hpp"
#include "editor/document/Scene.hpp"
#include "editor/ui/AnimationClock.hpp"
#include "editor/ui/Viewport.hpp"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QUndoStack>

namespace speculum::ui {

namespace {

const QString kProjectSuffix = QStringLiteral(".speculum.json");
const QString kProjectFilter = QObject::tr("speculum projects (*.speculum.json);;JSON files (*.json)");
const QString kLastFolderKey = QStringLiteral("files/lastFolder");

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , m_scene(new document::Scene(this))
    , m_undoStack(new QUndoStack(this))
    , m_clock(new AnimationClock(this)) {
    m_viewport = new Viewport(*m_scene, *m_clock, this);
    setCentralWidget(m_viewport);

    createActions();
    createStatusBar();
    createLogDock();

    connect(m_undoStack, &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(m_scene, &document::Scene::projectPathChanged, this, &MainWindow::updateTitle);
    connect(m_viewport, &Viewport::frameRendered, this, &MainWindow::onFrameRendered);
    connect(m_viewport, &Viewport::warningsChanged, this, &MainWindow::onWarningsChanged);
    connect(m_viewport, &Viewport::rendererFailed, this, &MainWindow::logMessage);

    newProject();
}

MainWindow::~MainWindow() = default;

// ---- document operations without dialogs ----

render::Status MainWindow::openProjectFile(const QString& path) {
    std::vector<std::string> warnings;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    render::Status status = document::openProject(*m_scene, absolute, warnings);
    if (!status) {
        logMessage(tr("Could not open %1: %2").arg(absolute, QString::fromStdString(status.error())));
        return status;
    }
    // The old document's commands refer to nodes that no longer exist.
    m_undoStack->clear();
    m_undoStack->setClean();
    for (const auto& w : warnings) {
        logMessage(QString::fromStdString(w));
    }
    QSettings().setValue(kLastFolderKey, QFileInfo(absolute).absolutePath());
    logMessage(tr("Opened %1").arg(absolute));
    statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(absolute).fileName()), 5000);
    updateTitle();
    return status;
}

render::Status MainWindow::saveProjectFile(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    render::Status status = document::saveProject(*m_scene, absolute);
    if (!status) {
        logMessage(tr("Could not save %1: %2").arg(absolute, QString::fromStdString(status.error())));
        return status;
    }
    m_scene->setProjectPath(absolute);
    m_undoStack->setClean();
    QSettings().setValue(kLastFolderKey, QFileInfo(absolute).absolutePath());
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(absolute).fileName()), 5000);
    updateTitle();
    return status;
}

void MainWindow::newProject() {
    m_scene->reset(document::SceneData{});
    m_scene->setProjectPath(QString());
    m_undoStack->clear();
    m_undoStack->setClean();
    m_clock->setTime(0.0);
    updateTitle();
}

void MainWindow::logMessage(const QString& message) {
    m_logLines << message;
    if (m_log) {
        m_log->appendPlainText(message);
    }
    qInfo("%s", qPrintable(message));
}

// ---- menu actions ----

void MainWindow::onNew() {
    if (maybeSave()) {
        newProject();
    }
}

void MainWindow::onOpen() {
    if (!maybeSave()) {
        return;
    }
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Project"), dialogFolder(), kProjectFilter);
    if (path.isEmpty()) {
        return;
    }
    render::Status status = openProjectFile(path);
    if (!status) {
        // The error names the JSON path of the problem; the current document is unchanged.
        QMessageBox::critical(this, tr("Open Project"),
                              tr("Could not open %1:\n\n%2")
                                  .arg(QFileInfo(path).fileName(), QString::fromStdString(status.error())));
    }
}

bool MainWindow::onSave() {
    if (m_scene->projectPath().isEmpty()) {
        return onSaveAs();
    }
    render::Status status = saveProjectFile(m_scene->projectPath());
    if (!status) {
        QMessageBox::critical(this, tr("Save Project"), QString::fromStdString(status.error()));
        return false;
    }
    return true;
}

bool MainWindow::onSaveAs() {
    QString suggestion = m_scene->projectPath();
    if (suggestion.isEmpty()) {
        suggestion = dialogFolder() + QStringLiteral("/untitled") + kProjectSuffix;
    }
    QString path = QFileDialog::getSaveFileName(this, tr("Save Project As"), suggestion, kProjectFilter);
    if (path.isEmpty()) {
        return false;
    }
    if (!path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) {
        path += kProjectSuffix;
    }
    render::Status status = saveProjectFile(path);
    if (!status) {
        QMessageBox::critical(this, tr("Save Project"), QString::fromStdString(status.error()));
        return false;
    }
    return true;
}

bool MainWindow::maybeSave() {
    if (m_undoStack->isClean()) {
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
        event->accept();
    } else {
        event->ignore();
    }
}

QString MainWindow::dialogFolder() const {
    if (!m_scene->projectPath().isEmpty()) {
        return QFileInfo(m_scene->projectPath()).absolutePath();
    }
    const QString last = QSettings().value(kLastFolderKey).toString();
    return last.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) : last;
}

void MainWindow::updateTitle() {
    const QString name =
        m_scene->projectPath().isEmpty() ? tr("Untitled") : QFileInfo(m_scene->projectPath()).fileName();
    // "[*]" is where Qt shows the modified marker.
    setWindowTitle(tr("%1[*] — speculum").arg(name));
    setWindowModified(!m_undoStack->isClean());
}

void MainWindow::showControls() {
    QMessageBox::information(this, tr("Viewport Controls"),
                             tr("<table>"
                                "<tr><td><b>Left drag</b></td><td>orbit around the camera target</td></tr>"
                                "<tr><td><b>Middle drag</b> or <b>Shift+left drag</b></td><td>pan</td></tr>"
                                "<tr><td><b>Mouse wheel</b></td><td>zoom</td></tr>"
                                "<tr><td><b>Double-click</b></td><td>back to the scene camera</td></tr>"
                                "<tr><td><b>Space</b></td><td>play / pause the animation</td></tr>"
                                "</table><p>Moving the view does not change the document.</p>"));
}

void MainWindow::showAbout() {
    QMessageBox::about(
        this, tr("About speculum"),
        tr("<h3>speculum %1</h3><p>A scene editor for reflections: planar mirrors and "
           "environment-mapped curved reflectors, measured against a ray-traced reference.</p>")
            .arg(QApplication::applicationVersion()));
}

// ---- status bar and log ----

void MainWindow::onFrameRendered(const render::FrameReport& report, double animationTime) {
    QString text = tr("CPU %1 ms").arg(report.cpuMs, 0, 'f', 2);
    if (report.gpuMs >= 0.0) {
        text += tr(" · GPU %1 ms").arg(report.gpuMs, 0, 'f', 2);
    }
    m_frameLabel->setText(text);
    m_timeLabel->setText(tr("t = %1 s").arg(animationTime, 0, 'f', 2));
}

void MainWindow::onWarningsChanged(const QStringList& warnings) {
    for (const QString& w : warnings) {
        logMessage(tr("Viewport: %1").arg(w));
    }
    if (!warnings.isEmpty()) {
        statusBar()->showMessage(warnings.front(), 8000);
    }
}

// ---- construction ----

void MainWindow::createActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* newAction = file->addAction(tr("&New"), this, &MainWindow::onNew);
    newAction->setShortcut(QKeySequence::New);
    QAction* openAction = file->addAction(tr("&Open…"), this, &MainWindow::onOpen);
    openAction->setShortcut(QKeySequence::Open);
    QAction* saveAction = file->addAction(tr("&Save"), this, &MainWindow::onSave);
    saveAction->setShortcut(QKeySequence::Save);
    QAction* saveAsAction = file->addAction(tr("Save &As…"), this, &MainWindow::onSaveAs);
    saveAsAction->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    QAction* quitAction = file->addAction(tr("&Quit"), this, &QWidget::close);
    quitAction->setShortcut(QKeySequence::Quit);
    quitAction->setMenuRole(QAction::QuitRole);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_undoStack->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = m_undoStack->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    m_playAction = view->addAction(tr("&Play Animation"));
    m_playAction->setCheckable(true);
    m_playAction->setShortcut(Qt::Key_Space);
    // The viewport has focus most of the time; the shortcut must work from anywhere in the window.
    m_playAction->setShortcutContext(Qt::WindowShortcut);
    connect(m_playAction, &QAction::toggled, m_clock, &AnimationClock::setPlaying);
    connect(m_clock, &AnimationClock::playingChanged, m_playAction, &QAction::setChecked);
    QAction* rewind = view->addAction(tr("&Rewind Animation"), m_clock, [this] { m_clock->setTime(0.0); });
    rewind->setShortcut(Qt::Key_Home);
    QAction* resetView = view->addAction(tr("Reset &View"), m_viewport, &Viewport::resetView);
    resetView->setShortcut(Qt::Key_F);
    view->addSeparator();
    m_viewMenu = view;

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("Viewport &Controls"), this, &MainWindow::showControls);
    QAction* about = help->addAction(tr("&About speculum"), this, &MainWindow::showAbout);
    about->setMenuRole(QAction::AboutRole);
}

void MainWindow::createStatusBar() {
    m_frameLabel = new QLabel(this);
    m_timeLabel = new QLabel(this);
    m_frameLabel->setMinimumWidth(200);
    m_timeLabel->setMinimumWidth(90);
    statusBar()->addPermanentWidget(m_frameLabel);
    statusBar()->addPermanentWidget(m_timeLabel);
}

void MainWindow::createLogDock() {
    auto* dock = new QDockWidget(tr("Log"), this);
    dock->setObjectName(QStringLiteral("logDock"));
    m_log = new QPlainTextEdit(dock);
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(2000);
    for (const QString& line : m_logLines) {
        m_log->appendPlainText(line);
    }
    dock->setWidget(m_log);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->hide();
    QAction* toggle = dock->toggleViewAction();
    toggle->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    m_viewMenu->addAction(toggle);
}

} // namespace speculum::ui
