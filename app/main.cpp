// speculum: the editor when run with no command (or a project file), the headless commands otherwise.
#include "app/CliOptions.hpp"
#include "app/HeadlessCommands.hpp"
#include "editor/ui/Editor.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    using namespace speculum::app;
    const std::vector<std::string> args(argv + 1, argv + argc);
    auto options = parseCommandLine(args);
    if (!options) {
        std::cerr << "speculum: " << options.error() << "\n";
        return 2;
    }
    switch (options->command) {
    case Command::Help:
        std::cout << usageText();
        return 0;
    case Command::Version:
        std::cout << "speculum " << SPECULUM_VERSION << "\n";
        return 0;
    case Command::Render:
        return runRender(*options);
    case Command::Explain:
        return runExplain(*options);
    case Command::Bench:
        return runBench(*options);
    case Command::Export:
        return runExport(*options);
    case Command::Editor:
        break;
    }
    return speculum::ui::runEditor(argc, argv, options->project);
}
