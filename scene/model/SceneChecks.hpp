#pragma once

#include "scene/model/SceneData.hpp"

#include <optional>
#include <string>

namespace speculum::scene {

// Rules over several numbers at once that both the project reader and the inspector apply, so that an
// edit can never make a value the reader refuses. Single numbers are checked against
// render/frame/SceneLimits.hpp where they are read or edited.

// The first problem of a camera: which field ("position", "target", "up", "fovY", "near", "far") and what
// is wrong with it, in the reader's words ("must differ from the camera position"). Computed so that it
// cannot overflow whatever the values (directions are scaled before lengths are taken), so the field
// named is the real cause.
struct FieldProblem {
    std::string field;
    std::string what;
};
std::optional<FieldProblem> cameraProblem(const CameraData& camera);

// The first problem of a saved editor view ("position" or "target"), by the camera's rules for those two
// points: coordinates within range, and apart by at least what the renderers can tell apart. The rest of
// the view is the scene camera's, so no other rule applies (a view straight down along the camera's up is
// fine). The reader refuses what this names, and the scene keeps no view that it names, so that a saved
// file always opens.
std::optional<FieldProblem> editorViewProblem(const EditorView& view);

// Numbers as messages show them: shortest round-trip form ("1e+12", "0.001").
std::string formatLimit(double value);

} // namespace speculum::scene
