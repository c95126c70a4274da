#include "editor/document/Commands.hpp"

#include <QUndoStack>
#include <QtGlobal>
#include <cassert>

namespace speculum::document {

namespace {

// QUndoCommand::id() values; any distinct non-negative numbers.
enum CommandId { SetNodeDataId = 1001, SetSettingsId, SetCameraId, SetNodesDataId };

QString quoted(const std::string& name) {
    return QStringLiteral("\u201c%1\u201d").arg(QString::fromStdString(name));
}

// A command made for (or run on) a node that is not in the scene is a programmer error: the undo stack and
// the scene went out of step. Continuing would corrupt the document, so stop loudly.
const scene::Node& requireNode(const scene::Scene& scene, scene::NodeId id, const char* where) {
    const scene::Node* node = scene.findNode(id);
    if (!node) {
        qFatal("%s", where);
    }
    return *node;
}

} // namespace

bool pushEdit(QUndoStack& stack, QUndoCommand* command) {
    assert(command && "pushEdit(): no command");
    if (command->isObsolete()) {
        delete command; // changes nothing: no step, and the redo steps and the clean state stay
        return false;
    }
    stack.push(command);
    return true;
}

// ---- SetNodesDataCommand ----

SetNodesDataCommand::SetNodesDataCommand(scene::Scene& scene, std::vector<Change> changes,
                                         const QString& text, const QString& mergeKey, QUndoCommand* parent)
    : QUndoCommand(parent)
    , m_scene(scene)
    , m_mergeKey(mergeKey) {
    m_nodes.reserve(changes.size());
    m_before.reserve(changes.size());
    m_after.reserve(changes.size());
    for (Change& change : changes) {
        m_nodes.push_back(change.id);
        m_before.push_back(
            requireNode(scene, change.id, "SetNodesDataCommand::SetNodesDataCommand(): no such node").data());
        m_after.push_back(std::move(change.data));
    }
    if (!text.isEmpty()) {
        setText(text);
    } else if (m_before.size() == 1) {
        setText(QStringLiteral("Edit %1").arg(quoted(m_before.front().name)));
    } else {
        setText(QStringLiteral("Edit %1 nodes").arg(m_before.size()));
    }
    setObsolete(m_after == m_before);
}

void SetNodesDataCommand::undo() {
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        m_scene.setNodeData(m_nodes[i], m_before[i]);
    }
}

void SetNodesDataCommand::redo() {
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        m_scene.setNodeData(m_nodes[i], m_after[i]);
    }
}

int SetNodesDataCommand::id() const {
    return m_mergeKey.isEmpty() ? -1 : SetNodesDataId;
}

bool SetNodesDataCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetNodesDataCommand*>(other);
    if (!next || next->m_nodes != m_nodes || next->m_mergeKey != m_mergeKey || m_mergeKey.isEmpty()) {
        return false;
    }
    m_after = next->m_after;
    // Back where it started (a drag that returned, or was cancelled): the step changes nothing.
    setObsolete(m_after == m_before);
    return true;
}

// ---- SetNodeDataCommand ----

SetNodeDataCommand::SetNodeDataCommand(scene::Scene& scene, scene::NodeId id, scene::NodeData data,
                                       const QString& text, const QString& mergeKey, QUndoCommand* parent)
    : SetNodesDataCommand(scene, {{id, std::move(data)}}, text, mergeKey, parent) {}

int SetNodeDataCommand::id() const {
    return SetNodesDataCommand::id() == -1 ? -1 : SetNodeDataId;
}

// ---- RenameNodeCommand ----

RenameNodeCommand::RenameNodeCommand(scene::Scene& scene, scene::NodeId id, std::string name,
                                     QUndoCommand* parent)
    : QUndoCommand(parent)
    , m_scene(scene)
    , m_node(id)
    , m_before(requireNode(scene, id, "RenameNodeCommand::RenameNodeCommand(): no such node").name())
    , m_after(std::move(name)) {
    setText(QStringLiteral("Rename %1 to %2").arg(quoted(m_before), quoted(m_after)));
    setObsolete(m_after == m_before);
}

void RenameNodeCommand::undo() {
    scene::NodeData data = requireNode(m_scene, m_node, "RenameNodeCommand::undo(): no such node").data();
    data.name = m_before;
    m_scene.setNodeData(m_node, data);
}

void RenameNodeCommand::redo() {
    scene::NodeData data = requireNode(m_scene, m_node, "RenameNodeCommand::redo(): no such node").data();
    data.name = m_after;
    m_scene.setNodeData(m_node, data);
}

// ---- AddNodeCommand ----

AddNodeCommand::AddNodeCommand(scene::Scene& scene, scene::NodeTree tree, scene::NodeId parent, int index,
                               QUndoCommand* parent_)
    : QUndoCommand(parent_)
    , m_scene(scene)
    , m_tree(std::move(tree))
    , m_parent(parent)
    , m_index(index) {
    setText(QStringLiteral("Add %1").arg(quoted(m_tree.data.name)));
}

void AddNodeCommand::redo() {
    if (!m_detached) {
        // First run: build the nodes (this is where their ids are assigned, once).
        m_detached = m_scene.createNode(m_tree);
    }
    m_node = m_scene.insertNode(m_parent, m_index, std::move(m_detached));
}

void AddNodeCommand::undo() {
    m_detached = m_scene.takeNode(m_node);
}

// ---- RemoveNodeCommand ----

RemoveNodeCommand::RemoveNodeCommand(scene::Scene& scene, scene::NodeId id, QUndoCommand* parent)
    : QUndoCommand(parent)
    , m_scene(scene)
    , m_node(id) {
    setText(QStringLiteral("Delete %1")
                .arg(quoted(
                    requireNode(scene, id, "RemoveNodeCommand::RemoveNodeCommand(): no such node").name())));
}

void RemoveNodeCommand::redo() {
    m_parent = m_scene.parentOf(m_node);
    m_index = m_scene.indexOf(m_node);
    m_detached = m_scene.takeNode(m_node);
}

void RemoveNodeCommand::undo() {
    m_scene.insertNode(m_parent, m_index, std::move(m_detached));
}

// ---- MoveNodeCommand ----

MoveNodeCommand::MoveNodeCommand(scene::Scene& scene, scene::NodeId id, scene::NodeId newParent, int newIndex,
                                 QUndoCommand* parent)
    : QUndoCommand(parent)
    , m_scene(scene)
    , m_node(id)
    , m_oldParent(scene.parentOf(id))
    , m_oldIndex(scene.indexOf(id))
    , m_newParent(newParent)
    , m_newIndex(newIndex) {
    assert(!scene.isAncestor(id, newParent) &&
           "MoveNodeCommand::MoveNodeCommand(): cannot move a node into its own subtree");
    setText(QStringLiteral("Move %1").arg(
        quoted(requireNode(scene, id, "MoveNodeCommand::MoveNodeCommand(): no such node").name())));
    setObsolete(movesNothing());
}

bool MoveNodeCommand::movesNothing() const {
    if (m_newParent != m_oldParent) {
        return false;
    }
    // Where insertNode() would put it once taken out: the index clamped to the siblings left, -1 = last.
    const int siblings = m_scene.childCount(m_newParent) - 1;
    const int landing = m_newIndex < 0 || m_newIndex > siblings ? siblings : m_newIndex;
    return landing == m_oldIndex;
}

void MoveNodeCommand::move(scene::NodeId parent, int index) {
    m_scene.insertNode(parent, index, m_scene.takeNode(m_node));
}

void MoveNodeCommand::redo() {
    move(m_newParent, m_newIndex);
}
void MoveNodeCommand::undo() {
    move(m_oldParent, m_oldIndex);
}

// ---- SetSettingsCommand ----

SetSettingsCommand::SetSettingsCommand(scene::Scene& scene, scene::SceneSettings settings, bool mergeable,
                                       QUndoCommand* parent)
    : QUndoCommand(parent)
    , m_scene(scene)
    , m_before(scene.settings())
    , m_after(std::move(settings))
    , m_mergeable(mergeable) {
    setText(QStringLiteral("Change scene settings"));
    setObsolete(m_after == m_before);
}

void SetSettingsCommand::undo() {
    m_scene.setSettings(m_before);
}
void SetSettingsCommand::redo() {
    m_scene.setSettings(m_after);
}
int SetSettingsCommand::id() const {
    return m_mergeable ? SetSettingsId : -1;
}

bool SetSettingsCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetSettingsCommand*>(other);
    if (!next || !next->m_mergeable || !m_mergeable || next->m_mergeKey != m_mergeKey) {
        return false;
    }
    m_after = next->m_after;
    setObsolete(m_after == m_before); // a slider dragged back to where it started
    return true;
}

// ---- SetCameraCommand ----

SetCameraCommand::SetCameraCommand(scene::Scene& scene, scene::CameraData camera, bool mergeable,
                                   QUndoCommand* parent)
    : QUndoCommand(parent)
    , m_scene(scene)
    , m_before(scene.camera())
    , m_after(std::move(camera))
    , m_mergeable(mergeable) {
    setText(QStringLiteral("Move camera"));
    setObsolete(m_after == m_before);
}

void SetCameraCommand::undo() {
    m_scene.setCamera(m_before);
}
void SetCameraCommand::redo() {
    m_scene.setCamera(m_after);
}
int SetCameraCommand::id() const {
    return m_mergeable ? SetCameraId : -1;
}

bool SetCameraCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetCameraCommand*>(other);
    if (!next || !next->m_mergeable || !m_mergeable || next->m_mergeKey != m_mergeKey) {
        return false;
    }
    m_after = next->m_after;
    setObsolete(m_after == m_before); // an orbit back to where it started
    return true;
}

} // namespace speculum::document
