#pragma once

#include <array>
#include <optional>
#include <vector>

namespace speculum::ui {

// How exact "Compare with exact" makes its reference, and how big: the width of both images (the height
// follows the aspect of the stills `speculum render` writes), and the paths per rough pixel it refines up
// to. The exact image is traced progressively, each level with four times the paths of the one before (its
// noise halves), and shown as soon as it is done.
struct ComparisonQuality {
    int width = 480;
    int paths = 0;               // the last level's paths per rough pixel; 0: as many as fit the budget
    double budgetSeconds = 20.0; // for paths = 0: levels are added while their estimate fits
};

// The aspect of the compared images: that of a still at its default size (1280×720), whatever the
// viewport's shape, so that the comparison's cost and figures do not follow the window's layout.
inline constexpr double kComparisonAspect = 16.0 / 9.0;
int comparisonHeight(int width);

// Paths per rough pixel of the levels the refinement goes through (noise halves from one to the next).
inline constexpr std::array<int, 4> kComparisonPathLevels{4, 16, 64, 256};

// What a trace of the scene found: what a path costs on this machine for this scene, how much of the image
// is rough (the only pixels more paths cost anything), and what every trace pays before its first path
// (the scene's acceleration structure). A quick probe (a small image, few paths) gives the first figures;
// each level traced gives better ones.
struct TraceProbe {
    double secondsPerPath = 0.0; // per path traced: one a pixel, plus the extra ones of rough pixels
    double roughFraction = 0.0;  // of the pixels, 0..1
    double setupSeconds = 0.0;
};

// The paths one level traces at `pixels` pixels, and the time that takes.
double tracedPaths(double roughFraction, int pixels, int paths);
double estimateLevelSeconds(const TraceProbe& probe, int pixels, int paths);

// The levels to trace, in order, each with its estimated time: with a chosen path count, every level
// below it and that count; with none (auto), levels while their running total fits the budget (the first
// always). A scene with no rough pixel needs one level: more paths change nothing.
struct PlannedLevel {
    int paths = 0;
    double seconds = 0.0;
};
std::vector<PlannedLevel> planComparisonLevels(const ComparisonQuality& quality, const TraceProbe& probe);

// The level after one of `donePaths` paths, as the levels traced so far measured the scene (`measured`),
// `elapsedSeconds` into the comparison: none when that was the last (the chosen count reached, nothing
// rough, or on auto when the next one's estimate would take the comparison past the budget).
std::optional<PlannedLevel> nextComparisonLevel(const ComparisonQuality& quality, int donePaths,
                                                const TraceProbe& measured, double elapsedSeconds);

} // namespace speculum::ui
