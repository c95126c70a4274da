#include "scene/evaluate/Snapshot.hpp"

#include "scene/import/ModelNodes.hpp"
#include "scene/model/NodeMath.hpp"

#include <QDir>
#include <QFileInfo>
#include <cmath>
#include <glm/geometric.hpp>

namespace speculum::scene {

namespace {

class SnapshotBuilder {
public:
    SnapshotBuilder(const Scene& scene, double time, MeshLibrary& meshes, std::vector<Warning>& warnings)
        : m_projectDir(QFileInfo(scene.projectPath()).absoluteDir())
        , m_hasProject(!scene.projectPath().isEmpty())
        , m_time(time)
        , m_meshes(meshes)
        , m_warnings(warnings) {}

    void visit(const Node& node, const glm::dmat4& parentWorld, render::FrameInput& frame) {
        const NodeData& d = node.data();
        if (d.hidden) {
            return; // with everything under it
        }
        const glm::dmat4 world = parentWorld * animatedLocalMatrix(d, m_time);
        render::Material material = d.material ? resolved(*d.material) : render::Material{};

        render::MeshHandle mesh;
        // A whole model file on a plain node without a material of its own draws every part with the
        // file's own material, where the file's node tree places it (a material on the node overrides
        // them all, and mirrors and reflectors need the one flattened surface).
        if (d.mesh && !d.mesh->builtin && !d.mesh->part && !d.material && !d.reflector && !d.mirror) {
            addModelParts(d, world, frame);
        } else if (d.mesh) {
            MeshComponent source = *d.mesh;
            source.file = absolute(source.file);
            base::Result<render::MeshHandle> loaded = m_meshes.get(source, m_warnings);
            if (loaded) {
                mesh = *loaded;
            } else {
                m_warnings.push_back(meshSkipped(d.name, source.file, loaded.error()));
            }
        }

        if (d.reflector) {
            addReflector(d, world, mesh, material, frame);
        } else if (mesh) {
            frame.items.push_back(render::DrawItem{d.name, world, mesh, material, true});
        }
        if (d.light) {
            frame.lights.push_back(light(d, world));
        }
        if (d.mirror) {
            render::Mirror mirror;
            static_cast<render::MirrorParams&>(mirror) = *d.mirror;
            mirror.name = d.name;
            mirror.world = world;
            mirror.hasMaterial = d.material.has_value();
            mirror.material = material;
            frame.mirrors.push_back(std::move(mirror));
        }
        for (const auto& child : node.children()) {
            visit(*child, world, frame);
        }
    }

private:
    // The render material with its paths made absolute and embedded textures decoded.
    render::Material resolved(const MaterialComponent& component) {
        render::Material material = component;
        for (render::TextureSource* source :
             {&material.texture, &material.emissionTexture, &material.normalTexture}) {
            if (source->path.empty()) {
                continue;
            }
            source->path = absolute(source->path);
            source->image = m_meshes.embeddedTexture(source->path, m_warnings);
        }
        return material;
    }

    void addModelParts(const NodeData& d, const glm::dmat4& world, render::FrameInput& frame) {
        const std::string file = absolute(d.mesh->file);
        const auto model = m_meshes.model(file, m_warnings);
        if (!model) {
            m_warnings.push_back(meshSkipped(d.name, file, model.error()));
            return;
        }
        const ImportedModel& m = **model;
        detail::forEachPlacedPart(m, [&](int index, const glm::dmat4& placement) {
            const ImportedPart& part = m.parts[static_cast<std::size_t>(index)];
            if (!part.mesh) {
                return;
            }
            const bool hasMaterial =
                part.material >= 0 && part.material < static_cast<int>(m.materials.size());
            render::Material material = hasMaterial
                                            ? resolved(m.materials[static_cast<std::size_t>(part.material)])
                                            : render::Material{};
            const std::string name =
                d.name + "/" + (part.name.empty() ? "part " + std::to_string(index) : part.name);
            frame.items.push_back(render::DrawItem{name, world * placement, part.mesh, material, true});
        });
    }

    // The model holds absolute paths (the reader resolves them); a relative one set by code is taken relative
    // to the project file, as in the file format.
    std::string absolute(const std::string& path) const {
        if (path.empty() || !m_hasProject || !QDir::isRelativePath(QString::fromStdString(path))) {
            return path;
        }
        return QDir::cleanPath(m_projectDir.absoluteFilePath(QString::fromStdString(path))).toStdString();
    }

    void addReflector(const NodeData& d, const glm::dmat4& world, const render::MeshHandle& mesh,
                      const render::Material& material, render::FrameInput& frame) {
        if (!mesh) {
            // With the node's model file: when that failed to load, the editor puts the file's reason
            // instead.
            m_warnings.push_back(
                reflectorWithoutMesh(d.name, d.mesh ? absolute(d.mesh->file) : std::string()));
            return;
        }
        render::Reflector r;
        static_cast<render::ReflectorParams&>(r) = *d.reflector;
        r.name = d.name;
        r.world = world;
        r.mesh = mesh;
        r.material = material;
        frame.reflectors.push_back(std::move(r));
    }

    static render::Light light(const NodeData& d, const glm::dmat4& world) {
        render::Light out;
        static_cast<render::LightParams&>(out) = *d.light;
        out.name = d.name;
        out.position = glm::dvec3(world[3]);
        // Directions transform with the linear part; normalise away any scale. A degenerate matrix keeps −Y.
        const glm::dvec3 down = glm::dvec3(world * glm::dvec4(0.0, -1.0, 0.0, 0.0));
        const double length = glm::length(down);
        out.direction = length > 0.0 && std::isfinite(length) ? down / length : glm::dvec3(0.0, -1.0, 0.0);
        return out;
    }

    QDir m_projectDir;
    bool m_hasProject;
    double m_time;
    MeshLibrary& m_meshes;
    std::vector<Warning>& m_warnings;
};

} // namespace

render::FrameInput snapshot(const Scene& scene, double timeSeconds, MeshLibrary& meshes,
                            std::vector<Warning>& warnings) {
    render::FrameInput frame;
    frame.settings = scene.settings();
    frame.camera = scene.camera();
    frame.time = timeSeconds;
    SnapshotBuilder builder(scene, timeSeconds, meshes, warnings);
    for (const auto& node : scene.topLevelNodes()) {
        builder.visit(*node, glm::dmat4(1.0), frame);
    }
    return frame;
}

} // namespace speculum::scene
