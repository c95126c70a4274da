// The environment map's mirror views are planned by the camera's mirror planner, face by face, without
// GL: which mirrors the capture point sees in each cube face or direct-fill component, how deep they nest
// (the reflector's mirrorDepth), and why the others are skipped.
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

MeshHandle sphere() {
    static const auto mesh = std::make_shared<const MeshData>(makeSphere(16));
    return mesh;
}

// A mirror of `size` at `position` whose reflective side (local +Y) faces `normal`.
Mirror mirrorFacing(const std::string& name, glm::dvec3 position, glm::dvec3 normal, double size = 2.0) {
    Mirror m;
    m.name = name;
    const glm::dvec3 y = glm::normalize(normal);
    const glm::dvec3 helper = std::abs(y.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 x = glm::normalize(glm::cross(helper, y));
    const glm::dvec3 z = glm::cross(x, y);
    m.world = glm::dmat4(glm::dvec4(x, 0), glm::dvec4(y, 0), glm::dvec4(z, 0), glm::dvec4(position, 1));
    m.size = {size, size};
    return m;
}

// A chrome ball at the origin seen by the camera on +Z; a mirror on the −X side facing the ball (the
// camera sees it edge-on from far, the ball head-on), and one on +X facing away from the ball.
FrameInput scene(ReflectorMap map, ReflectorFill fill = ReflectorFill::Resampled, int mirrorDepth = 1) {
    FrameInput input;
    input.camera.position = {0.0, 0.0, 6.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.far = 50.0;
    input.mirrors.push_back(mirrorFacing("Facing", {-3, 0, 0}, {1, 0, 0}));
    input.mirrors.push_back(mirrorFacing("Away", {3, 0, 0}, {1, 0, 0}));
    Reflector r;
    r.name = "Ball";
    r.mesh = sphere();
    r.map = map;
    r.fill = fill;
    r.resolution = 64;
    r.mirrorDepth = mirrorDepth;
    input.reflectors = {r};
    return input;
}

std::vector<const PlannedPass*> passesOf(const EnvmapPlan& map, const std::string& target, PassKind kind) {
    std::vector<const PlannedPass*> found;
    for (const PlannedPass& p : map.passes)
        if (p.target == target && p.kind == kind)
            found.push_back(&p);
    return found;
}

std::vector<const SkippedEffect*> skipsOf(const EnvmapPlan& map, const std::string& target) {
    std::vector<const SkippedEffect*> found;
    for (const SkippedEffect& s : map.skipped)
        if (s.target == target)
            found.push_back(&s);
    return found;
}

TEST(EnvmapMirrors, AMirrorTheReflectorSeesHasViewsInTheMapFacesItShowsIn) {
    const FramePlan plan = planFrame(scene(ReflectorMap::Cube), {}, {320, 240});
    ASSERT_FALSE(plan.envmaps.empty());
    const EnvmapPlan& map = plan.envmaps[0];
    EXPECT_EQ(map.target, "Ball");
    ASSERT_EQ(map.faces.size(), 6u);
    EXPECT_EQ(map.faces[1].label, "−X face");

    // The facing mirror fills the −X face (it spans 90° seen from 3 units): one view there, and maybe
    // slivers of the faces around it; never in the +X face behind the capture point.
    const auto mirrorPasses = passesOf(map, "Facing", PassKind::Mirror);
    ASSERT_FALSE(mirrorPasses.empty());
    bool inMinusX = false;
    for (const PlannedPass* p : mirrorPasses) {
        const MirrorView& view = map.views[static_cast<std::size_t>(p->view)];
        EXPECT_EQ(view.mirror, 0);
        EXPECT_EQ(view.depth, 1);
        EXPECT_NE(view.face, 0) << "not in the +X face";
        EXPECT_FALSE(view.ownTarget) << "the map nests every mirror with the stencil technique";
        inMinusX |= view.face == 1;
        const std::string& label = map.faces[static_cast<std::size_t>(view.face)].label;
        EXPECT_EQ(p->code, PlanReason::MirrorInStencil);
        EXPECT_EQ(p->details.mapFace, "Ball's map, " + label);
        // The virtual capture point is the centre mirrored in the mirror's plane x = −3.
        EXPECT_NEAR(view.eye.x, -6.0, 1e-9);
    }
    EXPECT_TRUE(inMinusX);
    // Each view comes with its mask and its surface, in execution order: mask, mirror, surface.
    EXPECT_EQ(passesOf(map, "Facing", PassKind::MirrorMask).size(), mirrorPasses.size());
    EXPECT_EQ(passesOf(map, "Facing", PassKind::MirrorSurface).size(), mirrorPasses.size());
    ASSERT_GE(map.passes.size(), 3u);
    EXPECT_EQ(map.passes[0].kind, PassKind::MirrorMask);
    EXPECT_EQ(map.passes[1].kind, PassKind::Mirror);

    // Faces the facing mirror is not in skip it with a reason naming the face.
    bool outsideNamed = false;
    for (const SkippedEffect* s : skipsOf(map, "Facing"))
        outsideNamed |= s->code == PlanReason::MirrorOutsideView &&
                        s->details.mapFace == "Ball's map, +X face" && s->face == 0;
    EXPECT_TRUE(outsideNamed);
}

TEST(EnvmapMirrors, AMirrorBehindTheCapturePointIsSkippedWithAReason) {
    const FramePlan plan = planFrame(scene(ReflectorMap::Cube), {}, {320, 240});
    ASSERT_FALSE(plan.envmaps.empty());
    const EnvmapPlan& map = plan.envmaps[0];
    EXPECT_TRUE(passesOf(map, "Away", PassKind::Mirror).empty());
    // Once per face seen from the capture point itself (deeper, in the facing mirror, the depth limit).
    std::vector<const SkippedEffect*> behind;
    for (const SkippedEffect* s : skipsOf(map, "Away"))
        if (s->code == PlanReason::MirrorBehind && s->details.seenIn.empty())
            behind.push_back(s);
    ASSERT_EQ(behind.size(), 6u);
    // The sentence names the capture point and the face.
    EXPECT_EQ(behind[0]->reason(), "no reflection: the capture point is behind the mirror (it sees its back) "
                                   "(seen directly, in Ball's map, " +
                                       map.faces[static_cast<std::size_t>(behind[0]->face)].label + ")");
}

TEST(EnvmapMirrors, MirrorsNestToTheReflectorsOwnDepth) {
    FrameInput input = scene(ReflectorMap::Cube, ReflectorFill::Resampled, 3);
    // Two facing mirrors around the ball: each sees the other.
    input.mirrors[1] = mirrorFacing("Away", {3, 0, 0}, {-1, 0, 0});
    input.settings.mirrorDepth = 1; // the camera's limit is not the map's
    const FramePlan plan = planFrame(input, {}, {320, 240});
    ASSERT_FALSE(plan.envmaps.empty());
    int deepest = 0;
    for (const MirrorView& v : plan.envmaps[0].views) {
        deepest = std::max(deepest, v.depth);
        if (v.parent >= 0) {
            const MirrorView& parent = plan.envmaps[0].views[static_cast<std::size_t>(v.parent)];
            EXPECT_EQ(parent.face, v.face) << "a view nests within its own face";
            EXPECT_EQ(v.depth, parent.depth + 1);
            EXPECT_EQ(v.stencilLevel, parent.stencilLevel + 1);
        }
    }
    EXPECT_EQ(deepest, 3);
    bool limitNamed = false;
    for (const SkippedEffect& s : plan.envmaps[0].skipped)
        limitNamed |= s.code == PlanReason::MirrorDepthLimit && s.details.limit == 3;
    EXPECT_TRUE(limitNamed);
}

TEST(EnvmapMirrors, DirectFillPlansEachComponentWithAClipPlane) {
    const FramePlan plan =
        planFrame(scene(ReflectorMap::DualParaboloid, ReflectorFill::Direct), {}, {320, 240});
    ASSERT_FALSE(plan.envmaps.empty());
    const EnvmapPlan& map = plan.envmaps[0];
    ASSERT_EQ(map.faces.size(), 2u);
    EXPECT_TRUE(map.faces[0].warped);
    EXPECT_EQ(map.faces[0].label, "−Z half");
    // The facing mirror straddles z = 0: both halves show part of it.
    const auto mirrorPasses = passesOf(map, "Facing", PassKind::Mirror);
    ASSERT_EQ(mirrorPasses.size(), 2u);
    for (const PlannedPass* p : mirrorPasses) {
        EXPECT_FALSE(p->details.area) << "no pixels to count: a clip plane, not an oblique near plane";
        const MirrorView& view = map.views[static_cast<std::size_t>(p->view)];
        // In drawn (reflected) coordinates relative to the capture point, the reflection keeps what lies
        // beyond the mirror's plane x = −3 and cuts the capture point's side.
        EXPECT_LT(glm::dot(view.clipPlane, glm::dvec4(0, 0, 0, 1)), 0.0);
        EXPECT_GT(glm::dot(view.clipPlane, glm::dvec4(-3.1, 0, 0, 1)), 0.0);
    }
}

TEST(EnvmapMirrors, NoMirrorViewsWhenTheMapIsReusedOrItsDepthIsZero) {
    FrameInput input = scene(ReflectorMap::Cube);
    PlannerState state;
    state.mapOf(0).signature = envmapSignature(input, 0);
    state.mapOf(0).reflector = input.reflectors[0].name;
    state.mapOf(0).settings = envmapSettingsKey(input.reflectors[0]);
    EXPECT_TRUE(planFrame(input, state, {320, 240}).envmaps.empty()) << "a reused map draws nothing";

    input.reflectors[0].mirrorDepth = 0;
    const FramePlan plan = planFrame(input, {}, {320, 240});
    ASSERT_FALSE(plan.envmaps.empty());
    EXPECT_TRUE(plan.envmaps[0].views.empty());
    ASSERT_EQ(plan.envmaps[0].skipped.size(), 2u);
    EXPECT_EQ(plan.envmaps[0].skipped[0].code, PlanReason::MapMirrorDepthZero);
}

} // namespace
} // namespace speculum::render
