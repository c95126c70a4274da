#pragma once

#include "app/bench/Results.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace speculum::app::bench {

// "cube 128", "parallax on 256", "pcf 5", "tessellation 8": a configuration named for sentences.
std::string displayName(const Configuration& config);

// Writes one plot per swept family (plot-<family>.png: error against frame time, Pareto front marked,
// points labelled) into `folder`, then report.md: what each step of accuracy costs, in plain words,
// with the plots embedded. Needs a QGuiApplication for the plots' fonts.
render::Status writeReport(const std::filesystem::path& folder, const RunInfo& run,
                           const std::vector<Record>& records);

} // namespace speculum::app::bench
