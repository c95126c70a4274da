#include "editor/document/SweepResults.hpp"

#include "accuracy/Sweep.hpp"
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
    if (!traits.proxyMakesSense || traits.ownProxy) {
        return std::nullopt;
    }
    scene::ReflectorParallax proxy;
    proxy.shape = scene::ParallaxShape::Box;
    proxy.min = traits.proxy.min;
    proxy.max = traits.proxy.max;
    return proxy;
}

SweepApplication applySweepSettings(scene::Scene& scene, const accuracy::Settings& settings,
                                    const QString& text,
                                    const std::optional<scene::ReflectorParallax>& derivedProxy) {
    SweepApplication out;
    // Edited copies of the nodes that change, in file order; settings.mirrorDepth separately.
    std::map<scene::NodeId, scene::NodeData> edited;
    std::vector<scene::NodeId> order;
    auto edit = [&](const scene::Node& node) -> scene::NodeData& {
        auto [it, fresh] = edited.try_emplace(node.id(), node.data());
        if (fresh) {
            order.push_back(node.id());
        }
        return it->second;
    };
    // What a node holds so far: earlier keys of the record may have edited it already.
    auto sofar = [&](const scene::Node& node) -> const scene::NodeData& {
        const auto it = edited.find(node.id());
        return it != edited.end() ? it->second : node.data();
    };
    std::optional<scene::SceneSettings> sceneSettings;

    for (const auto& setting : settings) {
        // Named copies, not a structured binding: clang 14 (the fuzz and sanitizer builds) cannot
        // capture structured bindings in the lambdas below.
        const QString key = QString::fromStdString(setting.first);
        const QString value = QString::fromStdString(setting.second);
        // Both come from the results file: shown escaped in the applied / skipped lists.
        const QString what = QString::fromStdString(base::printable(key.toStdString(), 40) + " = " +
                                                    base::printable(value.toStdString(), 40));
        bool isInt = false;
        const int n = value.toInt(&isInt);
        int matched = 0;
        QString problem;
        if (key == QStringLiteral("map") || key == QStringLiteral("resolution") ||
            key == QStringLiteral("fill") || key == QStringLiteral("parallax")) {
            scene.forEachNode([&](const scene::Node& node) {
                if (!node.data().reflector || matched > 0) {
                    return; // at most one reflector; the first is the one the snapshot draws
                }
                ++matched;
                const scene::ReflectorComponent& current = *sofar(node).reflector;
                scene::ReflectorComponent r = current;
                if (key == QStringLiteral("map")) {
                    const auto map = scene::reflectorMapFromString(value.toStdString());
                    map ? void(r.map = *map) : void(problem = QStringLiteral("unknown map type"));
                } else if (key == QStringLiteral("resolution")) {
                    isInt&& n >= 8 && n <= 8192
                        ? void(r.resolution = n)
                        : void(problem = QStringLiteral("not a resolution in 8..8192"));
                } else if (key == QStringLiteral("fill")) {
                    const auto fill = scene::reflectorFillFromString(value.toStdString());
                    fill ? void(r.fill = *fill) : void(problem = QStringLiteral("unknown fill"));
                } else if (value == QStringLiteral("off")) {
                    r.parallax.reset();
                } else if (value == QStringLiteral("on")) {
                    if (!r.parallax && !derivedProxy) {
                        problem = QStringLiteral("the reflector has no proxy of its own and none around the "
                                                 "scene encloses it");
                    } else if (!r.parallax) {
                        r.parallax = derivedProxy;
                    }
                } else {
                    problem = QStringLiteral("expected on or off");
                }
                if (problem.isEmpty() && !(r == current)) {
                    edit(node).reflector = r;
                }
            });
            if (matched == 0) {
                problem = QStringLiteral("the scene has no curved reflector");
            }
        } else if (key == QStringLiteral("technique")) {
            const auto technique = scene::mirrorTechniqueFromString(value.toStdString());
            scene.forEachNode([&](const scene::Node& node) {
                if (node.data().mirror) {
                    ++matched;
                    if (technique && sofar(node).mirror->technique != *technique) {
                        edit(node).mirror->technique = *technique;
                    }
                }
            });
            problem = !technique     ? QStringLiteral("unknown technique")
                      : matched == 0 ? QStringLiteral("the scene has no planar mirror")
                                     : QString();
        } else if (key == QStringLiteral("mirrorDepth")) {
            if (isInt && n >= 0 && n <= 16) {
                scene::SceneSettings s = sceneSettings.value_or(scene.settings());
                s.mirrorDepth = n;
                sceneSettings = s;
            } else {
                problem = QStringLiteral("not a depth in 0..16");
            }
        } else if (key == QStringLiteral("pcf")) {
            const bool valid = isInt && n >= 1 && n <= 15 && n % 2 == 1;
            scene.forEachNode([&](const scene::Node& node) {
                if (node.data().light && node.data().light->shadows) {
                    ++matched;
                    if (valid && sofar(node).light->shadows->pcf != n) {
                        edit(node).light->shadows->pcf = n;
                    }
                }
            });
            problem = !valid         ? QStringLiteral("not an odd kernel in 1..15")
                      : matched == 0 ? QStringLiteral("no light casts shadows")
                                     : QString();
        } else if (key == QStringLiteral("tessellation")) {
            const bool valid = isInt && n >= 1 && n <= 64;
            scene.forEachNode([&](const scene::Node& node) {
                const auto& mesh = node.data().mesh;
                if (mesh && mesh->builtin == scene::BuiltinMesh::Teapot) {
                    ++matched;
                    if (valid && sofar(node).mesh->tessellation != n) {
                        edit(node).mesh->tessellation = n;
                    }
                }
            });
            problem = !valid         ? QStringLiteral("not a tessellation in 1..64")
                      : matched == 0 ? QStringLiteral("the scene has no built-in teapot")
                                     : QString();
        } else if (key == QStringLiteral("reflectedDetail")) {
            if (value == QStringLiteral("simplified") || value == QStringLiteral("full")) {
                scene::SceneSettings s = sceneSettings.value_or(scene.settings());
                s.simplifyReflections = value == QStringLiteral("simplified");
                sceneSettings = s;
            } else {
                problem = QStringLiteral("expected simplified or full");
            }
        } else {
            problem = QStringLiteral("this version does not know the setting");
        }
        (problem.isEmpty() ? out.applied : out.skipped)
            << (problem.isEmpty() ? what : what + QStringLiteral(": ") + problem);
    }

    // A later key of the record can undo an earlier one (map = cube, then map = the current type): a node
    // edited back to what it holds is no change, and an application of nothing gets no command.
    std::erase_if(order, [&](scene::NodeId id) {
        const scene::Node* node = scene.findNode(id);
        return node && edited.at(id) == node->data();
    });
    if (sceneSettings && *sceneSettings == scene.settings()) {
        sceneSettings.reset();
    }
    if (order.empty() && !sceneSettings) {
        return out;
    }
    out.command = std::make_unique<QUndoCommand>(text);
    for (scene::NodeId id : order) {
        new SetNodeDataCommand(scene, id, edited.at(id), text, {}, out.command.get());
    }
    if (sceneSettings) {
        new SetSettingsCommand(scene, *sceneSettings, false, out.command.get());
    }
    return out;
}

} // namespace speculum::document
