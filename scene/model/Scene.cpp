#include "scene/model/Scene.hpp"

#include "scene/model/SceneChecks.hpp"

#include <algorithm>
#include <cassert>

namespace speculum::scene {

Node* Node::child(int index) const {
    assert(index >= 0 && index < childCount() && "Node::child(): index out of range");
    return m_children[static_cast<std::size_t>(index)].get();
}

NodeTree Node::toTree() const {
    NodeTree tree{m_data, {}};
    tree.children.reserve(m_children.size());
    for (const auto& child : m_children) {
        tree.children.push_back(child->toTree());
    }
    return tree;
}

Scene::Scene(QObject* parent)
    : QObject(parent) {}

Scene::~Scene() = default;

void Scene::reset(SceneData data) {
    emit aboutToReset();
    m_byId.clear();
    m_nodes.clear();
    m_settings = std::move(data.settings);
    m_camera = std::move(data.camera);
    setEditorView(std::move(data.editorView));
    m_unknown = std::move(data.unknown);
    for (const NodeTree& tree : data.nodes) {
        auto node = createNode(tree);
        index(*node);
        m_nodes.push_back(std::move(node));
    }
    emit sceneReset();
    emit changed();
}

SceneData Scene::toData() const {
    SceneData data;
    data.settings = m_settings;
    data.camera = m_camera;
    data.editorView = m_editorView;
    data.unknown = m_unknown;
    data.nodes.reserve(m_nodes.size());
    for (const auto& node : m_nodes) {
        data.nodes.push_back(node->toTree());
    }
    return data;
}

void Scene::setProjectPath(const QString& path) {
    if (path == m_projectPath) {
        return;
    }
    m_projectPath = path;
    emit projectPathChanged(path);
}

int Scene::childCount(NodeId parent) const {
    if (parent == kNoNode) {
        return static_cast<int>(m_nodes.size());
    }
    const Node* node = findNode(parent);
    return node ? node->childCount() : 0;
}

Node* Scene::findNode(NodeId id) const {
    auto it = m_byId.find(id);
    return it == m_byId.end() ? nullptr : it->second;
}

int Scene::indexOf(NodeId id) const {
    const Node* node = findNode(id);
    if (!node) {
        return -1;
    }
    const auto& siblings = node->m_parent ? node->m_parent->m_children : m_nodes;
    auto it = std::find_if(siblings.begin(), siblings.end(), [&](const auto& n) { return n.get() == node; });
    return static_cast<int>(it - siblings.begin());
}

NodeId Scene::parentOf(NodeId id) const {
    const Node* node = findNode(id);
    return node && node->m_parent ? node->m_parent->m_id : kNoNode;
}

bool Scene::isAncestor(NodeId ancestor, NodeId id) const {
    for (const Node* node = findNode(id); node; node = node->m_parent) {
        if (node->m_id == ancestor) {
            return true;
        }
    }
    return false;
}

bool Scene::isHidden(NodeId id) const {
    for (const Node* node = findNode(id); node; node = node->m_parent) {
        if (node->data().hidden) {
            return true;
        }
    }
    return false;
}

void Scene::setSettings(const SceneSettings& settings) {
    m_settings = settings;
    emit settingsChanged();
    emit changed();
}

void Scene::setCamera(const CameraData& camera) {
    m_camera = camera;
    emit cameraChanged();
    emit changed();
}

void Scene::setEditorView(std::optional<EditorView> view) {
    if (view && editorViewProblem(*view)) {
        view.reset();
    }
    m_editorView = std::move(view);
}

void Scene::setNodeData(NodeId id, const NodeData& data) {
    Node* node = findNode(id);
    assert(node && "Scene::setNodeData(): no such node");
    if (!node) {
        return;
    }
    node->m_data = data;
    emit nodeChanged(id);
    emit changed();
}

std::unique_ptr<Node> Scene::createNode(const NodeTree& tree) {
    std::unique_ptr<Node> node(new Node(m_nextId++, tree.data));
    for (const NodeTree& childTree : tree.children) {
        auto child = createNode(childTree);
        child->m_parent = node.get();
        node->m_children.push_back(std::move(child));
    }
    return node;
}

std::vector<std::unique_ptr<Node>>& Scene::siblingsOf(NodeId parent) {
    if (parent == kNoNode) {
        return m_nodes;
    }
    Node* node = findNode(parent);
    assert(node && "Scene::siblingsOf(): no such parent");
    return node->m_children;
}

NodeId Scene::insertNode(NodeId parent, int index, std::unique_ptr<Node> node) {
    assert(node && "Scene::insertNode(): null node");
    assert(!findNode(node->m_id) && "Scene::insertNode(): node is already in the scene");
    assert((parent == kNoNode || findNode(parent)) && "Scene::insertNode(): no such parent");
    auto& siblings = siblingsOf(parent);
    const int count = static_cast<int>(siblings.size());
    if (index < 0 || index > count) {
        index = count;
    }
    const NodeId id = node->m_id;
    emit nodeAboutToBeAdded(parent, index);
    node->m_parent = parent == kNoNode ? nullptr : findNode(parent);
    this->index(*node);
    siblings.insert(siblings.begin() + index, std::move(node));
    emit nodeAdded(id, parent, index);
    emit changed();
    return id;
}

std::unique_ptr<Node> Scene::takeNode(NodeId id) {
    Node* node = findNode(id);
    assert(node && "Scene::takeNode(): no such node");
    if (!node) {
        return nullptr;
    }
    const NodeId parent = node->m_parent ? node->m_parent->m_id : kNoNode;
    const int index = indexOf(id);
    emit nodeAboutToBeRemoved(id, parent, index);
    auto& siblings = siblingsOf(parent);
    std::unique_ptr<Node> taken = std::move(siblings[static_cast<std::size_t>(index)]);
    siblings.erase(siblings.begin() + index);
    unindex(*taken);
    taken->m_parent = nullptr;
    emit nodeRemoved(id, parent, index);
    emit changed();
    return taken;
}

void Scene::index(Node& node) {
    m_byId[node.m_id] = &node;
    for (auto& child : node.m_children) {
        index(*child);
    }
}

void Scene::unindex(const Node& node) {
    m_byId.erase(node.m_id);
    for (const auto& child : node.m_children) {
        unindex(*child);
    }
}

} // namespace speculum::scene
