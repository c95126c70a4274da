#include "editor/document/NodeFactory.hpp"

#include <QFileInfo>
#include <set>

namespace speculum::document {

namespace {

MaterialComponent material(const glm::dvec3& color, double specular = 0.3, double shininess = 32.0) {
    MaterialComponent m;
    m.color = color;
    m.specular = specular;
    m.shininess = shininess;
    return m;
}

NodeTree node(const std::string& name, const glm::dvec3& at) {
    NodeTree tree;
    tree.data.name = name;
    tree.data.transform.translate = at;
    return tree;
}

bool hasReflector(const NodeTree& tree) {
    if (tree.data.reflector) {
        return true;
    }
    for (const NodeTree& child : tree.children) {
        if (hasReflector(child)) {
            return true;
        }
    }
    return false;
}

void dropReflectors(NodeTree& tree, bool& dropped) {
    if (tree.data.reflector) {
        tree.data.reflector.reset();
        dropped = true;
    }
    for (NodeTree& child : tree.children) {
        dropReflectors(child, dropped);
    }
}

} // namespace

QString displayName(NewNodeKind kind) {
    switch (kind) {
    case NewNodeKind::Empty:
        return QStringLiteral("Empty");
    case NewNodeKind::Teapot:
        return QStringLiteral("Teapot");
    case NewNodeKind::Sphere:
        return QStringLiteral("Sphere");
    case NewNodeKind::Box:
        return QStringLiteral("Box");
    case NewNodeKind::Plane:
        return QStringLiteral("Plane");
    case NewNodeKind::Mirror:
        return QStringLiteral("Mirror");
    case NewNodeKind::ReflectorSphere:
        return QStringLiteral("Chrome sphere");
    case NewNodeKind::ReflectorTeapot:
        return QStringLiteral("Chrome teapot");
    case NewNodeKind::PointLight:
        return QStringLiteral("Point light");
    case NewNodeKind::DirectionalLight:
        return QStringLiteral("Directional light");
    case NewNodeKind::SpotLight:
        return QStringLiteral("Spot light");
    }
    return QStringLiteral("Node");
}

NodeTree makeNode(NewNodeKind kind, const glm::dvec3& at) {
    NodeTree tree = node(displayName(kind).toStdString(), at);
    NodeData& d = tree.data;
    switch (kind) {
    case NewNodeKind::Empty:
        break;
    case NewNodeKind::Teapot:
        // Newell's teapot is about 3 units tall-ish wide; a quarter of that fits next to the other shapes.
        d.transform.scale = glm::dvec3(0.25);
        d.mesh = MeshComponent::fromBuiltin(BuiltinMesh::Teapot);
        d.material = material({0.9, 0.9, 0.9}, 0.5);
        break;
    case NewNodeKind::Sphere:
        d.transform.scale = glm::dvec3(0.5);
        d.mesh = MeshComponent::fromBuiltin(BuiltinMesh::Sphere);
        d.material = material({0.8, 0.3, 0.25});
        break;
    case NewNodeKind::Box:
        d.transform.scale = glm::dvec3(0.5);
        d.mesh = MeshComponent::fromBuiltin(BuiltinMesh::Box);
        d.material = material({0.3, 0.5, 0.8});
        break;
    case NewNodeKind::Plane:
        d.transform.scale = {2.0, 1.0, 2.0};
        d.mesh = MeshComponent::fromBuiltin(BuiltinMesh::Plane);
        d.material = material({0.8, 0.8, 0.8}, 0.1, 16.0);
        break;
    case NewNodeKind::Mirror:
        d.mirror = MirrorComponent{};
        d.mirror->size = {2.0, 2.0};
        d.mirror->reflectivity = 0.9;
        break;
    case NewNodeKind::ReflectorSphere:
    case NewNodeKind::ReflectorTeapot:
        d.transform.scale = glm::dvec3(kind == NewNodeKind::ReflectorSphere ? 0.4 : 0.25);
        d.mesh = MeshComponent::fromBuiltin(kind == NewNodeKind::ReflectorSphere ? BuiltinMesh::Sphere
                                                                                 : BuiltinMesh::Teapot);
        d.material = material({0.95, 0.95, 0.95}, 1.0, 96.0);
        d.reflector = ReflectorComponent{};
        d.reflector->map = ReflectorMap::DualParaboloid;
        break;
    case NewNodeKind::PointLight:
    case NewNodeKind::DirectionalLight:
    case NewNodeKind::SpotLight:
        d.light = LightComponent{};
        d.light->type = kind == NewNodeKind::PointLight         ? LightType::Point
                        : kind == NewNodeKind::DirectionalLight ? LightType::Directional
                                                                : LightType::Spot;
        d.light->shadows = ShadowComponent{};
        d.light->shadows->pcf = 3;
        // Lights go above the point: they light it from there (directional and spot look down −Y).
        d.transform.translate = at + glm::dvec3(0.0, 2.0, 0.0);
        break;
    }
    return tree;
}

NodeTree makeModelNode(const QString& absolutePath, const glm::dvec3& at, bool asReflector) {
    const QFileInfo info(absolutePath);
    NodeTree tree = node(info.completeBaseName().toStdString(), at);
    tree.data.mesh = MeshComponent::fromFile(info.absoluteFilePath().toStdString());
    tree.data.material = material({0.8, 0.8, 0.8});
    if (asReflector) {
        tree.data.reflector = ReflectorComponent{};
        tree.data.material = material({0.95, 0.95, 0.95}, 1.0, 96.0);
    }
    return tree;
}

std::string uniqueName(const Scene& scene, const std::string& base) {
    std::set<std::string> names;
    scene.forEachNode([&](const Node& n) { names.insert(n.name()); });
    if (!names.count(base)) {
        return base;
    }
    for (int i = 2;; ++i) {
        std::string candidate = base + " " + std::to_string(i);
        if (!names.count(candidate)) {
            return candidate;
        }
    }
}

NodeId reflectorNode(const Scene& scene) {
    NodeId found = kNoNode;
    scene.forEachNode([&](const Node& n) {
        if (found == kNoNode && n.data().reflector) {
            found = n.id();
        }
    });
    return found;
}

render::Status canAdd(const Scene& scene, const NodeTree& tree) {
    if (!hasReflector(tree)) {
        return render::Done{};
    }
    if (const NodeId existing = reflectorNode(scene); existing != kNoNode) {
        return render::Error{"A scene has at most one curved reflector, and \"" +
                             scene.findNode(existing)->name() +
                             "\" already is one. Remove its reflector first, or make this a mirror."};
    }
    return render::Done{};
}

NodeTree duplicateTree(const Scene& scene, NodeId id, bool* droppedReflector) {
    const Node* n = scene.findNode(id);
    if (!n) {
        return {};
    }
    NodeTree tree = n->toTree();
    tree.data.name = uniqueName(scene, tree.data.name);
    bool dropped = false;
    dropReflectors(tree, dropped);
    if (droppedReflector) {
        *droppedReflector = dropped;
    }
    return tree;
}

} // namespace speculum::document
