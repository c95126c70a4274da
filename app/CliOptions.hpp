#pragma once

#include "base/Result.hpp"
#include "base/Shard.hpp"
#include "render/plan/RenderOptions.hpp"

#include <optional>
#include <string>
#include <vector>

namespace speculum::app {

enum class Command { Editor, Render, Explain, Bench, Time, Export, Join, Help, Version };
// The word that names a command on the command line ("render"); "speculum" for the editor, help, version.
std::string commandWord(Command command);

// The parsed command line. Values are validated here, before any work, so
// bad input costs nothing and writes nothing.
struct CliOptions {
    Command command = Command::Editor;
    std::string project; // PROJECT, empty for the editor with a new scene
    // The editor's --recover FILE: a recovery file another editor left (RecoveryStore), restored as the
    // open document. Recovery's Restore in New Window starts an editor so.
    std::string recover;
    std::string output; // render -o, export -o
    std::string outDir; // bench --out
    int width = 1280;
    int height = 720;
    bool sizeGiven = false; // --size was on the command line (bench picks its own default otherwise)
    int ssaa = 1;
    double time = 0.0;
    bool reference = false;
    int samples = 16; // render --reference: paths per sample through rough reflections (TraceSettings)
    // render --screen-space-sources: screen-space mirrors in the colour of where their reflection comes from
    bool screenSpaceSources = false;
    bool json = false;
    bool quick = false;
    bool convergence = false; // bench --convergence: also study the reference's convergence
    int frame = 1; // explain: which of consecutive frames of the same scene to explain (reuse shows from 2)
    // explain --preview SCALE[,CUT] [--preview-drag]: the frame as the editor's preview of that level
    render::PreviewPolicy preview;
    // explain --pixel X,Y: explain this pixel of the frame (x from the left, y from the top): its exact path
    // beside the raster's recipe. Absent: explain the whole frame.
    std::optional<glm::ivec2> pixel;
    // render, bench, export: go on without a referenced model or texture that is missing or unreadable
    // (each is then a warning); without it such a file is an error and nothing is written.
    bool keepGoing = false;
    int frames = 100; // time: frames timed after the warm-up
    bool animated =
        false; // time, explain --frame: the animation plays (1/60 s a frame), maps redrawn as needed
    bool halfFloat = false; // time: the camera's view always in half float with its composite (to compare)
    bool quiet = false;     // --quiet: no progress on stderr (warnings and errors still)
    // render --frames A..B: an animation, frames A to B (both included); join --frames: the frames expected
    std::optional<std::pair<int, int>> frameRange;
    int fps = 24; // render, join: frames per second (--fps)
    bool fpsGiven = false;
    std::optional<double> turntable;    // render --turntable SECONDS: orbit the camera once in that time
    std::optional<base::Shard> shard;   // render, bench --shard K/N [--contiguous]
    std::vector<std::string> mergeDirs; // bench --merge DIR...
    std::string helpText;               // Help: what to print (the usage, or one command's own help)
};

// Exit status for a command line that cannot be parsed (as for the usage errors of most tools).
inline constexpr int kUsageError = 2;

// Errors are one line without the "speculum: error: " prefix; every value from the command line in them is
// escaped and shortened (base::quoted). A first word that is neither a command nor a path to a file is an
// unknown command, with the nearest command word suggested.
base::Result<CliOptions> parseCommandLine(const std::vector<std::string>& args);

std::string usageText();

} // namespace speculum::app
