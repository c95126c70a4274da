#include "editor/ui/HandleDrag.hpp"

#include "editor/document/Commands.hpp"
#include "scene/evaluate/PickScene.hpp"

#include <QUndoStack>

namespace speculum::ui {

HandleDrag::HandleDrag(scene::Scene& scene, QUndoStack& undoStack)
    : m_scene(scene)
    , m_undoStack(undoStack) {}

QString HandleDrag::mergeKey() const {
    return QStringLiteral("handle#%1").arg(m_serial);
}

bool HandleDrag::press(const Gizmo& gizmo, int axis, QPointF position, scene::NodeId lead,
                       const std::vector<scene::NodeId>& nodes, double time) {
    release(); // a press while a drag is under way (its release was lost) ends that drag first
    const scene::Node* leadNode = m_scene.findNode(lead);
    const int lastAxis = gizmo.mode() == HandleMode::Scale ? Gizmo::kUniformAxis : 2;
    if (!gizmo.isValid() || axis < 0 || axis > lastAxis || !leadNode) {
        return false;
    }
    std::vector<DraggedNode> dragged;
    for (scene::NodeId id : nodes) {
        const scene::Node* node = m_scene.findNode(id);
        if (!node) {
            return false;
        }
        dragged.push_back({id, node->data(), scene::parentWorldMatrix(m_scene, id, time)});
    }
    ++m_serial;
    m_state = State::Pressed;
    m_gizmo = gizmo;
    m_axis = axis;
    m_pressPosition = position;
    m_lead = lead;
    m_leadStart = leadNode->data();
    m_leadParentWorld = scene::parentWorldMatrix(m_scene, lead, time);
    m_nodes = std::move(dragged);
    return true;
}

void HandleDrag::move(QPointF position, const std::optional<SnapSteps>& snap) {
    if (!isActive() || !m_scene.findNode(m_lead)) {
        return; // the lead node went away (an undo during the drag): nothing to measure on
    }
    if (m_state == State::Pressed && position == m_pressPosition) {
        return;
    }
    m_state = State::Dragging;
    const scene::NodeData lead = m_gizmo.drag(m_leadStart, m_axis, m_pressPosition, position, snap);
    std::vector<document::SetNodesDataCommand::Change> changes;
    for (const DraggedNode& dragged : m_nodes) {
        if (!m_scene.findNode(dragged.id)) {
            continue;
        }
        changes.push_back({dragged.id, dragged.id == m_lead
                                           ? lead
                                           : followDrag(m_gizmo.mode(), m_leadStart, lead, m_leadParentWorld,
                                                        dragged.start, dragged.parentWorld)});
    }
    if (changes.empty()) {
        return;
    }
    static const char* const verbs[] = {"Select", "Move", "Rotate", "Scale"};
    const QLatin1String verb(verbs[int(m_gizmo.mode())]);
    const QString text =
        changes.size() == 1
            ? QStringLiteral("%1 \u201c%2\u201d").arg(verb, QString::fromStdString(changes.front().data.name))
            : QStringLiteral("%1 %2 nodes").arg(verb).arg(changes.size());
    // A move that changes nothing (along no axis on screen) is no command at all.
    document::pushEdit(m_undoStack,
                       new document::SetNodesDataCommand(m_scene, std::move(changes), text, mergeKey()));
}

void HandleDrag::release() {
    if (!isActive()) {
        return;
    }
    m_state = m_state == State::Dragging ? State::Committed : State::Idle;
}

void HandleDrag::cancel() {
    if (!isActive()) {
        return;
    }
    std::vector<document::SetNodesDataCommand::Change> changes;
    for (const DraggedNode& dragged : m_nodes) {
        if (m_scene.findNode(dragged.id)) {
            changes.push_back({dragged.id, dragged.start});
        }
    }
    if (!changes.empty()) {
        // Merges into the drag's step and so cancels it out; pushes nothing when nothing moved.
        document::pushEdit(m_undoStack,
                           new document::SetNodesDataCommand(m_scene, std::move(changes),
                                                             QStringLiteral("Cancel drag"), mergeKey()));
    }
    m_state = State::Cancelled;
}

} // namespace speculum::ui
