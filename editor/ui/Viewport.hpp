#pragma once

#include "editor/ui/Gizmo.hpp"
#include "editor/ui/SnapSettings.hpp"
#include "editor/ui/ViewportHandles.hpp"
#include "editor/ui/ViewportNavigation.hpp"
#include "editor/view/AdaptiveResolution.hpp"
#include "render/inspect/PixelExplanation.hpp"
#include "render/renderer/Renderer.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/SceneData.hpp"
#include "scene/model/Warning.hpp"

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QStringList>
#include <QTimer>
#include <memory>
#include <optional>
#include <utility>

class QPainter;
class QUndoStack;

namespace speculum::scene {
class Scene;
} // namespace speculum::scene
namespace speculum::view {
class AnimationClock;
class Selection;
} // namespace speculum::view

namespace speculum::ui {

class ViewportModels;
class CoarseLevelJobs;
class ViewportOverlay;

// The live 3D view: draws a snapshot of the document every frame with render::Renderer into this widget's
// framebuffer object. All GL work happens inside render/; this class only manages the renderer's lifetime
// (created in initializeGL, freed on QOpenGLContext::aboutToBeDestroyed) and feeds it, decides when frames
// are drawn and at what quality, and hands the mouse, the wheel and the keys on: the view's camera and its
// moves are ViewportNavigation's, picking, the handles and the left button's clicks and handle drags
// ViewportHandles'. Viewport.cpp drives the frames, ViewportInput.cpp hands the input on, ViewportMarks.cpp
// paints the marks over the frame.
//
// Mouse: a click selects what is under the cursor (through mirrors: clicking a reflection selects the
// reflected object; Alt+click selects the mirror itself), Ctrl+click adds it to the selection or takes it
// out; the handles sit on the current node, and dragging one moves, rotates or scales every selected node
// (a node under a selected ancestor goes with it) by the same displacement, angle or factor, each about its
// own origin (one undo step per drag); left drag elsewhere orbits around the camera target (the scene
// follows the mouse, setInvertVerticalOrbit), middle (or Shift+left) drag pans, the wheel zooms,
// double-click returns to the scene camera. While navigating or dragging a handle, frames are previews
// drawn at a reduced resolution when full frames would be slow (adaptive resolution, below); the full
// frame follows when the view rests.
// Navigation moves the view's own free camera, unless "look through the scene camera" is on: then it
// edits the document's camera (undoable, one step per drag).
//
// It draws only when what it shows changes: an edit, a new document, navigation, a time jump, a model
// read in, a resize, or the clock playing over a scene where something is animated.
//
// Handles, the selection outline and light markers are painted with QPainter on a transparent child
// widget over the GL frame, projected with the renderer's matrices; they are not part of the frame
// (grabFramebuffer() shows the scene only).
class Viewport : public QOpenGLWidget {
    Q_OBJECT

public:
    // `meshes` is the document session's mesh library: the viewport draws and picks with it, and hands it
    // the models its workers read.
    Viewport(scene::Scene& scene, scene::MeshLibrary& meshes, view::AnimationClock& clock,
             QWidget* parent = nullptr);
    ~Viewport() override;

    // Enables selection and handles; without it the viewport only views.
    void setEditing(view::Selection* selection, QUndoStack* undoStack);

    // Frames drawn since the widget was created (tests wait on this, and count that none is drawn idle).
    int framesRendered() const { return m_framesRendered; }
    // Whether frames keep coming on their own: the clock plays and something in the scene moves.
    bool isAnimating() const { return m_tick.isActive(); }
    const render::FrameReport& lastReport() const { return m_lastReport; }
    double lastFrameTime() const { return m_lastFrameTime; }
    // Frames per second over the last second of drawing (0 before that).
    double framesPerSecond() const { return m_fps; }
    // Why the viewport cannot draw (no OpenGL 3.3, shader errors); empty when it can.
    const QString& rendererError() const { return m_rendererError; }

    // The renderer, for work that must run on this widget's context (still export): call makeCurrent()
    // first. Null until the widget has been shown (or when it failed).
    render::Renderer* renderer() { return m_renderer.get(); }
    // Builds the simplified levels of big meshes for the renderer's reflected views (tests wait on it).
    CoarseLevelJobs& coarseLevelJobs() { return *m_coarseLevels; }
    // The document's mesh library (the session's own). Model files the scene references are read on
    // workers (ViewportModels) when a frame or waitForModels() asks for them; one not read yet is an empty
    // stand-in until it is.
    scene::MeshLibrary& meshes() { return m_meshes; }
    // Starts the reads of the model files the scene references that are not read yet (a frame does too),
    // without waiting for them.
    void readModels();
    bool modelsLoading() const;
    // Starts the reads of the model files the scene references that are not read yet, and runs the event
    // loop until every one is read (or failed): export does, so a still never lacks a model that is still
    // loading.
    void waitForModels();
    // Warnings of a snapshot of the scene made with meshes() (an export) with the ones about model files
    // that failed on the workers put right (the stand-ins would make them say "no triangles", or nothing):
    // ViewportModels::correct.
    std::vector<scene::Warning> correctModelWarnings(std::vector<scene::Warning> warnings);
    // A model read elsewhere (Import's worker), so the viewport does not read the file again.
    void adoptModel(const std::string& absolutePath, std::shared_ptr<const scene::ImportedModel> model);
    const render::Camera& viewCamera() const { return m_navigation.camera(); }
    // The document's camera (what `speculum render` draws), as the renderer takes it.
    render::Camera sceneCamera() const;
    // Moves the view to `camera`'s position, target and up (a view preset); the field of view and near
    // plane stay the view's. Looking through the scene camera, it is an edit of that camera, as
    // navigation is. Repaints.
    void setViewCamera(const render::Camera& camera);
    // A step of the keypad's orbit (degrees, as view::ViewCamera::orbit turns) or zoom (wheel notches):
    // moves the view as a preset does, an edit step of its own when looking through the scene camera.
    void orbitView(double yawDegrees, double pitchDegrees);
    void zoomView(double notches);
    // Where the view looks from and at, for the project's saved editor view (scene::EditorView).
    std::pair<glm::dvec3, glm::dvec3> viewPositionTarget() const;
    // Puts the view at `position` looking at `target` (a saved editor view: view::ViewCamera::place),
    // keeping the view's up, field of view and near plane (the scene camera's right after a reset);
    // nothing happens when the two points coincide. Not an edit, even looking through the scene camera.
    // Repaints.
    void placeView(const glm::dvec3& position, const glm::dvec3& target);

    // View ▸ Invert Vertical Orbit. By default dragging down raises the camera (the scene follows the
    // mouse, as in Blender and three.js); inverted, it lowers it. Not remembered here: the window keeps
    // the preference.
    void setInvertVerticalOrbit(bool inverted) { m_navigation.setInvertVerticalOrbit(inverted); }
    bool invertsVerticalOrbit() const { return m_navigation.invertsVerticalOrbit(); }
    // How handle drags snap (View ▸ Snap While Dragging, Snap Steps…): with Ctrl held, or without it when
    // `always` is set. Not remembered here: the window keeps the settings.
    void setSnapSettings(const SnapSettings& settings) { m_snap = settings; }
    const SnapSettings& snapSettings() const { return m_snap; }
    // View ▸ Show Guides: the ground grid, the scene camera's wireframe, the pivot and the axis gizmo,
    // painted over the frame (ViewportOverlay; remembered in QSettings there).
    void setGuidesVisible(bool visible);
    bool guidesVisible() const;
    // View ▸ Show Screen-Space Sources: each screen-space mirror's pixels in the colour of where their
    // reflection comes from (green, met in the image; blue, the reflector's map; red, the background),
    // with a legend. Not remembered: a teaching view, off when the editor starts.
    void setScreenSpaceSourcesVisible(bool visible);
    bool screenSpaceSourcesVisible() const { return m_screenSpaceSources; }

    // Adaptive resolution: while the view is navigated (orbit, pan, zoom, the wheel) or a
    // handle is dragged, frames are drawn at a reduced resolution, scaled up, chosen from the measured
    // frame time so a frame takes about previewFrameBudget() (never below a quarter of the width and
    // height), then with fewer levels of mirror nesting when that is not enough; meanwhile the environment
    // map keeps what it has and, during a handle drag, shadow maps are drawn smaller. kRestMs after the
    // last such input, one frame at full quality follows. Off: every frame at full quality.
    static constexpr int kRestMs = 250;
    static constexpr double kMinPreviewScale = view::AdaptiveResolution::kMinScale;
    void setAdaptiveResolution(bool on);
    bool adaptiveResolution() const { return m_adaptive; }
    // Milliseconds a preview frame should take until it is on screen (view::AdaptiveResolution; 40 by
    // default).
    void setPreviewFrameBudget(double milliseconds);
    double previewFrameBudget() const { return m_resolution.budget(); }
    // Whether input came within the last kRestMs (the next frame is a preview if it needs to be).
    bool isInteracting() const { return m_interacting; }
    // The last frame: a preview (reduced resolution or mirror depth)? Its level, the fraction of the
    // width and height it was drawn at (1: full), and how many device pixels were drawn.
    bool lastFrameReduced() const { return m_lastLevel.reduced(); }
    const view::PreviewLevel& lastFrameLevel() const { return m_lastLevel; }
    double lastFrameScale() const { return m_lastLevel.scale; }
    QSize lastFrameDrawnSize() const { return m_lastDrawnSize; }
    // Wall time of the last frame's drawing (paintGL up to the end of rendering), in milliseconds.
    double lastFrameMs() const { return m_lastFrameMs; }

    HandleMode handleMode() const { return m_handles.mode(); }
    void setHandleMode(HandleMode mode);
    void setLookThroughSceneCamera(bool on);

    // What a click at a widget position (logical pixels) would select: a node id, or 0.
    std::uint64_t pickAt(QPointF position, bool mirrorItself = false);
    // Where a handle axis of the current node lies on screen (for tests and benchmarks): the tip of
    // `axis` (move/scale) or a point on its ring (rotate); nothing when no handles are shown.
    std::optional<QPointF> handlePoint(int axis);
    // The point the view looks at, where new nodes are placed.
    glm::dvec3 lookAtPoint() const { return m_navigation.camera().target; }

    void paintOverlay(QPainter& painter); // called by the overlay widget

    QSize sizeHint() const override { return {960, 600}; }

public slots:
    // Back to the scene's camera after mouse navigation.
    void resetView();
    // Moves the view so the selected nodes fill it (all nodes when nothing is selected).
    void frameSelected();

    // The inspect tool: while on, a left click explains the pixel under it (pixelInspected) instead of
    // selecting; its path stays drawn in the view until cleared or the tool is turned off.
    void setInspecting(bool on);
    bool inspecting() const { return m_inspecting; }
    void clearInspection();
    // The inspected pixel's path as the view draws it (world-space lines; empty: none).
    const std::vector<render::GuideLine>& inspectedPath() const { return m_inspectionGuides; }
    // Explains the pixel at `position` (widget coordinates): renders the frame once with the pixel's
    // recipe recorded and traces the pixel, then draws its path. Used by the click and by tests.
    void inspectAt(QPointF position);
    // Draws the segment arriving at this vertex of the inspected path wider (-1: none).
    void highlightInspectedStep(int vertex);

signals:
    // The inspect tool explained a pixel: both recipes and their difference, and the frame they are of.
    void pixelInspected(const speculum::render::inspect::PixelExplanation& explanation,
                        const speculum::render::FrameInput& input);
    void inspectionFailed(const QString& message);
    // After every frame, with the renderer's report and the animation time it showed.
    void frameRendered(const speculum::render::FrameReport& report, double animationTime);
    // When the set of warnings (snapshot + renderer) differs from the previous frame's.
    void warningsChanged(const QStringList& warnings);
    void rendererFailed(const QString& message);
    void handleModeChanged(speculum::ui::HandleMode mode);
    // A new or opened document has put the view back on its scene camera (Scene::sceneReset; the
    // viewport's own connection runs first, so this comes after the reset). Connect here to put a
    // saved editor view in its place with placeView().
    void viewReset();

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
    // paintGL's steps: the preview's level, the target it draws into, the frame counter behind
    // framesPerSecond(), and the frame's warnings.
    view::PreviewLevel previewLevel(bool previewing, int mirrorDepth);
    std::vector<render::GuideLine> guideLines() const;
    render::RenderTarget frameTarget(bool composedAsStored) const;
    void countFrame();
    void reportFrameWarnings(bool composedAsStored, const std::vector<scene::Warning>& warnings);
    void updateTicking();
    void reportWarnings(QStringList warnings);
    void interacted(); // navigation or a handle drag: previews until kRestMs after the last one
    void rested();
    void frameOnScreen(); // frameSwapped: the frame's whole cost is known
    ScreenProjection projection() const;
    ViewOnScreen viewOnScreen() const; // for the handles: the view camera and the frame's time

    scene::Scene& m_scene;
    view::AnimationClock& m_clock;
    view::Selection* m_selection = nullptr;
    QUndoStack* m_undoStack = nullptr;
    scene::MeshLibrary& m_meshes; // kept across frames: the renderer keys GPU meshes on the handles
    std::unique_ptr<render::Renderer> m_renderer;
    CoarseLevelJobs* m_coarseLevels = nullptr; // big meshes' simplified levels, built off the GUI thread
    QString m_rendererError;
    bool m_skipsSrgbDecode = false; // the context has EXT_texture_sRGB_decode (initializeGL)
    ViewportNavigation m_navigation;
    ViewportHandles m_handles;
    SnapSettings m_snap;
    QTimer m_tick;                // drives repaints while the animation plays over a scene that moves
    bool m_sceneAnimated = false; // scene::sceneHasAnimation, kept up to date on every change
    ViewportOverlay* m_overlay = nullptr;
    ViewportModels* m_models = nullptr; // reads the scene's model files off the GUI thread

    render::FrameReport m_lastReport;
    double m_lastFrameTime = 0.0;
    int m_framesRendered = 0;
    QStringList m_warnings;
    QElapsedTimer m_fpsTimer;
    int m_fpsFrames = 0;
    double m_fps = 0.0;

    // Adaptive resolution.
    bool m_adaptive = true;
    bool m_screenSpaceSources = false;
    bool m_inspecting = false;
    std::vector<render::GuideLine> m_inspectionGuides; // the inspected pixel's path, drawn in every frame
    // What the path was drawn from, to redraw it with a step highlighted.
    std::optional<std::pair<render::inspect::PixelExplanation, render::FrameInput>> m_inspected;
    bool m_interacting = false;
    QTimer m_rest; // single shot: kRestMs after the last navigation or handle move
    view::AdaptiveResolution m_resolution;
    QSize m_previewSizeFor;     // the widget size m_resolution learnt at
    double m_fullFrameMs = 0.0; // the last full-quality frame until on screen, to start a gesture from
    view::PreviewLevel m_lastLevel;
    QSize m_lastDrawnSize;
    double m_lastFrameMs = 0.0;
    QElapsedTimer m_frameClock; // from the start of the last paintGL
    bool m_timingFrame = false; // the last frame's frameSwapped has not come yet
    bool m_learning = false;    // the last frame was drawn at m_resolution's level
    int m_maxDepthCut = 0;      // mirror levels of the scene beyond the first
};

} // namespace speculum::ui
