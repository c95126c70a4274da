// Which meshes the mirrors' views and the environment map draw simplified, and how the plan says so.
#include "PlanScenes.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Simplify.hpp"
#include "render/plan/Planner.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

// A big sphere and a small box in front of a wall mirror the camera looks at; the sphere's simplified
// level built already (`built`), or not yet.
FrameInput bigMeshInAMirror(bool built = true) {
    FrameInput input = test::cameraAtOrigin();
    input.mirrors.push_back(test::wall("Mirror", -6.0, true, 6.0));
    const MeshHandle big = freezeMesh(makeSphere(256));
    if (built) {
        EXPECT_FALSE(coarseLevel(*big).indices.empty());
    }
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
    EXPECT_EQ(statue.simplifiedTriangles, coarseLevel(big).triangleCount());
    // The sentence the pass shows names the mesh and both triangle counts.
    EXPECT_NE(mirror->reason().find("; draws a big mesh simplified ('Statue' " +
                                    std::to_string(big.triangleCount()) + " → " +
                                    std::to_string(coarseLevel(big).triangleCount()) + " triangles, within "),
              std::string::npos)
        << mirror->reason();
    EXPECT_TRUE(passOf(plan, PassKind::Main)->details.bigMeshes.empty())
        << "the camera's own view always draws every triangle";
}

TEST(ReflectedDetail, AMeshWithoutItsLevelYetIsDrawnWholeAndTheLevelAskedFor) {
    const FrameInput input = bigMeshInAMirror(false);
    const FramePlan plan = planFrame(input, {}, {320, 240});
    EXPECT_TRUE(plan.coarseItems.empty()) << "nothing simplified to draw yet";
    ASSERT_EQ(plan.coarseLevelsWanted.size(), 1u);
    EXPECT_EQ(plan.coarseLevelsWanted[0], input.items[0].mesh);
    EXPECT_EQ(input.items[0].mesh->coarse.ready(), nullptr) << "planning never builds a level itself";
    const PlannedPass* mirror = passOf(plan, PassKind::Mirror);
    ASSERT_NE(mirror, nullptr);
    EXPECT_NE(
        mirror->reason().find("; draws big meshes whole while their simplified level is built: 'Statue' (" +
                              std::to_string(input.items[0].mesh->triangleCount()) + " triangles)"),
        std::string::npos)
        << mirror->reason();

    FrameInput twice = input; // one mesh drawn by two items is asked for once
    twice.items.push_back(twice.items[0]);
    EXPECT_EQ(planFrame(twice, {}, {320, 240}).coarseLevelsWanted.size(), 1u);

    FrameInput unreflected = input;
    unreflected.mirrors.clear();
    EXPECT_TRUE(planFrame(unreflected, {}, {320, 240}).coarseLevelsWanted.empty())
        << "a scene with nothing reflecting the mesh never pays for its level";

    FrameInput off = input;
    off.settings.simplifyReflections = false;
    EXPECT_TRUE(planFrame(off, {}, {320, 240}).coarseLevelsWanted.empty());
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
    input.reflectors = {ball};
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
