#pragma once

#include "editor/document/MeshLibrary.hpp"
#include "editor/document/SceneData.hpp"
#include "editor/ui/Gizmo.hpp"
#include "editor/ui/HandleDrag.hpp"
#include "editor/view/ViewCamera.hpp"
#include "render/Renderer.hpp"

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QPoint>
#include <QStringList>
#include <QTimer>
#include <memory>

class QPainter;
class QUndoStack;

namespace speculum::document {
class Scene;
}
namespace speculum::view {
class AnimationClock;
class Selection;
} // namespace speculum::view

namespace speculum::ui {

class ViewportModels;
class ViewportOverlay;

// The live 3D view: draws a snapshot of the document every frame with render::Renderer into this widget's
// framebuffer object. All GL work happens inside render/; this class only manages the renderer's lifetime
// (created in initializeGL, freed on QOpenGLContext::aboutToBeDestroyed) and feeds it.
//
// Mouse: a click selects what is under the cursor (through mirrors: clicking a reflection selects the
// reflected object; Alt+click selects the mirror itself), Ctrl+click adds it to the selection or takes it
// out; the handles sit on the current node, and dragging one moves, rotates or scales every selected node
// (a node under a selected ancestor goes with it) by the same displacement, angle or factor, each about its
// own origin (one undo step per drag); left drag elsewhere orbits around the camera target,
// middle (or Shift+left) drag pans, the wheel zooms, double-click returns to the scene camera.
// Navigation moves the view's own free camera, unless "look through the scene camera" is on: then it
// edits the document's camera (undoable, one step per drag).
//
// Handles, the selection outline and light markers are painted with QPainter on a transparent child
// widget over the GL frame, projected with the renderer's matrices; they are not part of the frame
// (grabFramebuffer() shows the scene only).
class Viewport : public QOpenGLWidget {
    Q_OBJECT

public:
    // `meshes` is the document session's mesh library: the viewport draws and picks with it, and hands it
    // the models its workers read.
    Viewport(document::Scene& scene, document::MeshLibrary& meshes, view::AnimationClock& clock,
             QWidget* parent = nullptr);
    ~Viewport() override;

    // Enables selection and handles; without it the viewport only views.
    void setEditing(view::Selection* selection, QUndoStack* undoStack);

    // Frames drawn since the widget was created (tests wait on this).
    int framesRendered() const { return m_framesRendered; }
    const render::FrameReport& lastReport() const { return m_lastReport; }
    double lastFrameTime() const { return m_lastFrameTime; }
    // Frames per second over the last second of drawing (0 before that).
    double framesPerSecond() const { return m_fps; }
    // Why the viewport cannot draw (no OpenGL 3.3, shader errors); empty when it can.
    const QString& rendererError() const { return m_rendererError; }

    // The renderer, for work that must run on this widget's context (still export): call makeCurrent()
    // first. Null until the widget has been shown (or when it failed).
    render::Renderer* renderer() { return m_renderer.get(); }
    // The document's mesh library. Asking for it starts the reads of the scene's model files on workers
    // (ViewportModels): a file not read yet is an empty stand-in until it is; waitForModels() waits for
    // them (export does, so a still never lacks a model that is still loading).
    document::MeshLibrary& meshes();
    bool modelsLoading() const;
    // Runs the event loop until every model file the scene references is read (or failed).
    void waitForModels();
    // Warnings of a snapshot of the scene made with meshes() (an export) with the ones about model files
    // that failed on the workers put right (the stand-ins would make them say "no triangles", or nothing).
    std::vector<std::string> correctModelWarnings(std::vector<std::string> warnings);
    // A model read elsewhere (Import's worker), so the viewport does not read the file again.
    void adoptModel(const std::string& absolutePath, std::shared_ptr<const document::ImportedModel> model);
    const render::Camera& viewCamera() const { return m_view.camera(); }

    HandleMode handleMode() const { return m_handleMode; }
    void setHandleMode(HandleMode mode);
    bool looksThroughSceneCamera() const { return m_sceneCameraMode; }
    void setLookThroughSceneCamera(bool on);

    // What a click at a widget position (logical pixels) would select: a node id, or 0.
    std::uint64_t pickAt(QPointF position, bool mirrorItself = false);
    // Where a handle axis of the current node lies on screen (for tests and benchmarks): the tip of
    // `axis` (move/scale) or a point on its ring (rotate); nothing when no handles are shown.
    std::optional<QPointF> handlePoint(int axis);
    // The point the view looks at, where new nodes are placed.
    glm::dvec3 lookAtPoint() const { return m_view.camera().target; }

    void paintOverlay(QPainter& painter); // called by the overlay widget

    QSize sizeHint() const override { return {960, 600}; }

public slots:
    // Back to the scene's camera after mouse navigation.
    void resetView();
    // Moves the view so the selected nodes fill it (all nodes when nothing is selected).
    void frameSelected();

signals:
    // After every frame, with the renderer's report and the animation time it showed.
    void frameRendered(const speculum::render::FrameReport& report, double animationTime);
    // When the set of warnings (snapshot + renderer) differs from the previous frame's.
    void warningsChanged(const QStringList& warnings);
    void rendererFailed(const QString& message);
    void handleModeChanged(speculum::ui::HandleMode mode);

protected:
    void initializeGL() override;
    void paintGL() override;
    void resizeEvent(QResizeEvent* event) override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    void releaseGlResources();
    void paintError();
    void updateTicking();
    void reportWarnings(QStringList warnings);
    void navigated(); // after orbit/pan/zoom
    void updateGizmo();
    ScreenProjection projection() const;

    document::Scene& m_scene;
    view::AnimationClock& m_clock;
    view::Selection* m_selection = nullptr;
    QUndoStack* m_undoStack = nullptr;
    document::MeshLibrary& m_meshes; // kept across frames: the renderer keys GPU meshes on the handles
    std::unique_ptr<render::Renderer> m_renderer;
    QString m_rendererError;
    view::ViewCamera m_view;
    QTimer m_tick; // drives repaints while the animation plays
    ViewportOverlay* m_overlay = nullptr;
    ViewportModels* m_models = nullptr; // reads the scene's model files off the GUI thread

    render::FrameReport m_lastReport;
    double m_lastFrameTime = 0.0;
    int m_framesRendered = 0;
    QStringList m_warnings;
    QElapsedTimer m_fpsTimer;
    int m_fpsFrames = 0;
    double m_fps = 0.0;

    HandleMode m_handleMode = HandleMode::Move;
    bool m_sceneCameraMode = false;
    Gizmo m_gizmo;
    int m_hoverAxis = -1;

    // A press on a handle hands the gesture to m_handleDrag; the rest (click, orbit, pan) is the widget's.
    enum class Drag { None, PendingClick, Orbit, Pan, Handle };
    Drag m_drag = Drag::None;
    QPoint m_lastMouse;
    QPointF m_pressPosition;
    bool m_pressAlt = false;
    bool m_pressCtrl = false;
    std::unique_ptr<HandleDrag> m_handleDrag; // with editing on
    int m_gestureSerial = 0;
};

} // namespace speculum::ui
