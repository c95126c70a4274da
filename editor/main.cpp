// speculum: the editor when run with no command (or a project file), the headless commands otherwise.
#include "app/AnimationCommand.hpp"
#include "app/CliOptions.hpp"
#include "app/HeadlessCommands.hpp"
#include "app/Interrupt.hpp"
#include "app/Progress.hpp"
#include "app/ProjectInput.hpp"
#include "app/StandardOutput.hpp"
#include "app/TimeCommand.hpp"
#include "editor/ui/Editor.hpp"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

bool hasEnvironment(const char* name) {
    const char* value = std::getenv(name);
    return value && *value;
}

// Qt aborts (a five-line message, exit 134) when it finds no platform to show windows on. Say it in one
// line instead, before Qt starts: no X11 or Wayland display, and no platform chosen (QT_QPA_PLATFORM, as
// the tests and screenshots use with "offscreen").
bool editorHasDisplay() {
    return hasEnvironment("DISPLAY") || hasEnvironment("WAYLAND_DISPLAY") ||
           hasEnvironment("QT_QPA_PLATFORM");
}

// A command run without the editor; nothing for Command::Editor.
std::optional<int> runCommand(const speculum::app::CliOptions& options) {
    using namespace speculum::app;
    switch (options.command) {
    case Command::Help:
        std::cout << options.helpText;
        return 0;
    case Command::Version:
        std::cout << "speculum " << SPECULUM_VERSION << "\n";
        return 0;
    case Command::Render:
        return runRender(options);
    case Command::Explain:
        return runExplain(options);
    case Command::Bench:
        return runBench(options);
    case Command::Time:
        return runTime(options);
    case Command::Export:
        return runExport(options);
    case Command::Join:
        return runJoin(options);
    case Command::Editor:
        break;
    }
    return std::nullopt;
}

int run(int argc, char** argv) {
    using namespace speculum::app;
    const std::vector<std::string> args(argv + 1, argv + argc);
    auto options = parseCommandLine(args);
    if (!options) {
        printError(options.error());
        return kUsageError;
    }
    Progress::setQuiet(options->quiet);
    if (options->command != Command::Editor) {
        // From here a Ctrl-C or SIGTERM stops the command at its next step (exit 130) instead of killing
        // it between a temporary file and its rename.
        const StopOnSignal stop;
        std::optional<int> status = runCommand(*options);
        if (StopOnSignal::requested())
            status = interrupted(commandWord(options->command),
                                 *status == 0 ? "its output was complete before it stopped"
                                              : "nothing was written");
        return finishStandardOutput(*status);
    }
    if (!editorHasDisplay()) {
        printError("the editor needs a display (DISPLAY and WAYLAND_DISPLAY are unset); without one, use "
                   "'speculum render PROJECT -o OUT.png' (see speculum --help)");
        return 1;
    }
    return speculum::ui::runEditor(argc, argv, options->project, options->recover);
}

} // namespace

int main(int argc, char** argv) {
    // A backstop: every command reports its errors itself, but an exception that still escapes (a library
    // that throws) ends in one line and status 1, not in std::terminate's abort.
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        speculum::app::printError(std::string("unexpected failure: ") + e.what());
    } catch (...) {
        speculum::app::printError("unexpected failure");
    }
    return 1;
}
