#pragma once

#include <string>

namespace speculum::app::bench {

struct Options {
    std::string project;
    std::string outDir;
    bool quick = false;
    int width = 0; // 0: the default size (1280x720, or 480x270 with quick)
    int height = 0;
    bool keepGoing = false; // go on without a missing or unreadable model or texture (a warning each)
};

// `speculum bench PROJECT --out DIR [--quick] [--size WxH]`: sweeps the settings the scene uses, measures
// each configuration's time, memory and error against the exact tracer, and writes results.csv,
// results.json, the plots, the images and report.md into DIR (all or nothing). Progress goes to stderr,
// the report's path to stdout. Returns the exit status: 0, or 1 after one line on stderr.
int run(const Options& options);

} // namespace speculum::app::bench
