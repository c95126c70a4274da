#pragma once

#include "editor/ui/Gizmo.hpp"
#include "editor/ui/HandleDrag.hpp"

#include <QPointF>
#include <Qt>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

class QUndoStack;

namespace speculum::scene {
class MeshLibrary;
class Scene;
} // namespace speculum::scene
namespace speculum::view {
class Selection;
} // namespace speculum::view

namespace speculum::ui {

// The view as the user sees it, which the handles are hit in and clicks pick in: the view camera on the
// widget's size, and the animation time of the frame on screen.
struct ViewOnScreen {
    ScreenProjection screen;
    double time = 0.0;
};

// What is under the cursor and the handles of the viewport, with the left button's gestures on them.
//
// Picking: lights by their marker, everything else through the mirrors with scene::pick (a reflection
// picks the reflected object; asked for the mirror itself, the mirror).
//
// Handles: the move, rotate or scale handles (Gizmo) of the selection's current node, the axis the cursor
// hovers, and the left button:
//
//     None ──press on a handle──▶ Handle ──move: HandleDrag──▶ … ──release / Esc──▶ None
//       └────press elsewhere──▶ PendingClick ──release──▶ None (the click selects)
//                                    └── move beyond the slop ──▶ None (the press becomes an orbit)
//
// Ctrl+press always picks, even over a handle, to add to the selection or take out of it. A handle drag
// edits every selected node through HandleDrag (one undo step per drag; Esc leaves none).
//
// It has no widget: the viewport hands it the view on screen and repaints, or sets the cursor, when told.
// Without setEditing it only picks.
class ViewportHandles {
public:
    // `meshes` gives the document's mesh library with the scene's model files on their way (a pick asks for
    // it only when the click is on no light).
    ViewportHandles(scene::Scene& scene, std::function<scene::MeshLibrary&()> meshes);
    ~ViewportHandles();

    void setEditing(view::Selection* selection, QUndoStack* undoStack);

    HandleMode mode() const { return m_mode; }
    // False when `mode` is the mode already.
    bool setMode(HandleMode mode);
    // The selection changed: the hovered axis was another node's.
    void clearHover() { m_hoverAxis = -1; }
    // The cursor at `position` with no button held: true when the hovered axis changed.
    bool hover(QPointF position, const ViewOnScreen& view);
    int hoverAxis() const { return m_hoverAxis; }

    enum class Press { None, PendingClick, Handle };
    Press press() const { return m_press; }
    // A left press at `position`: on a handle (not with Ctrl) its drag starts, elsewhere a click may follow.
    void press(QPointF position, Qt::KeyboardModifiers modifiers, const ViewOnScreen& view);
    // Another press took over: the left button's gesture ends as it is, finishing nothing.
    void forgetPress() { m_press = Press::None; }
    QPointF pressPosition() const { return m_pressPosition; }
    // The mouse at `position` with a click pending: true (and no click any more) once it has gone beyond
    // the slop, when the press becomes a drag of the view.
    bool leavesClick(QPointF position);
    // The mouse at `position` with a handle held: the nodes follow.
    void dragHandle(QPointF position, const std::optional<SnapSteps>& snap); // Gizmo::drag
    scene::NodeId clickTarget(scene::NodeId hit, bool deeper) const;
    // A button released: a pending click selects, a handle drag ends with its undo step. False when no
    // left-button gesture was on.
    bool release(const ViewOnScreen& view);
    // Esc: a handle drag puts every node back and leaves no undo step. False when none was on.
    bool cancelHandleDrag();

    // What a click at `position` (widget pixels) would select: a node id, or 0.
    std::uint64_t pickAt(QPointF position, bool mirrorItself, const ViewOnScreen& view);
    // Where the tip of `axis` (move, scale) or a point on its ring (rotate) lies on screen; nothing when no
    // handles are shown.
    std::optional<QPointF> handlePoint(int axis, const ViewOnScreen& view);
    // The handles to paint (during a drag, as the drag began) and the axis to highlight (held or hovered,
    // -1: none); null when none are shown.
    const Gizmo* shownGizmo(const ViewOnScreen& view, int& activeAxis);

private:
    void setUpGizmo(const ViewOnScreen& view);
    bool isEditing() const { return m_selection && m_undoStack; }

    scene::Scene& m_scene;
    std::function<scene::MeshLibrary&()> m_meshes;
    view::Selection* m_selection = nullptr;
    QUndoStack* m_undoStack = nullptr;
    HandleMode m_mode = HandleMode::Move;
    Gizmo m_gizmo; // the current node's handles as the view shows them, set up before each use
    int m_hoverAxis = -1;

    Press m_press = Press::None;
    QPointF m_pressPosition;
    bool m_pressAlt = false;
    bool m_pressCtrl = false;
    std::unique_ptr<HandleDrag> m_handleDrag; // with editing on
};

} // namespace speculum::ui
