#pragma once

#include "accuracy/Plot.hpp"
#include "accuracy/Results.hpp"

#include <sstream>

// The convergence study in the report (accuracy internal, for Report.cpp).
namespace speculum::accuracy {

// Noise and error of the reference against paths per rough pixel, log-log, with the slope −½ that Monte
// Carlo noise follows drawn through the first point.
PlotSpec convergencePlot(const ConvergenceStudy& study, const RunInfo& run);

// "## Convergence of the reference": the table, the plot, the slope and the sample count the run needs.
void convergenceSection(std::ostringstream& md, const ConvergenceStudy& study);

} // namespace speculum::accuracy
