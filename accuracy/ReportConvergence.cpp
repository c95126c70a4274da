#include "accuracy/ReportConvergence.hpp"

#include <cmath>
#include <cstdio>

namespace speculum::accuracy {

namespace {

std::string number(const char* pattern, double value) {
    char text[48];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

} // namespace

PlotSpec convergencePlot(const ConvergenceStudy& study, const RunInfo& run) {
    PlotSpec spec;
    spec.title = "Convergence of the reference";
    spec.subtitle = run.sceneName + " at " + std::to_string(run.width) + "x" + std::to_string(run.height) +
                    ": the exact image traced with more and more paths per rough pixel";
    spec.xLabel = "paths per rough pixel (log scale)";
    spec.yLabel = "sRGB RMS (log scale)";
    spec.logX = spec.logY = true;
    spec.series = {"noise (the tracer's estimate)", "error against the most paths", "slope −½"};
    for (const ConvergencePoint& p : study.points) {
        if (p.noise > 0.0)
            spec.points.push_back({double(p.samples), p.noise, std::to_string(p.samples), 0, false});
        if (p.rmse > 0.0)
            spec.points.push_back({double(p.samples), p.rmse, "", 1, false});
    }
    if (!study.points.empty() && study.points.front().noise > 0.0) {
        const ConvergencePoint& first = study.points.front();
        const ConvergencePoint& last = study.points.back();
        const double end = first.noise * std::sqrt(double(first.samples) / double(last.samples));
        spec.points.push_back({double(first.samples), first.noise, "", 2, false});
        spec.points.push_back({double(last.samples), end, "", 2, false});
    }
    return spec;
}

void convergenceSection(std::ostringstream& md, const ConvergenceStudy& study) {
    md << "## Convergence of the reference\n\n";
    if (study.exact || study.points.empty()) {
        md << "No pixel of the frame sees a rough surface, so the reference is exact with one path per "
              "pixel: it has no noise to converge.\n\n";
        return;
    }
    md << "The exact image averages random paths where it sees rough surfaces, so it carries noise. Traced "
          "with "
          "four times as many paths at each step, its noise (the tracer's own per-pixel estimate, in sRGB) "
          "should halve: a slope of −½ on this log-log plot. The error against the image with the most paths "
          "flattens towards that image's own noise.\n\n"
          "![Convergence of the reference](plot-convergence.png)\n\n"
          "| paths per rough pixel | traced in | noise (sRGB RMS) | RMSE against the most paths |\n"
          "|---|---|---|---|\n";
    for (const ConvergencePoint& p : study.points)
        md << "| " << p.samples << " | " << number("%.0f ms", p.traceMs) << " | " << number("%.5f", p.noise)
           << " | " << (p.rmse > 0.0 ? number("%.5f", p.rmse) : std::string("–")) << " |\n";
    md << "\nThe noise falls with slope " << number("%.2f", study.slope) << " (−0.50 expected). ";
    const double target = 0.1 * study.smallestError;
    md << "The smallest error this run must judge is " << number("%.5f", study.smallestError)
       << " (sRGB RMSE); a reference good enough to judge it has noise below a tenth of that, "
       << number("%.5f", target) << ": ";
    if (!(target > 0.0))
        md << "no configuration differs from the reference at all, so there is no error to judge.\n\n";
    else if (study.enough)
        md << "**" << *study.enough << " paths per rough pixel** get there.\n\n";
    else if (study.extrapolated >= kMaxExtrapolated)
        md << "none of the counts traced gets there, and along the fitted slope no practical count "
              "would.\n\n";
    else
        md << "none of the counts traced gets there; along the fitted slope it takes about **"
           << study.extrapolated << " paths per rough pixel**.\n\n";
}

} // namespace speculum::accuracy
