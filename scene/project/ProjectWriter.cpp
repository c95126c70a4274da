#include "base/AtomicFile.hpp"
#include "render/frame/SceneNames.hpp"
#include "scene/project/JsonWriter.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>

namespace speculum::scene {

namespace {

// Field order is DESIGN.md's, a field added since beside its kin (editorView after camera); unknown
// fields kept from the file follow the known ones.
class ProjectWriter {
public:
    explicit ProjectWriter(const QDir& baseDir)
        : m_baseDir(baseDir) {}

    QByteArray write(const SceneData& scene) {
        w.beginObject();
        w.key("format");
        w.value("speculum-scene");
        w.key("version");
        w.value(kProjectFormatVersion);
        w.key("settings");
        writeSettings(scene.settings);
        w.key("camera");
        writeCamera(scene.camera);
        if (scene.editorView) {
            w.key("editorView");
            writeEditorView(*scene.editorView);
        }
        w.key("nodes");
        writeNodes(scene.nodes);
        writeExtra(scene.extra);
        w.endObject();
        return w.finish();
    }

private:
    void vec(const char* key, const glm::dvec3& v) {
        w.key(key);
        const double values[3] = {v.x, v.y, v.z};
        w.numbers(values, 3);
    }

    void vec(const char* key, const glm::dvec2& v) {
        w.key(key);
        const double values[2] = {v.x, v.y};
        w.numbers(values, 2);
    }

    template <typename T>
    void field(const char* key, const T& value) {
        w.key(key);
        w.value(value);
    }

    void writeExtra(const QJsonObject& extra) {
        for (const QString& name : JsonWriter::sortedKeys(extra)) {
            w.key(name.toStdString());
            w.value(extra.value(name));
        }
    }

    std::string relative(const std::string& absolutePath) const {
        return m_baseDir.relativeFilePath(QString::fromStdString(absolutePath)).toStdString();
    }

    void writeSettings(const SceneSettings& s) {
        w.beginObject();
        vec("background", s.background);
        field("mirrorDepth", s.mirrorDepth);
        field("ambient", s.ambient);
        if (!s.simplifyReflections) // written only where it differs from the default: files stay as they were
            field("simplifyReflections", QJsonValue(s.simplifyReflections));
        const SceneSettings defaults;
        if (s.glossyFilter != defaults.glossyFilter)
            field("glossyFilter", render::names::fileName(render::names::kGlossyFilters, s.glossyFilter));
        if (s.glossyTaps != defaults.glossyTaps)
            field("glossyTaps", s.glossyTaps);
        if (s.prefilterSamples != defaults.prefilterSamples)
            field("prefilterSamples", s.prefilterSamples);
        writeExtra(s.extra);
        w.endObject();
    }

    void writeCamera(const CameraData& c) {
        w.beginObject();
        vec("position", c.position);
        vec("target", c.target);
        vec("up", c.up);
        field("fovY", c.fovY);
        field("near", c.near);
        field("far", c.far);
        writeExtra(c.extra);
        w.endObject();
    }

    void writeEditorView(const EditorView& v) {
        w.beginObject();
        vec("position", v.position);
        vec("target", v.target);
        writeExtra(v.extra);
        w.endObject();
    }

    void writeNodes(const std::vector<NodeTree>& nodes) {
        w.beginArray();
        for (const NodeTree& node : nodes) {
            writeNode(node);
        }
        w.endArray();
    }

    void writeNode(const NodeTree& node) {
        const NodeData& d = node.data;
        w.beginObject();
        field("name", d.name);
        w.key("transform");
        writeTransform(d.transform);
        if (d.mesh) {
            w.key("mesh");
            writeMesh(*d.mesh);
        }
        if (d.material) {
            w.key("material");
            writeMaterial(*d.material);
        }
        if (d.light) {
            w.key("light");
            writeLight(*d.light);
        }
        if (d.mirror) {
            w.key("mirror");
            writeMirror(*d.mirror);
        }
        if (d.reflector) {
            w.key("reflector");
            writeReflector(*d.reflector);
        }
        if (d.animation) {
            w.key("animation");
            writeAnimation(*d.animation);
        }
        writeExtra(d.extra);
        if (!node.children.empty()) {
            w.key("children");
            writeNodes(node.children);
        }
        w.endObject();
    }

    void writeTransform(const Transform& t) {
        w.beginObject();
        vec("translate", t.translate);
        vec("rotate", t.rotate);
        vec("scale", t.scale);
        writeExtra(t.extra);
        w.endObject();
    }

    void writeMesh(const MeshComponent& m) {
        w.beginObject();
        if (m.builtin) {
            field("builtin", toString(*m.builtin));
            field("tessellation", m.tessellation);
        } else {
            field("file", relative(m.file));
            if (m.part) {
                field("part", *m.part);
            }
        }
        writeExtra(m.extra);
        w.endObject();
    }

    void writeMaterial(const MaterialComponent& m) {
        w.beginObject();
        vec("color", m.color);
        field("ambient", m.ambient);
        field("diffuse", m.diffuse);
        field("specular", m.specular);
        field("shininess", m.shininess);
        vec("emission", m.emission);
        if (!m.texture.empty()) {
            field("texture", relative(m.texture));
        }
        // The fields imported models use; defaults are left out so older files are written unchanged.
        const MaterialComponent defaults;
        if (m.specularColor != defaults.specularColor) {
            vec("specularColor", m.specularColor);
        }
        if (!m.emissionTexture.empty()) {
            field("emissionTexture", relative(m.emissionTexture));
        }
        if (!m.normalTexture.empty()) {
            field("normalTexture", relative(m.normalTexture));
        }
        if (m.normalScale != defaults.normalScale) {
            field("normalScale", m.normalScale);
        }
        if (m.wrap != defaults.wrap) {
            // One name when u and v agree, else [u, v].
            if (m.wrap[0] == m.wrap[1]) {
                field("wrap", toString(m.wrap[0]));
            } else {
                w.key("wrap");
                w.value(QJsonValue(QJsonArray{QString::fromUtf8(toString(m.wrap[0]).data()),
                                              QString::fromUtf8(toString(m.wrap[1]).data())}));
            }
        }
        if (m.opacity != defaults.opacity) {
            field("opacity", m.opacity);
        }
        if (m.alphaMode != defaults.alphaMode) {
            field("alphaMode", toString(m.alphaMode));
        }
        if (m.alphaCutoff != defaults.alphaCutoff) {
            field("alphaCutoff", m.alphaCutoff);
        }
        writeExtra(m.extra);
        w.endObject();
    }

    void writeLight(const LightComponent& l) {
        const LightComponent defaults;
        w.beginObject();
        field("type", render::names::fileName(render::names::kLightTypes, l.type));
        vec("color", l.color);
        field("intensity", l.intensity);
        // The cone only means something for spots; other lights carry it only when someone changed it (so
        // switching a spot to a point light and back loses nothing).
        if (l.type == LightType::Spot || l.spotAngle != defaults.spotAngle ||
            l.spotBlend != defaults.spotBlend) {
            field("spotAngle", l.spotAngle);
            field("spotBlend", l.spotBlend);
        }
        if (l.shadows) {
            w.key("shadows");
            w.beginObject();
            field("mapSize", l.shadows->mapSize);
            field("pcf", l.shadows->pcf);
            writeExtra(l.shadows->extra);
            w.endObject();
        }
        writeExtra(l.extra);
        w.endObject();
    }

    void writeMirror(const MirrorComponent& m) {
        w.beginObject();
        vec("size", m.size);
        field("reflectivity", m.reflectivity);
        field("technique", render::names::fileName(render::names::kMirrorTechniques, m.technique));
        vec("tint", m.tint);
        field("fresnel", QJsonValue(m.fresnel));
        field("roughness", m.roughness);
        writeExtra(m.extra);
        w.endObject();
    }

    void writeReflector(const ReflectorComponent& r) {
        w.beginObject();
        field("map", render::names::fileName(render::names::kReflectorMaps, r.map));
        field("resolution", r.resolution);
        field("reflectivity", r.reflectivity);
        field("fresnel", QJsonValue(r.fresnel));
        field("fill", render::names::fileName(render::names::kReflectorFills, r.fill));
        if (r.parallax) {
            w.key("parallax");
            w.beginObject();
            field("shape", toString(r.parallax->shape));
            if (r.parallax->shape == ParallaxShape::Sphere) {
                field("radius", r.parallax->radius);
            } else {
                vec("min", r.parallax->min);
                vec("max", r.parallax->max);
            }
            writeExtra(r.parallax->extra);
            w.endObject();
        }
        field("update", render::names::fileName(render::names::kReflectorUpdates, r.update));
        field("mirrorDepth", r.mirrorDepth);
        field("roughness", r.roughness);
        writeExtra(r.extra);
        w.endObject();
    }

    void writeAnimation(const AnimationComponent& a) {
        w.beginObject();
        if (a.bounce) {
            w.key("bounce");
            w.beginObject();
            field("height", a.bounce->height);
            field("period", a.bounce->period);
            writeExtra(a.bounce->extra);
            w.endObject();
        }
        if (a.orbit) {
            w.key("orbit");
            w.beginObject();
            vec("center", a.orbit->center);
            field("radius", a.orbit->radius);
            field("period", a.orbit->period);
            writeExtra(a.orbit->extra);
            w.endObject();
        }
        writeExtra(a.extra);
        w.endObject();
    }

    QDir m_baseDir;
    JsonWriter w;
};

} // namespace

QByteArray serializeProject(const SceneData& data, const QDir& baseDir) {
    return ProjectWriter(baseDir).write(data);
}

base::Status saveProject(const SceneData& data, const QString& path) {
    const QFileInfo info(path);
    const QDir baseDir = info.absoluteDir();
    const QByteArray bytes = serializeProject(data, baseDir);

    // Never write a file we could not read back.
    std::vector<std::string> ignored;
    base::Result<SceneData> check = parseProject(bytes, baseDir, ignored);
    if (!check) {
        return base::Error{"cannot save " + path.toStdString() + ": " + check.error()};
    }

    // One mechanism for every file speculum writes (base::AtomicFile): a temporary in the same folder,
    // every write, the fsync and the close checked, then a rename. QSaveFile (Qt 6.4) was not enough on
    // its own: it commits a file whose buffered write failed part-way unless flush() is checked.
    return base::writeFileAtomically(
        QFile::encodeName(path).toStdString(),
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
}

base::Status saveProject(const Scene& scene, const QString& path) {
    return saveProject(scene.toData(), path);
}

} // namespace speculum::scene
