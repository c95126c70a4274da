#pragma once

#include "accuracy/Results.hpp"

#include <sstream>
#include <vector>

// A run joined from shards in the report (accuracy internal, for Report.cpp).
namespace speculum::accuracy {

// "## Where it ran": the shards a merged run joined (bench --merge), each one's host and renderer, whether
// its times come from one machine, and the shard that measured each configuration. Nothing for a run on one
// machine.
void shardsSection(std::ostringstream& md, const RunInfo& run, const std::vector<Record>& records);

} // namespace speculum::accuracy
