// The levels "Compare with exact" refines its exact image through, and their time estimates: four times
// the paths from one level to the next, up to a chosen count or, on auto, while the estimate fits the
// budget; one level where nothing on screen is rough.
#include "editor/ui/ComparisonLevels.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace speculum::ui {
namespace {

std::vector<int> pathsOf(const std::vector<PlannedLevel>& levels) {
    std::vector<int> paths;
    for (const PlannedLevel& level : levels)
        paths.push_back(level.paths);
    return paths;
}

TEST(ComparisonLevels, TheImagesHaveTheAspectOfAStill) {
    EXPECT_EQ(comparisonHeight(480), 270);
    EXPECT_EQ(comparisonHeight(1280), 720);
    EXPECT_GE(comparisonHeight(1), 9);
}

TEST(ComparisonLevels, MorePathsCostOnlyWhereTheImageIsRough) {
    const TraceProbe probe{1e-6, 0.25};
    const double four = estimateLevelSeconds(probe, 100000, 4);
    const double sixteen = estimateLevelSeconds(probe, 100000, 16);
    EXPECT_DOUBLE_EQ(four, 100000 * (1.0 + 0.25 * 3) * 1e-6);
    EXPECT_DOUBLE_EQ(sixteen - four, 100000 * 0.25 * 12 * 1e-6);
    const TraceProbe exact{1e-6, 0.0};
    EXPECT_DOUBLE_EQ(estimateLevelSeconds(exact, 100000, 256), estimateLevelSeconds(exact, 100000, 4));
}

TEST(ComparisonLevels, AChosenCountIsReachedThroughTheLevelsBelowIt) {
    const TraceProbe probe{1e-6, 0.3};
    EXPECT_EQ(pathsOf(planComparisonLevels({480, 4}, probe)), (std::vector{4}));
    EXPECT_EQ(pathsOf(planComparisonLevels({480, 64}, probe)), (std::vector{4, 16, 64}));
    EXPECT_EQ(pathsOf(planComparisonLevels({480, 256}, probe)), (std::vector{4, 16, 64, 256}));
    // A chosen count is kept whatever it costs: the user asked for it and sees the estimate.
    const TraceProbe slow{1e-3, 1.0};
    EXPECT_EQ(pathsOf(planComparisonLevels({480, 256}, slow)), (std::vector{4, 16, 64, 256}));
}

TEST(ComparisonLevels, AutoRefinesWhileTheEstimateFitsTheBudget) {
    // 480×270 pixels, all rough: a level of P paths costs 129600·P·perPath seconds.
    const TraceProbe probe{1e-6, 1.0};
    const std::vector<PlannedLevel> levels = planComparisonLevels({480, 0, 20.0}, probe);
    EXPECT_EQ(pathsOf(levels), (std::vector{4, 16, 64})); // 0.5 + 2.1 + 8.3 s; 256 more would be 33 s
    double total = 0.0;
    for (const PlannedLevel& level : levels)
        total += level.seconds;
    EXPECT_LE(total, 20.0);
    EXPECT_NEAR(levels.back().seconds, 129600 * 64 * 1e-6, 1e-9);
    // The first level always runs, even past the budget: there is no comparison without it.
    EXPECT_EQ(pathsOf(planComparisonLevels({480, 0, 0.01}, probe)), (std::vector{4}));
}

TEST(ComparisonLevels, EveryTracePaysItsSetupOnce) {
    const TraceProbe probe{1e-6, 0.5, 0.2};
    EXPECT_DOUBLE_EQ(estimateLevelSeconds(probe, 1000, 4), 0.2 + 1000 * 2.5 * 1e-6);
}

TEST(ComparisonLevels, TheNextLevelFollowsWhatTheLastOneMeasured) {
    const TraceProbe measured{1e-6, 1.0, 0.0}; // 480×270, all rough: P paths take 0.1296·P s
    const ComparisonQuality automatic{480, 0, 20.0};
    auto next = nextComparisonLevel(automatic, 16, measured, 3.0);
    ASSERT_TRUE(next.has_value());
    EXPECT_EQ(next->paths, 64); // 3 + 8.3 s fit in 20
    EXPECT_NEAR(next->seconds, 129600 * 64 * 1e-6, 1e-9);
    EXPECT_FALSE(nextComparisonLevel(automatic, 64, measured, 12.0)) << "256 paths would take 33 s more";
    EXPECT_FALSE(nextComparisonLevel(automatic, 256, measured, 1.0)) << "no level above the last";
    // A chosen count: its levels whatever they cost, and the count itself when it is not a level.
    EXPECT_EQ(nextComparisonLevel({480, 64}, 16, measured, 100.0)->paths, 64);
    EXPECT_FALSE(nextComparisonLevel({480, 64}, 64, measured, 0.0));
    EXPECT_EQ(nextComparisonLevel({480, 100}, 64, measured, 0.0)->paths, 100);
    // Nothing rough: the first level was exact.
    EXPECT_FALSE(nextComparisonLevel(automatic, 4, TraceProbe{1e-6, 0.0, 0.0}, 0.0));
}

TEST(ComparisonLevels, NothingRoughNeedsOneLevel) {
    const TraceProbe exact{1e-6, 0.0};
    EXPECT_EQ(pathsOf(planComparisonLevels({480, 0}, exact)), (std::vector{4}));
    EXPECT_EQ(pathsOf(planComparisonLevels({480, 256}, exact)), (std::vector{4}));
}

} // namespace
} // namespace speculum::ui
