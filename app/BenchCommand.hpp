#pragma once

#include <string>

namespace speculum::app::bench {

struct Options {
    std::string project;
    std::string outDir;
    bool quick = false;
    bool convergence = false; // also study the reference's convergence (accuracy::studyConvergence)
    int width = 0;            // 0: the default size (1280x720, or 480x270 with quick)
    int height = 0;
    bool keepGoing = false; // go on without a missing or unreadable model or texture (a warning each)
};

// `speculum bench PROJECT --out DIR [--quick] [--convergence] [--size WxH]`: loads the project, runs the
// accuracy sweep (accuracy::runSweep) on a headless context and writes results.csv, results.json, the plots,
// the images and report.md into DIR (all or nothing). Progress goes to stderr, the report's path to stdout.
// Returns the exit status: 0, or 1 after one line on stderr (130 when interrupted).
int run(const Options& options);

} // namespace speculum::app::bench
