// What the reflector's map costs, said before the work: a map that would take minutes on a software
// renderer (an 8192² cube pre-filtered with 1024 samples, redrawn every frame) is warned of with its
// estimate; an interactive view (PlanOptions::maxMapSeconds) draws it smaller and with fewer samples, and
// says so; the demo-sized maps cost neither a warning nor a cap.
#include "PlanScenes.hpp"
#include "render/plan/MapCost.hpp"
#include "render/plan/Planner.hpp"

#include <gtest/gtest.h>

namespace speculum::render {
namespace {

// The ball's map at this resolution, pre-filtered with `samples`, redrawn every frame.
FrameInput ballWithMap(int resolution, int samples, double roughness) {
    FrameInput input = test::roughBall(roughness);
    input.settings.prefilterSamples = samples;
    input.reflectors[0].resolution = resolution;
    input.reflectors[0].update = ReflectorUpdate::Always;
    return input;
}

std::vector<std::string> costWarnings(const FramePlan& plan) {
    std::vector<std::string> found;
    for (const std::string& w : plan.warnings)
        if (w.find("software renderer") != std::string::npos)
            found.push_back(w);
    return found;
}

TEST(MapCostPlanner, AMapThatWouldTakeMinutesIsWarnedOfWithItsEstimate) {
    const FrameInput input = ballWithMap(8192, 1024, 0.5);
    const MapCost cost = mapCost(input.reflectors[0], 8192, input.settings, 1024);
    EXPECT_GT(cost.softwareSeconds(), 60.0) << "minutes, as measured";
    const FramePlan plan = planFrame(input, {});
    const std::vector<std::string> warnings = costWarnings(plan);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("reflector \"Ball\": its 8192² cube map pre-filtered with 1024 samples"),
              std::string::npos)
        << warnings[0];
    EXPECT_NE(warnings[0].find("roughly"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("every frame"), std::string::npos) << warnings[0];
    EXPECT_EQ(plan.reflectorResolution(0), 8192) << "a still draws it as asked";
    EXPECT_EQ(plan.prefilterSamples, 0);
}

TEST(MapCostPlanner, AnInteractiveViewDrawsACostlyMapSmallerAndSaysSo) {
    const FrameInput input = ballWithMap(8192, 1024, 0.5);
    PlanOptions options;
    options.maxMapSeconds = kInteractiveMapSeconds;
    const FramePlan plan = planFrame(input, {}, {}, options);
    EXPECT_LT(plan.reflectorResolution(0), 8192);
    EXPECT_GE(plan.reflectorResolution(0), 64);
    const int samples = plan.prefilterSamples > 0 ? plan.prefilterSamples : input.settings.prefilterSamples;
    EXPECT_GE(samples, 8);
    EXPECT_LE(
        mapCost(input.reflectors[0], plan.reflectorResolution(0), input.settings, samples).softwareSeconds(),
        kInteractiveMapSeconds);
    const std::vector<std::string> warnings = costWarnings(plan);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("while editing"), std::string::npos) << warnings[0];
    // What the passes draw is the capped map (plannedInput), so what is allocated is what was planned.
    const std::optional<FrameInput> drawn = plannedInput(input, plan);
    ASSERT_TRUE(drawn.has_value());
    EXPECT_EQ(drawn->reflectors[0].resolution, plan.reflectorResolution(0));
    EXPECT_EQ(drawn->settings.prefilterSamples, samples);
}

TEST(MapCostPlanner, DemoSizedMapsAreNeitherWarnedOfNorCapped) {
    for (const int resolution : {256, 512, 1024}) {
        const FrameInput input = ballWithMap(resolution, 64, 0.3);
        PlanOptions options;
        options.maxMapSeconds = kInteractiveMapSeconds;
        const FramePlan plan = planFrame(input, {}, {}, options);
        EXPECT_TRUE(costWarnings(plan).empty()) << resolution;
        EXPECT_EQ(plan.reflectorResolution(0), resolution);
        EXPECT_EQ(plan.prefilterSamples, 0) << resolution;
    }
}

// Several reflectors drawn at several bounces share the interactive view's time: together their maps stay
// within it, each capped further than one alone.
TEST(MapCostPlanner, ReflectorsAndBouncesShareTheInteractiveTime) {
    FrameInput input = ballWithMap(2048, 64, 0.5);
    input.reflectors.push_back(input.reflectors[0]);
    input.reflectors[1].name = "Other ball";
    input.reflectors[1].world = glm::translate(glm::dmat4(1.0), glm::dvec3(3.0, 0.0, 0.0));
    input.settings.reflectorBounces = 2;
    PlanOptions options;
    options.maxMapSeconds = kInteractiveMapSeconds;
    const FramePlan plan = planFrame(input, {}, {}, options);
    const FramePlan alone = planFrame(ballWithMap(2048, 64, 0.5), {}, {}, options);
    const int samples = plan.prefilterSamples > 0 ? plan.prefilterSamples : input.settings.prefilterSamples;
    double seconds = 0.0;
    for (int i = 0; i < 2; ++i) {
        EXPECT_LE(plan.reflectorResolution(i), alone.reflectorResolution(0));
        seconds += 3.0 * mapCost(input.reflectors[static_cast<std::size_t>(i)], plan.reflectorResolution(i),
                                 input.settings, samples)
                             .softwareSeconds();
    }
    EXPECT_LE(seconds, kInteractiveMapSeconds * 1.0001) << "two maps drawn at three bounces each";
}

} // namespace
} // namespace speculum::render
