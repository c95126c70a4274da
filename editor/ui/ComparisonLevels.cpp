#include "editor/ui/ComparisonLevels.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::ui {

int comparisonHeight(int width) {
    return std::max(9, static_cast<int>(std::lround(width / kComparisonAspect)));
}

double tracedPaths(double roughFraction, int pixels, int paths) {
    // Every pixel traces one path; a rough one traces the rest of its paths too.
    return double(pixels) * (1.0 + roughFraction * std::max(0, paths - 1));
}

double estimateLevelSeconds(const TraceProbe& probe, int pixels, int paths) {
    return probe.setupSeconds + tracedPaths(probe.roughFraction, pixels, paths) * probe.secondsPerPath;
}

std::vector<PlannedLevel> planComparisonLevels(const ComparisonQuality& quality, const TraceProbe& probe) {
    const int pixels = quality.width * comparisonHeight(quality.width);
    std::vector<int> paths;
    if (probe.roughFraction <= 0.0) {
        paths = {kComparisonPathLevels.front()}; // exact at the first level
    } else if (quality.paths > 0) {
        for (int level : kComparisonPathLevels)
            if (level < quality.paths)
                paths.push_back(level);
        paths.push_back(quality.paths);
    } else {
        paths.assign(kComparisonPathLevels.begin(), kComparisonPathLevels.end());
    }
    std::vector<PlannedLevel> levels;
    double total = 0.0;
    for (int p : paths) {
        const double seconds = estimateLevelSeconds(probe, pixels, p);
        if (quality.paths <= 0 && !levels.empty() && total + seconds > quality.budgetSeconds)
            break;
        total += seconds;
        levels.push_back({p, seconds});
    }
    return levels;
}

std::optional<PlannedLevel> nextComparisonLevel(const ComparisonQuality& quality, int donePaths,
                                                const TraceProbe& measured, double elapsedSeconds) {
    if (measured.roughFraction <= 0.0 || (quality.paths > 0 && donePaths >= quality.paths))
        return std::nullopt;
    const auto above = std::find_if(kComparisonPathLevels.begin(), kComparisonPathLevels.end(),
                                    [&](int level) { return level > donePaths; });
    int paths = 0;
    if (quality.paths > 0)
        paths = above != kComparisonPathLevels.end() ? std::min(*above, quality.paths) : quality.paths;
    else if (above != kComparisonPathLevels.end())
        paths = *above;
    else
        return std::nullopt;
    const int pixels = quality.width * comparisonHeight(quality.width);
    const double seconds = estimateLevelSeconds(measured, pixels, paths);
    if (quality.paths <= 0 && elapsedSeconds + seconds > quality.budgetSeconds)
        return std::nullopt;
    return PlannedLevel{paths, seconds};
}

} // namespace speculum::ui
