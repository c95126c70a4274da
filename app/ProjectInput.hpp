#pragma once

#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"
#include "scene/model/Warning.hpp"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace speculum::render {
class Renderer;
}

namespace speculum::app {

// What a command does with a model or texture the scene names that is missing or cannot be read.
enum class MissingFiles {
    Fail,      // an error naming the node and the file (render, bench, export by default)
    KeepGoing, // a warning per file, and the frame goes on without it (--keep-going)
    Report,    // left to the renderer, which lists it among the frame's warnings (explain)
};

// The texture files a project names, each decoded once when its files are checked: what decoded, for the
// frame to draw without reading the file again, and what did not.
struct CheckedTextures {
    std::map<std::string, std::shared_ptr<const render::TextureImage>> decoded;
    std::set<std::string> bad; // paths that are missing or do not decode
    bool dropBad = false;      // the frame goes on without them (KeepGoing) rather than showing the checker
};

// Every file a project reads: the project itself, then the models and textures its nodes name (absolute),
// and the problems found with them ("node 'Box': texture '/a/b.png': file not found").
struct ProjectFiles {
    std::vector<std::string> inputs;
    std::vector<std::string> problems;
    std::vector<std::string> textureProblems; // the texture ones (the snapshot itself warns of models)
    std::vector<std::string> textureNotes;    // textures read smaller than their files, one line each
    CheckedTextures textures;
};

// A project loaded for a headless command: the frame at one time, and the mesh library its meshes came
// from (kept, so that a command can ask for other tessellations of the same built-ins).
// Scene time between frames where a command plays the animation (`time --animated`,
// `explain --frame N --animated`), as the playing editor's 60 frames a second.
inline constexpr double kAnimationFrameStep = 1.0 / 60.0;

struct ProjectFrame {
    render::FrameInput input;
    std::unique_ptr<scene::MeshLibrary> meshes;
    std::set<int> teapotTessellations; // of the built-in teapots the scene has (empty: none)
    std::vector<std::string> inputs;   // as ProjectFiles::inputs: what no output may overwrite
    // The scene itself, for commands that evaluate it at other times too (`time --animated`).
    std::unique_ptr<scene::Scene> scene;
    CheckedTextures textures; // for useCheckedTextures() on each later snapshot
};

// Opens PROJECT into `scene`; load warnings go to stderr. Errors name the file and, for a bad file, the
// JSON path.
base::Status loadProjectScene(const std::string& project, scene::Scene& scene);

// The models and textures `scene` names, each imported (into `meshes`, so a later snapshot reuses it) or
// decoded (a texture file that exists but does not decode is as much a problem as a missing one). The
// readers' notes on the models are appended to `warnings`.
ProjectFiles checkProjectFiles(const std::string& project, const scene::Scene& scene,
                               scene::MeshLibrary& meshes, std::vector<scene::Warning>& warnings);

// Applies `policy` to the problems found: Fail gives one error line (the first problem, how many more, and
// the option that goes on); KeepGoing prints each as a warning; Report does nothing.
base::Status applyMissingFiles(const ProjectFiles& files, MissingFiles policy);

// Gives each texture of `frame` named by a path the image decoded when the files were checked, and clears
// the bad ones when `textures.dropBad` (the warning was given then; the renderer would repeat it).
void useCheckedTextures(render::FrameInput& frame, const CheckedTextures& textures);

// Loads PROJECT and evaluates it at `time`; warnings go to stderr. Errors name the file and, for a bad
// file, the JSON path; with MissingFiles::Fail, a missing or unreadable model or texture is an error too.
base::Result<ProjectFrame> loadProjectFrame(const std::string& project, double time,
                                            MissingFiles policy = MissingFiles::Report);

// The message made safe for one line on a terminal: control characters become visible escapes. A
// backstop for text from deeper layers (renderer warnings, library errors) that may quote a name raw;
// the layers themselves quote with base::quoted.
std::string oneLine(std::string_view message);

// Prints "speculum: warning: ..." lines on stderr, one line each (a scene warning's message).
// "speculum: warning: ..." on stderr, each line once per run.
void printWarnings(const std::vector<std::string>& warnings);
// Prints each frame plan's warnings as soon as the frame is planned, before it is drawn: a map that will
// take minutes is said before the wait, not after it.
void warnAsPlanned(render::Renderer& renderer);
void printWarnings(const std::vector<scene::Warning>& warnings);

// Prints "speculum: error: ..." on stderr, one line.
void printError(const std::string& message);

} // namespace speculum::app
