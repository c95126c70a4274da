#pragma once

#include "editor/document/SceneData.hpp"
#include "render/Result.hpp"

#include <QString>
#include <QStringList>
#include <QUndoCommand>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace speculum::document {

class Scene;

// One configuration of a `speculum bench` run, as results.json records it.
struct SweepRecord {
    QString id;     // "envmap-cube-128"
    QString family; // "envmap", "mirror-depth", ...
    QString label;  // "128"
    QString series; // "cube"
    bool sceneSetting = false;
    // Every setting the scene has, as this configuration renders it: ("map", "cube"), ("pcf", "5"), ...
    std::vector<std::pair<QString, QString>> settings;
    std::optional<double> gpuMs; // absent where the run had no GPU timer
    double cpuMs = 0.0;
    double memoryBytes = 0.0;
    double rmse = 0.0;
    double psnr = 0.0;
    std::optional<double> psnrMirrors;
    std::optional<double> psnrReflector;

    // The time the chart plots: the GPU's where measured (what the settings cost the frame), else the CPU's.
    double ms() const { return gpuMs.value_or(cpuMs); }
};

struct SweepResults {
    QString scene; // the project the bench ran on
    QString size;  // "480x270"
    bool gpuTimes = false;
    std::vector<SweepRecord> records;
};

// Reads a bench results.json. Errors name the file and what is wrong ("results[3].psnr: expected a number").
render::Result<SweepResults> loadSweepResults(const QString& path);

// Indices of the records on the Pareto front of time against PSNR (nothing both faster and at least as
// accurate), ordered by time.
std::vector<std::size_t> paretoFront(const std::vector<SweepRecord>& records);

struct SweepApplication {
    std::unique_ptr<QUndoCommand> command; // null when nothing would change
    QStringList applied;                   // "map = cube", ...
    QStringList skipped;                   // "parallax on: ..." with the reason
};

// The undoable edit that gives the document a record's settings: the reflector's map, resolution, fill and
// parallax, every mirror's technique, settings.mirrorDepth, every shadowed light's PCF kernel and every
// built-in teapot's tessellation, each through the commands the inspector uses (one undo step named
// `text`). `derivedProxy` is the proxy the bench means by "parallax on" when the reflector has none of its
// own (a box around the scene); without it "parallax on" is skipped for such a reflector.
SweepApplication applySweepSettings(Scene& scene, const std::vector<std::pair<QString, QString>>& settings,
                                    const QString& text,
                                    const std::optional<ReflectorParallax>& derivedProxy = std::nullopt);

} // namespace speculum::document
