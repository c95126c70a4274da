#pragma once

#include "base/Result.hpp"

#include <string>
#include <vector>

namespace speculum::base {

// A share of a list of independent items (the frames of a clip, the configurations of a sweep) for one of
// several machines: `speculum render --frames 0..239 --shard K/N` and `speculum bench --shard K/N`. K counts
// from 0, so a Slurm array task passes its SLURM_ARRAY_TASK_ID as it is. Interleaved shards take every Nth
// item from the Kth (each machine sees the whole clip's time range, so the shares cost about the same);
// contiguous ones take the Kth of N runs as even as can be (for a clip whose frames reuse the previous
// frame's maps, a run replays least).
struct Shard {
    int index = 0;
    int count = 1;
    bool contiguous = false;

    bool whole() const { return count == 1; }
};

inline constexpr int kMaxShards = 100000;

// "K/N" with 0 <= K < N <= kMaxShards; the error names the option ("--shard: ...").
Result<Shard> parseShard(const std::string& option, const std::string& text);

// The items of [0, itemCount) this shard takes, ascending.
std::vector<int> shardItems(const Shard& shard, int itemCount);

// "2/8" (and " contiguous" when so), as the shards' outputs record it.
std::string shardText(const Shard& shard);

} // namespace speculum::base
