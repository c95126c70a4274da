// The preview level the viewport draws at while navigating, from measured frame times.
// Frames are simulated with a cost model: a fixed part, a part that goes with the pixels (the square of the
// scale), a part per level of mirror nesting, and what the window system adds on top.
#include "editor/view/AdaptiveResolution.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <set>

namespace {

using speculum::view::AdaptiveResolution;
using speculum::view::PreviewLevel;

struct CostModel {
    double fixedMs = 5.0;
    double pixelsMs = 100.0; // at full resolution
    double perDepthMs = 0.0; // each level of mirror nesting drawn
    int depth = 1;           // the scene's mirror depth
    double overheadMs = 8.0; // composition, after the drawing
    double draw(const PreviewLevel& l) const {
        const int drawn = std::max(1, depth - l.mirrorDepthCut);
        return fixedMs + pixelsMs * l.scale * l.scale + perDepthMs * drawn;
    }
};

// Runs `frames` preview frames; returns the levels seen over the last `tail` of them.
std::set<std::pair<double, int>> run(AdaptiveResolution& a, const CostModel& m, int frames, int tail = 10) {
    std::set<std::pair<double, int>> seen;
    for (int i = 0; i < frames; ++i) {
        const PreviewLevel l = a.level();
        const double draw = m.draw(l);
        a.learn(draw, draw + m.overheadMs, m.depth - 1);
        if (i >= frames - tail) {
            seen.insert({l.scale, l.mirrorDepthCut});
        }
    }
    return seen;
}

TEST(AdaptiveResolution, AFastSceneIsNeverReduced) {
    AdaptiveResolution a;
    const CostModel m{2.0, 10.0, 0.0, 1, 5.0};
    a.begin(m.draw({}));
    EXPECT_FALSE(a.level().reduced());
    run(a, m, 50);
    EXPECT_FALSE(a.level().reduced());
}

TEST(AdaptiveResolution, APixelBoundSceneSettlesOnOneScaleWithinTheBudget) {
    AdaptiveResolution a;
    const CostModel m{5.0, 120.0, 0.0, 1, 8.0};
    a.begin(m.draw({}) + m.overheadMs);
    const double start = a.level().scale;
    EXPECT_LT(start, 1.0) << "a full frame takes three times the budget";
    EXPECT_GE(start, AdaptiveResolution::kMinScale);
    const auto settled = run(a, m, 120);
    ASSERT_EQ(settled.size(), 1u) << "no flicker between sizes";
    const PreviewLevel l{settled.begin()->first, settled.begin()->second};
    EXPECT_LE(m.draw(l) + m.overheadMs, a.budget());
    EXPECT_GT(l.scale, 0.4) << "not needlessly small";
    EXPECT_EQ(l.mirrorDepthCut, 0) << "pixels were enough";
    const PreviewLevel better{l.scale + 1.0 / 16.0, 0};
    EXPECT_GT(m.draw(better) + m.overheadMs, 0.7 * a.budget()) << "close to the best that fits";
}

TEST(AdaptiveResolution, WhenPixelsAreNotTheCostMirrorsNestLessDeep) {
    AdaptiveResolution a;
    // The mirrors demo on llvmpipe: eight mirror views over four levels cost more than the pixels.
    const CostModel m{4.0, 40.0, 12.0, 4, 8.0};
    a.begin(m.draw({}) + m.overheadMs);
    const auto settled = run(a, m, 150);
    ASSERT_EQ(settled.size(), 1u);
    const PreviewLevel l{settled.begin()->first, settled.begin()->second};
    EXPECT_EQ(l.scale, AdaptiveResolution::kMinScale);
    EXPECT_GT(l.mirrorDepthCut, 0);
    EXPECT_LE(l.mirrorDepthCut, 3) << "never below one level";
    EXPECT_LE(m.draw(l) + m.overheadMs, a.budget());
}

TEST(AdaptiveResolution, NeverBelowAQuarterNorTheLastMirrorLevel) {
    AdaptiveResolution a;
    const CostModel m{200.0, 100.0, 50.0, 3, 8.0}; // nothing fits
    a.begin(m.draw({}));
    run(a, m, 100);
    EXPECT_EQ(a.level().scale, AdaptiveResolution::kMinScale);
    EXPECT_EQ(a.level().mirrorDepthCut, 2);
}

TEST(AdaptiveResolution, ItComesBackUpWhenTheViewGetsCheaperAndAGestureStartsWhereTheLastEnded) {
    AdaptiveResolution a;
    CostModel m{5.0, 160.0, 0.0, 1, 8.0};
    a.begin(m.draw({}));
    run(a, m, 60);
    const PreviewLevel slow = a.level();
    ASSERT_LT(slow.scale, 0.6);
    m.pixelsMs = 20.0; // the expensive part left the view
    run(a, m, 100);
    EXPECT_GT(a.level().scale, slow.scale);
    const PreviewLevel learnt = a.level();
    a.begin(1000.0); // a new gesture: what was learnt counts, not the full frame's time
    EXPECT_EQ(a.level(), learnt);
    a.forget(); // the widget was resized
    a.begin(1000.0);
    EXPECT_LT(a.level().scale, learnt.scale);
}

TEST(AdaptiveResolution, ABadMeasurementIsIgnoredAndABadBudgetRefused) {
    AdaptiveResolution a;
    a.begin(0.0);
    a.learn(std::nan(""), 10.0, 0);
    a.learn(10.0, std::numeric_limits<double>::infinity(), 0);
    EXPECT_FALSE(a.level().reduced());
    a.setBudget(-1.0);
    a.setBudget(std::nan(""));
    EXPECT_EQ(a.budget(), AdaptiveResolution::kDefaultBudgetMs);
    a.setBudget(25.0);
    EXPECT_EQ(a.budget(), 25.0);
}

} // namespace
