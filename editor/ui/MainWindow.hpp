#pragma once

#include "render/Result.hpp"

#include <QMainWindow>
#include <QString>
#include <QStringList>

class QAction;
class QLabel;
class QMenu;
class QPlainTextEdit;
class QUndoStack;

namespace speculum::document {
class Scene;
}
namespace speculum::render {
struct FrameReport;
}

namespace speculum::ui {

class AnimationClock;
class Viewport;

// The editor's top-level window: owns the open document (Scene + its undo stack), the animation clock and
// the viewport, and the File/Edit/View/Help menus.
//
// The file operations come in two layers: openProjectFile()/saveProjectFile()/newProject() do the work
// and return a Status without any dialog (for tests and scripted use); the menu actions add the file
// dialogs, the unsaved-changes prompt and the error boxes.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    document::Scene& scene() { return *m_scene; }
    QUndoStack& undoStack() { return *m_undoStack; }
    Viewport& viewport() { return *m_viewport; }
    AnimationClock& clock() { return *m_clock; }

    // Loads a project; on failure the open document stays exactly as it was and the error (which names
    // the JSON path or the file problem) is returned. Load warnings go to the log.
    render::Status openProjectFile(const QString& path);
    // Writes the document to path; on success it becomes the document's file and the undo stack is clean.
    render::Status saveProjectFile(const QString& path);
    // Replaces the document with an empty scene (no prompt).
    void newProject();

    // Appends a line to the log panel (and stderr).
    void logMessage(const QString& message);
    const QStringList& logLines() const { return m_logLines; }

protected:
    void closeEvent(QCloseEvent* event) override;

private slots:
    void onNew();
    void onOpen();
    bool onSave();
    bool onSaveAs();
    void showControls();
    void showAbout();
    void updateTitle();
    void onFrameRendered(const speculum::render::FrameReport& report, double animationTime);
    void onWarningsChanged(const QStringList& warnings);

private:
    void createActions();
    void createStatusBar();
    void createLogDock();
    // Asks to save unsaved changes. Returns false when the user cancels (or saving fails).
    bool maybeSave();
    QString dialogFolder() const;

    document::Scene* m_scene = nullptr;
    QUndoStack* m_undoStack = nullptr;
    AnimationClock* m_clock = nullptr;
    Viewport* m_viewport = nullptr;

    QMenu* m_viewMenu = nullptr;
    QAction* m_playAction = nullptr;
    QLabel* m_frameLabel = nullptr;
    QLabel* m_timeLabel = nullptr;
    QPlainTextEdit* m_log = nullptr;
    QStringList m_logLines;
};

} // namespace speculum::ui
