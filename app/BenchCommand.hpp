#pragma once

#include "base/Shard.hpp"

#include <optional>
#include <string>
#include <vector>

namespace speculum::app::bench {

struct Options {
    std::string project;
    std::string outDir;
    bool quick = false;
    bool convergence = false; // also study the reference's convergence (accuracy::studyConvergence)
    int width = 0;            // 0: the default size (1280x720, or 480x270 with quick)
    int height = 0;
    bool keepGoing = false; // go on without a missing or unreadable model or texture (a warning each)
    // --shard K/N: measure only this share of the sweep's configurations (base::shardItems over them).
    std::optional<base::Shard> shard;
    // --merge DIR...: join the results of shard runs (each DIR an --out of `bench --shard`) into outDir.
    std::vector<std::string> mergeDirs;
};

// `speculum bench PROJECT --out DIR [--quick] [--convergence] [--size WxH]`: loads the project, runs the
// accuracy sweep (accuracy::runSweep) on a headless context and writes results.csv, results.json, the plots,
// the images and report.md into DIR (all or nothing). Progress goes to stderr, the report's path to stdout.
// With --shard K/N it measures only its share of the configurations and writes results.json and
// results.csv of that share, its images and, under shard/, its frames and references kept exactly (for the
// merge), but no report; results.json's path goes to stdout. With --merge DIR... it reads the shards'
// folders (accuracy::mergeShards) and writes into --out what a one-machine run writes, the errors the
// same and the times those each shard measured, saying where each configuration ran; the shards'
// folders are left as they are.
// Returns the exit status: 0, or 1 after one line on stderr (130 when interrupted).
int run(const Options& options);

} // namespace speculum::app::bench
