#pragma once

#include "editor/ui/Gizmo.hpp"
#include "scene/model/Scene.hpp"

#include <QPointF>
#include <glm/mat4x4.hpp>
#include <vector>

class QUndoStack;

namespace speculum::ui {

// A drag of a move, rotate or scale handle, apart from the widget that feeds it: it takes plain mouse
// positions (widget pixels) and the handles as set up for the view camera (Gizmo), and edits the document
// through undoable commands only.
//
//     Idle ──press──▶ Pressed ──move──▶ Dragging ──release──▶ Committed
//                       │  ▲ release       │
//                       │  └─▶ Idle        │
//                       └──── cancel ──────┴──▶ Cancelled
//
// Every mouse move pushes the nodes' new data with the drag's own merge key, so the whole drag is one undo
// step. Cancel (Esc) pushes the data they had when the drag began under the same key: the merged step then
// changes nothing and leaves the undo stack (SetNodesDataCommand::mergeWith makes it obsolete), so the
// stack's count and clean state are what they were before the press.
class HandleDrag {
public:
    enum class State { Idle, Pressed, Dragging, Committed, Cancelled };

    HandleDrag(scene::Scene& scene, QUndoStack& undoStack);

    // Starts a drag of `axis` of `gizmo` (set up on the node `lead` as drawn at animation time `time`) at
    // `position`. The drag moves `nodes` (the selection's roots); lead's handles measure it. Returns false
    // (and starts nothing) when the handles, the axis or a node is not valid. A drag under way ends first.
    bool press(const Gizmo& gizmo, int axis, QPointF position, scene::NodeId lead,
               const std::vector<scene::NodeId>& nodes, double time);
    // The mouse is at `position`: the nodes follow (Pressed becomes Dragging once the mouse has moved);
    // With `snap`, what the drag changes snaps to its steps (Gizmo::drag).
    void move(QPointF position, const std::optional<SnapSteps>& snap = std::nullopt);
    // Mouse released: the drag's step (if it changed anything) stays.
    void release();
    // Puts every node back as it was at the press, leaving no undo step.
    void cancel();

    State state() const { return m_state; }
    bool isActive() const { return m_state == State::Pressed || m_state == State::Dragging; }
    // The handles as they were when the drag began (drawn while it lasts) and the axis held.
    const Gizmo& gizmo() const { return m_gizmo; }
    int axis() const { return m_axis; }

private:
    struct DraggedNode {
        scene::NodeId id = scene::kNoNode;
        scene::NodeData start;
        glm::dmat4 parentWorld{1.0};
    };
    QString mergeKey() const;

    scene::Scene& m_scene;
    QUndoStack& m_undoStack;
    State m_state = State::Idle;
    Gizmo m_gizmo;
    int m_axis = -1;
    QPointF m_pressPosition;
    // The node the handles sit on, as it was at the press; the drag is measured on it.
    scene::NodeId m_lead = scene::kNoNode;
    scene::NodeData m_leadStart;
    glm::dmat4 m_leadParentWorld{1.0};
    std::vector<DraggedNode> m_nodes;
    int m_serial = 0; // one merge key per drag
};

} // namespace speculum::ui
