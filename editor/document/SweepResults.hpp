#pragma once

#include "accuracy/Results.hpp"
#include "base/Result.hpp"
#include "scene/model/SceneData.hpp"

#include <QString>
#include <QStringList>
#include <QUndoCommand>
#include <memory>
#include <optional>
#include <vector>

namespace speculum::scene {
class Scene;
}

namespace speculum::document {

// A `speculum bench` run as results.json records it: accuracy's own record type, the one the bench writes.
using SweepResults = accuracy::ResultsFile;

// Reads a bench results.json. Errors name the file and what is wrong ("results[3].psnr: expected a number").
base::Result<SweepResults> loadSweepResults(const QString& path);

// What "parallax on" means for the scene's reflector when it has no proxy of its own: the sweep's box
// around the scene (accuracy::sceneTraits), so the applied setting is the one that was measured. None
// when the reflector has a proxy of its own, or no box around the scene encloses it.
std::optional<scene::ReflectorParallax> sweepParallaxProxy(const render::FrameInput& scene);

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
SweepApplication
applySweepSettings(scene::Scene& scene, const accuracy::Settings& settings, const QString& text,
                   const std::optional<scene::ReflectorParallax>& derivedProxy = std::nullopt);

} // namespace speculum::document
