#pragma once

#include "base/Result.hpp"

#include <string>
#include <vector>

namespace speculum::accuracy {

struct PlotPoint {
    double x = 0.0;
    double y = 0.0;
    std::string label;
    int series = 0;
    bool sceneSetting = false; // drawn larger, as a diamond: "where the scene is now"
};

// An error-against-cost scatter plot: points by series (joined in the order given, e.g. by resolution),
// each labelled, with the Pareto front drawn as the staircase bounding what is attainable.
struct PlotSpec {
    std::string title;
    std::string subtitle;
    std::string xLabel;
    std::string yLabel;
    // Lower y is better (FLIP): the axis runs downward, so better is still up and the front's staircase
    // still bounds what is attainable from below.
    bool yDown = false;
    // Logarithmic axes (all values positive): ticks at 1, 2 and 5 times the powers of ten. A log-log plot
    // shows a power law as a straight line.
    bool logX = false;
    bool logY = false;
    std::vector<std::string> series; // names, for the legend
    std::vector<PlotPoint> points;
    std::vector<std::size_t> front; // indices into points, ordered by x
};

// Paints the plot with QPainter into a PNG of width × height pixels. Needs a QGuiApplication (the
// "offscreen" platform is enough: nothing is shown). Errors: the file cannot be written.
base::Status writePlot(const std::string& path, const PlotSpec& spec, int width = 1200, int height = 800);

// "Nice" axis ticks covering [lo, hi]: steps of 1, 2 or 5 × 10^k, about `count` of them.
std::vector<double> niceTicks(double lo, double hi, int count);

} // namespace speculum::accuracy
