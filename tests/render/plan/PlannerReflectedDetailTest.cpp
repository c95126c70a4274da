// Which meshes the mirrors' views and the environment map draw simplified, and how the plan says so.
#include "PlanScenes.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

// A big sphere and a small box in front of a wall mirror the camera looks at.
FrameInput bigMeshInAMirror() {
    FrameInput input = test::cameraAtOrigin();
    input.mirrors.push_back(test::wall("Mirror", -6.0, true, 6.0));
    const MeshHandle big = freezeMesh(makeSphere(256));
    EXPECT_FALSE(big->coarse.indices.empty());
    input.items.push_back({"Statue", glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -3)), big, {}, true});
    input.items.push_back(
        {"Box", glm::translate(glm::dmat4(1.0), glm::dvec3(1, 0, -3)), freezeMesh(makeBox()), {}, true});
    return input;
}

const PlannedPass* passOf(const FramePlan& plan, PassKind kind) {
    for (const PlannedPass& pass : plan.passes)
        if (pass.kind == kind)
            return &pass;
    return nullptr;
}

TEST(ReflectedDetail, MirrorViewsDrawBigMeshesSimplifiedAndSaySo) {
    const FrameInput input = bigMeshInAMirror();
    const FramePlan plan = planFrame(input, {}, {320, 240});
    ASSERT_EQ(plan.coarseItems, (std::vector<bool>{true, false}));
    const PlannedPass* mirror = passOf(plan, PassKind::Mirror);
    ASSERT_NE(mirror, nullptr);
    const MeshData& big = *input.items[0].mesh;
    ASSERT_EQ(mirror->details.bigMeshes.size(), 1u);
    const ReflectedMesh& statue = mirror->details.bigMeshes[0];
    EXPECT_EQ(statue.name, "Statue");
    EXPECT_EQ(statue.triangles, big.triangleCount());
    EXPECT_EQ(statue.simplifiedTriangles, big.coarse.triangleCount());
    // The sentence the pass shows names the mesh and both triangle counts.
    EXPECT_NE(mirror->reason().find("; draws a big mesh simplified ('Statue' " +
                                    std::to_string(big.triangleCount()) + " → " +
                                    std::to_string(big.coarse.triangleCount()) + " triangles, within "),
              std::string::npos)
        << mirror->reason();
    EXPECT_TRUE(passOf(plan, PassKind::Main)->details.bigMeshes.empty())
        << "the camera's own view always draws every triangle";
}

TEST(ReflectedDetail, TurnedOffTheMirrorSaysItDrawsThemWhole) {
    FrameInput input = bigMeshInAMirror();
    input.settings.simplifyReflections = false;
    const FramePlan plan = planFrame(input, {}, {320, 240});
    EXPECT_TRUE(plan.coarseItems.empty());
    const PlannedPass* mirror = passOf(plan, PassKind::Mirror);
    ASSERT_NE(mirror, nullptr);
    ASSERT_EQ(mirror->details.bigMeshes.size(), 1u);
    EXPECT_EQ(mirror->details.bigMeshes[0].name, "Statue");
    EXPECT_EQ(mirror->details.bigMeshes[0].triangles, input.items[0].mesh->triangleCount());
    EXPECT_FALSE(mirror->details.bigMeshes[0].simplifiedTriangles) << "drawn whole";
}

TEST(ReflectedDetail, NothingReflectedNothingSimplified) {
    FrameInput input = bigMeshInAMirror();
    input.mirrors.clear();
    const FramePlan plan = planFrame(input, {}, {320, 240});
    EXPECT_TRUE(plan.coarseItems.empty());
    for (const PlannedPass& pass : plan.passes)
        EXPECT_TRUE(pass.details.bigMeshes.empty()) << pass.reason();
}

TEST(ReflectedDetail, TheEnvironmentMapDrawsThemSimplifiedToo) {
    FrameInput input = bigMeshInAMirror();
    input.mirrors.clear();
    Reflector ball;
    ball.name = "Ball";
    ball.mesh = freezeMesh(makeSphere());
    ball.world = glm::translate(glm::dmat4(1.0), glm::dvec3(-1.5, 0, -4));
    input.reflector = ball;
    const FramePlan plan = planFrame(input, {}, {320, 240});
    const PlannedPass* envmap = passOf(plan, PassKind::Envmap);
    ASSERT_NE(envmap, nullptr);
    ASSERT_EQ(envmap->details.bigMeshes.size(), 1u);
    EXPECT_EQ(envmap->details.bigMeshes[0].name, "Statue");
    EXPECT_TRUE(envmap->details.bigMeshes[0].simplifiedTriangles);
    EXPECT_EQ(plan.coarseItems, (std::vector<bool>{true, false}));
}

} // namespace
} // namespace speculum::render
