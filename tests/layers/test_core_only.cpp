// Built against speculum_render_core alone, with no other include path: if the planner (or anything it
// pulls in) included a GL, Embree or OpenImageIO header, this would not compile, and if it used one of
// their symbols, it would not link. The test then plans a small frame, so the planner's code is linked.
#include "render/FrameInput.hpp"
#include "render/mesh/Primitives.hpp"
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
    light.shadows.enabled = true;
    input.lights.push_back(light);

    const FramePlan plan = planFrame(input, {});
    ASSERT_FALSE(plan.passes.empty());
    EXPECT_EQ(plan.passes.front().kind, PassKind::Shadow);
    EXPECT_EQ(plan.passes.front().target, "Lamp");
}

} // namespace
} // namespace speculum::render
