// Built against speculum_render_core alone, with no other include path: if the planner (or anything it
// pulls in) included a GL, Embree or OpenImageIO header, this would not compile, and if it used one of
// their symbols, it would not link. The test then plans a small frame, so the planner's code is linked.
#include "render/frame/FrameInput.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/FrameReport.hpp"
#include "render/plan/Planner.hpp"

#include <gtest/gtest.h>
#include <memory>

namespace speculum::render {
namespace {

TEST(LayersCoreOnly, PlansAFrameWithoutGl) {
    FrameInput input;
    auto box = std::make_shared<const MeshData>(makeBox());
    input.items.push_back({"Box", glm::dmat4(1.0), box, {}, true});
    Light light;
    light.name = "Lamp";
    light.position = {0, 4, 0};
    light.shadows = ShadowParams{};
    input.lights.push_back(light);

    const FramePlan plan = planFrame(input, {});
    ASSERT_FALSE(plan.passes.empty());
    EXPECT_EQ(plan.passes.front().kind, PassKind::Shadow);
    EXPECT_EQ(plan.passes.front().target, "Lamp");

    // What a frame reports is core too: the plan as planned, and what ran of it with its outcome.
    FrameReport report;
    report.plan = plan;
    report.ran.push_back({0, "", 1.0, 0.5});
    report.ran.push_back({int(plan.passes.size()) - 1, "found something", 2.0, 0.5});
    EXPECT_EQ(report.reason(report.ran[0]), plan.passes.front().reason());
    EXPECT_EQ(report.reason(report.ran[1]), plan.passes.back().reason() + "; found something");
    EXPECT_EQ(report.countRan(PassKind::Shadow, "Lamp"), 1u);
    EXPECT_EQ(report.countRan(PassKind::Shadow, "Elsewhere"), 0u);
}

} // namespace
} // namespace speculum::render
