#include "editor/document/SweepResults.hpp"

#include "accuracy/Sweep.hpp"
#include "accuracy/Variation.hpp"
#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "editor/document/Commands.hpp"
#include "scene/model/Scene.hpp"
#include "scene/project/JsonDuplicateKeys.hpp"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <map>

namespace speculum::document {

base::Result<SweepResults> loadSweepResults(const QString& path) {
    // The user picks this file: named escaped in messages, read only if it is a regular file (a FIFO
    // would block the GUI thread), and a repeated key is refused rather than half-read.
    const std::string name = base::printable(QFileInfo(path).fileName().toStdString());
    const base::Result<std::string> bytes =
        base::readRegularFile(QFile::encodeName(path).toStdString(), std::uintmax_t(256) << 20);
    if (!bytes) {
        return base::Error{name + ": " + bytes.error()};
    }
    QJsonParseError parseError;
    const QJsonDocument json = QJsonDocument::fromJson(QByteArray::fromStdString(*bytes), &parseError);
    if (json.isNull()) {
        return base::Error{name + ": not JSON (" + parseError.errorString().toStdString() + ")"};
    }
    if (const std::optional<std::string> duplicate = scene::findDuplicateKey(*bytes)) {
        return base::Error{name + ": " + *duplicate};
    }
    return accuracy::readJson(json.object(), name);
}

std::optional<scene::ReflectorParallax> sweepParallaxProxy(const render::FrameInput& scene) {
    const accuracy::SceneTraits traits = accuracy::sceneTraits(scene, std::nullopt);
    if (!traits.proxyMakesSense || traits.ownProxy)
        return std::nullopt;
    return traits.proxy;
}

namespace {

// The document's nodes and settings as a record's settings change them: edited copies, in file order.
class SweepEdits {
public:
    SweepEdits(scene::Scene& scene, const std::optional<scene::ReflectorParallax>& derivedProxy)
        : m_scene(scene)
        , m_derivedProxy(derivedProxy) {}

    // Applies one setting's change; the reason it cannot, or an empty string.
    std::string apply(const accuracy::Variation& v) {
        for (const accuracy::FieldAssignment& a : v.fields)
            if (std::string problem = field(a); !problem.empty())
                return problem;
        if (v.parallax)
            return parallax(*v.parallax);
        if (v.tessellation)
            return tessellation(*v.tessellation);
        if (v.roughness)
            return roughness(*v.roughness);
        return {};
    }

    std::unique_ptr<QUndoCommand> command(const QString& text) {
        // A later key of the record can undo an earlier one (map = cube, then map = the current type): a
        // node edited back to what it holds is no change, and an application of nothing gets no command.
        std::erase_if(m_order, [&](scene::NodeId id) {
            const scene::Node* node = m_scene.findNode(id);
            return node && m_edited.at(id) == node->data();
        });
        if (m_settings && *m_settings == m_scene.settings())
            m_settings.reset();
        if (m_order.empty() && !m_settings)
            return nullptr;
        auto command = std::make_unique<QUndoCommand>(text);
        for (scene::NodeId id : m_order)
            new SetNodeDataCommand(m_scene, id, m_edited.at(id), text, {}, command.get());
        if (m_settings)
            new SetSettingsCommand(m_scene, *m_settings, false, command.get());
        return command;
    }

private:
    scene::NodeData& edit(const scene::Node& node) {
        auto [it, fresh] = m_edited.try_emplace(node.id(), node.data());
        if (fresh)
            m_order.push_back(node.id());
        return it->second;
    }

    // What a node holds so far: earlier keys of the record may have edited it already.
    const scene::NodeData& sofar(const scene::Node& node) const {
        const auto it = m_edited.find(node.id());
        return it != m_edited.end() ? it->second : node.data();
    }

    // Calls f(node) for each node `has` picks (as its data is so far); returns how many.
    template <typename Has, typename F>
    int forEach(Has&& has, F&& f, bool firstOnly = false) {
        int count = 0;
        m_scene.forEachNode([&](const scene::Node& node) {
            if (has(sofar(node)) && !(firstOnly && count > 0)) {
                ++count;
                f(node);
            }
        });
        return count;
    }

    // A declared field on every component of its part, checked by its declaration.
    std::string field(const accuracy::FieldAssignment& a) {
        std::optional<std::string> problem;
        const auto set = [&](auto& component) {
            auto copy = component;
            if (auto p = render::setField(copy, a.field, a.value))
                problem = p;
            else
                component = copy;
        };
        switch (a.part) {
        case accuracy::Part::Settings: {
            scene::SceneSettings s = m_settings.value_or(m_scene.settings());
            set(s);
            m_settings = s;
            break;
        }
        case accuracy::Part::Mirrors:
            if (forEach([](const scene::NodeData& d) { return d.mirror.has_value(); },
                        [&](const scene::Node& n) { set(*edit(n).mirror); }) == 0)
                return "the scene has no planar mirror";
            break;
        case accuracy::Part::Reflector:
            // At most one reflector; the first is the one the snapshot draws.
            if (forEach([](const scene::NodeData& d) { return d.reflector.has_value(); },
                        [&](const scene::Node& n) { set(*edit(n).reflector); }, true) == 0)
                return "the scene has no curved reflector";
            break;
        case accuracy::Part::Shadows:
            if (forEach([](const scene::NodeData& d) { return d.light && d.light->shadows; },
                        [&](const scene::Node& n) { set(*edit(n).light->shadows); }) == 0)
                return "no light casts shadows";
            break;
        }
        return problem.value_or(std::string());
    }

    std::string parallax(bool on) {
        std::string problem;
        const auto set = [&](const scene::Node& n) {
            auto& proxy = edit(n).reflector->parallax;
            if (!on)
                proxy.reset();
            else if (!proxy && !m_derivedProxy)
                problem = "the reflector has no proxy of its own and none around the scene encloses it";
            else if (!proxy)
                proxy = m_derivedProxy;
        };
        if (forEach([](const scene::NodeData& d) { return d.reflector.has_value(); }, set, true) == 0)
            return "the scene has no curved reflector";
        return problem;
    }

    std::string tessellation(int n) {
        const auto teapot = [](const scene::NodeData& d) {
            return d.mesh && d.mesh->builtin == scene::BuiltinMesh::Teapot;
        };
        if (forEach(teapot, [&](const scene::Node& node) { edit(node).mesh->tessellation = n; }) == 0)
            return "the scene has no built-in teapot";
        return {};
    }

    // Every surface that is rough, at this roughness (the bench's rough references do the same).
    std::string roughness(double r) {
        const auto rough = [](const scene::NodeData& d) {
            return (d.mirror && d.mirror->roughness > 0.0) || (d.reflector && d.reflector->roughness > 0.0);
        };
        const auto set = [&](const scene::Node& node) {
            scene::NodeData& d = edit(node);
            if (d.mirror && d.mirror->roughness > 0.0)
                d.mirror->roughness = r;
            if (d.reflector && d.reflector->roughness > 0.0)
                d.reflector->roughness = r;
        };
        return forEach(rough, set) == 0 ? "the scene has no rough surface" : std::string();
    }

    scene::Scene& m_scene;
    std::optional<scene::ReflectorParallax> m_derivedProxy;
    std::map<scene::NodeId, scene::NodeData> m_edited;
    std::vector<scene::NodeId> m_order;
    std::optional<scene::SceneSettings> m_settings;
};

} // namespace

SweepApplication applySweepSettings(scene::Scene& scene, const accuracy::Settings& settings,
                                    const QString& text,
                                    const std::optional<scene::ReflectorParallax>& derivedProxy) {
    SweepApplication out;
    SweepEdits edits(scene, derivedProxy);
    for (const auto& [column, value] : settings) {
        // Both come from the results file: shown escaped in the applied / skipped lists.
        const QString what =
            QString::fromStdString(base::printable(column, 40) + " = " + base::printable(value, 40));
        const base::Result<accuracy::Variation> change = accuracy::variationOf(column, value);
        const std::string problem = change ? edits.apply(*change) : change.error();
        if (problem.empty())
            out.applied << what;
        else
            out.skipped << what + QStringLiteral(": ") + QString::fromStdString(problem);
    }
    out.command = edits.command(text);
    return out;
}

} // namespace speculum::document
