#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "render/frame/GlossyLimits.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/frame/SceneNames.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/model/SceneChecks.hpp"
#include "scene/project/JsonDuplicateKeys.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QSet>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>

namespace speculum::scene {

namespace {

// Validation unwinds through many small readers; an exception thrown here and caught in parseProject keeps
// each reader a straight line. It never leaves this file.
struct ParseFailure {
    std::string message;
};

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw ParseFailure{path.empty() ? what : path + ": " + what};
}

std::string num(double v) {
    return QString::number(v, 'g', QLocale::FloatingPointShortest).toStdString();
}

// Keys come from the file (unknown fields are named in warnings): shown escaped, never raw.
std::string join(const std::string& path, const QString& key) {
    const std::string shown = base::printable(key.toStdString(), 40);
    return path.empty() ? shown : path + "." + shown;
}

std::string indexed(const std::string& path, qsizetype i) {
    return path + "[" + std::to_string(i) + "]";
}

// ---- scalar readers: each names the path in its error ----

double readNumber(const QJsonValue& v, const std::string& path) {
    if (!v.isDouble()) {
        fail(path, "expected a number");
    }
    const double d = v.toDouble();
    if (!std::isfinite(d)) {
        fail(path, "expected a finite number");
    }
    return d;
}

// A length or position: every coordinate within ±kMaxCoordinate (render/frame/SceneLimits.hpp).
void requireCoordinate(double v, const std::string& path) {
    if (std::abs(v) > render::kMaxCoordinate) {
        fail(path, "must be within ±" + num(render::kMaxCoordinate) +
                       " (the largest coordinate a scene may "
                       "hold), got " +
                       num(v));
    }
}

template <int N>
void requireCoordinates(const glm::vec<N, double>& v, const std::string& path) {
    for (int i = 0; i < N; ++i) {
        if (std::abs(v[i]) > render::kMaxCoordinate) {
            fail(path, "coordinates must be within ±" + num(render::kMaxCoordinate) +
                           " (the largest coordinate a scene may hold), got " + num(v[i]));
        }
    }
}

// A factor that multiplies light (intensities, material coefficients): 0..kMaxIntensity.
void requireIntensity(double v, const std::string& path) {
    if (v < 0.0) {
        fail(path, "must not be negative, got " + num(v));
    }
    if (v > render::kMaxIntensity) {
        fail(path, "must be at most " + num(render::kMaxIntensity) + ", got " + num(v));
    }
}

// Seconds of an animation cycle: a tiny period makes t / period overflow, a huge one stands still.
void requirePeriod(double v, const std::string& path) {
    if (!(v > 0.0)) {
        fail(path, "must be greater than 0, got " + num(v));
    }
    if (v < render::kMinPeriod || v > render::kMaxPeriod) {
        fail(path, "must be in " + num(render::kMinPeriod) + ".." + num(render::kMaxPeriod) +
                       " seconds, got " + num(v));
    }
}

// A positive extent (mirror size, proxy radius): kMinScale..kMaxCoordinate.
void requireExtent(double v, const std::string& path, const char* what) {
    if (!(v > 0.0)) {
        fail(path, std::string(what) + " must be greater than 0");
    }
    if (v < render::kMinScale || v > render::kMaxCoordinate) {
        fail(path, std::string(what) + " must be in " + num(render::kMinScale) + ".." +
                       num(render::kMaxCoordinate) + ", got " + num(v));
    }
}

int readInt(const QJsonValue& v, const std::string& path) {
    const double d = v.isDouble() ? v.toDouble() : NAN;
    if (!std::isfinite(d) || d != std::floor(d) || std::abs(d) > 1e9) {
        fail(path, "expected an integer");
    }
    return static_cast<int>(d);
}

std::string readString(const QJsonValue& v, const std::string& path) {
    if (!v.isString()) {
        fail(path, "expected a string");
    }
    return v.toString().toStdString();
}

template <int N>
glm::vec<N, double> readVec(const QJsonValue& v, const std::string& path) {
    const std::string what = "expected " + std::to_string(N) + " numbers";
    if (!v.isArray() || v.toArray().size() != N) {
        fail(path, what);
    }
    const QJsonArray a = v.toArray();
    glm::vec<N, double> out(0.0);
    for (int i = 0; i < N; ++i) {
        if (!a[i].isDouble() || !std::isfinite(a[i].toDouble())) {
            fail(path, what);
        }
        out[i] = a[i].toDouble();
    }
    return out;
}

void requireRange(double v, double lo, double hi, const std::string& path) {
    if (v < lo || v > hi) {
        fail(path, "must be in " + num(lo) + ".." + num(hi) + ", got " + num(v));
    }
}

void requireNonNegative(double v, const std::string& path) {
    if (v < 0.0) {
        fail(path, "must not be negative, got " + num(v));
    }
}

glm::dvec3 readColor(const QJsonValue& v, const std::string& path) {
    const glm::dvec3 c = readVec<3>(v, path);
    for (int i = 0; i < 3; ++i) {
        if (c[i] < 0.0 || c[i] > 1.0) {
            fail(path, "colour components must be in 0..1 (linear RGB), got " + num(c[i]));
        }
    }
    return c;
}

bool readBool(const QJsonValue& v, const std::string& path) {
    if (!v.isBool()) {
        fail(path, "expected true or false");
    }
    return v.toBool();
}

template <typename E>
E readEnum(const QJsonValue& v, const std::string& path, const char* what,
           std::optional<E> (*parse)(std::string_view), const char* expected) {
    const std::string s = readString(v, path);
    const std::optional<E> e = parse(s);
    if (!e) {
        fail(path, std::string("unknown ") + what + " \"" + base::printable(s, 40) + "\" (expected " +
                       expected + ")");
    }
    return *e;
}

// The document's enums list their values in the order of the name tables (the index is the value).
static_assert(int(LightType::Spot) + 1 == render::names::kLightTypes.size());
static_assert(int(MirrorTechnique::Texture) + 1 == render::names::kMirrorTechniques.size());
static_assert(int(ReflectorMap::TennisBall) + 1 == render::names::kReflectorMaps.size());
static_assert(int(ReflectorFill::Resampled) + 1 == render::names::kReflectorFills.size());
static_assert(int(ReflectorUpdate::Once) + 1 == render::names::kReflectorUpdates.size());

// A choice spelled as in render/frame/SceneNames.hpp: the one list the writer, the inspector and the sweep
// use.
template <typename E, std::size_t N>
E readNamed(const QJsonValue& v, const std::string& path, const char* what,
            const std::array<render::names::Name, N>& names) {
    static_assert(N > 0);
    const std::string s = readString(v, path);
    const std::optional<E> e = render::names::fromFileName<E>(names, s);
    if (!e) {
        fail(path, std::string("unknown ") + what + " \"" + base::printable(s, 40) + "\" (expected " +
                       render::names::choices(names) + ")");
    }
    return *e;
}

// ---- objects: tracks which keys were read so the rest become warnings and `extra` ----

class ObjectReader {
public:
    ObjectReader(const QJsonValue& v, std::string path, std::vector<std::string>& warnings)
        : m_path(std::move(path))
        , m_warnings(warnings) {
        if (!v.isObject()) {
            fail(m_path, "expected an object");
        }
        m_object = v.toObject();
    }

    const std::string& path() const { return m_path; }
    std::string at(const char* key) const { return join(m_path, QString::fromLatin1(key)); }
    bool has(const char* key) const { return m_object.contains(QLatin1String(key)); }

    // The value, or Undefined when absent; marks the key as known either way.
    QJsonValue get(const char* key) {
        m_known.insert(QString::fromLatin1(key));
        return m_object.value(QLatin1String(key));
    }

    template <typename T, typename F>
    void optional(const char* key, T& out, F&& read) {
        const QJsonValue v = get(key);
        if (!v.isUndefined()) {
            out = read(v, at(key));
        }
    }

    // Unknown keys: warned about and returned for `extra`.
    QJsonObject finish() {
        QJsonObject extra;
        for (auto it = m_object.begin(); it != m_object.end(); ++it) {
            if (!m_known.contains(it.key())) {
                m_warnings.push_back(join(m_path, it.key()) + ": unknown field, ignored");
                extra.insert(it.key(), it.value());
            }
        }
        return extra;
    }

private:
    QJsonObject m_object;
    std::string m_path;
    std::vector<std::string>& m_warnings;
    QSet<QString> m_known;
};

class ProjectReader {
public:
    ProjectReader(const QDir& baseDir, std::vector<std::string>& warnings)
        : m_baseDir(baseDir)
        , m_warnings(warnings) {}

    SceneData readScene(const QJsonValue& root) {
        ObjectReader o(root, "", m_warnings);
        readHeader(o);
        SceneData scene;
        if (const QJsonValue v = o.get("settings"); !v.isUndefined()) {
            scene.settings = readSettings(v, "settings");
        }
        if (const QJsonValue v = o.get("camera"); !v.isUndefined()) {
            scene.camera = readCamera(v, "camera");
        }
        if (const QJsonValue v = o.get("editorView"); !v.isUndefined()) {
            scene.editorView = readEditorView(v, "editorView");
        }
        if (const QJsonValue v = o.get("nodes"); !v.isUndefined()) {
            scene.nodes = readNodeList(v, "nodes");
        }
        checkWorld(scene.nodes, "nodes", glm::dmat4(1.0), 1.0, 1.0);
        scene.extra = o.finish();
        return scene;
    }

private:
    // Each number is in range on its own; composed down the tree they may still not be: scales multiply
    // (five levels of 1e9 overflow a float) and a parent's scale stretches its children's translations.
    // Bounds in the singular values of the world matrix: between the products of the smallest and of the
    // largest |scale| along the chain.
    void checkWorld(const std::vector<NodeTree>& nodes, const std::string& listPath, const glm::dmat4& parent,
                    double parentMax, double parentMin) {
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            const NodeTree& node = nodes[i];
            const std::string path = indexed(listPath, static_cast<qsizetype>(i));
            const Transform& t = node.data.transform;
            const glm::dvec3 s = glm::abs(t.scale);
            const double worldMax = parentMax * std::max({s.x, s.y, s.z});
            const double worldMin = parentMin * std::min({s.x, s.y, s.z});
            const std::string who = node.data.name.empty() ? std::string("the unnamed node")
                                                           : "node " + base::quoted(node.data.name, 40);
            if (worldMax > render::kMaxScale) {
                fail(path, who + ": its world scale (its own scale times its parents') reaches " +
                               num(worldMax) + ", more than " + num(render::kMaxScale));
            }
            if (worldMin < render::kMinScale) {
                fail(path, who + ": its world scale (its own scale times its parents') falls to " +
                               num(worldMin) + ", less than " + num(render::kMinScale));
            }
            // Where its origin can be, animations included, in the parent's space and then in the world.
            glm::dvec3 local = t.translate;
            double reach = 0.0;
            if (const auto& a = node.data.animation) {
                if (a->orbit) {
                    local = a->orbit->center;
                    reach += a->orbit->radius;
                }
                if (a->bounce) {
                    reach += std::abs(a->bounce->height);
                }
            }
            const glm::dvec3 origin = glm::dvec3(parent * glm::dvec4(local, 1.0));
            for (int k = 0; k < 3; ++k) {
                const double extreme = std::abs(origin[k]) + parentMax * reach;
                if (!(extreme <= render::kMaxCoordinate)) {
                    fail(path, who + ": its world position reaches " + num(extreme) + ", beyond ±" +
                                   num(render::kMaxCoordinate) +
                                   " (its parents' scales multiply its translation and animation)");
                }
            }
            checkWorld(node.children, path + ".children", parent * localMatrix(t), worldMax, worldMin);
        }
    }

    // Checked (and the file upgraded to the current version) before the reader runs, by parseProject.
    void readHeader(ObjectReader& o) {
        o.get("format");
        o.get("version");
    }

    SceneSettings readSettings(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        SceneSettings s;
        o.optional("background", s.background, readColor);
        o.optional("mirrorDepth", s.mirrorDepth, readInt);
        requireRange(s.mirrorDepth, 0, render::kMaxMirrorDepth, o.at("mirrorDepth"));
        o.optional("ambient", s.ambient, readNumber);
        requireRange(s.ambient, 0.0, 1.0, o.at("ambient"));
        o.optional("simplifyReflections", s.simplifyReflections, readBool);
        o.optional("glossyFilter", s.glossyFilter, [](const QJsonValue& t, const std::string& p) {
            return readNamed<GlossyFilter>(t, p, "glossy filter", render::names::kGlossyFilters);
        });
        o.optional("glossyTaps", s.glossyTaps, readInt);
        requireRange(s.glossyTaps, render::kMinGlossyTaps, render::kMaxGlossyTaps, o.at("glossyTaps"));
        o.optional("prefilterSamples", s.prefilterSamples, readInt);
        requireRange(s.prefilterSamples, render::kMinPrefilterSamples, render::kMaxPrefilterSamples,
                     o.at("prefilterSamples"));
        s.extra = o.finish();
        return s;
    }

    CameraData readCamera(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        CameraData c;
        o.optional("position", c.position, readVec<3>);
        o.optional("target", c.target, readVec<3>);
        o.optional("up", c.up, readVec<3>);
        o.optional("fovY", c.fovY, readNumber);
        o.optional("near", c.near, readNumber);
        o.optional("far", c.far, readNumber);
        // The same rules as the inspector's (SceneChecks.hpp), computed so that they cannot overflow:
        // the field named is the one that is wrong.
        if (const std::optional<FieldProblem> problem = cameraProblem(c)) {
            fail(join(o.path(), QString::fromStdString(problem->field)), problem->what);
        }
        c.extra = o.finish();
        return c;
    }

    // Both points are required: the struct's defaults are those of a new scene's camera, not this scene's,
    // so a view with one of them missing is no view the editor saved.
    EditorView readEditorView(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        EditorView view;
        for (const char* key : {"position", "target"}) {
            if (!o.has(key)) {
                fail(o.at(key), "missing");
            }
        }
        o.optional("position", view.position, readVec<3>);
        o.optional("target", view.target, readVec<3>);
        // The camera's rules for these two points (SceneChecks.hpp); the scene keeps no view they refuse.
        if (const std::optional<FieldProblem> problem = editorViewProblem(view)) {
            fail(join(o.path(), QString::fromStdString(problem->field)), problem->what);
        }
        view.extra = o.finish();
        return view;
    }

    std::vector<NodeTree> readNodeList(const QJsonValue& v, const std::string& path) {
        if (!v.isArray()) {
            fail(path, "expected an array of nodes");
        }
        const QJsonArray a = v.toArray();
        std::vector<NodeTree> nodes;
        nodes.reserve(static_cast<std::size_t>(a.size()));
        for (qsizetype i = 0; i < a.size(); ++i) {
            nodes.push_back(readNode(a[i], indexed(path, i)));
        }
        return nodes;
    }

    NodeTree readNode(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        NodeTree node;
        NodeData& d = node.data;
        o.optional("name", d.name, readString);
        if (const QJsonValue t = o.get("transform"); !t.isUndefined()) {
            d.transform = readTransform(t, o.at("transform"));
        }
        readComponent(o, "mesh", d.mesh, &ProjectReader::readMesh);
        readComponent(o, "material", d.material, &ProjectReader::readMaterial);
        readComponent(o, "light", d.light, &ProjectReader::readLight);
        readComponent(o, "mirror", d.mirror, &ProjectReader::readMirror);
        readComponent(o, "reflector", d.reflector, &ProjectReader::readReflector);
        readComponent(o, "animation", d.animation, &ProjectReader::readAnimation);
        if (d.reflector) {
            if (!d.mesh) {
                fail(o.at("reflector"),
                     "needs a mesh on the same node (the reflector's surface is its mesh)");
            }
            if (!m_firstReflector.empty()) {
                fail(o.at("reflector"),
                     "a scene has at most one reflector (the first is " + m_firstReflector + ")");
            }
            m_firstReflector = path;
        }
        if (const QJsonValue c = o.get("children"); !c.isUndefined()) {
            node.children = readNodeList(c, o.at("children"));
        }
        d.extra = o.finish();
        return node;
    }

    template <typename T>
    void readComponent(ObjectReader& o, const char* key, std::optional<T>& out,
                       T (ProjectReader::*read)(const QJsonValue&, const std::string&)) {
        if (const QJsonValue v = o.get(key); !v.isUndefined()) {
            out = (this->*read)(v, o.at(key));
        }
    }

    Transform readTransform(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        Transform t;
        o.optional("translate", t.translate, readVec<3>);
        o.optional("rotate", t.rotate, readVec<3>);
        o.optional("scale", t.scale, readVec<3>);
        requireCoordinates<3>(t.translate, o.at("translate"));
        // Rotations are turned into matrices in double (NodeMath): any finite angle gives a rotation.
        for (int i = 0; i < 3; ++i) {
            if (t.scale[i] == 0.0) {
                fail(o.at("scale"), "components must be non-zero (a zero scale flattens the node)");
            }
            const double s = std::abs(t.scale[i]);
            if (s < render::kMinScale || s > render::kMaxScale) {
                fail(o.at("scale"), "components must be in " + num(render::kMinScale) + ".." +
                                        num(render::kMaxScale) + " in size (negative mirrors), got " +
                                        num(t.scale[i]));
            }
        }
        t.extra = o.finish();
        return t;
    }

    std::string readPath(const QJsonValue& v, const std::string& path) {
        const std::string s = readString(v, path);
        if (s.empty()) {
            fail(path, "expected a file path, got an empty string");
        }
        return QDir::cleanPath(m_baseDir.absoluteFilePath(QString::fromStdString(s))).toStdString();
    }

    MeshComponent readMesh(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        const QJsonValue builtin = o.get("builtin");
        const QJsonValue file = o.get("file");
        const QJsonValue tessellation = o.get("tessellation");
        const QJsonValue part = o.get("part");
        MeshComponent m;
        if (!builtin.isUndefined() && !file.isUndefined()) {
            fail(path, "has both \"builtin\" and \"file\" (expected one of them)");
        }
        if (!builtin.isUndefined()) {
            m = MeshComponent::fromBuiltin(readEnum<BuiltinMesh>(builtin, o.at("builtin"), "builtin mesh",
                                                                 builtinMeshFromString,
                                                                 "teapot, sphere, box or plane"));
            if (!tessellation.isUndefined()) {
                m.tessellation = readInt(tessellation, o.at("tessellation"));
                requireRange(m.tessellation, render::kMinTessellation, render::kMaxTessellation,
                             o.at("tessellation"));
            }
            if (!part.isUndefined()) {
                fail(o.at("part"), "only file meshes have a part");
            }
        } else if (!file.isUndefined()) {
            m = MeshComponent::fromFile(readPath(file, o.at("file")));
            if (!tessellation.isUndefined()) {
                fail(o.at("tessellation"), "only built-in meshes have a tessellation");
            }
            if (!part.isUndefined()) {
                m.part = readInt(part, o.at("part"));
                if (*m.part < 0) {
                    fail(o.at("part"), "must not be negative, got " + std::to_string(*m.part));
                }
            }
        } else {
            fail(path, "expected \"builtin\" or \"file\"");
        }
        m.extra = o.finish();
        return m;
    }

    // "repeat" | "clamp" | "mirror" for both directions, or [u, v].
    static std::array<TextureWrap, 2> readWrap(const QJsonValue& v, const std::string& path) {
        const auto one = [](const QJsonValue& value, const std::string& at) {
            return readEnum<TextureWrap>(value, at, "wrap mode", textureWrapFromString,
                                         "\"repeat\", \"clamp\" or \"mirror\"");
        };
        if (v.isString()) {
            const TextureWrap both = one(v, path);
            return {both, both};
        }
        if (!v.isArray() || v.toArray().size() != 2) {
            fail(path, "expected a wrap mode or [u, v] wrap modes");
        }
        const QJsonArray a = v.toArray();
        return {one(a[0], indexed(path, 0)), one(a[1], indexed(path, 1))};
    }

    MaterialComponent readMaterial(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        MaterialComponent m;
        o.optional("color", m.color, readColor);
        o.optional("ambient", m.ambient, readNumber);
        requireIntensity(m.ambient, o.at("ambient"));
        o.optional("diffuse", m.diffuse, readNumber);
        requireIntensity(m.diffuse, o.at("diffuse"));
        o.optional("specular", m.specular, readNumber);
        requireIntensity(m.specular, o.at("specular"));
        o.optional("shininess", m.shininess, readNumber);
        requireRange(m.shininess, 0.0, render::kMaxShininess, o.at("shininess"));
        o.optional("emission", m.emission, readColor);
        if (const QJsonValue t = o.get("texture"); !t.isUndefined()) {
            m.texture = readPath(t, o.at("texture"));
        }
        o.optional("specularColor", m.specularColor, readColor);
        if (const QJsonValue t = o.get("emissionTexture"); !t.isUndefined()) {
            m.emissionTexture = readPath(t, o.at("emissionTexture"));
        }
        if (const QJsonValue t = o.get("normalTexture"); !t.isUndefined()) {
            m.normalTexture = readPath(t, o.at("normalTexture"));
        }
        o.optional("normalScale", m.normalScale, readNumber);
        requireRange(m.normalScale, -render::kMaxNormalScale, render::kMaxNormalScale, o.at("normalScale"));
        if (const QJsonValue w = o.get("wrap"); !w.isUndefined()) {
            m.wrap = readWrap(w, o.at("wrap"));
        }
        o.optional("opacity", m.opacity, readNumber);
        requireRange(m.opacity, 0.0, 1.0, o.at("opacity"));
        if (const QJsonValue a = o.get("alphaMode"); !a.isUndefined()) {
            const std::string s = readString(a, o.at("alphaMode"));
            const std::optional<AlphaMode> mode = alphaModeFromString(s);
            if (!mode) {
                fail(o.at("alphaMode"),
                     "expected \"opaque\", \"mask\" or \"blend\", got \"" + base::printable(s, 40) + "\"");
            }
            m.alphaMode = *mode;
        }
        o.optional("alphaCutoff", m.alphaCutoff, readNumber);
        requireRange(m.alphaCutoff, 0.0, 1.0, o.at("alphaCutoff"));
        m.extra = o.finish();
        return m;
    }

    ShadowComponent readShadows(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        ShadowComponent s;
        o.optional("mapSize", s.mapSize, readInt);
        // Shadow maps are square power-of-two textures; the largest is the GL_MAX_TEXTURE_SIZE of large GPUs.
        if (s.mapSize < render::kMinShadowMapSize || s.mapSize > render::kMaxShadowMapSize ||
            !render::isPowerOfTwo(s.mapSize)) {
            fail(o.at("mapSize"), "must be a power of two in " + std::to_string(render::kMinShadowMapSize) +
                                      ".." + std::to_string(render::kMaxShadowMapSize) + ", got " +
                                      std::to_string(s.mapSize));
        }
        o.optional("pcf", s.pcf, readInt);
        // An odd kernel is centred on the looked-up texel.
        if (s.pcf < render::kMinPcfWidth || s.pcf > render::kMaxPcfWidth || s.pcf % 2 == 0) {
            fail(o.at("pcf"), "must be an odd kernel width in " + std::to_string(render::kMinPcfWidth) +
                                  ".." + std::to_string(render::kMaxPcfWidth) + ", got " +
                                  std::to_string(s.pcf));
        }
        s.extra = o.finish();
        return s;
    }

    LightComponent readLight(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        LightComponent l;
        o.optional("type", l.type, [](const QJsonValue& t, const std::string& p) {
            return readNamed<LightType>(t, p, "light type", render::names::kLightTypes);
        });
        o.optional("color", l.color, readColor);
        o.optional("intensity", l.intensity, readNumber);
        requireIntensity(l.intensity, o.at("intensity"));
        o.optional("spotAngle", l.spotAngle, readNumber);
        if (!(l.spotAngle > 0.0 && l.spotAngle <= 90.0)) {
            fail(o.at("spotAngle"), "must be in (0, 90] degrees, got " + num(l.spotAngle));
        }
        o.optional("spotBlend", l.spotBlend, readNumber);
        requireRange(l.spotBlend, 0.0, 1.0, o.at("spotBlend"));
        if (const QJsonValue s = o.get("shadows"); !s.isUndefined()) {
            l.shadows = readShadows(s, o.at("shadows"));
        }
        l.extra = o.finish();
        return l;
    }

    MirrorComponent readMirror(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        MirrorComponent m;
        o.optional("size", m.size, readVec<2>);
        requireExtent(m.size.x, o.at("size"), "extents");
        requireExtent(m.size.y, o.at("size"), "extents");
        o.optional("reflectivity", m.reflectivity, readNumber);
        requireRange(m.reflectivity, 0.0, 1.0, o.at("reflectivity"));
        o.optional("technique", m.technique, [](const QJsonValue& t, const std::string& p) {
            return readNamed<MirrorTechnique>(t, p, "mirror technique", render::names::kMirrorTechniques);
        });
        o.optional("tint", m.tint, readColor);
        o.optional("fresnel", m.fresnel, readBool);
        // `blur` (before roughness existed) is read as the roughness, same value; `roughness` wins.
        const bool hasRoughness = !o.get("roughness").isUndefined();
        o.optional(hasRoughness ? "roughness" : "blur", m.roughness, readNumber);
        requireRange(m.roughness, 0.0, 1.0, o.at(hasRoughness ? "roughness" : "blur"));
        if (hasRoughness)
            o.get("blur"); // superseded: not kept as an unknown field, so a save does not write it back
        m.extra = o.finish();
        return m;
    }

    ReflectorComponent readReflector(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        ReflectorComponent r;
        o.optional("map", r.map, [](const QJsonValue& t, const std::string& p) {
            return readNamed<ReflectorMap>(t, p, "reflector map", render::names::kReflectorMaps);
        });
        o.optional("resolution", r.resolution, readInt);
        requireRange(r.resolution, render::kMinEnvironmentMapSize, render::kMaxEnvironmentMapSize,
                     o.at("resolution"));
        o.optional("reflectivity", r.reflectivity, readNumber);
        requireRange(r.reflectivity, 0.0, 1.0, o.at("reflectivity"));
        o.optional("fresnel", r.fresnel, readBool);
        o.optional("fill", r.fill, [](const QJsonValue& t, const std::string& p) {
            return readNamed<ReflectorFill>(t, p, "reflector fill", render::names::kReflectorFills);
        });
        if (const QJsonValue p = o.get("parallax"); !p.isUndefined()) {
            r.parallax = readParallax(p, o.at("parallax"));
        }
        o.optional("update", r.update, [](const QJsonValue& t, const std::string& p) {
            return readNamed<ReflectorUpdate>(t, p, "reflector update", render::names::kReflectorUpdates);
        });
        o.optional("mirrorDepth", r.mirrorDepth, readInt);
        requireRange(r.mirrorDepth, 0, render::kMaxMirrorDepth, o.at("mirrorDepth"));
        o.optional("roughness", r.roughness, readNumber);
        requireRange(r.roughness, 0.0, 1.0, o.at("roughness"));
        r.extra = o.finish();
        return r;
    }

    ReflectorParallax readParallax(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        ReflectorParallax p;
        const QJsonValue shape = o.get("shape");
        if (shape.isUndefined()) {
            fail(path, "expected a \"shape\" (sphere or box)");
        }
        p.shape = readEnum<ParallaxShape>(shape, o.at("shape"), "parallax shape", parallaxShapeFromString,
                                          "sphere or box");
        if (p.shape == ParallaxShape::Sphere) {
            o.optional("radius", p.radius, readNumber);
            if (!(p.radius > 0.0)) {
                fail(o.at("radius"), "must be greater than 0, got " + num(p.radius));
            }
            requireExtent(p.radius, o.at("radius"), "the radius");
        } else {
            o.optional("min", p.min, readVec<3>);
            o.optional("max", p.max, readVec<3>);
            for (int i = 0; i < 3; ++i) {
                if (!(p.min[i] < 0.0 && p.max[i] > 0.0)) {
                    fail(o.at(p.min[i] < 0.0 ? "max" : "min"),
                         "the box must contain the capture point (min < 0 < max on every axis)");
                }
                requireExtent(-p.min[i], o.at("min"), "the distances to the box's faces");
                requireExtent(p.max[i], o.at("max"), "the distances to the box's faces");
            }
        }
        p.extra = o.finish();
        return p;
    }

    AnimationComponent readAnimation(const QJsonValue& v, const std::string& path) {
        ObjectReader o(v, path, m_warnings);
        AnimationComponent a;
        if (const QJsonValue b = o.get("bounce"); !b.isUndefined()) {
            ObjectReader bo(b, o.at("bounce"), m_warnings);
            BounceAnimation bounce;
            bo.optional("height", bounce.height, readNumber);
            requireCoordinate(bounce.height, bo.at("height"));
            bo.optional("period", bounce.period, readNumber);
            requirePeriod(bounce.period, bo.at("period"));
            bounce.extra = bo.finish();
            a.bounce = bounce;
        }
        if (const QJsonValue r = o.get("orbit"); !r.isUndefined()) {
            ObjectReader ro(r, o.at("orbit"), m_warnings);
            OrbitAnimation orbit;
            ro.optional("center", orbit.center, readVec<3>);
            requireCoordinates<3>(orbit.center, ro.at("center"));
            ro.optional("radius", orbit.radius, readNumber);
            requireNonNegative(orbit.radius, ro.at("radius"));
            requireCoordinate(orbit.radius, ro.at("radius"));
            ro.optional("period", orbit.period, readNumber);
            requirePeriod(orbit.period, ro.at("period"));
            orbit.extra = ro.finish();
            a.orbit = orbit;
        }
        a.extra = o.finish();
        return a;
    }

    QDir m_baseDir;
    std::vector<std::string>& m_warnings;
    std::string m_firstReflector; // path of the node holding the scene's reflector, once seen
};

std::string syntaxError(const QByteArray& json, const QJsonParseError& error) {
    // QJsonParseError gives a byte offset; people count lines and characters.
    const qsizetype offset = std::clamp<qsizetype>(error.offset, 0, json.size());
    int line = 1;
    qsizetype lineStart = 0;
    for (qsizetype i = 0; i < offset; ++i) {
        if (json[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    const int column =
        static_cast<int>(QString::fromUtf8(json.mid(lineStart, offset - lineStart)).size()) + 1;
    return "line " + std::to_string(line) + ", column " + std::to_string(column) +
           ": JSON syntax error: " + error.errorString().toStdString();
}

} // namespace

base::Result<SceneData> parseProject(const QByteArray& json, const QDir& baseDir,
                                     std::vector<std::string>& warnings) {
    QByteArray bytes = json;
    if (bytes.startsWith("\xEF\xBB\xBF")) {
        bytes.remove(0, 3); // a UTF-8 byte order mark some editors add
    }
    if (bytes.trimmed().isEmpty()) {
        return base::Error{"the file is empty"};
    }
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        return base::Error{syntaxError(bytes, parseError)};
    }
    if (!document.isObject()) {
        return base::Error{"expected a JSON object at the top level"};
    }
    // The parser keeps one value of a repeated key and drops the other without a word; refused instead.
    if (const std::optional<std::string> duplicate =
            findDuplicateKey(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())))) {
        return base::Error{*duplicate};
    }
    QJsonObject root = document.object();
    const base::Result<int> version = readProjectHeader(root);
    if (!version) {
        return base::Error{version.error()};
    }
    upgradeToCurrentVersion(root, *version);
    std::vector<std::string> newWarnings;
    try {
        ProjectReader reader(baseDir, newWarnings);
        SceneData scene = reader.readScene(root);
        warnings.insert(warnings.end(), newWarnings.begin(), newWarnings.end());
        return scene;
    } catch (const ParseFailure& failure) {
        return base::Error{failure.message};
    }
}

base::Result<SceneData> loadProject(const QString& path, std::vector<std::string>& warnings) {
    // Only a regular file, opened without blocking: a FIFO or /dev/stdin would hang the CLI and the
    // editor's GUI thread for good. A project is text; 256 MiB is far beyond any real one.
    const base::Result<std::string> bytes =
        base::readRegularFile(QFile::encodeName(path).toStdString(), std::uintmax_t(256) << 20);
    if (!bytes) {
        return base::Error{base::printable(QFileInfo(path).fileName().toStdString()) + ": " + bytes.error()};
    }
    return parseProject(QByteArray::fromStdString(*bytes), QFileInfo(path).absoluteDir(), warnings);
}

base::Status openProject(Scene& scene, const QString& path, std::vector<std::string>& warnings) {
    base::Result<SceneData> data = loadProject(path, warnings);
    if (!data) {
        return base::Error{data.error()};
    }
    scene.reset(std::move(data).value());
    scene.setProjectPath(QFileInfo(path).absoluteFilePath());
    return base::Done{};
}

} // namespace speculum::scene
