#include "scene/import/ModelNodes.hpp"

#include "render/mesh/MeshRepair.hpp"
#include "scene/model/NodeMath.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <sstream>

namespace speculum::scene {
namespace detail {

void forEachPlacedPart(const ImportedModel& model, const std::function<void(int, const glm::dmat4&)>& visit) {
    struct Item {
        const ImportedNode* node;
        glm::dmat4 parent;
    };
    std::vector<Item> stack{{&model.root, glm::dmat4(1.0)}};
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        const glm::dmat4 world = item.parent * item.node->local;
        for (int part : item.node->parts) {
            if (part >= 0 && part < static_cast<int>(model.parts.size()) && model.parts[part].mesh) {
                visit(part, world);
            }
        }
        // Reversed so that children come off the stack in file order.
        for (auto it = item.node->children.rbegin(); it != item.node->children.rend(); ++it) {
            stack.push_back({&*it, world});
        }
    }
}

render::Bounds placedBounds(const ImportedModel& model) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    forEachPlacedPart(model, [&](int part, const glm::dmat4& world) {
        const render::MeshData& mesh = *model.parts[part].mesh;
        if (world == glm::dmat4(1.0)) {
            const render::Bounds b = render::computeBounds(mesh);
            lo = glm::min(lo, glm::dvec3(b.min));
            hi = glm::max(hi, glm::dvec3(b.max));
            return;
        }
        for (const glm::vec3& p : mesh.positions) {
            const glm::dvec3 q(world * glm::dvec4(glm::dvec3(p), 1.0));
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
    });
    if (lo.x > hi.x) {
        return {};
    }
    return {glm::vec3(lo), glm::vec3(hi)};
}

double shortestFloat(double value) {
    const auto narrow = static_cast<float>(value);
    if (!std::isfinite(narrow)) {
        return value;
    }
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, narrow).ptr;
    double wide = value;
    std::from_chars(text, end, wide);
    return wide;
}

glm::dvec3 shortestFloat(const glm::dvec3& value) {
    return {shortestFloat(value.x), shortestFloat(value.y), shortestFloat(value.z)};
}

bool decomposeTransform(const glm::dmat4& matrix, Transform& out) {
    out.translate = glm::dvec3(matrix[3]);
    glm::dmat3 linear(matrix);
    glm::dvec3 scale(glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2]));
    bool exact =
        scale.x > 1e-12 && scale.y > 1e-12 && scale.z > 1e-12 && std::isfinite(glm::determinant(linear));
    if (!exact) {
        out.rotate = glm::dvec3(0.0);
        out.scale = glm::dvec3(1.0);
        return false;
    }
    if (glm::determinant(linear) < 0.0) {
        scale.x = -scale.x; // a mirror: one negative scale
    }
    glm::dmat3 r(linear[0] / scale.x, linear[1] / scale.y, linear[2] / scale.z);
    // Shear leaves the columns non-orthogonal; Gram-Schmidt gives the nearest rotation we can express.
    const glm::dmat3 rtr = glm::transpose(r) * r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (std::abs(rtr[i][j] - (i == j ? 1.0 : 0.0)) > 1e-4) {
                exact = false;
            }
        }
    }
    if (!exact) {
        r[0] = glm::normalize(r[0]);
        r[1] = glm::normalize(r[1] - r[0] * glm::dot(r[0], r[1]));
        r[2] = glm::cross(r[0], r[1]);
    }
    // R = Rz(c)·Ry(b)·Rx(a): row 2 column 0 is −sin b (GLM indexes [column][row]).
    const double sinB = std::clamp(-r[0][2], -1.0, 1.0);
    double a = 0.0, b = std::asin(sinB), c = 0.0;
    if (std::abs(sinB) < 0.9999999) {
        a = std::atan2(r[1][2], r[2][2]);
        c = std::atan2(r[0][1], r[0][0]);
    } else {
        // Gimbal lock: only a ± c is defined; put it all in c.
        c = std::atan2(-r[1][0], r[1][1]);
    }
    out.rotate = glm::degrees(glm::dvec3(a, b, c));
    out.scale = scale;
    return exact;
}

} // namespace detail

base::Result<render::MeshData> flattenModel(const ImportedModel& model) {
    // Count first so that an absurd model is refused before anything big is allocated.
    std::size_t vertexCount = 0, triangleCount = 0;
    bool anyUvs = false, anyColors = false;
    detail::forEachPlacedPart(model, [&](int part, const glm::dmat4&) {
        const render::MeshData& mesh = *model.parts[part].mesh;
        vertexCount += mesh.vertexCount();
        triangleCount += mesh.triangleCount();
        anyUvs |= !mesh.uvs.empty();
        anyColors |= !mesh.colors.empty();
    });
    if (triangleCount == 0) {
        return base::Error{"the model contains no triangles"};
    }
    if (triangleCount > render::kMaxMeshTriangles ||
        vertexCount > std::numeric_limits<std::uint32_t>::max()) {
        std::ostringstream out;
        out << "the model is too large (" << triangleCount << " triangles, " << vertexCount
            << " vertices placed; the limit is " << render::kMaxMeshTriangles << " triangles)";
        return base::Error{out.str()};
    }

    render::MeshData out;
    out.positions.reserve(vertexCount);
    out.normals.reserve(vertexCount);
    if (anyUvs) {
        out.uvs.reserve(vertexCount);
    }
    if (anyColors) {
        out.colors.reserve(vertexCount);
    }
    out.indices.reserve(triangleCount * 3);
    detail::forEachPlacedPart(model, [&](int part, const glm::dmat4& world) {
        const render::MeshData& mesh = *model.parts[part].mesh;
        const glm::dmat3 linear(world);
        const double determinant = glm::determinant(linear);
        // Normals transform by the inverse transpose; a singular transform has none (repair rebuilds them).
        const bool invertible = std::isfinite(determinant) && std::abs(determinant) > 1e-300;
        const glm::dmat3 normalMatrix = invertible ? glm::inverseTranspose(linear) : glm::dmat3(0.0);
        // A mirroring transform turns counter-clockwise triangles clockwise; swap two corners to undo it.
        const bool mirrored = determinant < 0.0;
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            out.positions.emplace_back(world * glm::dvec4(glm::dvec3(mesh.positions[v]), 1.0));
            out.normals.emplace_back(normalMatrix * glm::dvec3(mesh.normals[v])); // repair normalises
            if (anyUvs) {
                out.uvs.push_back(mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[v]);
            }
            if (anyColors) {
                out.colors.push_back(mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[v]);
            }
        }
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            out.indices.insert(out.indices.end(),
                               {base + mesh.indices[t], base + mesh.indices[t + (mirrored ? 2 : 1)],
                                base + mesh.indices[t + (mirrored ? 1 : 2)]});
        }
    });
    // The parts are repaired already; this only catches what the node transforms broke (a zero scale).
    render::RepairReport report;
    return render::repairMesh(std::move(out), report);
}

namespace {

void appendContents(const ImportedModel& model, const ImportedNode& node, const std::string& path,
                    NodeTree& tree, std::vector<std::string>* notes);
void appendParts(const ImportedModel& model, const ImportedNode& node, const std::string& path,
                 NodeTree& tree);

NodeTree convertNode(const ImportedModel& model, const ImportedNode& node, const std::string& path,
                     std::vector<std::string>* notes) {
    // Assimp's FBX pivot helpers ("Box_$AssimpFbx$_Translation" → ... → "Box") and empty identity nodes
    // with a single child fold into that child.
    const ImportedNode* current = &node;
    glm::dmat4 local = node.local;
    while (current->parts.empty() && current->children.size() == 1 &&
           (current->name.find("$AssimpFbx$") != std::string::npos || current->local == glm::dmat4(1.0))) {
        current = &current->children.front();
        local = local * current->local;
    }
    NodeTree tree;
    tree.data.name = current->name.empty() ? std::string("node") : current->name;
    if (!detail::decomposeTransform(local, tree.data.transform) && notes != nullptr) {
        notes->push_back("node '" + tree.data.name + "' has a shear or singular transform; approximated");
    }
    Transform& t = tree.data.transform;
    t.translate = detail::shortestFloat(t.translate);
    t.rotate = detail::shortestFloat(t.rotate);
    t.scale = detail::shortestFloat(t.scale);
    appendContents(model, *current, path, tree, notes);
    return tree;
}

// A node that draws one part draws it itself (mesh {file, part} and the part's material); a node with
// several parts gets one child per part. Then the child nodes that draw something.
void appendContents(const ImportedModel& model, const ImportedNode& node, const std::string& path,
                    NodeTree& tree, std::vector<std::string>* notes) {
    const auto valid = [&](int part) {
        return part >= 0 && part < static_cast<int>(model.parts.size()) && model.parts[part].mesh;
    };
    if (node.parts.size() == 1 && valid(node.parts.front()) && !tree.data.mesh) {
        const int part = node.parts.front();
        const ImportedPart& p = model.parts[part];
        tree.data.mesh = MeshComponent::fromFile(path);
        tree.data.mesh->part = part;
        if (p.material >= 0 && p.material < static_cast<int>(model.materials.size())) {
            tree.data.material = model.materials[p.material];
        }
    } else {
        appendParts(model, node, path, tree);
    }
    for (const ImportedNode& child : node.children) {
        NodeTree converted = convertNode(model, child, path, notes);
        // Nodes that draw nothing (FBX cameras and lights, empty groups) are left out.
        if (converted.children.empty() && !converted.data.mesh) {
            continue;
        }
        tree.children.push_back(std::move(converted));
    }
}

void appendParts(const ImportedModel& model, const ImportedNode& node, const std::string& path,
                 NodeTree& tree) {
    for (int part : node.parts) {
        if (part < 0 || part >= static_cast<int>(model.parts.size()) || !model.parts[part].mesh) {
            continue;
        }
        const ImportedPart& p = model.parts[part];
        NodeTree child;
        child.data.name = !p.name.empty() ? p.name : "part " + std::to_string(part);
        child.data.mesh = MeshComponent::fromFile(path);
        child.data.mesh->part = part;
        if (p.material >= 0 && p.material < static_cast<int>(model.materials.size())) {
            child.data.material = model.materials[p.material];
        }
        tree.children.push_back(std::move(child));
    }
}

} // namespace

NodeTree modelNodeTree(const ImportedModel& model, const std::string& path, const std::string& rootName,
                       std::vector<std::string>* warnings) {
    // speculum's root carries the unit scale only; the file's root node (glTF makes a file's only node
    // the root, with its name and transform) becomes a child unless it is an unnamed identity group.
    NodeTree root;
    root.data.name = rootName;
    const double unit = model.unitScale > 0.0 && std::isfinite(model.unitScale) ? model.unitScale : 1.0;
    root.data.transform.scale = glm::dvec3(unit);
    ImportedNode fileRoot = model.root;
    fileRoot.local = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / unit)) * model.root.local;
    const bool generic = fileRoot.name.empty() || fileRoot.name == "RootNode" || fileRoot.name == "Scene" ||
                         fileRoot.name == "<glTF root>";
    if (generic && fileRoot.local == glm::dmat4(1.0)) {
        appendContents(model, fileRoot, path, root, warnings);
    } else {
        NodeTree child = convertNode(model, fileRoot, path, warnings);
        if (!child.children.empty() || child.data.mesh) {
            root.children.push_back(std::move(child));
        }
    }
    return root;
}

} // namespace speculum::scene
