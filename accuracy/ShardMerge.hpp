#pragma once

#include "accuracy/Results.hpp"
#include "base/Result.hpp"

#include <filesystem>
#include <map>
#include <vector>

namespace speculum::accuracy {

// A shard run's output folder (bench --shard K/N --out DIR), read back for the merge.
struct ShardFolder {
    std::filesystem::path folder;
    RunInfo run; // run.shard is set
    std::vector<Record> records;
};

// Reads DIR/results.json. Errors, one line naming the folder: no results.json, not JSON, a whole run's
// output rather than a shard's, a record the shard's share does not hold.
base::Result<ShardFolder> readShardFolder(const std::filesystem::path& folder);

// The shards joined into one run, as a run on one machine would have it.
struct MergedShards {
    // The run: the references in the order the whole run traces them, the furnace and the convergence study
    // of the shard that ran them, RunInfo::shards (each shard's host and renderer) and the renderers.
    RunInfo run;
    std::vector<Record>
        records; // in the whole sweep's order, each with its RanOn; no ties nor flipToBest yet
    std::vector<std::filesystem::path> recordFolder;                // per record: the shard that measured it
    std::map<ReferenceKind, std::filesystem::path> referenceFolder; // the shard whose trace each one is
    std::string projectDigest;
};

// Reads every folder and joins them. Errors, one line each: a folder that is not a shard's output; shards
// of different runs (another N, another kind of shard, size, quick, project file or configuration list);
// a configuration two folders hold (naming both); one no folder holds (naming the shard that measures it).
base::Result<MergedShards> mergeShards(const std::vector<std::filesystem::path>& folders);

} // namespace speculum::accuracy
