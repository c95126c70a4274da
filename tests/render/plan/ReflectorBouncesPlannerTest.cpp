// Several curved reflectors, planned without GL: each gets a map of its own; with reflectorBounces the maps
// are drawn again bounce by bounce, in order; maps whose inputs did not change are reused; a reflector no
// view sees gets none unless another's map shows it; and the planner caps the maps and bounces of a frame
// and says what it left out.
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace speculum::render {
namespace {

MeshHandle sphere() {
    static const auto mesh = std::make_shared<const MeshData>(makeSphere(16));
    return mesh;
}

Reflector ball(const std::string& name, glm::dvec3 at, double radius = 0.5) {
    Reflector r;
    r.name = name;
    r.mesh = sphere();
    r.world = glm::scale(glm::translate(glm::dmat4(1.0), at), glm::dvec3(radius));
    r.resolution = 64;
    return r;
}

// Balls in a row along X, the camera at +Z looking at the middle of the row.
FrameInput balls(int count, int bounces = 0) {
    FrameInput input;
    input.camera.position = {0.0, 0.0, 6.0 + count};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.fovY = 90.0;
    input.camera.far = 100.0;
    input.settings.reflectorBounces = bounces;
    for (int i = 0; i < count; ++i)
        input.reflectors.push_back(
            ball("Ball " + std::to_string(i), {1.2 * i - 0.6 * (count - 1), 0.0, 0.0}));
    return input;
}

struct EnvmapPass {
    std::string target;
    int bounce = 0;
    PlanReason code{};
    bool operator==(const EnvmapPass&) const = default;
};

std::vector<EnvmapPass> envmapPasses(const FramePlan& plan) {
    std::vector<EnvmapPass> out;
    for (const PlannedPass& p : plan.passes)
        if (p.kind == PassKind::Envmap)
            out.push_back({p.target, p.details.bounce, p.code});
    return out;
}

std::vector<PlanReason> skipsOf(const FramePlan& plan, PlanReason code) {
    std::vector<PlanReason> out;
    for (const SkippedEffect& s : plan.skipped)
        if (s.code == code)
            out.push_back(s.code);
    return out;
}

// What the renderer records once it ran every envmap pass of `plan`.
void record(const FramePlan& plan, PlannerState& state) {
    for (const EnvmapPlan& map : plan.envmaps)
        recordEnvmap(map, state);
}

TEST(ReflectorBouncesPlanner, EachReflectorGetsItsOwnMapBeforeTheMainPass) {
    const FrameInput input = balls(2);
    const FramePlan plan = planFrame(input, {});
    const std::vector<EnvmapPass> expected = {{"Ball 0", 0, PlanReason::EnvmapFirstMap},
                                              {"Ball 1", 0, PlanReason::EnvmapFirstMap}};
    EXPECT_EQ(envmapPasses(plan), expected);
    ASSERT_EQ(plan.envmaps.size(), 2u);
    for (int i = 0; i < 2; ++i) {
        const EnvmapPlan& map = plan.envmaps[static_cast<std::size_t>(i)];
        EXPECT_EQ(map.reflector, i);
        EXPECT_EQ(map.capture.centre, envmapCapture(input, i).centre) << "each from its own centre";
        EXPECT_EQ(map.signature, envmapSignature(input, i));
    }
    EXPECT_NE(plan.envmaps[0].signature, plan.envmaps[1].signature);
    const PlannedPass* first = nullptr;
    for (const PlannedPass& p : plan.passes)
        if (!first && (p.kind == PassKind::Envmap || p.kind == PassKind::Main))
            first = &p;
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first->kind, PassKind::Envmap);
    EXPECT_NE(plan.passes.front().reason().find("the other reflector in it with its plain material"),
              std::string::npos)
        << plan.passes.front().reason();
}

TEST(ReflectorBouncesPlanner, BouncesDrawEveryMapAgainInOrder) {
    const FramePlan plan = planFrame(balls(2, 2), {});
    const std::vector<EnvmapPass> expected = {
        {"Ball 0", 0, PlanReason::EnvmapFirstMap}, {"Ball 1", 0, PlanReason::EnvmapFirstMap},
        {"Ball 0", 1, PlanReason::EnvmapBounce},   {"Ball 1", 1, PlanReason::EnvmapBounce},
        {"Ball 0", 2, PlanReason::EnvmapBounce},   {"Ball 1", 2, PlanReason::EnvmapBounce}};
    EXPECT_EQ(envmapPasses(plan), expected);
    ASSERT_EQ(plan.envmaps.size(), 6u);
    for (std::size_t k = 0; k < plan.envmaps.size(); ++k) {
        EXPECT_EQ(plan.envmaps[k].bounce, static_cast<int>(k / 2));
        EXPECT_EQ(plan.envmaps[k].reflector, static_cast<int>(k % 2));
    }
    const std::string reason = plan.passes[2].reason();
    EXPECT_NE(reason.find("bounce 1 of 2: the other reflector in it with its map of bounce 0"),
              std::string::npos)
        << reason;
}

TEST(ReflectorBouncesPlanner, MapsWhoseInputsDidNotChangeAreReusedAtEveryBounce) {
    FrameInput input = balls(2, 1);
    PlannerState state;
    record(planFrame(input, state), state);
    const FramePlan again = planFrame(input, state);
    EXPECT_TRUE(envmapPasses(again).empty());
    EXPECT_EQ(skipsOf(again, PlanReason::EnvmapUnchanged).size(), 2u);
    // Moving one ball changes what both maps see: both are drawn again, at every bounce.
    input.reflectors[1].world = glm::translate(input.reflectors[1].world, glm::dvec3(0.0, 0.2, 0.0));
    EXPECT_EQ(envmapPasses(planFrame(input, state)).size(), 4u);
}

TEST(ReflectorBouncesPlanner, AMapDrawnAloneIsDrawnOnceWithTheOthersMapsAsTheyAre) {
    FrameInput input = balls(2, 2);
    input.reflectors[1].update = ReflectorUpdate::Once;
    PlannerState state;
    record(planFrame(input, state), state);
    // Only ball 0 follows the scene: the map of ball 1 it reads does not change between bounces, so one
    // pass (at the last bounce) draws what three would.
    input.items.push_back({"Box",
                           glm::translate(glm::dmat4(1.0), glm::dvec3(0, 3, 0)),
                           std::make_shared<const MeshData>(makeBox()),
                           {},
                           true});
    const std::vector<EnvmapPass> expected = {{"Ball 0", 2, PlanReason::EnvmapChanged}};
    EXPECT_EQ(envmapPasses(planFrame(input, state)), expected);
}

TEST(ReflectorBouncesPlanner, ATimeSlicedMapDrawsItsFaceOnceAtTheLastBounce) {
    FrameInput input = balls(3, 2);
    input.reflectors[2].update = ReflectorUpdate::TimeSliced;
    PlannerState state;
    record(planFrame(input, state), state);
    input.reflectors[0].world = glm::translate(input.reflectors[0].world, glm::dvec3(0.0, 0.3, 0.0));
    const FramePlan plan = planFrame(input, state);
    const std::vector<EnvmapPass> expected = {
        {"Ball 0", 0, PlanReason::EnvmapChanged},   {"Ball 1", 0, PlanReason::EnvmapChanged},
        {"Ball 0", 1, PlanReason::EnvmapBounce},    {"Ball 1", 1, PlanReason::EnvmapBounce},
        {"Ball 0", 2, PlanReason::EnvmapBounce},    {"Ball 1", 2, PlanReason::EnvmapBounce},
        {"Ball 2", 2, PlanReason::EnvmapTimeSliced}};
    EXPECT_EQ(envmapPasses(plan), expected);
    ASSERT_EQ(plan.envmaps.back().faces.size(), 1u) << "one face a frame";
}

// A reflector deleted before another leaves its record to the next one, whose map it is not: the next
// gets a map of its own, whatever its policy.
TEST(ReflectorBouncesPlanner, AReflectorNeverTakesTheMapOfOneDeletedBeforeIt) {
    FrameInput input = balls(2);
    for (Reflector& r : input.reflectors)
        r.update = ReflectorUpdate::Once;
    PlannerState state;
    record(planFrame(input, state), state);
    input.reflectors.erase(input.reflectors.begin());
    const std::vector<EnvmapPass> expected = {{"Ball 1", 0, PlanReason::EnvmapFirstMap}};
    EXPECT_EQ(envmapPasses(planFrame(input, state)), expected);
}

TEST(ReflectorBouncesPlanner, OneReflectorHasNothingToBounceOffAndSaysSo) {
    const FramePlan plan = planFrame(balls(1, 3), {});
    const std::vector<EnvmapPass> expected = {{"Ball 0", 0, PlanReason::EnvmapFirstMap}};
    EXPECT_EQ(envmapPasses(plan), expected);
    ASSERT_EQ(skipsOf(plan, PlanReason::BouncesUnused).size(), 1u);
}

TEST(ReflectorBouncesPlanner, AnUnseenReflectorGetsAMapOnlyWhereAnotherMapShowsIt) {
    FrameInput input = balls(1);
    input.reflectors.push_back(ball("Behind", {0.0, 0.0, 30.0})); // behind the camera
    FramePlan plan = planFrame(input, {});
    EXPECT_EQ(envmapPasses(plan).size(), 1u);
    bool outOfSight = false;
    for (const SkippedEffect& s : plan.skipped)
        outOfSight = outOfSight || (s.target == "Behind" && s.code == PlanReason::EnvmapOutOfSight);
    EXPECT_TRUE(outOfSight) << "with no bounces it is drawn plain in the seen ball's map";
    input.settings.reflectorBounces = 1;
    plan = planFrame(input, {});
    ASSERT_EQ(envmapPasses(plan).size(), 4u);
    const PlannedPass* behind = nullptr;
    for (const PlannedPass& p : plan.passes)
        if (p.kind == PassKind::Envmap && p.target == "Behind")
            behind = &p;
    ASSERT_NE(behind, nullptr);
    EXPECT_NE(behind->reason().find("not seen, but in Ball 0's map"), std::string::npos) << behind->reason();
}

TEST(ReflectorBouncesPlanner, ThirtyTwoReflectorsInViewAreCappedAndTheRestSaid) {
    FrameInput input;
    input.camera.position = {0.0, 0.0, 20.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.fovY = 90.0;
    input.camera.far = 200.0;
    input.settings.reflectorBounces = kMaxReflectorBounces;
    for (int i = 0; i < 32; ++i)
        input.reflectors.push_back(
            ball("Ball " + std::to_string(i), {(i % 8) * 1.5 - 5.0, (i / 8) * 1.5 - 2.0, -0.1 * i}));
    const FramePlan plan = planFrame(input, {});
    EXPECT_EQ(skipsOf(plan, PlanReason::EnvmapOverCap).size(), 32u - kMaxReflectorMaps);
    std::vector<bool> mapped(32, false);
    for (const EnvmapPlan& map : plan.envmaps)
        mapped[static_cast<std::size_t>(map.reflector)] = true;
    EXPECT_EQ(std::count(mapped.begin(), mapped.end(), true), kMaxReflectorMaps);
    // The nearest the camera keep their maps: the first balls sit nearest (z falls with the index).
    EXPECT_TRUE(mapped[0]);
    EXPECT_FALSE(mapped[31]);
    EXPECT_LE(static_cast<int>(plan.envmaps.size()), kMaxEnvmapPasses);
    EXPECT_EQ(static_cast<int>(plan.envmaps.size()), kMaxReflectorMaps * 3) << "bounces cut to 2 for 16 maps";
    ASSERT_EQ(skipsOf(plan, PlanReason::BouncesCapped).size(), 1u);
    for (const SkippedEffect& s : plan.skipped) {
        if (s.code == PlanReason::BouncesCapped) {
            EXPECT_NE(s.reason().find("cut to 2 of the 4 asked"), std::string::npos) << s.reason();
        }
    }
}

TEST(ReflectorBouncesPlanner, EachReflectorKeepsItsOwnResolutionAndPrefilter) {
    FrameInput input = balls(2);
    input.reflectors[0].resolution = 32;
    input.reflectors[1].resolution = 128;
    input.reflectors[1].map = ReflectorMap::Octahedral;
    input.reflectors[1].roughness = 0.3;
    const FramePlan plan = planFrame(input, {});
    EXPECT_EQ(plan.reflectorResolution(0), 32);
    EXPECT_EQ(plan.reflectorResolution(1), 128);
    int prefilters = 0;
    for (const PlannedPass& p : plan.passes)
        if (p.kind == PassKind::Prefilter) {
            ++prefilters;
            EXPECT_EQ(p.reflector, 1);
        }
    EXPECT_EQ(prefilters, 1) << "only the rough one is pre-filtered";
}

} // namespace
} // namespace speculum::render
