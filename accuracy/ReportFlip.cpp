#include "accuracy/ReportFlip.hpp"

#include "accuracy/Report.hpp"

#include <algorithm>
#include <cstdio>

namespace speculum::accuracy {

namespace {

std::string flipText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4f", value);
    return text;
}

std::string msText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, value < 10.0 ? "%.2f ms" : "%.1f ms", value);
    return text;
}

std::string bold(const Record& r) {
    return "**" + displayName(r.config) + "**";
}

std::string describeFlip(const std::vector<const Record*>& rows, const FlipView& flip, std::size_t i,
                         const std::string& costName) {
    return bold(*rows[i]) + ": FLIP " + flipText(-flip.points[i].psnr) + " at " +
           msText(flip.points[i].cost) + " " + costName;
}

// Names of the rows in `indices` but not in `others`, joined for a sentence.
std::string onlyIn(const std::vector<const Record*>& rows, const std::vector<std::size_t>& indices,
                   const std::vector<std::size_t>& others) {
    std::string names;
    for (std::size_t i : indices)
        if (std::find(others.begin(), others.end(), i) == others.end())
            names += (names.empty() ? "" : ", ") + bold(*rows[i]);
    return names;
}

} // namespace

std::optional<FlipView> analyseFlip(const std::vector<const Record*>& rows,
                                    const std::vector<Point>& psnrPoints, Metric metric) {
    FlipView view;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::optional<double> flip = focusFlip(*rows[i], metric);
        if (!flip)
            return std::nullopt;
        view.points.push_back(flipPoint(psnrPoints[i].cost, *flip));
        const Point& p = view.points.back();
        const Point& b = view.points[view.best];
        if (p.psnr > b.psnr || (p.psnr == b.psnr && p.cost < b.cost))
            view.best = i;
    }
    view.front = paretoFront(view.points);
    for (std::size_t i = 0; i < rows.size(); ++i)
        if (rows[i]->flipToBest && *rows[i]->flipToBest <= flipJnd() &&
            (!view.cheapest || view.points[i].cost < view.points[*view.cheapest].cost))
            view.cheapest = i;
    return view;
}

std::vector<std::string> flipLines(const std::vector<const Record*>& rows, const FlipView& flip,
                                   const PsnrRanking& psnr) {
    std::vector<std::string> lines;
    lines.push_back("Best by FLIP: " + describeFlip(rows, flip, flip.best, psnr.costName) +
                    tiedNote(*rows[flip.best], rows) + ".");
    if (flip.cheapest)
        lines.push_back("Cheapest that looks the same as the best by FLIP (on 99 % of the judged pixels less "
                        "than one just-noticeable difference, FLIP " +
                        flipText(flipJnd()) + ", from the best's image): " +
                        describeFlip(rows, flip, *flip.cheapest, psnr.costName) + ".");
    if (flip.front.size() >= 2) {
        std::string line = "Each step along FLIP's Pareto front (cheapest first): ";
        for (std::size_t k = 1; k < flip.front.size(); ++k) {
            const std::size_t a = flip.front[k - 1], b = flip.front[k];
            line += (k > 1 ? "; " : "") + displayName(rows[a]->config) + " → " +
                    displayName(rows[b]->config) + " costs +" +
                    msText(flip.points[b].cost - flip.points[a].cost) + " for FLIP −" +
                    flipText(flip.points[b].psnr - flip.points[a].psnr);
        }
        lines.push_back(line + ".");
    }
    if (flip.best != psnr.best)
        lines.push_back(
            "FLIP and PSNR disagree on the best: PSNR ranks " + bold(*rows[psnr.best]) + " first, FLIP " +
            bold(*rows[flip.best]) +
            " (PSNR weighs every value's squared error alike; FLIP what a viewer flipping between "
            "the images would notice: edges, and colour after the eye's blur).");
    if (flip.cheapest && psnr.cheapest && *flip.cheapest != *psnr.cheapest)
        lines.push_back("The cheap pick differs: within 1 dB PSNR it is " + bold(*rows[*psnr.cheapest]) +
                        ", within one JND of the best's image by FLIP " + bold(*rows[*flip.cheapest]) + ".");
    const std::string psnrOnly = onlyIn(rows, psnr.front, flip.front),
                      flipOnly = onlyIn(rows, flip.front, psnr.front);
    if (!psnrOnly.empty() || !flipOnly.empty())
        lines.push_back("The two Pareto fronts differ: " +
                        (psnrOnly.empty() ? std::string() : "only PSNR's has " + psnrOnly) +
                        (!psnrOnly.empty() && !flipOnly.empty() ? "; " : "") +
                        (flipOnly.empty() ? std::string() : "only FLIP's has " + flipOnly) + ".");
    return lines;
}

std::string tiedNote(const Record& record, const std::vector<const Record*>& rows) {
    std::vector<std::string> names;
    for (const Record* r : rows)
        if (std::find(record.tiedWith.begin(), record.tiedWith.end(), r->config.id) != record.tiedWith.end())
            names.push_back(bold(*r));
    if (names.empty())
        return {};
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return ", tied within the reference's noise with " + list + " (their difference is smaller than the " +
           "exact image's own noise can tell apart, so the reference does not rank them)";
}

PlotSpec flipPlot(const PlotSpec& psnrPlot, const FlipView& flip, Metric metric) {
    PlotSpec spec = psnrPlot;
    const std::size_t colon = spec.title.find(':');
    spec.title = spec.title.substr(0, colon) + ": FLIP against frame time";
    spec.yLabel = flipAxisLabel(metric);
    spec.yDown = true;
    for (std::size_t i = 0; i < spec.points.size() && i < flip.points.size(); ++i)
        spec.points[i].y = -flip.points[i].psnr;
    spec.front = flip.front;
    return spec;
}

} // namespace speculum::accuracy
