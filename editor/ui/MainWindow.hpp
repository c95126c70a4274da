#pragma once

#include "base/Result.hpp"
#include "editor/document/DocumentSession.hpp"
#include "editor/document/EditOperations.hpp"
#include "editor/document/NodeFactory.hpp"
#include "scene/export/AnimationExport.hpp"
#include "scene/export/GltfExport.hpp"
#include "scene/export/StillExport.hpp"
#include "scene/project/Recovery.hpp"

#include <QMainWindow>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QPlainTextEdit;
class QProgressBar;
class QProgressDialog;
class QToolButton;
class QUndoStack;

namespace speculum::render {
struct FrameReport;
}
namespace speculum::view {
class AnimationClock;
class Selection;
} // namespace speculum::view

namespace speculum::ui {

class AccuracyPanel;
class AnimationExportJob;
class Inspector;
class ModelImportJob;
class RenderPassesPanel;
class SceneTreeModel;
class SceneTreePanel;
struct SnapSettings;
class Viewport;

// A path, file name or value from the user or a file, made safe for a one-line message: control
// characters escaped, long text shortened (base::printable). Full paths in the log keep more.
QString shown(const QString& text, std::size_t maxChars = 80);
constexpr std::size_t kShownPathChars = 1024;

// The editor's top-level window: holds the open document (a DocumentSession: the scene, its undo stack and
// its mesh library), the selection, the animation clock and the viewport, with the Scene, Properties,
// Render passes, Accuracy and Log docks around it and the File/Edit/Add/View/Help menus.
//
// Operations come in two layers: the public functions below return a Status without any dialog (for tests
// and scripted use), and change the document only through the document layer's operations
// (document/EditOperations.hpp, DocumentSession); the menu actions add file dialogs, prompts and error
// boxes.
// Every menu action has an objectName ("actionSave", "addMirror", ...) so tests can trigger it.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    document::DocumentSession& session() { return *m_session; }
    scene::Scene& scene() { return m_session->scene(); }
    const scene::Scene& scene() const { return m_session->scene(); }
    QUndoStack& undoStack() { return m_session->undoStack(); }
    Viewport& viewport() { return *m_viewport; }
    view::AnimationClock& clock() { return *m_clock; }
    view::Selection& selection() { return *m_selection; }
    Inspector& inspector() { return *m_inspector; }
    SceneTreePanel& sceneTree() { return *m_treePanel; }
    SceneTreeModel& sceneTreeModel() { return *m_treeModel; }
    RenderPassesPanel& passesPanel() { return *m_passesPanel; }
    AccuracyPanel& accuracyPanel() { return *m_accuracyPanel; }
    // A menu action by object name, or null.
    QAction* action(const QString& objectName) const;

    // Loads a project; on failure the open document stays exactly as it was and the error (which names
    // the JSON path or the file problem) is returned. Load warnings go to the log.
    base::Status openProjectFile(const QString& path);
    // Writes the document to path; on success it becomes the document's file and the undo stack is clean.
    // Writing over the document's own file after another editor or program changed it is refused unless
    // overwriteDiskChanges (File ▸ Save asks first: reload, keep mine, save as).
    base::Status saveProjectFile(const QString& path, bool overwriteDiskChanges = false);
    // Replaces the document with an empty scene (no prompt).
    void newProject();
    // Unsaved changes: edits since the last save, or a document restored from a recovery file.
    bool isModified() const;

    // Adds a node of the Add menu where the view looks, selects it; one undo step.
    base::Status addNode(document::NewNodeKind kind);
    // Model import. A model file (any format Assimp reads) is read on a worker thread, with progress and
    // a Cancel button in the status bar, while the window keeps working; then its node tree (a node per
    // file node, a child per part with its material) is added as one undo step and selected. It keeps its
    // real size unless "Fit imports to a unit box" is on, and lands on the ground (y = 0) where the view
    // looks, moved along +X past what is already there. asReflector makes the whole file the curved
    // reflector's surface instead. A failed or cancelled import leaves the document as it was.
    //
    // Starts an import (queued behind a running one). Fails at once only when the file does not exist.
    // `interactive`: a failure also shows a message box (menu and drops); otherwise only the log and the
    // status bar say it.
    base::Status startModelImport(const QString& path, bool asReflector = false, bool interactive = false);
    // Starts an import and waits for it (running the event loop: the window repaints meanwhile); returns
    // its outcome ("cancelled" when cancelled). For tests and scripted use.
    base::Status importModelFile(const QString& path, bool asReflector = false);
    bool isImporting() const;
    // Cancels the running import and the queued ones (the status bar's Cancel).
    void cancelImports();
    bool fitImportsToUnitBox() const;
    void setFitImportsToUnitBox(bool on); // remembered in QSettings
    // Tests: called on the import worker at every progress report (e.g. to hold an import in flight).
    void setImportWorkerHook(std::function<void(double)> hook) { m_importHook = std::move(hook); }
    // Delete and Duplicate act on every selected node (a node under a selected ancestor goes with the
    // ancestor), as one undo step; the copies of a duplicate are selected afterwards.
    base::Status deleteSelected();
    base::Status duplicateSelected();
    // Copies the selected nodes to the clipboard (document::copyNodes); Cut deletes them after, as one step.
    void copySelected();
    base::Status cutSelected();
    // Adds the clipboard's nodes at the top level, where they were, and selects them.
    base::Status paste();
    // Edit ▸ Select All: every node of the scene.
    void selectAll();

    // File ▸ Export Scene as glTF 2.0. mayReplace: asked before files beside a .gltf that no earlier
    // export wrote are replaced (scene::exportGltf); without it such an export is refused.
    base::Status exportGltfFile(const QString& path, const scene::ReplaceUnrelatedFiles& mayReplace = {});
    // File ▸ Export Still, without the dialog: renders on the viewport's context with the same code as
    // `speculum render`. `progress` may cancel (return false).
    base::Result<scene::StillExportResult> exportStillFile(const QString& path,
                                                           const scene::StillExportSettings& settings,
                                                           const render::ProgressCallback& progress = {});
    // File ▸ Export Animation, without the dialog: checks the settings, then draws the frames on a worker
    // (AnimationExportJob) and returns at once; a window-modal progress dialog shows the frame, the time
    // left and Cancel meanwhile. The document is only read, never changed. When the export ends:
    // animationExportFinished(), lastAnimationExport(), a status bar message, and the result opened in the
    // desktop's player (a clip) or file manager (a sequence's folder) unless setOpensExports(false).
    base::Status startAnimationExport(const QString& path, const scene::AnimationSettings& settings);
    bool animationExportRunning() const;
    void cancelAnimationExport(); // as the progress dialog's Cancel
    const std::optional<scene::AnimationResult>& lastAnimationExport() const { return m_lastAnimationExport; }
    void setOpensExports(bool on) { m_opensExports = on; }

    // Crash recovery. The store defaults to RecoveryStore::forThisProcess(); tests use their own folder.
    void setRecoveryStore(const scene::RecoveryStore& store);
    const scene::RecoveryStore& recoveryStore() const { return *m_recovery; }
    // Writes the recovery file now if there are unsaved changes (the timer does it every 30 s, or every
    // SPECULUM_AUTOSAVE_SECONDS).
    base::Status autosaveNow();
    // Loads an orphaned recovery file as the open document, marked modified and titled as its project;
    // the orphan's files are removed once this editor's own recovery file holds the document.
    base::Status restoreRecovery(const scene::RecoveryStore::Recovered& recovered);
    // The same for the recovery file at scenePath (the editor's --recover, from another editor's dialog).
    base::Status restoreRecoveryFile(const QString& scenePath);
    // Starts another editor that restores `recovered` (RecoveryDialog's Restore in New Window).
    base::Status restoreInNewEditor(const scene::RecoveryStore::Recovered& recovered);
    // The program restoreInNewEditor starts; this program unless set (tests name the speculum binary).
    void setNewEditorProgram(const QString& program) { m_newEditorProgram = program; }
    // At start-up and from File ▸ Recover Unsaved Changes: lists every document editors that stopped left
    // unsaved (RecoveryDialog); each is restored or discarded by name, the rest kept for later.
    // sayWhenNothing: a message when there is nothing to recover (the menu; start-up stays silent).
    void offerRecovery(bool sayWhenNothing = false);
    // The edits not yet saved, oldest first (named in the recovery note): those of a restored document,
    // then the undo stack's since the save.
    QStringList unsavedEdits() const;

    // Window layout and dock state from the last session (QSettings).
    void restoreLayout();
    QStringList recentFiles() const;

    // Appends a line to the log panel (and stderr).
    void logMessage(const QString& message);
    const QStringList& logLines() const { return m_logLines; }

signals:
    // After every import request ends: ok, or the error ("cancelled" when cancelled). The added root node
    // is the current selection when ok.
    void importFinished(const QString& path, bool ok, const QString& message);
    // The viewport's right-click menu, about to open (tests close it from here).
    void viewportMenuShown(QMenu* menu);
    // An animation export ended (done, failed or cancelled): lastAnimationExport() says how.
    void animationExportFinished();

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    // The document's file changed on disk: asks before a save whether to reload it, overwrite it with
    // this version, or save this version as another file.
    enum class DiskChoice { Reload, KeepMine, SaveAs, Cancel };
    DiskChoice askAboutDiskChange();

private slots:
    void onNew();
    void onOpen();
    void onOpenExample(); // File ▸ Open Example…: the open dialog in the example projects' folder
    void openFromDialog(const QString& title, const QString& folder);
    bool onSave();
    bool onSaveAs();
    void onProjectChangedOnDisk(const QString& path);
    void onImportModel(bool asReflector);
    void onExportGltf();
    void onExportStill();
    void onExportAnimation();
    void showControls();
    void showAbout();
    void updateTitle();
    void updateEditActions();
    void onFrameRendered(const speculum::render::FrameReport& report, double animationTime);
    void onWarningsChanged(const QStringList& warnings);

private:
    base::Result<scene::StillExportResult> exportRasterStill(const QString& path,
                                                             const scene::StillExportSettings& settings,
                                                             const render::ProgressCallback& progress);
    void logStillExport(const QString& path, const scene::StillExportSettings& settings,
                        base::Result<scene::StillExportResult>& result);
    // ---- Export Animation (MainWindowAnimation.cpp)
    render::FrameInput animationFrame(double time); // the export's frame source, on the GUI thread
    QProgressDialog* animationProgressDialog(const QString& path);
    void showAnimationProgress(const scene::AnimationProgress& progress);
    void animationExportEnded(const scene::AnimationResult& result);
    void logAnimationExport(const scene::AnimationResult& result);
    AnimationExportJob* m_animationJob = nullptr; // QObject child
    QProgressDialog* m_animationProgress = nullptr;
    QString m_animationPath; // as the user wrote it: a clip, or a sequence's pattern
    scene::AnimationSettings m_animationSettings;
    std::optional<std::vector<scene::Warning>> m_animationSceneWarnings; // the first frame's
    std::optional<scene::AnimationResult> m_lastAnimationExport;
    bool m_opensExports = true;
    // Construction: a builder per menu (MainWindowActions.cpp) and per dock (MainWindow.cpp).
    void createActions();
    void createFileMenu();
    void createEditMenu();
    void createAddMenu();
    void createViewMenu();
    void createHandleModeActions(QMenu* view);
    void createHelpMenu();
    void createStatusBar();
    void createDocks();
    QDockWidget* createSceneDock();
    QDockWidget* createInspectorDock();
    QDockWidget* createPassesDock(QDockWidget* treeDock);
    QDockWidget* createAccuracyDock(QDockWidget* inspectorDock);
    QDockWidget* createInspectDock(QDockWidget* inspectorDock);
    void placeAccuracyDock(QDockWidget* accuracyDock, QDockWidget* inspectorDock);
    QDockWidget* createLogDock();
    QDockWidget* createHistoryDock(QDockWidget* treeDock);
    void createViewportMenu();
    void rebuildRecentMenu();
    void addRecentFile(const QString& path);
    base::Status addTree(scene::NodeTree tree);
    void createImportStatus();
    void startNextImport();
    void onImportDone(); // the running job's finished()
    void showImportProgress(double fraction, const QString& phase);
    // Asks to save unsaved changes. Returns false when the user cancels (or saving fails).
    bool maybeSave();
    QString dialogFolder() const;
    QAction* makeAction(QMenu* menu, const QString& name, const QString& text,
                        const QKeySequence& shortcut = {});

    document::DocumentSession* m_session = nullptr; // QObject child
    view::AnimationClock* m_clock = nullptr;
    view::Selection* m_selection = nullptr;
    Viewport* m_viewport = nullptr;
    SceneTreeModel* m_treeModel = nullptr;
    SceneTreePanel* m_treePanel = nullptr;
    Inspector* m_inspector = nullptr;
    RenderPassesPanel* m_passesPanel = nullptr;
    AccuracyPanel* m_accuracyPanel = nullptr;
    int m_propertiesWidth = 0; // the Properties dock's width before the Accuracy panel opened beside it
    std::unique_ptr<scene::RecoveryStore> m_recovery;
    QStringList m_restoredEdits; // the unsaved edits a restored recovery file named
    QString m_newEditorProgram;
    QTimer m_autosave;

    QMenu* m_viewMenu = nullptr;
    QMenu* m_addMenu = nullptr;
    QMenu* m_recentMenu = nullptr;
    QAction* m_playAction = nullptr;
    QAction* m_deleteAction = nullptr;
    QAction* m_duplicateAction = nullptr;
    QAction* m_copyAction = nullptr;
    QAction* m_cutAction = nullptr;
    QAction* m_renameAction = nullptr;
    QLabel* m_frameLabel = nullptr;
    QLabel* m_timeLabel = nullptr;
    QPlainTextEdit* m_log = nullptr;
    QStringList m_logLines;
    QString m_shownViewportWarning; // the last viewport warning put in the status bar

    struct ImportRequest {
        QString path; // absolute
        bool asReflector = false;
        bool interactive = false;
        int serial = 0; // requests end in the order they were made
    };
    int m_importSerial = 0; // of the last request made
    int m_doneSerial = 0;   // of the last request ended
    std::deque<ImportRequest> m_importQueue;
    ImportRequest m_importing;
    ModelImportJob* m_importJob = nullptr; // the running one, owned (QObject child)
    std::function<void(double)> m_importHook;
    QWidget* m_importStatus = nullptr; // progress bar + Cancel in the status bar, shown while importing
    QLabel* m_importLabel = nullptr;
    QProgressBar* m_importProgress = nullptr;
    QToolButton* m_importCancel = nullptr;
    QAction* m_fitImportsAction = nullptr;
    bool offerFitToScene(const ImportRequest& request, const QString& fileName,
                         const document::PlacedModel& placed);
    bool frameIfOutOfView(const render::math::Box& box);
    void reportImported(const QString& fileName, const document::PlacedModel& placed,
                        const std::vector<std::string>& warnings);

    // ---- time (MainWindowTime.cpp): the timeline toolbar (Play, Rewind, the time slider and
    // its "t = … s" readout) and the clock back to 0, paused, whenever the document is replaced (New, Open,
    // Restore). The slider's range is one loop of the scene's animation, kept up to date on every edit.
    void createTimeline();
    void updateTimelineRange();
    void resetClock();
    // MainWindowView.cpp: view presets and guides, and the project's saved editor view.
    void createViewPlacement();
    void rememberEditorView(); // the viewport's view into the document, for the next save
    class TimeSlider* m_timeSlider = nullptr;

    // ---- input (MainWindowActions.cpp): View ▸ Invert Vertical Orbit, remembered in QSettings.
    // Off (the default): dragging down raises the view, as in Blender and three.js (ViewCamera::orbitByDrag).
public:
    bool invertsVerticalOrbit() const;
    void setInvertVerticalOrbit(bool on);
    // View ▸ Snap While Dragging and Snap Steps…: SnapSettings, remembered in QSettings, handed to the
    // viewport.
    void setSnapSettings(const SnapSettings& settings);

private:
    void createSnapActions(QMenu* view);
    void editSnapSettings();
    QAction* m_invertOrbitAction = nullptr;
    QAction* m_snapAlwaysAction = nullptr;
};

} // namespace speculum::ui
