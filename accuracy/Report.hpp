#pragma once

#include "accuracy/Results.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace speculum::accuracy {

// "cube 128", "parallax on 256", "pcf 5", "tessellation 8": a configuration named for sentences.
std::string displayName(const Configuration& config);

// What the sweep found for one family, in plain words: the best setting, the cheapest within 1 dB of it,
// the scene's own, each step along the Pareto front, and notes (a family whose settings hardly change the
// error; parallax mattering more than resolution). One finding a line, in Markdown (settings in **bold**):
// the same lines report.md has under the family's heading.
struct FamilyFindings {
    Family family = Family::Scene;
    std::string title;    // "Environment map: type, fill and resolution"
    std::string judgedBy; // "PSNR on reflector pixels": the pixels the family's settings change
    std::vector<std::string> lines;
};

// The findings of every swept family, in the report's order (families the records lack are left out).
// `furnace`: the run's white-furnace rows, which the glossy family's lines cite.
std::vector<FamilyFindings> findings(const std::vector<Record>& records,
                                     const std::vector<FurnaceRow>& furnace = {});

// Writes one plot per swept family (plot-<family>.png: error against frame time, Pareto front marked,
// points labelled) into `folder`, then report.md: what each step of accuracy costs, in plain words,
// with the plots embedded. Needs a QGuiApplication for the plots' fonts.
base::Status writeReport(const std::filesystem::path& folder, const RunInfo& run,
                         const std::vector<Record>& records);

} // namespace speculum::accuracy
