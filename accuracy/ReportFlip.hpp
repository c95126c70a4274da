#pragma once

#include "accuracy/Analysis.hpp"
#include "accuracy/Plot.hpp"
#include "accuracy/Results.hpp"

#include <optional>
#include <string>
#include <vector>

// The report's second judge: what FLIP says about a family beside what PSNR says, and the ties the
// reference's noise leaves (accuracy internal, for Report.cpp).
namespace speculum::accuracy {

struct FlipView {
    std::vector<Point> points; // flipPoint(cost, mean FLIP on the family's pixels), per row
    std::vector<std::size_t> front;
    std::size_t best = 0;
    // The cheapest a viewer cannot tell from the best: Record::flipToBest within one JND (flipJnd).
    std::optional<std::size_t> cheapest;
};

// None when a row lacks perceptual figures (a results.json from before they were measured).
std::optional<FlipView> analyseFlip(const std::vector<const Record*>& rows,
                                    const std::vector<Point>& psnrPoints, Metric metric);

// What the PSNR ranking of one family was, for flipLines to compare with.
struct PsnrRanking {
    std::vector<std::size_t> front;
    std::size_t best = 0;
    std::optional<std::size_t> cheapest; // within 1 dB of the best
    std::string costName;                // "GPU" or "CPU"
};

// The FLIP findings, Markdown: the best and the cheapest that looks the same as the best, the steps of FLIP's
// Pareto front, and each place where FLIP and PSNR disagree (a different best, a different cheapest pick,
// settings on one front but not the other).
std::vector<std::string> flipLines(const std::vector<const Record*>& rows, const FlipView& flip,
                                   const PsnrRanking& psnr);

// ", tied within the reference's noise with **a** and **b**" for a row whose error the reference cannot
// tell from others of its family; empty otherwise.
std::string tiedNote(const Record& record, const std::vector<const Record*>& rows);

// FLIP against cost, the axis downward (lower is better), the FLIP front marked.
PlotSpec flipPlot(const PlotSpec& psnrPlot, const FlipView& flip, Metric metric);

} // namespace speculum::accuracy
