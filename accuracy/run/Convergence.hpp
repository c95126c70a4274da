#pragma once

#include "accuracy/Results.hpp"
#include "accuracy/run/SweepRun.hpp"
#include "base/Result.hpp"

#include <functional>
#include <string>
#include <vector>

namespace speculum::accuracy {

// The paths per rough pixel the study traces: ×4 each step, so the noise should halve each step.
std::vector<int> convergenceSamples(bool quick); // 4 … 1024, quick 4 … 256

// Is the reference good enough? Traces the scene's reference at each of convergenceSamples(sweep.quick) paths
// per rough pixel (everything else exact with one path), measures each image's noise (the tracer's own
// per-pixel estimate, carried into sRGB) and its RMSE against the image with the most paths, fits the
// slope of log noise against log samples (−½ for Monte Carlo), and picks the fewest samples whose noise is
// below a tenth of `smallestError` (the smallest error the run must judge), extrapolating along the slope
// when none of the traced counts is enough. `progress` gets a line per count; `stop` cancels ("stopped").
base::Result<ConvergenceStudy> studyConvergence(const SweepInput& sweep, int width, int height,
                                                double smallestError,
                                                const std::function<void(const std::string&)>& progress = {},
                                                const std::function<bool()>& stop = {});

// Picks the samples again for another smallest error (ConvergenceStudy::enough or ::extrapolated): a merge of
// shards knows the run's smallest error only once every shard's records are in.
void judgeConvergence(ConvergenceStudy& study, double smallestError);

} // namespace speculum::accuracy
