#include "accuracy/ReportShards.hpp"

#include "accuracy/Report.hpp"

#include <set>

namespace speculum::accuracy {

namespace {

// The machines (host and renderer) the shards ran on.
std::size_t machineCount(const RunInfo& run) {
    std::set<std::pair<std::string, std::string>> machines;
    for (const ShardOrigin& o : run.shards)
        machines.emplace(o.host, o.renderer);
    return machines.size();
}

} // namespace

void shardsSection(std::ostringstream& md, const RunInfo& run, const std::vector<Record>& records) {
    if (run.shards.empty())
        return;
    md << "## Where it ran\n\nThis run was measured in " << run.shards.size()
       << " shards (`bench --shard K/N`) and joined by `bench --merge`. The errors, the ties and each "
          "configuration's distance to its family's best are what a run on one machine finds (the merge "
          "compares the frames the shards kept); the times were measured where each configuration ran, "
          "every shard timing its own configurations in rounds of its own.\n\n";
    md << "| shard | host | renderer | configurations |\n|---|---|---|---|\n";
    for (const ShardOrigin& o : run.shards)
        md << "| " << o.shard << " | " << o.host << " | " << o.renderer << " | " << o.configurations
           << " |\n";
    md << "\n";
    if (run.timesFromSeveralMachines())
        md << "**The times come from " << machineCount(run)
           << " different machines.** Compare a time only with those measured on the same machine; the "
              "plots, "
              "the Pareto fronts and the cheapest picks set them side by side as if one machine had measured "
              "them all.\n\n";
    else
        md << "Every shard ran on the same machine, but in runs of its own: compare times across shards "
              "with the care times of separate runs need.\n\n";
    md << "| configuration | shard | host |\n|---|---|---|\n";
    for (const Record& r : records)
        md << "| " << displayName(r.config) << " (`" << r.config.id << "`) | "
           << (r.ranOn ? r.ranOn->shard : std::string("–")) << " | "
           << (r.ranOn ? r.ranOn->host : std::string("–")) << " |\n";
    md << "\n";
}

} // namespace speculum::accuracy
