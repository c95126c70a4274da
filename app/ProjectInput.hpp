#pragma once

#include "editor/document/MeshLibrary.hpp"
#include "editor/document/Scene.hpp"
#include "render/FrameInput.hpp"
#include "render/Result.hpp"

#include <memory>
#include <set>
#include <string>

namespace speculum::app {

// A project loaded for a headless command: the frame at one time, and the mesh library its meshes came
// from (kept, so that a command can ask for other tessellations of the same built-ins).
struct ProjectFrame {
    render::FrameInput input;
    std::unique_ptr<document::MeshLibrary> meshes;
    std::set<int> teapotTessellations; // of the built-in teapots the scene has (empty: none)
};

// Opens PROJECT into `scene`; load warnings go to stderr. Errors name the file and, for a bad file, the
// JSON path.
render::Status loadProjectScene(const std::string& project, document::Scene& scene);

// Loads PROJECT and evaluates it at `time`; warnings go to stderr. Errors name the file and, for a bad
// file, the JSON path.
render::Result<ProjectFrame> loadProjectFrame(const std::string& project, double time);

// Prints "speculum: warning: ..." lines on stderr.
void printWarnings(const std::vector<std::string>& warnings);

} // namespace speculum::app
