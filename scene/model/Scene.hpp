#pragma once

#include "scene/model/SceneData.hpp"

#include <QObject>
#include <QString>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

namespace speculum::scene {

// Stable identity of a node for the lifetime of a Scene (undo commands, tree models). Never reused, never
// written to the file. 0 means "none" (as a parent: the scene's top level).
using NodeId = std::uint64_t;
inline constexpr NodeId kNoNode = 0;

class Scene;

class Node {
public:
    NodeId id() const { return m_id; }
    const NodeData& data() const { return m_data; }
    const std::string& name() const { return m_data.name; }
    Node* parent() const { return m_parent; }
    const std::vector<std::unique_ptr<Node>>& children() const { return m_children; }
    int childCount() const { return static_cast<int>(m_children.size()); }
    Node* child(int index) const;

    // The node and its subtree as a value (ids are not part of it).
    NodeTree toTree() const;

private:
    friend class Scene;
    explicit Node(NodeId id, NodeData data)
        : m_id(id)
        , m_data(std::move(data)) {}

    NodeId m_id;
    NodeData m_data;
    Node* m_parent = nullptr;
    std::vector<std::unique_ptr<Node>> m_children;
};

// The open document: settings, camera and a tree of nodes. Views read it and listen to its signals; only
// undoable commands (Commands.hpp) are meant to call the mutators, so every change can be undone.
class Scene : public QObject {
    Q_OBJECT

public:
    explicit Scene(QObject* parent = nullptr);
    ~Scene() override;

    // Replaces everything (used after a successful load), the editor view included, which is in place when
    // sceneReset is emitted. Fresh ids are assigned; emits aboutToReset and sceneReset. The undo stack of
    // the old document must be cleared by the caller.
    void reset(SceneData data);
    SceneData toData() const;

    // The file this document was loaded from or last saved to; empty for a new document. Paths in the model
    // are absolute, so this only picks the default folder for dialogs and the title.
    const QString& projectPath() const { return m_projectPath; }
    void setProjectPath(const QString& path);

    const SceneSettings& settings() const { return m_settings; }
    const CameraData& camera() const { return m_camera; }

    // The editor's own view, saved with the project (SceneData.hpp): reset() takes it from the data and
    // toData() gives it back, so saves and recovery files carry it. It is not part of the scene's content:
    // setting it pushes no undo step, leaves the undo stack's clean state alone (the document does not
    // become modified) and emits nothing, so that views do not redraw and the editor, which is its only
    // writer (before each save), does not hear its own change back. A view the project reader would refuse
    // (editorViewProblem(), SceneChecks.hpp: the points out of range or too close) is dropped, leaving no
    // view, so that a saved file always opens.
    const std::optional<EditorView>& editorView() const { return m_editorView; }
    void setEditorView(std::optional<EditorView> view);

    const std::vector<std::unique_ptr<Node>>& topLevelNodes() const { return m_nodes; }
    int childCount(NodeId parent) const;                 // parent = kNoNode: top level
    Node* findNode(NodeId id) const;                     // nullptr when no such node
    int indexOf(NodeId id) const;                        // position among its siblings, -1 when no such node
    NodeId parentOf(NodeId id) const;                    // kNoNode for top level (and unknown ids)
    bool isAncestor(NodeId ancestor, NodeId node) const; // true also when ancestor == node
    bool isHidden(NodeId id) const; // the node or one above it is hidden (NodeData::hidden)

    // Calls f(const Node&) for every node, parents before children, in file order.
    template <typename F>
    void forEachNode(F&& f) const {
        for (const auto& node : m_nodes) {
            visit(*node, f);
        }
    }

    // ---- mutators: call from commands ----
    void setSettings(const SceneSettings& settings);
    void setCamera(const CameraData& camera);
    void setNodeData(NodeId id, const NodeData& data);

    // Builds a detached subtree with fresh ids, ready for insertNode().
    std::unique_ptr<Node> createNode(const NodeTree& tree);
    // Inserts a detached subtree under parent (kNoNode = top level) at index (clamped; -1 = append).
    // Returns the subtree root's id.
    NodeId insertNode(NodeId parent, int index, std::unique_ptr<Node> node);
    // Detaches a subtree and hands it over (ids kept, so re-inserting it restores them).
    std::unique_ptr<Node> takeNode(NodeId id);

signals:
    void aboutToReset();
    void sceneReset();
    void projectPathChanged(const QString& path);
    void settingsChanged();
    void cameraChanged();
    void nodeChanged(speculum::scene::NodeId id);
    void nodeAboutToBeAdded(speculum::scene::NodeId parent, int index);
    void nodeAdded(speculum::scene::NodeId id, speculum::scene::NodeId parent, int index);
    void nodeAboutToBeRemoved(speculum::scene::NodeId id, speculum::scene::NodeId parent, int index);
    void nodeRemoved(speculum::scene::NodeId id, speculum::scene::NodeId parent, int index);
    // After any change of content above (not projectPathChanged): for views that simply redraw.
    void changed();

private:
    template <typename F>
    static void visit(const Node& node, F& f) {
        f(node);
        for (const auto& child : node.m_children) {
            visit(*child, f);
        }
    }
    std::vector<std::unique_ptr<Node>>& siblingsOf(NodeId parent);
    void index(Node& node);
    void unindex(const Node& node);

    SceneSettings m_settings;
    CameraData m_camera;
    std::optional<EditorView> m_editorView;
    UnknownFields m_unknown; // the file's unknown top-level, settings, camera and editor view fields
    std::vector<std::unique_ptr<Node>> m_nodes;
    QString m_projectPath;
    NodeId m_nextId = 1;
    std::unordered_map<NodeId, Node*> m_byId;
};

} // namespace speculum::scene
