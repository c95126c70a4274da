// MainWindow: menus and what runs behind them (the edit operations of the document layer, export).
#include "editor/document/EditOperations.hpp"
#include "editor/document/NodeClipboard.hpp"
#include "editor/document/NodeFactory.hpp"
#include "editor/ui/AppIdentity.hpp"
#include "editor/ui/ExportStillDialog.hpp"
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/SceneTreePanel.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "scene/export/GltfExport.hpp"
#include "scene/import/ModelFormats.hpp"
#include "scene/model/Scene.hpp"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QClipboard>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>
#include <algorithm>
#include <vector>

namespace speculum::ui {

namespace {

const QString kProjectSuffix = QStringLiteral(".speculum.json");
const QString kProjectFilter = QObject::tr("speculum projects (*.speculum.json);;JSON files (*.json)");

} // namespace

QAction* MainWindow::makeAction(QMenu* menu, const QString& name, const QString& text,
                                const QKeySequence& shortcut) {
    auto* a = new QAction(text, this);
    a->setObjectName(name);
    if (!shortcut.isEmpty()) {
        a->setShortcut(shortcut);
    }
    if (menu) {
        menu->addAction(a);
    }
    return a;
}

// ---- view preferences ----

namespace {

const QString kInvertVerticalOrbitKey = QStringLiteral("view/invertVerticalOrbit");

} // namespace

bool MainWindow::invertsVerticalOrbit() const {
    return QSettings().value(kInvertVerticalOrbitKey, false).toBool();
}

void MainWindow::setInvertVerticalOrbit(bool on) {
    QSettings().setValue(kInvertVerticalOrbitKey, on);
    if (m_invertOrbitAction && m_invertOrbitAction->isChecked() != on) {
        m_invertOrbitAction->setChecked(on); // toggles back into here once, with nothing left to do
    }
    m_viewport->setInvertVerticalOrbit(on);
}

// ---- editing ----

base::Status MainWindow::addTree(scene::NodeTree tree) {
    auto added = document::addNodeTree(scene(), undoStack(), std::move(tree));
    if (!added) {
        statusBar()->showMessage(QString::fromStdString(added.error()), 8000);
        return base::Error{added.error()};
    }
    m_selection->selectNode(*added);
    return base::Done{};
}

base::Status MainWindow::addNode(document::NewNodeKind kind) {
    document::NewNodePlacement placement;
    placement.focus = m_viewport->lookAtPoint();
    placement.viewPosition = m_viewport->viewCamera().position;
    placement.timeSeconds = m_clock->time();
    return addTree(document::placeNewNode(scene(), m_viewport->meshes(), kind, placement));
}

base::Status MainWindow::deleteSelected() {
    return document::deleteNodes(scene(), undoStack(), m_selection->roots());
}

base::Status MainWindow::duplicateSelected() {
    auto duplicated = document::duplicateNodes(scene(), undoStack(), m_selection->roots(),
                                               m_selection->node(), &m_viewport->meshes(), m_clock->time());
    if (!duplicated) {
        return base::Error{duplicated.error()};
    }
    m_selection->setNodes(duplicated->copies, duplicated->currentCopy);
    return base::Done{};
}

void MainWindow::copySelected() {
    const std::vector<scene::NodeId> roots = m_selection->roots();
    if (roots.empty()) {
        return;
    }
    const QByteArray copied = document::copyNodes(scene(), roots);
    auto* mime = new QMimeData;
    mime->setData(QString::fromLatin1(document::kNodesMimeType), copied);
    mime->setText(QString::fromUtf8(copied)); // readable, and pasteable from a text editor
    QGuiApplication::clipboard()->setMimeData(mime);
    statusBar()->showMessage(
        roots.size() == 1 ? tr("Copied 1 node.") : tr("Copied %1 nodes.").arg(roots.size()), 4000);
}

base::Status MainWindow::cutSelected() {
    const std::vector<scene::NodeId> roots = m_selection->roots();
    if (roots.empty()) {
        return base::Error{"nothing is selected"};
    }
    copySelected();
    return document::deleteNodes(scene(), undoStack(), roots);
}

base::Status MainWindow::paste() {
    const QMimeData* mime = QGuiApplication::clipboard()->mimeData();
    const QString type = QString::fromLatin1(document::kNodesMimeType);
    const QByteArray copied = !mime                   ? QByteArray()
                              : mime->hasFormat(type) ? mime->data(type)
                                                      : mime->text().toUtf8();
    auto pasted = document::pasteNodes(scene(), undoStack(), copied);
    if (!pasted) {
        statusBar()->showMessage(tr("Nothing pasted: %1").arg(QString::fromStdString(pasted.error())), 8000);
        return base::Error{pasted.error()};
    }
    m_selection->setNodes(pasted->nodes, pasted->nodes.front());
    return base::Done{};
}

void MainWindow::selectAll() {
    std::vector<scene::NodeId> all;
    scene().forEachNode([&](const scene::Node& node) { all.push_back(node.id()); });
    m_selection->setNodes(all, m_selection->node());
}

void MainWindow::updateEditActions() {
    const bool hasNode = !m_selection->roots().empty();
    m_deleteAction->setEnabled(hasNode);
    m_duplicateAction->setEnabled(hasNode);
    m_copyAction->setEnabled(hasNode);
    m_cutAction->setEnabled(hasNode);
    m_renameAction->setEnabled(m_selection->selectedNode() != nullptr);
}

// ---- export ----

base::Status MainWindow::exportGltfFile(const QString& path, const scene::ReplaceUnrelatedFiles& mayReplace) {
    std::vector<std::string> warnings;
    m_viewport->waitForModels(); // read on workers: none may be missing from the file
    auto status = scene::exportGltf(scene(), path, m_viewport->meshes(), warnings, mayReplace);
    for (const auto& w : warnings) {
        logMessage(QString::fromStdString(w));
    }
    // The exporter found a failed model file empty (its stand-in): the read's own error says why.
    for (const scene::Warning& w : m_viewport->correctModelWarnings({})) {
        logMessage(QString::fromStdString(w.message));
    }
    if (status) {
        logMessage(tr("Exported %1").arg(path));
        statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), 5000);
    } else {
        logMessage(tr("glTF export failed: %1").arg(QString::fromStdString(status.error())));
    }
    return status;
}

base::Result<scene::StillExportResult> MainWindow::exportStillFile(const QString& path,
                                                                   const scene::StillExportSettings& settings,
                                                                   const render::ProgressCallback& progress) {
    if (auto valid = scene::validateStillExport(settings, path.toStdString()); !valid) {
        return base::Error{valid.error()};
    }
    // An exact still needs no GL: the tracer draws it, as `speculum render --reference` does.
    if (!settings.reference && (!m_viewport->isValid() || !m_viewport->renderer())) {
        return base::Error{m_viewport->rendererError().isEmpty()
                               ? std::string("the viewport has no OpenGL context yet")
                               : m_viewport->rendererError().toStdString()};
    }
    // The scene's model files are read on workers: a still must not lack one that is still loading.
    m_viewport->waitForModels();
    auto result = settings.reference
                      ? scene::exportStill(nullptr, scene(), m_viewport->meshes(), settings, path, progress)
                      : exportRasterStill(path, settings, progress);
    logStillExport(path, settings, result);
    return result;
}

// Renders on the viewport's context, with its renderer: the same renderer code the CLI uses. Anything the
// progress callback lets run (the event loop) may make another context current: take it back.
base::Result<scene::StillExportResult>
MainWindow::exportRasterStill(const QString& path, const scene::StillExportSettings& settings,
                              const render::ProgressCallback& progress) {
    m_viewport->makeCurrent();
    const render::ProgressCallback keepContext = [&](double fraction, const std::string& stage) {
        const bool goOn = !progress || progress(fraction, stage);
        m_viewport->makeCurrent();
        return goOn;
    };
    auto result = scene::exportStill(m_viewport->renderer(), scene(), m_viewport->meshes(), settings, path,
                                     keepContext, render::gl::contextDescription());
    m_viewport->doneCurrent();
    m_viewport->update();
    return result;
}

void MainWindow::logStillExport(const QString& path, const scene::StillExportSettings& settings,
                                base::Result<scene::StillExportResult>& result) {
    if (!result) {
        logMessage(tr("Still export failed: %1").arg(QString::fromStdString(result.error())));
        return;
    }
    result->sceneWarnings = m_viewport->correctModelWarnings(std::move(result->sceneWarnings));
    for (const scene::Warning& w : result->sceneWarnings) {
        logMessage(QString::fromStdString(w.message));
    }
    for (const auto& w : result->warnings) {
        logMessage(QString::fromStdString(w));
    }
    logMessage(tr("Exported %1 (%2×%3, %4 samples per pixel, %5 ms)")
                   .arg(path)
                   .arg(settings.width)
                   .arg(settings.height)
                   .arg(result->still.samples)
                   .arg(result->still.totalMs, 0, 'f', 0));
}

// ---- menu actions ----

void MainWindow::onNew() {
    if (maybeSave()) {
        newProject();
    }
}

void MainWindow::onOpen() {
    openFromDialog(tr("Open Project"), dialogFolder());
}

void MainWindow::onOpenExample() {
    const QString folder = examplesFolder();
    if (folder.isEmpty()) {
        QMessageBox::warning(this, tr("Open Example"),
                             tr("The example projects are not installed (looked for share/speculum/scenes "
                                "beside %1).")
                                 .arg(shown(QCoreApplication::applicationDirPath())));
        return;
    }
    openFromDialog(tr("Open Example"), folder);
}

void MainWindow::openFromDialog(const QString& title, const QString& folder) {
    if (!maybeSave()) {
        return;
    }
    const QString path = QFileDialog::getOpenFileName(this, title, folder, kProjectFilter);
    if (path.isEmpty()) {
        return;
    }
    base::Status status = openProjectFile(path);
    if (!status) {
        // The error names the JSON path of the problem; the current document is unchanged.
        QMessageBox::critical(
            this, tr("Open Project"),
            tr("Could not open %1:\n\n%2")
                .arg(shown(QFileInfo(path).fileName()), QString::fromStdString(status.error())));
    }
}

bool MainWindow::onSave() {
    if (scene().projectPath().isEmpty()) {
        return onSaveAs();
    }
    bool overwrite = false;
    if (m_session->changedOnDisk()) {
        switch (askAboutDiskChange()) {
        case DiskChoice::KeepMine:
            overwrite = true;
            break;
        case DiskChoice::SaveAs:
            return onSaveAs();
        case DiskChoice::Reload:
            openProjectFile(scene().projectPath()); // says itself what went wrong
            return false;                           // this version was not saved
        case DiskChoice::Cancel:
            return false;
        }
    }
    base::Status status = saveProjectFile(scene().projectPath(), overwrite);
    if (!status) {
        QMessageBox::critical(this, tr("Save Project"), QString::fromStdString(status.error()));
        return false;
    }
    return true;
}

bool MainWindow::onSaveAs() {
    QString suggestion = scene().projectPath();
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
    // The file dialog asked before replacing an existing file: the user chose to write over it.
    base::Status status = saveProjectFile(path, true);
    if (!status) {
        QMessageBox::critical(this, tr("Save Project"), QString::fromStdString(status.error()));
        return false;
    }
    return true;
}

MainWindow::DiskChoice MainWindow::askAboutDiskChange() {
    const QString name = QFileInfo(scene().projectPath()).fileName();
    QMessageBox box(QMessageBox::Warning, tr("File Changed on Disk"),
                    tr("%1 changed on disk since this editor opened or saved it: another editor or program "
                       "saved it.\n\nReload it (this version's unsaved changes are lost), keep this version "
                       "(overwrite the file), or save this version as another file?")
                        .arg(name),
                    QMessageBox::Cancel, this);
    QPushButton* reload = box.addButton(tr("&Reload"), QMessageBox::DestructiveRole);
    QPushButton* keepMine = box.addButton(tr("&Keep Mine"), QMessageBox::AcceptRole);
    QPushButton* saveAs = box.addButton(tr("Save &As…"), QMessageBox::ActionRole);
    box.setDefaultButton(saveAs); // the choice that loses nothing
    box.exec();
    if (box.clickedButton() == reload) {
        return DiskChoice::Reload;
    }
    if (box.clickedButton() == keepMine) {
        return DiskChoice::KeepMine;
    }
    return box.clickedButton() == saveAs ? DiskChoice::SaveAs : DiskChoice::Cancel;
}

void MainWindow::onProjectChangedOnDisk(const QString& path) {
    logMessage(
        tr("%1 changed on disk (another editor or program saved it); saving will ask first").arg(path));
    statusBar()->showMessage(tr("%1 changed on disk").arg(QFileInfo(path).fileName()), 10000);
}

void MainWindow::onImportModel(bool asReflector) {
    const QString path =
        QFileDialog::getOpenFileName(this, asReflector ? tr("Import Reflector Surface") : tr("Import Model"),
                                     dialogFolder(), scene::modelFileFilter());
    if (path.isEmpty()) {
        return;
    }
    // The rest happens on the worker; a failure there shows its own message box.
    if (auto status = startModelImport(path, asReflector, true); !status) {
        QMessageBox::critical(this, tr("Import Model"), QString::fromStdString(status.error()));
    }
}

void MainWindow::onExportGltf() {
    QString base = scene().projectPath();
    base = base.isEmpty()
               ? dialogFolder() + QStringLiteral("/scene.gltf")
               : QFileInfo(base).absolutePath() + QLatin1Char('/') +
                     QFileInfo(base).fileName().section(QLatin1Char('.'), 0, 0) + QStringLiteral(".gltf");
    QString path = QFileDialog::getSaveFileName(this, tr("Export Scene as glTF 2.0"), base,
                                                tr("glTF 2.0 (*.gltf);;glTF 2.0 binary (*.glb)"));
    if (path.isEmpty()) {
        return;
    }
    if (!path.endsWith(QStringLiteral(".gltf"), Qt::CaseInsensitive) &&
        !path.endsWith(QStringLiteral(".glb"), Qt::CaseInsensitive)) {
        path += QStringLiteral(".gltf");
    }
    const auto askToReplace = [this](const std::vector<std::string>& paths) {
        QStringList names;
        for (const std::string& p : paths) {
            names << QString::fromStdString(p);
        }
        return QMessageBox::question(this, tr("Export glTF"),
                                     tr("The export writes files beside it that already exist and that no "
                                        "earlier export to this file wrote:\n\n%1\n\nReplace them?")
                                         .arg(names.join(QLatin1Char('\n'))),
                                     QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes;
    };
    if (auto status = exportGltfFile(path, askToReplace); !status) {
        QMessageBox::critical(this, tr("Export glTF"), QString::fromStdString(status.error()));
    }
}

void MainWindow::onExportStill() {
    QString base = scene().projectPath();
    base = base.isEmpty()
               ? dialogFolder() + QStringLiteral("/render.png")
               : QFileInfo(base).absolutePath() + QLatin1Char('/') +
                     QFileInfo(base).fileName().section(QLatin1Char('.'), 0, 0) + QStringLiteral(".png");
    ExportStillDialog dialog(base, m_clock->time(), this);
    if (dialog.exec() != QDialog::Accepted) {
        return;
    }
    scene::StillExportSettings settings = dialog.settings();
    if (dialog.useCurrentView()) {
        settings.camera = m_viewport->viewCamera();
    }
    QProgressDialog progress(tr("Rendering %1…").arg(QFileInfo(dialog.outputPath()).fileName()), tr("Cancel"),
                             0, 1000, this);
    progress.setWindowTitle(tr("Export Still"));
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(300);
    auto result =
        exportStillFile(dialog.outputPath(), settings, [&](double fraction, const std::string& stage) {
            progress.setValue(int(fraction * 1000));
            progress.setLabelText(
                tr("Rendering %1 (%2)…")
                    .arg(QFileInfo(dialog.outputPath()).fileName(), QString::fromStdString(stage)));
            QApplication::processEvents();
            return !progress.wasCanceled();
        });
    progress.reset();
    if (!result) {
        if (progress.wasCanceled()) {
            statusBar()->showMessage(tr("Export cancelled; nothing was written."), 5000);
        } else {
            QMessageBox::critical(this, tr("Export Still"), QString::fromStdString(result.error()));
        }
        return;
    }
    statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(dialog.outputPath()).fileName()), 5000);
}

void MainWindow::showControls() {
    QMessageBox::information(
        this, tr("Viewport Controls"),
        tr("<table>"
           "<tr><td><b>Click</b></td><td>select (in a mirror: the reflected object); a model in parts: the "
           "model first, each click again one level deeper</td></tr>"
           "<tr><td><b>Alt+click</b></td><td>select a mirror itself</td></tr>"
           "<tr><td><b>Ctrl+click</b></td><td>add to the selection or remove from it (also in the "
           "scene tree, where Shift+click selects a range)</td></tr>"
           "<tr><td><b>Drag a handle</b></td><td>move / rotate / scale every selected node (the handles "
           "sit on the current, last selected one; each node turns and scales about its own origin)"
           "</td></tr>"
           "<tr><td><b>Ctrl</b> while dragging a handle</td><td>snap: by default to the grid's lines, "
           "to 15°, to scale factors in steps of 0.1 (View ▸ Snap Steps… sets the steps; with View ▸ "
           "Snap While Dragging on, Ctrl drags freely instead)</td></tr>"
           "<tr><td><b>Drag the scale handles' centre</b></td><td>scale evenly</td></tr>"
           "<tr><td><b>Q / W / E / R</b></td><td>no handles / move / rotate / scale</td></tr>"
           "<tr><td><b>Left drag</b></td><td>orbit around the camera target</td></tr>"
           "<tr><td><b>Middle drag</b> or <b>Shift+left drag</b></td><td>pan</td></tr>"
           "<tr><td><b>Mouse wheel</b></td><td>zoom</td></tr>"
           "<tr><td><b>F</b></td><td>frame the selection</td></tr>"
           "<tr><td><b>Double-click</b> or <b>Shift+F</b></td><td>back to the scene camera</td></tr>"
           "<tr><td><b>Numpad 1 / 3 / 7</b></td><td>front / right / top view (with Ctrl: back / left / "
           "bottom), NumLock on or off</td></tr>"
           "<tr><td><b>Numpad 4 / 6 / 8 / 2</b></td><td>orbit 15° left / right / up / down</td></tr>"
           "<tr><td><b>Numpad + / −</b></td><td>zoom in / out</td></tr>"
           "<tr><td><b>Numpad 0</b> / <b>Numpad .</b></td><td>back to the scene camera / frame the "
           "selection</td></tr>"
           "<tr><td><b>Esc</b> while dragging</td><td>cancel the drag</td></tr>"
           "<tr><td><b>Right-click</b></td><td>the menu of Add, the Edit commands and the view</td></tr>"
           "<tr><td><b>Ctrl+C / Ctrl+X / Ctrl+V</b></td><td>copy / cut / paste nodes (also between "
           "windows)</td></tr>"
           "<tr><td><b>Ctrl+Alt+Z</b></td><td>the undo history: click a step to go back to it</td></tr>"
           "<tr><td><b>H</b> / <b>Alt+H</b></td><td>hide the selection / show every hidden node (the tick "
           "in the scene tree shows or hides one)</td></tr>"
           "<tr><td><b>Space</b> / <b>Home</b></td><td>play or pause / rewind the animation</td></tr>"
           "</table><p>Moving the view does not change the document, unless View ▸ Look Through Scene "
           "Camera is on.</p>"));
}

void MainWindow::showAbout() {
    QMessageBox::about(
        this, tr("About speculum"),
        tr("<h3>speculum %1</h3><p>A scene editor for reflections: planar mirrors and "
           "environment-mapped curved reflectors, measured against a ray-traced reference.</p>")
            .arg(QApplication::applicationVersion()));
}

// ---- construction ----

// One builder per menu, in the menu bar's order (Add is built between Edit and View).
void MainWindow::createActions() {
    createFileMenu();
    createEditMenu();
    createAddMenu();
    createViewMenu();
    createHelpMenu();
}

void MainWindow::createFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    connect(makeAction(file, QStringLiteral("actionNew"), tr("&New"), QKeySequence::New), &QAction::triggered,
            this, &MainWindow::onNew);
    connect(makeAction(file, QStringLiteral("actionOpen"), tr("&Open…"), QKeySequence::Open),
            &QAction::triggered, this, &MainWindow::onOpen);
    connect(makeAction(file, QStringLiteral("actionOpenExample"), tr("Open &Example…")), &QAction::triggered,
            this, &MainWindow::onOpenExample);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    rebuildRecentMenu();
    connect(makeAction(file, QStringLiteral("actionSave"), tr("&Save"), QKeySequence::Save),
            &QAction::triggered, this, &MainWindow::onSave);
    connect(makeAction(file, QStringLiteral("actionSaveAs"), tr("Save &As…"), QKeySequence::SaveAs),
            &QAction::triggered, this, &MainWindow::onSaveAs);
    connect(makeAction(file, QStringLiteral("actionRecover"), tr("Recover &Unsaved Changes…")),
            &QAction::triggered, this, [this] { offerRecovery(true); });
    file->addSeparator();
    connect(makeAction(file, QStringLiteral("actionImportModel"), tr("&Import Model…"),
                       QKeySequence(Qt::CTRL | Qt::Key_I)),
            &QAction::triggered, this, [this] { onImportModel(false); });
    m_fitImportsAction =
        makeAction(file, QStringLiteral("actionFitImports"), tr("&Fit Imports to a Unit Box"));
    m_fitImportsAction->setCheckable(true);
    m_fitImportsAction->setChecked(fitImportsToUnitBox());
    m_fitImportsAction->setStatusTip(tr("Scale imported models to fit a 1-unit box instead of keeping their "
                                        "real size"));
    connect(m_fitImportsAction, &QAction::toggled, this, &MainWindow::setFitImportsToUnitBox);
    connect(makeAction(file, QStringLiteral("actionExportGltf"), tr("Export Scene as &glTF 2.0…"),
                       QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E)),
            &QAction::triggered, this, &MainWindow::onExportGltf);
    connect(makeAction(file, QStringLiteral("actionExportStill"), tr("Export S&till…"),
                       QKeySequence(Qt::CTRL | Qt::Key_E)),
            &QAction::triggered, this, &MainWindow::onExportStill);
    connect(makeAction(file, QStringLiteral("actionExportAnimation"), tr("Export &Animation…")),
            &QAction::triggered, this, &MainWindow::onExportAnimation);
    file->addSeparator();
    QAction* quit = makeAction(file, QStringLiteral("actionQuit"), tr("&Quit"), QKeySequence::Quit);
    quit->setMenuRole(QAction::QuitRole);
    connect(quit, &QAction::triggered, this, &QWidget::close);
}

void MainWindow::createEditMenu() {
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    // Undo/redo texts follow the command on top of the stack: "Undo Change Reflectivity of “Mirror”".
    QAction* undo = undoStack().createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("actionUndo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = undoStack().createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("actionRedo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    m_renameAction =
        makeAction(edit, QStringLiteral("actionRename"), tr("Re&name"), QKeySequence(Qt::Key_F2));
    connect(m_renameAction, &QAction::triggered, this, [this] { m_treePanel->editSelected(); });
    m_duplicateAction = makeAction(edit, QStringLiteral("actionDuplicate"), tr("D&uplicate"),
                                   QKeySequence(Qt::CTRL | Qt::Key_D));
    connect(m_duplicateAction, &QAction::triggered, this, [this] { duplicateSelected(); });
    m_deleteAction = makeAction(edit, QStringLiteral("actionDelete"), tr("&Delete"), QKeySequence::Delete);
    connect(m_deleteAction, &QAction::triggered, this, [this] { deleteSelected(); });
    edit->addSeparator();
    m_cutAction = makeAction(edit, QStringLiteral("actionCut"), tr("Cu&t"), QKeySequence::Cut);
    connect(m_cutAction, &QAction::triggered, this, [this] { cutSelected(); });
    m_copyAction = makeAction(edit, QStringLiteral("actionCopy"), tr("&Copy"), QKeySequence::Copy);
    connect(m_copyAction, &QAction::triggered, this, &MainWindow::copySelected);
    QAction* pasteAction = makeAction(edit, QStringLiteral("actionPaste"), tr("&Paste"), QKeySequence::Paste);
    connect(pasteAction, &QAction::triggered, this, [this] { paste(); });
    edit->addSeparator();
    QAction* selectAll =
        makeAction(edit, QStringLiteral("actionSelectAll"), tr("Select &All"), QKeySequence::SelectAll);
    connect(selectAll, &QAction::triggered, this, &MainWindow::selectAll);
    connect(makeAction(edit, QStringLiteral("actionSelectNone"), tr("Select &None"),
                       QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A)),
            &QAction::triggered, m_selection, &view::Selection::clear);
    // Editing shortcuts work wherever the focus is in the window, the scene tree and the docks as well as
    // the viewport, as in Blender, Godot and Unity. They do not steal keys from text fields:
    // before a shortcut fires Qt sends the focus widget a ShortcutOverride, which line edits, spin boxes
    // and the tree's rename editor accept for the keys they type with (Delete, Ctrl+A, letters), so
    // Delete in a name field deletes characters and Ctrl+A selects its text.
    for (QAction* a : {m_renameAction, m_duplicateAction, m_deleteAction, m_cutAction, m_copyAction,
                       pasteAction, selectAll}) {
        a->setShortcutContext(Qt::WindowShortcut);
    }
    updateEditActions();
}

void MainWindow::createViewMenu() {
    QMenu* view = menuBar()->addMenu(tr("&View"));
    m_playAction =
        makeAction(view, QStringLiteral("actionPlay"), tr("&Play Animation"), QKeySequence(Qt::Key_Space));
    m_playAction->setCheckable(true);
    // The viewport has focus most of the time; the shortcut must work from anywhere in the window.
    m_playAction->setShortcutContext(Qt::WindowShortcut);
    connect(m_playAction, &QAction::toggled, m_clock, &view::AnimationClock::setPlaying);
    connect(m_clock, &view::AnimationClock::playingChanged, m_playAction, &QAction::setChecked);
    // Its name says what pressing it does next, so the timeline's button shows whether the clock runs.
    connect(m_clock, &view::AnimationClock::playingChanged, m_playAction, [this](bool playing) {
        m_playAction->setText(playing ? tr("&Pause Animation") : tr("&Play Animation"));
    });
    connect(
        makeAction(view, QStringLiteral("actionRewind"), tr("&Rewind Animation"), QKeySequence(Qt::Key_Home)),
        &QAction::triggered, m_clock, [this] { m_clock->setTime(0.0); });
    view->addSeparator();
    connect(makeAction(view, QStringLiteral("actionFrameSelected"), tr("&Frame Selection"),
                       QKeySequence(Qt::Key_F)),
            &QAction::triggered, m_viewport, &Viewport::frameSelected);
    connect(makeAction(view, QStringLiteral("actionResetView"), tr("Reset &View to Scene Camera"),
                       QKeySequence(Qt::SHIFT | Qt::Key_F)),
            &QAction::triggered, m_viewport, &Viewport::resetView);
    QAction* throughCamera =
        makeAction(view, QStringLiteral("actionSceneCamera"), tr("&Look Through Scene Camera"));
    throughCamera->setCheckable(true);
    throughCamera->setToolTip(
        tr("Navigation moves the scene camera (undoable) instead of a free editor camera"));
    connect(throughCamera, &QAction::toggled, m_viewport, &Viewport::setLookThroughSceneCamera);
    connect(makeAction(view, QStringLiteral("actionCameraFromView"), tr("Set Scene &Camera from View")),
            &QAction::triggered, this,
            [this] { document::setCameraFromView(scene(), undoStack(), m_viewport->viewCamera()); });
    view->addSeparator();
    // Hide and show, as Blender's H and Alt+H: from anywhere in the window (a name field still types H).
    QAction* hide =
        makeAction(view, QStringLiteral("actionHideSelected"), tr("&Hide Selected"), QKeySequence(Qt::Key_H));
    hide->setShortcutContext(Qt::WindowShortcut);
    connect(hide, &QAction::triggered, this,
            [this] { document::setNodesHidden(scene(), undoStack(), m_selection->roots(), true); });
    QAction* showAll =
        makeAction(view, QStringLiteral("actionShowAll"), tr("Show &All"), QKeySequence(Qt::ALT | Qt::Key_H));
    showAll->setShortcutContext(Qt::WindowShortcut);
    connect(showAll, &QAction::triggered, this, [this] { document::showAllNodes(scene(), undoStack()); });
    view->addSeparator();
    createHandleModeActions(view);
    view->addSeparator();
    m_invertOrbitAction =
        makeAction(view, QStringLiteral("actionInvertVerticalOrbit"), tr("&Invert Vertical Orbit"));
    m_invertOrbitAction->setCheckable(true);
    m_invertOrbitAction->setChecked(invertsVerticalOrbit());
    m_invertOrbitAction->setStatusTip(
        tr("Dragging the mouse down lowers the view instead of raising it (the default "
           "follows Blender and three.js: the scene follows the mouse)"));
    connect(m_invertOrbitAction, &QAction::toggled, this, &MainWindow::setInvertVerticalOrbit);
    setInvertVerticalOrbit(invertsVerticalOrbit()); // the viewport starts with the remembered choice
    createSnapActions(view);
    m_viewMenu = view;
}

// View ▸ Select Only / Move / Rotate / Scale Handles (Q, W, E, R): one of them checked, as the viewport's
// mode.
void MainWindow::createHandleModeActions(QMenu* view) {
    auto* handles = new QActionGroup(this);
    const std::pair<HandleMode, std::pair<const char*, QString>> modes[] = {
        {HandleMode::Select, {"actionHandleSelect", tr("&Select Only")}},
        {HandleMode::Move, {"actionHandleMove", tr("&Move Handles")}},
        {HandleMode::Rotate, {"actionHandleRotate", tr("R&otate Handles")}},
        {HandleMode::Scale, {"actionHandleScale", tr("S&cale Handles")}}};
    const Qt::Key keys[] = {Qt::Key_Q, Qt::Key_W, Qt::Key_E, Qt::Key_R};
    int k = 0;
    for (const auto& [mode, names] : modes) {
        QAction* a =
            makeAction(view, QString::fromLatin1(names.first), names.second, QKeySequence(keys[k++]));
        a->setCheckable(true);
        a->setChecked(mode == m_viewport->handleMode());
        // From anywhere in the window, like the edit actions above (a name field still types Q).
        a->setShortcutContext(Qt::WindowShortcut);
        handles->addAction(a);
        connect(a, &QAction::triggered, m_viewport, [this, mode = mode] { m_viewport->setHandleMode(mode); });
    }
}

// The viewport's right-click menu, as in Blender and Godot: what the Edit and Add menus do to the selection,
// and the view's own commands. The right button does nothing else in the viewport.
void MainWindow::createViewportMenu() {
    m_viewport->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_viewport, &QWidget::customContextMenuRequested, this, [this](const QPoint& at) {
        QMenu menu(m_viewport);
        menu.setObjectName(QStringLiteral("viewportMenu"));
        menu.addMenu(m_addMenu);
        menu.addSeparator();
        for (QAction* a : {m_duplicateAction, m_cutAction, m_copyAction,
                           action(QStringLiteral("actionPaste")), m_deleteAction}) {
            menu.addAction(a);
        }
        menu.addSeparator();
        for (const char* name : {"actionFrameSelected", "actionResetView", "actionCameraFromView"}) {
            menu.addAction(action(QString::fromLatin1(name)));
        }
        menu.addSeparator();
        for (const char* name :
             {"actionHandleSelect", "actionHandleMove", "actionHandleRotate", "actionHandleScale"}) {
            menu.addAction(action(QString::fromLatin1(name)));
        }
        emit viewportMenuShown(&menu);
        menu.exec(m_viewport->mapToGlobal(at));
    });
}

void MainWindow::createHelpMenu() {
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    makeAction(help, QStringLiteral("actionControls"), tr("Viewport &Controls"), QKeySequence::HelpContents);
    connect(action(QStringLiteral("actionControls")), &QAction::triggered, this, &MainWindow::showControls);
    QAction* about = makeAction(help, QStringLiteral("actionAbout"), tr("&About speculum"));
    about->setMenuRole(QAction::AboutRole);
    connect(about, &QAction::triggered, this, &MainWindow::showAbout);
}

void MainWindow::createAddMenu() {
    using document::NewNodeKind;
    m_addMenu = menuBar()->addMenu(tr("&Add"));
    m_addMenu->setObjectName(QStringLiteral("addMenu"));
    auto add = [this](QMenu* menu, const char* name, NewNodeKind kind, const QString& tip = {}) {
        QAction* a = makeAction(menu, QString::fromLatin1(name), document::displayName(kind));
        a->setStatusTip(tip);
        connect(a, &QAction::triggered, this, [this, kind] {
            if (auto status = addNode(kind); !status) {
                QMessageBox::warning(this, tr("Add"), QString::fromStdString(status.error()));
            }
        });
    };
    add(m_addMenu, "addMirror", NewNodeKind::Mirror,
        tr("A planar mirror: a rectangle reflecting on its +Y side"));
    QMenu* reflector = m_addMenu->addMenu(tr("Curved &Reflector"));
    add(reflector, "addReflectorSphere", NewNodeKind::ReflectorSphere);
    add(reflector, "addReflectorTeapot", NewNodeKind::ReflectorTeapot);
    connect(makeAction(reflector, QStringLiteral("addReflectorModel"), tr("Imported Mesh…")),
            &QAction::triggered, this, [this] { onImportModel(true); });
    m_addMenu->addSeparator();
    QMenu* primitives = m_addMenu->addMenu(tr("&Primitive"));
    add(primitives, "addTeapot", NewNodeKind::Teapot);
    add(primitives, "addSphere", NewNodeKind::Sphere);
    add(primitives, "addBox", NewNodeKind::Box);
    add(primitives, "addPlane", NewNodeKind::Plane);
    QMenu* lights = m_addMenu->addMenu(tr("&Light"));
    add(lights, "addPointLight", NewNodeKind::PointLight);
    add(lights, "addDirectionalLight", NewNodeKind::DirectionalLight);
    add(lights, "addSpotLight", NewNodeKind::SpotLight);
    add(m_addMenu, "addEmpty", NewNodeKind::Empty, tr("An empty node to group others under"));
    m_addMenu->addSeparator();
    m_addMenu->addAction(action(QStringLiteral("actionImportModel")));
}

} // namespace speculum::ui
