// The reflector's GGX pre-filter, planned without GL: a Prefilter pass right after the environment pass
// when a rough reflector reads the pre-filtered chain (GlossyFilter::Footprint), a skip with its reason
// otherwise (roughness 0, the Mip filter), and no pass again while the map and the sample count stay the
// same.
#include "PlanScenes.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

using test::roughBall;

const PlannedPass* passOf(const FramePlan& plan, PassKind kind) {
    const auto it = std::find_if(plan.passes.begin(), plan.passes.end(),
                                 [&](const PlannedPass& p) { return p.kind == kind; });
    return it == plan.passes.end() ? nullptr : &*it;
}

// The skip of the reflector's pre-filter; nullptr when the plan has none.
const SkippedEffect* prefilterSkip(const FramePlan& plan) {
    for (const SkippedEffect& s : plan.skipped)
        if (s.code == PlanReason::PrefilterSharp || s.code == PlanReason::PrefilterMipFilter ||
            s.code == PlanReason::PrefilterReused)
            return &s;
    return nullptr;
}

// What the renderer records once the map and the chain are drawn.
PlannerState afterRendering(const FrameInput& input) {
    PlannerState state;
    state.mapOf(0).signature = envmapSignature(input, 0);
    state.mapOf(0).reflector = input.reflectors[0].name;
    state.mapOf(0).settings = envmapSettingsKey(input.reflectors[0]);
    state.mapOf(0).prefilterKey =
        prefilterKey(*state.mapOf(0).signature, *state.mapOf(0).settings, input.settings.prefilterSamples);
    return state;
}

TEST(PrefilterPlanner, RoughFootprintReflectorFiltersRightAfterTheEnvironmentPass) {
    const FramePlan plan = planFrame(roughBall(0.35), {});
    std::vector<PassKind> kinds;
    for (const PlannedPass& p : plan.passes)
        kinds.push_back(p.kind);
    EXPECT_EQ(kinds,
              (std::vector{PassKind::Envmap, PassKind::Prefilter, PassKind::Main, PassKind::Composite}));
    const PlannedPass* prefilter = passOf(plan, PassKind::Prefilter);
    ASSERT_NE(prefilter, nullptr);
    EXPECT_EQ(prefilter->target, "Ball");
    EXPECT_EQ(prefilter->writes.target, PassTarget::OwnMap);
    EXPECT_EQ(prefilter->code, PlanReason::PrefilterMapRendered);
    EXPECT_EQ(prefilter->details.levels, 6);
    EXPECT_EQ(prefilter->details.samples, 64);
    // The sentence the pass shows, as explain prints it.
    EXPECT_EQ(prefilter->reason(),
              "convolves Ball's map with the GGX lobe into 6 levels (roughness r_k = k/5; "
              "0.35 reads between levels 1 and 2), 64 samples a texel; the map is rendered this frame");
    EXPECT_EQ(toString(PassKind::Prefilter), "prefilter");
    EXPECT_EQ(prefilterSkip(plan), nullptr);
}

TEST(PrefilterPlanner, RoughnessZeroPlansNoPrefilter) {
    for (GlossyFilter filter : {GlossyFilter::Footprint, GlossyFilter::Mip}) {
        const FramePlan plan = planFrame(roughBall(0.0, filter), {});
        EXPECT_EQ(passOf(plan, PassKind::Prefilter), nullptr);
        ASSERT_NE(prefilterSkip(plan), nullptr);
        EXPECT_EQ(prefilterSkip(plan)->code, PlanReason::PrefilterSharp);
    }
}

TEST(PrefilterPlanner, MipFilterPlansNoPrefilter) {
    const FramePlan plan = planFrame(roughBall(0.5, GlossyFilter::Mip), {});
    EXPECT_EQ(passOf(plan, PassKind::Prefilter), nullptr);
    EXPECT_NE(passOf(plan, PassKind::Envmap), nullptr);
    ASSERT_NE(prefilterSkip(plan), nullptr);
    EXPECT_EQ(prefilterSkip(plan)->code, PlanReason::PrefilterMipFilter);
    EXPECT_EQ(prefilterSkip(plan)->details.levels, 9) << "256² cube: 9 mip levels, LOD roughness × 8";
}

TEST(PrefilterPlanner, ReusedMapReusesTheChain) {
    const FrameInput input = roughBall(0.6);
    const FramePlan plan = planFrame(input, afterRendering(input));
    EXPECT_EQ(passOf(plan, PassKind::Envmap), nullptr);
    EXPECT_EQ(passOf(plan, PassKind::Prefilter), nullptr);
    ASSERT_NE(prefilterSkip(plan), nullptr);
    EXPECT_EQ(prefilterSkip(plan)->code, PlanReason::PrefilterReused);
}

TEST(PrefilterPlanner, NewRoughnessOrFilterKeepsTheChain) {
    // The chain holds every level: another roughness, or switching the filter back, reads the same chain.
    const FrameInput before = roughBall(0.2);
    const PlannerState state = afterRendering(before);
    FrameInput after = roughBall(0.9);
    EXPECT_EQ(passOf(planFrame(after, state), PassKind::Prefilter), nullptr);
}

TEST(PrefilterPlanner, ChangedSampleCountFiltersAgainWithoutCapturing) {
    const FrameInput before = roughBall(0.6);
    FrameInput after = before;
    after.settings.prefilterSamples = 256;
    const FramePlan plan = planFrame(after, afterRendering(before));
    EXPECT_EQ(passOf(plan, PassKind::Envmap), nullptr) << "the map is not captured again";
    const PlannedPass* prefilter = passOf(plan, PassKind::Prefilter);
    ASSERT_NE(prefilter, nullptr);
    EXPECT_EQ(prefilter->code, PlanReason::PrefilterSettingsChanged);
    EXPECT_EQ(prefilter->details.samples, 256);
}

TEST(PrefilterPlanner, ReusedMapWithoutAChainFiltersOnce) {
    // Roughness raised from 0 while the map is reused: the chain is made from the map as it is.
    const FrameInput sharp = roughBall(0.0);
    PlannerState state = afterRendering(sharp);
    state.mapOf(0).prefilterKey.reset();
    const FramePlan plan = planFrame(roughBall(0.5), state);
    EXPECT_EQ(passOf(plan, PassKind::Envmap), nullptr);
    const PlannedPass* prefilter = passOf(plan, PassKind::Prefilter);
    ASSERT_NE(prefilter, nullptr);
    EXPECT_EQ(prefilter->code, PlanReason::PrefilterFirstChain);
    EXPECT_EQ(prefilter->signature, prefilterKey(*state.mapOf(0).signature, *state.mapOf(0).settings, 64));
}

TEST(PrefilterPlanner, RecapturedMapIsFilteredAgain) {
    const FrameInput before = roughBall(0.5);
    FrameInput after = before;
    after.items[0].world = glm::translate(glm::dmat4(1.0), glm::dvec3(2.5, 0, 0));
    const FramePlan plan = planFrame(after, afterRendering(before));
    ASSERT_NE(passOf(plan, PassKind::Envmap), nullptr);
    const PlannedPass* prefilter = passOf(plan, PassKind::Prefilter);
    ASSERT_NE(prefilter, nullptr);
    EXPECT_EQ(prefilter->code, PlanReason::PrefilterMapRendered);
    EXPECT_EQ(prefilter->signature,
              prefilterKey(envmapSignature(after, 0), envmapSettingsKey(after.reflectors[0]), 64));
}

TEST(PrefilterPlanner, InvisibleReflectorPlansNoPrefilter) {
    FrameInput input = roughBall(0.5);
    input.camera.target = {0.0, 0.0, 10.0}; // looking away
    const FramePlan plan = planFrame(input, {});
    EXPECT_EQ(passOf(plan, PassKind::Envmap), nullptr);
    EXPECT_EQ(passOf(plan, PassKind::Prefilter), nullptr);
}

TEST(PrefilterPlanner, LevelsFollowTheMapSize) {
    FrameInput input = roughBall(1.0);
    input.reflectors[0].resolution = 8;          // 4 mip levels: r_k = k/3
    const FramePlan plan = planFrame(input, {}); // the pass below points into it
    const PlannedPass* prefilter = passOf(plan, PassKind::Prefilter);
    ASSERT_NE(prefilter, nullptr);
    EXPECT_EQ(prefilter->details.levels, 4);
    EXPECT_NE(prefilter->reason().find("(roughness r_k = k/3; 1 reads level 3)"), std::string::npos)
        << prefilter->reason();
}

} // namespace
} // namespace speculum::render
