#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/model/SceneChecks.hpp"
#include "scene/project/FieldReader.hpp"
#include "scene/project/JsonDuplicateKeys.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>
#include <algorithm>
#include <cmath>

namespace speculum::scene {

namespace json {

void FieldReader::finish(ObjectReader& o, UnknownFields& unknown, const std::string& key) {
    QJsonObject extra = o.finish();
    if (!extra.isEmpty())
        unknown[key] = std::move(extra);
}

std::string FieldReader::readPath(const QJsonValue& v, const std::string& path) {
    const std::string s = readString(v, path);
    if (s.empty())
        fail(path, "expected a file path, got an empty string");
    return QDir::cleanPath(m_baseDir.absoluteFilePath(QString::fromStdString(s))).toStdString();
}

// Exactly one source; a file's mesh has no tessellation, a built-in none of a file's parts.
void FieldReader::beforeFields(ObjectReader& o, MeshComponent& mesh) {
    const bool builtin = o.has("builtin"), file = o.has("file");
    if (builtin && file)
        fail(o.path(), "has both \"builtin\" and \"file\" (expected one of them)");
    if (!builtin && !file)
        fail(o.path(), "expected \"builtin\" or \"file\"");
    if (file && o.has("tessellation"))
        fail(o.at("tessellation"), "only built-in meshes have a tessellation");
    if (builtin && o.has("part"))
        fail(o.at("part"), "only file meshes have a part");
    mesh = file ? MeshComponent::fromFile({}) : MeshComponent::fromBuiltin(BuiltinMesh::Teapot);
}

// A built-in without a tessellation of its own gets its kind's.
void FieldReader::afterFields(ObjectReader& o, MeshComponent& mesh) {
    if (mesh.builtin && !o.has("tessellation"))
        mesh.tessellation = defaultTessellation(*mesh.builtin);
}

void FieldReader::beforeFields(ObjectReader& o, render::ParallaxParams&) {
    if (!o.has("shape"))
        fail(o.path(), "expected a \"shape\" (sphere or box)");
}

void FieldReader::afterFields(ObjectReader& o, render::ParallaxParams& proxy) {
    if (const auto problem = render::parallaxProblem(proxy))
        fail(o.at(problem->first), problem->second);
}

// The same rules as the inspector's (SceneChecks.hpp), computed so that they cannot overflow: the field
// named is the one that is wrong.
void FieldReader::afterFields(ObjectReader& o, render::Camera& camera) {
    if (const std::optional<FieldProblem> problem = cameraProblem(camera))
        fail(o.at(problem->field), problem->what);
}

// Both points are required: the struct's defaults are those of a new scene's camera, not this scene's,
// so a view with one of them missing is no view the editor saved.
void FieldReader::beforeFields(ObjectReader& o, EditorView&) {
    for (const char* key : {"position", "target"})
        if (!o.has(key))
            fail(o.at(key), "missing");
}

void FieldReader::afterFields(ObjectReader& o, EditorView& view) {
    if (const std::optional<FieldProblem> problem = editorViewProblem(view))
        fail(o.at(problem->field), problem->what);
}

} // namespace json

namespace {

using json::fail;
using json::indexed;

std::string num(double v) {
    return render::shortestNumber(v);
}

// The scene's structure around the declared fields: the header, the node tree and its children, each
// reflector's mesh, and the limits a node's world transform must stay within.
class ProjectReader {
public:
    ProjectReader(const QDir& baseDir, std::vector<std::string>& warnings)
        : m_fields(baseDir, warnings)
        , m_warnings(warnings) {}

    SceneData readScene(const QJsonValue& root) {
        json::ObjectReader o(root, "", m_warnings);
        o.get("format"); // checked (and the file upgraded) before the reader runs, by parseProject
        o.get("version");
        SceneData scene;
        m_fields.readFields(o, scene, scene.unknown, "");
        if (const QJsonValue v = o.get("nodes"); !v.isUndefined())
            scene.nodes = readNodeList(v, "nodes");
        checkWorld(scene.nodes, "nodes", glm::dmat4(1.0), 1.0, 1.0);
        m_fields.finish(o, scene.unknown, "");
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

    std::vector<NodeTree> readNodeList(const QJsonValue& v, const std::string& path) {
        if (!v.isArray())
            fail(path, "expected an array of nodes");
        const QJsonArray a = v.toArray();
        std::vector<NodeTree> nodes;
        nodes.reserve(static_cast<std::size_t>(a.size()));
        for (qsizetype i = 0; i < a.size(); ++i)
            nodes.push_back(readNode(a[i], indexed(path, i)));
        return nodes;
    }

    NodeTree readNode(const QJsonValue& v, const std::string& path) {
        json::ObjectReader o(v, path, m_warnings);
        NodeTree node;
        NodeData& d = node.data;
        m_fields.readFields(o, d, d.unknown, "");
        if (d.reflector) {
            if (!d.mesh)
                fail(o.at("reflector"),
                     "needs a mesh on the same node (the reflector's surface is its mesh)");
        }
        if (const QJsonValue c = o.get("children"); !c.isUndefined())
            node.children = readNodeList(c, o.at("children"));
        m_fields.finish(o, d.unknown, "");
        return node;
    }

    json::FieldReader m_fields;
    std::vector<std::string>& m_warnings;
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
    } catch (const json::ParseFailure& failure) {
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
