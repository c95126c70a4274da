#include "editor/document/SweepResults.hpp"

#include "editor/document/Commands.hpp"
#include "editor/document/JsonDuplicateKeys.hpp"
#include "editor/document/Scene.hpp"
#include "render/io/FileKind.hpp"
#include "render/io/Printable.hpp"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace speculum::document {

namespace {

std::optional<double> number(const QJsonValue& v) {
    if (v.isDouble() && std::isfinite(v.toDouble())) {
        return v.toDouble();
    }
    return std::nullopt;
}

} // namespace

render::Result<SweepResults> loadSweepResults(const QString& path) {
    // The user picks this file: named escaped in messages, read only if it is a regular file (a FIFO
    // would block the GUI thread), and a repeated key is refused rather than half-read.
    const std::string name = render::printable(QFileInfo(path).fileName().toStdString());
    const render::Result<std::string> bytes =
        render::readRegularFile(QFile::encodeName(path).toStdString(), std::uintmax_t(256) << 20);
    if (!bytes) {
        return render::Error{name + ": " + bytes.error()};
    }
    QJsonParseError parseError;
    const QJsonDocument json = QJsonDocument::fromJson(QByteArray::fromStdString(*bytes), &parseError);
    if (json.isNull()) {
        return render::Error{name + ": not JSON (" + parseError.errorString().toStdString() + ")"};
    }
    if (const std::optional<std::string> duplicate = findDuplicateKey(*bytes)) {
        return render::Error{name + ": " + *duplicate};
    }
    const QJsonObject root = json.object();
    if (root.value(QStringLiteral("format")).toString() != QStringLiteral("speculum-bench")) {
        return render::Error{name + ": not a speculum bench result (format is not \"speculum-bench\")"};
    }
    SweepResults out;
    out.scene = root.value(QStringLiteral("scene")).toString();
    const QJsonValue size = root.value(QStringLiteral("size"));
    out.size =
        size.isArray()
            ? QStringLiteral("%1x%2").arg(size.toArray().at(0).toInt()).arg(size.toArray().at(1).toInt())
            : size.toString();
    const QJsonArray results = root.value(QStringLiteral("results")).toArray();
    for (qsizetype i = 0; i < results.size(); ++i) {
        const QJsonObject r = results.at(i).toObject();
        const std::string where = name + ": results[" + std::to_string(i) + "].";
        SweepRecord record;
        record.id = r.value(QStringLiteral("id")).toString();
        record.family = r.value(QStringLiteral("family")).toString();
        record.label = r.value(QStringLiteral("label")).toString();
        record.series = r.value(QStringLiteral("series")).toString();
        record.sceneSetting = r.value(QStringLiteral("sceneSetting")).toBool();
        const QJsonObject settings = r.value(QStringLiteral("settings")).toObject();
        for (auto it = settings.begin(); it != settings.end(); ++it) {
            const QString value = it->isDouble() ? QString::number(it->toDouble()) : it->toString();
            record.settings.emplace_back(it.key(), value);
        }
        record.gpuMs = number(r.value(QStringLiteral("gpuMs")));
        const auto cpu = number(r.value(QStringLiteral("cpuMs")));
        const auto psnr = number(r.value(QStringLiteral("psnr")));
        const auto rmse = number(r.value(QStringLiteral("rmse")));
        if (!cpu || !psnr || !rmse) {
            return render::Error{where + (!cpu ? "cpuMs" : !psnr ? "psnr" : "rmse") + ": expected a number"};
        }
        if (record.family.isEmpty()) {
            return render::Error{where + "family: expected a name"};
        }
        record.cpuMs = *cpu;
        record.psnr = *psnr;
        record.rmse = *rmse;
        record.memoryBytes = number(r.value(QStringLiteral("memoryBytes"))).value_or(0.0);
        record.psnrMirrors = number(r.value(QStringLiteral("psnrMirrors")));
        record.psnrReflector = number(r.value(QStringLiteral("psnrReflector")));
        out.gpuTimes = out.gpuTimes || record.gpuMs.has_value();
        out.records.push_back(std::move(record));
    }
    if (out.records.empty()) {
        return render::Error{name + ": no results"};
    }
    return out;
}

std::vector<std::size_t> paretoFront(const std::vector<SweepRecord>& records) {
    std::vector<std::size_t> order(records.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return records[a].ms() != records[b].ms() ? records[a].ms() < records[b].ms()
                                                  : records[a].psnr > records[b].psnr;
    });
    std::vector<std::size_t> front;
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t i : order) {
        if (records[i].psnr > best) { // better than everything at least as fast
            front.push_back(i);
            best = records[i].psnr;
        }
    }
    return front;
}

SweepApplication applySweepSettings(Scene& scene, const std::vector<std::pair<QString, QString>>& settings,
                                    const QString& text,
                                    const std::optional<ReflectorParallax>& derivedProxy) {
    SweepApplication out;
    // Edited copies of the nodes that change, in file order; settings.mirrorDepth separately.
    std::map<NodeId, NodeData> edited;
    std::vector<NodeId> order;
    auto edit = [&](const Node& node) -> NodeData& {
        auto [it, fresh] = edited.try_emplace(node.id(), node.data());
        if (fresh) {
            order.push_back(node.id());
        }
        return it->second;
    };
    std::optional<SceneSettings> sceneSettings;

    for (const auto& setting : settings) {
        // Named references, not a structured binding: clang 14 (the fuzz and sanitizer builds) cannot
        // capture structured bindings in the lambdas below.
        const QString& key = setting.first;
        const QString& value = setting.second;
        // Both come from the results file: shown escaped in the applied / skipped lists.
        const QString what = QString::fromStdString(render::printable(key.toStdString(), 40) + " = " +
                                                    render::printable(value.toStdString(), 40));
        bool isInt = false;
        const int n = value.toInt(&isInt);
        int matched = 0;
        QString problem;
        if (key == QStringLiteral("map") || key == QStringLiteral("resolution") ||
            key == QStringLiteral("fill") || key == QStringLiteral("parallax")) {
            scene.forEachNode([&](const Node& node) {
                if (!node.data().reflector || matched > 0) {
                    return; // at most one reflector; the first is the one the snapshot draws
                }
                ++matched;
                // Earlier keys of this record may have edited it already.
                const auto done = edited.find(node.id());
                const ReflectorComponent& current =
                    done != edited.end() ? *done->second.reflector : *node.data().reflector;
                ReflectorComponent r = current;
                if (key == QStringLiteral("map")) {
                    const auto map = reflectorMapFromString(value.toStdString());
                    map ? void(r.map = *map) : void(problem = QStringLiteral("unknown map type"));
                } else if (key == QStringLiteral("resolution")) {
                    isInt&& n >= 8 && n <= 8192
                        ? void(r.resolution = n)
                        : void(problem = QStringLiteral("not a resolution in 8..8192"));
                } else if (key == QStringLiteral("fill")) {
                    const auto fill = reflectorFillFromString(value.toStdString());
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
            const auto technique = mirrorTechniqueFromString(value.toStdString());
            scene.forEachNode([&](const Node& node) {
                if (node.data().mirror) {
                    ++matched;
                    if (technique && node.data().mirror->technique != *technique) {
                        edit(node).mirror->technique = *technique;
                    }
                }
            });
            problem = !technique     ? QStringLiteral("unknown technique")
                      : matched == 0 ? QStringLiteral("the scene has no planar mirror")
                                     : QString();
        } else if (key == QStringLiteral("mirrorDepth")) {
            if (isInt && n >= 0 && n <= 16) {
                SceneSettings s = scene.settings();
                s.mirrorDepth = n;
                if (!(s == scene.settings())) {
                    sceneSettings = s;
                }
            } else {
                problem = QStringLiteral("not a depth in 0..16");
            }
        } else if (key == QStringLiteral("pcf")) {
            const bool valid = isInt && n >= 1 && n <= 15 && n % 2 == 1;
            scene.forEachNode([&](const Node& node) {
                if (node.data().light && node.data().light->shadows) {
                    ++matched;
                    if (valid && node.data().light->shadows->pcf != n) {
                        edit(node).light->shadows->pcf = n;
                    }
                }
            });
            problem = !valid         ? QStringLiteral("not an odd kernel in 1..15")
                      : matched == 0 ? QStringLiteral("no light casts shadows")
                                     : QString();
        } else if (key == QStringLiteral("tessellation")) {
            const bool valid = isInt && n >= 1 && n <= 64;
            scene.forEachNode([&](const Node& node) {
                const auto& mesh = node.data().mesh;
                if (mesh && mesh->builtin == BuiltinMesh::Teapot) {
                    ++matched;
                    if (valid && mesh->tessellation != n) {
                        edit(node).mesh->tessellation = n;
                    }
                }
            });
            problem = !valid         ? QStringLiteral("not a tessellation in 1..64")
                      : matched == 0 ? QStringLiteral("the scene has no built-in teapot")
                                     : QString();
        } else {
            problem = QStringLiteral("this version does not know the setting");
        }
        (problem.isEmpty() ? out.applied : out.skipped)
            << (problem.isEmpty() ? what : what + QStringLiteral(": ") + problem);
    }

    if (order.empty() && !sceneSettings) {
        return out;
    }
    out.command = std::make_unique<QUndoCommand>(text);
    for (NodeId id : order) {
        new SetNodeDataCommand(scene, id, edited.at(id), text, {}, out.command.get());
    }
    if (sceneSettings) {
        new SetSettingsCommand(scene, *sceneSettings, false, out.command.get());
    }
    return out;
}

} // namespace speculum::document
