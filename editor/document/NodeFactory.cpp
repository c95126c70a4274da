#include "editor/document/NodeFactory.hpp"

#include "scene/evaluate/PickScene.hpp"
#include "scene/evaluate/Picking.hpp"

#include <QFileInfo>
#include <algorithm>
#include <cmath>
#include <set>

namespace speculum::document {

namespace {

scene::MaterialComponent material(const glm::dvec3& color, double specular = 0.3, double shininess = 32.0) {
    scene::MaterialComponent m;
    m.color = color;
    m.specular = specular;
    m.shininess = shininess;
    return m;
}

scene::NodeTree node(const std::string& name, const glm::dvec3& at) {
    scene::NodeTree tree;
    tree.data.name = name;
    tree.data.transform.translate = at;
    return tree;
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

scene::NodeTree makeNode(NewNodeKind kind, const glm::dvec3& at) {
    scene::NodeTree tree = node(displayName(kind).toStdString(), at);
    scene::NodeData& d = tree.data;
    switch (kind) {
    case NewNodeKind::Empty:
        break;
    case NewNodeKind::Teapot:
        // Newell's teapot is about 3 units tall-ish wide; a quarter of that fits next to the other shapes.
        d.transform.scale = glm::dvec3(0.25);
        d.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Teapot);
        d.material = material({0.9, 0.9, 0.9}, 0.5);
        break;
    case NewNodeKind::Sphere:
        d.transform.scale = glm::dvec3(0.5);
        d.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere);
        d.material = material({0.8, 0.3, 0.25});
        break;
    case NewNodeKind::Box:
        d.transform.scale = glm::dvec3(0.5);
        d.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Box);
        d.material = material({0.3, 0.5, 0.8});
        break;
    case NewNodeKind::Plane:
        d.transform.scale = {2.0, 1.0, 2.0};
        d.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Plane);
        d.material = material({0.8, 0.8, 0.8}, 0.1, 16.0);
        break;
    case NewNodeKind::Mirror:
        d.mirror = scene::MirrorComponent{};
        d.mirror->size = {2.0, 2.0};
        d.mirror->reflectivity = 0.9;
        break;
    case NewNodeKind::ReflectorSphere:
    case NewNodeKind::ReflectorTeapot:
        d.transform.scale = glm::dvec3(kind == NewNodeKind::ReflectorSphere ? 0.4 : 0.25);
        d.mesh = scene::MeshComponent::fromBuiltin(
            kind == NewNodeKind::ReflectorSphere ? scene::BuiltinMesh::Sphere : scene::BuiltinMesh::Teapot);
        d.material = material({0.95, 0.95, 0.95}, 1.0, 96.0);
        d.reflector = scene::ReflectorComponent{};
        d.reflector->map = scene::ReflectorMap::DualParaboloid;
        break;
    case NewNodeKind::PointLight:
    case NewNodeKind::DirectionalLight:
    case NewNodeKind::SpotLight:
        d.light = scene::LightComponent{};
        d.light->type = kind == NewNodeKind::PointLight         ? scene::LightType::Point
                        : kind == NewNodeKind::DirectionalLight ? scene::LightType::Directional
                                                                : scene::LightType::Spot;
        d.light->shadows = scene::ShadowComponent{};
        d.light->shadows->pcf = 3;
        // Lights go above the point: they light it from there (directional and spot look down −Y).
        d.transform.translate = at + glm::dvec3(0.0, 2.0, 0.0);
        break;
    }
    return tree;
}

scene::NodeTree makeModelNode(const QString& absolutePath, const glm::dvec3& at, bool asReflector) {
    const QFileInfo info(absolutePath);
    scene::NodeTree tree = node(info.completeBaseName().toStdString(), at);
    tree.data.mesh = scene::MeshComponent::fromFile(info.absoluteFilePath().toStdString());
    tree.data.material = material({0.8, 0.8, 0.8});
    if (asReflector) {
        tree.data.reflector = scene::ReflectorComponent{};
        tree.data.material = material({0.95, 0.95, 0.95}, 1.0, 96.0);
    }
    return tree;
}

glm::dvec3 placeOnGround(const render::math::Box& model, const glm::dvec3& focus,
                         const std::vector<render::math::Box>& occupied) {
    if (model.empty()) {
        return focus;
    }
    const glm::dvec3 size = model.max - model.min;
    const double scale = std::max({size.x, size.y, size.z, 1e-9});
    const double eps = 1e-6 * scale;
    // The ground: the top of the highest flat thing (a floor, a table top, a floor mirror) under the focus
    // and not above it; y = 0 when there is none.
    double ground = 0.0;
    bool onSupport = false;
    for (const auto& other : occupied) {
        if (other.empty()) {
            continue;
        }
        const glm::dvec3 e = other.max - other.min;
        const bool flat = e.y <= 0.1 * std::max(e.x, e.z);
        const bool under = focus.x >= other.min.x && focus.x <= other.max.x && focus.z >= other.min.z &&
                           focus.z <= other.max.z && other.max.y <= focus.y + eps;
        if (flat && under && (!onSupport || other.max.y > ground)) {
            ground = other.max.y;
            onSupport = true;
        }
    }
    glm::dvec3 offset(focus.x - model.center().x, ground - model.min.y, focus.z - model.center().z);
    // A tenth of the model's width between it and its neighbour.
    const double gap = std::max(0.1 * size.x, 0.01 * scale);
    auto overlaps = [&](const render::math::Box& other, const glm::dvec3& at) {
        for (int i = 0; i < 3; ++i) {
            if (!(model.min[i] + at[i] < other.max[i] - eps && other.min[i] < model.max[i] + at[i] - eps)) {
                return false;
            }
        }
        return true;
    };
    // Each step moves past the box in the way, so this ends after at most one step per box.
    for (std::size_t step = 0; step <= occupied.size(); ++step) {
        const render::math::Box* blocking = nullptr;
        for (const auto& other : occupied) {
            if (other.empty() || other.max.y <= ground + eps) {
                continue; // the ground itself, or something lying on it flat
            }
            if (overlaps(other, offset) && (!blocking || other.max.x > blocking->max.x)) {
                blocking = &other;
            }
        }
        if (!blocking) {
            break;
        }
        offset.x = blocking->max.x + gap - model.min.x;
    }
    return offset;
}

std::vector<render::math::Box> occupiedBoxes(const scene::Scene& scene, double timeSeconds,
                                             scene::MeshLibrary& meshes) {
    std::vector<render::math::Box> boxes;
    const auto worlds = scene::worldMatrices(scene, timeSeconds);
    std::vector<scene::Warning> ignored; // the viewport reports load problems already
    scene.forEachNode([&](const scene::Node& node) {
        const scene::NodeData& d = node.data();
        const auto it = worlds.find(node.id());
        if (it == worlds.end()) {
            return;
        }
        if (d.mesh) {
            if (auto mesh = meshes.get(*d.mesh, ignored); mesh && *mesh) {
                boxes.push_back(render::math::worldBounds(scene::meshBounds(*mesh), it->second));
            }
        }
        if (d.mirror) {
            const glm::vec2 h = glm::vec2(d.mirror->size * 0.5);
            boxes.push_back(
                render::math::worldBounds(render::Bounds{{-h.x, 0.0f, -h.y}, {h.x, 0.0f, h.y}}, it->second));
        }
    });
    return boxes;
}

void scaleAboutParentOrigin(scene::NodeData& node, double factor) {
    node.transform.translate *= factor;
    node.transform.scale *= factor;
}

std::string uniqueName(const scene::Scene& scene, const std::string& base) {
    std::set<std::string> names;
    scene.forEachNode([&](const scene::Node& n) { names.insert(n.name()); });
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

scene::NodeTree duplicateTree(const scene::Scene& scene, scene::NodeId id) {
    const scene::Node* n = scene.findNode(id);
    if (!n) {
        return {};
    }
    scene::NodeTree tree = n->toTree();
    tree.data.name = uniqueName(scene, tree.data.name);
    return tree;
}

} // namespace speculum::document
