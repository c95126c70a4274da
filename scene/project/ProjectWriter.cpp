#include "base/AtomicFile.hpp"
#include "scene/project/JsonWriter.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <type_traits>

namespace speculum::scene {

namespace {

// Writes what the declarations hold (render/frame/Field.hpp), in their order, then the unknown fields kept
// from the file; the scene's own structure (header, node tree) around them.
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
        writeFields(scene, scene.unknown, "");
        w.key("nodes");
        writeNodes(scene.nodes);
        writeExtra(scene.unknown, "");
        w.endObject();
        return w.finish();
    }

private:
    void writeNodes(const std::vector<NodeTree>& nodes) {
        w.beginArray();
        for (const NodeTree& node : nodes) {
            w.beginObject();
            writeFields(node.data, node.data.unknown, "");
            writeExtra(node.data.unknown, "");
            if (!node.children.empty()) {
                w.key("children");
                writeNodes(node.children);
            }
            w.endObject();
        }
        w.endArray();
    }

    template <typename T>
    void writeFields(const T& value, const UnknownFields& unknown, const std::string& key) {
        render::forEachField<T>([&](const auto& f) {
            using Owner = typename std::decay_t<decltype(f)>::OwnerType;
            const Owner& owner = value;
            const auto& member = owner.*f.member;
            if (!written(f, owner, member))
                return;
            w.key(f.spec.name);
            writeMember(member, f.spec, unknown,
                        key.empty() ? std::string(f.spec.name) : key + "." + std::string(f.spec.name));
        });
    }

    // Whether the file gets a field: what is absent stays absent, and each field's write rule
    // (FieldWrite) decides between its default and where it applies.
    template <typename F, typename Owner, typename M>
    static bool written(const F& f, const Owner& owner, const M& member) {
        if constexpr (render::IsOptional<M>::value) {
            if (!member)
                return false;
        }
        const bool isDefault = member == Owner{}.*f.member;
        switch (f.spec.write) {
        case render::FieldWrite::Always:
            return f.appliesTo(owner) || !isDefault;
        case render::FieldWrite::UnlessDefault:
            return !isDefault;
        case render::FieldWrite::WhenApplies:
            return f.appliesTo(owner);
        case render::FieldWrite::Everywhere:
            return true;
        }
        return true;
    }

    template <typename M>
    void writeMember(const M& member, const render::FieldSpec& spec, const UnknownFields& unknown,
                     const std::string& key) {
        if constexpr (render::IsOptional<M>::value) {
            writeMember(*member, spec, unknown, key);
        } else if constexpr (render::HasFields<M>) {
            w.beginObject();
            writeFields(member, unknown, key);
            writeExtra(unknown, key);
            w.endObject();
        } else {
            writeScalar(member, spec);
        }
    }

    template <typename M>
    void writeScalar(const M& value, const render::FieldSpec& spec) {
        if constexpr (std::is_enum_v<M>) {
            w.value(render::names::fileName(spec.choices, value));
        } else if constexpr (std::is_same_v<M, bool>) {
            w.value(QJsonValue(value));
        } else if constexpr (std::is_same_v<M, int> || std::is_same_v<M, double>) {
            w.value(value);
        } else if constexpr (std::is_same_v<M, glm::dvec2> || std::is_same_v<M, glm::dvec3>) {
            w.numbers(&value[0], M::length());
        } else if constexpr (std::is_same_v<M, render::TextureSource>) {
            w.value(relative(value.path));
        } else if constexpr (std::is_same_v<M, std::array<render::TextureWrap, 2>>) {
            // One name when u and v agree, else [u, v].
            const auto name = [&](render::TextureWrap wrap) {
                return QString::fromUtf8(render::names::fileName(spec.choices, wrap).data());
            };
            w.value(value[0] == value[1] ? QJsonValue(name(value[0]))
                                         : QJsonValue(QJsonArray{name(value[0]), name(value[1])}));
        } else if (spec.type == render::FieldType::Path) {
            w.value(relative(value));
        } else {
            w.value(std::string_view(value));
        }
    }

    // Unknown fields kept from the file follow the known ones, sorted.
    void writeExtra(const UnknownFields& unknown, const std::string& key) {
        const auto it = unknown.find(key);
        if (it == unknown.end())
            return;
        for (const QString& name : JsonWriter::sortedKeys(it->second)) {
            w.key(name.toStdString());
            w.value(it->second.value(name));
        }
    }

    // Relative to the project's folder where the file lies inside it or beside it (they share a folder
    // below the root: the project and its models move together); absolute where they share only the root
    // (a model from /usr/share in a project in the home folder), so moving the project does not lose it.
    std::string relative(const std::string& absolutePath) const {
        const QString path = QString::fromStdString(absolutePath);
        const QString relativePath = m_baseDir.relativeFilePath(path);
        if (!relativePath.startsWith(QStringLiteral("../")) && relativePath != QStringLiteral(".."))
            return relativePath.toStdString();
        const QStringList base = QDir::cleanPath(m_baseDir.absolutePath()).split(u'/', Qt::SkipEmptyParts);
        const QStringList file = QDir::cleanPath(path).split(u'/', Qt::SkipEmptyParts);
        const bool shareAFolder =
            !base.isEmpty() && !file.isEmpty() && base.front() == file.front() && QDir::isAbsolutePath(path);
        return shareAFolder ? relativePath.toStdString() : absolutePath;
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
    // every write, the fsync and the close checked, then a rename.
    return base::writeFileAtomically(
        QFile::encodeName(path).toStdString(),
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
}

base::Status saveProject(const Scene& scene, const QString& path) {
    return saveProject(scene.toData(), path);
}

} // namespace speculum::scene
