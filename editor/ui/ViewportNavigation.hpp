#pragma once

#include "editor/view/ViewCamera.hpp"
#include "render/frame/FrameInput.hpp"

#include <QPoint>
#include <QSize>
#include <utility>

class QUndoStack;

namespace speculum::scene {
class MeshLibrary;
class Scene;
} // namespace speculum::scene
namespace speculum::view {
class Selection;
} // namespace speculum::view

namespace speculum::ui {

// How the viewport's view moves: the view's own free camera (view::ViewCamera), put back on the scene
// camera, on a preset, on a saved view or around the selection (Frame Selection), and moved by the mouse
// (orbit and pan by how far it went since the last move, zoom by wheel notches).
//
// Looking through the scene camera, every move is also an edit of the document's camera: a
// SetCameraCommand pushed on the undo stack, merged by gesture (beginGesture: each mouse press starts one,
// a preset is one of its own) so that a drag is one undo step. Placing the view (a saved editor view) and
// putting it back on the scene camera are never edits.
//
// It has no widget: the viewport hands it the widget's size where a move depends on it, and repaints after
// each call that moves the view.
class ViewportNavigation {
public:
    explicit ViewportNavigation(scene::Scene& scene);

    // With an undo stack, looking through the scene camera edits it; without one, it only views.
    void setUndoStack(QUndoStack* undoStack) { m_undoStack = undoStack; }

    const render::Camera& camera() const { return m_view.camera(); }
    // Where the view looks from and at (scene::EditorView).
    std::pair<glm::dvec3, glm::dvec3> positionTarget() const;
    void setInvertVerticalOrbit(bool inverted) { m_view.setInvertedVertical(inverted); }
    bool invertsVerticalOrbit() const { return m_view.invertedVertical(); }
    // Turning it on puts the view on the scene camera.
    void setLookThroughSceneCamera(bool on);

    // Back on the scene camera: its position, target, up, field of view and planes. Not an edit.
    void reset();
    // At `position` looking at `target`, keeping the view's up, field of view and near plane (nothing
    // happens when the two points coincide). Not an edit.
    void place(const glm::dvec3& position, const glm::dvec3& target);
    // To `camera`'s position, target and up (a view preset): an edit step of its own when looking through
    // the scene camera.
    void setCamera(const render::Camera& camera);
    // Fits the selected nodes (every node when nothing is selected) into a view of `size` at animation time
    // `time`; false, and the view as it was, when there is nothing to frame.
    bool frameSelected(const view::Selection* selection, scene::MeshLibrary& meshes, double time, QSize size);

    // A mouse press: the scene camera's edits from here on are a new undo step.
    void beginGesture() { ++m_gestureSerial; }
    // Mouse drags of the view: the first position, then each new one; endDrag says whether one was on.
    enum class Drag { None, Orbit, Pan };
    void beginDrag(Drag drag, QPoint position);
    bool isDragging() const { return m_drag != Drag::None; }
    // Orbits (the scene follows the mouse unless the vertical orbit is inverted) or pans by the move since
    // the last position, measured against `widgetHeight`.
    void dragTo(QPoint position, int widgetHeight);
    bool endDrag();
    // The wheel: each notch (120 units of angle delta) 15% closer, or farther when negative.
    void zoom(double notches);
    // The keypad's steps: an orbit (view::ViewCamera::orbit) or a zoom, each an edit step of its own when
    // looking through the scene camera (a wheel's notches merge into the gesture under way).
    void orbitStep(double yawDegrees, double pitchDegrees);
    void zoomStep(double notches);

private:
    void moved(); // after every edit-worthy move: the scene camera's edit when looking through it

    scene::Scene& m_scene;
    QUndoStack* m_undoStack = nullptr;
    view::ViewCamera m_view;
    bool m_looksThroughSceneCamera = false;
    int m_gestureSerial = 0; // the merge key of the scene camera's edits
    Drag m_drag = Drag::None;
    QPoint m_lastMouse;
};

} // namespace speculum::ui
