// The environment pass of the curved reflector, planned without GL: it runs only when the reflector can
// be seen (directly or in a mirror), after the shadow passes and before the main pass, and its update
// policy reuses the map when nothing the map sees changed.
#include "render/imageio/TextureLoader.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <optional>

namespace speculum::render {
namespace {

MeshHandle sphere() {
    static const auto mesh = std::make_shared<const MeshData>(makeSphere(16));
    return mesh;
}

// A chrome ball at the origin on a box, a shadowing light; the camera at +Z looks at it.
FrameInput chromeScene(ReflectorUpdate update = ReflectorUpdate::OnChange) {
    FrameInput input;
    input.camera.position = {0.0, 0.0, 5.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.far = 50.0;
    static const auto box = std::make_shared<const MeshData>(makeBox());
    input.items.push_back({"Box", glm::translate(glm::dmat4(1.0), glm::dvec3(2, 0, 0)), box, {}, true});
    Light light;
    light.name = "Lamp";
    light.position = {0, 4, 0};
    light.shadows = ShadowParams{};
    input.lights.push_back(light);
    Reflector r;
    r.name = "Ball";
    r.mesh = sphere();
    r.update = update;
    input.reflectors = {r};
    return input;
}

std::vector<PassKind> kinds(const FramePlan& plan) {
    std::vector<PassKind> k;
    for (const auto& p : plan.passes)
        k.push_back(p.kind);
    return k;
}

// The code of the target's skip; none when the plan has none for it.
std::optional<PlanReason> skipCode(const FramePlan& plan, const std::string& target) {
    for (const auto& s : plan.skipped)
        if (s.target == target)
            return s.code;
    return std::nullopt;
}

bool hasEnvmap(const FramePlan& plan) {
    for (const auto& p : plan.passes)
        if (p.kind == PassKind::Envmap)
            return true;
    return false;
}

// What the renderer records after it ran the envmap pass.
PlannerState afterRendering(const FrameInput& input) {
    PlannerState state;
    state.mapOf(0).signature = envmapSignature(input, 0);
    state.mapOf(0).reflector = input.reflectors[0].name;
    state.mapOf(0).settings = envmapSettingsKey(input.reflectors[0]);
    return state;
}

TEST(ReflectorPlanner, EnvmapRunsAfterShadowsAndBeforeTheMainPass) {
    const FramePlan plan = planFrame(chromeScene(), {});
    EXPECT_EQ(kinds(plan),
              (std::vector{PassKind::Shadow, PassKind::Envmap, PassKind::Main, PassKind::Composite}));
    const PlannedPass& envmap = plan.passes[1];
    EXPECT_EQ(envmap.target, "Ball");
    EXPECT_EQ(envmap.code, PlanReason::EnvmapFirstMap);
    EXPECT_TRUE(envmap.details.seenIn.empty()) << "seen directly";
    EXPECT_EQ(envmap.details.map, ReflectorMap::Cube);
    // The sentence the pass shows, as explain prints it.
    EXPECT_EQ(envmap.reason(),
              "renders the scene around the reflector, lit and shadowed, from its centre into a "
              "cube map (6 faces of 256×256); the reflector is seen directly; no map yet");
}

// Traced in screen space, a sharp reflector needs the depth pyramid and its trace after the main pass; a
// rough one also needs the image's blurred pyramid, just before the trace, and each says why.
TEST(ReflectorPlanner, ARoughReflectorTracedInScreenSpaceBlursTheImageFirst) {
    FrameInput input = chromeScene();
    input.reflectors[0].technique = ReflectorTechnique::ScreenSpace;
    EXPECT_EQ(kinds(planFrame(input, {})),
              (std::vector{PassKind::Shadow, PassKind::Envmap, PassKind::Main, PassKind::ScreenDepth,
                           PassKind::ReflectorTrace, PassKind::Composite}));
    input.reflectors[0].roughness = 0.3;
    const FramePlan rough = planFrame(input, {});
    EXPECT_EQ(kinds(rough), (std::vector{PassKind::Shadow, PassKind::Envmap, PassKind::Prefilter,
                                         PassKind::Main, PassKind::ScreenDepth, PassKind::ScreenColour,
                                         PassKind::ReflectorTrace, PassKind::Composite}));
    EXPECT_TRUE(rough.skipped.empty());
    const PlannedPass& colour = rough.passes[5];
    EXPECT_EQ(colour.code, PlanReason::ScreenColourPyramid);
    EXPECT_EQ(toString(colour.code), "screen-colour-pyramid");
    EXPECT_NE(colour.reason().find("Ball's rough trace (roughness 30%)"), std::string::npos)
        << colour.reason();
    EXPECT_NE(rough.passes[6].reason().find("rough: a cone"), std::string::npos) << rough.passes[6].reason();
    EXPECT_EQ(toString(PassKind::ScreenColour), "screen-colour");
}

TEST(ReflectorPlanner, NoEnvmapWhenTheReflectorIsOutsideTheView) {
    FrameInput input = chromeScene();
    input.camera.target = {0.0, 0.0, 10.0}; // looking away
    const FramePlan plan = planFrame(input, {});
    EXPECT_FALSE(hasEnvmap(plan));
    EXPECT_EQ(skipCode(plan, "Ball"), PlanReason::EnvmapOutOfSight);

    input.camera.target = {0.0, 0.0, 0.0};
    input.reflectors[0].world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 8)); // behind the camera
    EXPECT_FALSE(hasEnvmap(planFrame(input, {})));
    input.reflectors[0].world =
        glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -60)); // beyond the far plane
    EXPECT_FALSE(hasEnvmap(planFrame(input, {})));
    // Barely inside the frustum's edge: still planned (the test is conservative, never wrong).
    input.reflectors[0].world = glm::translate(glm::dmat4(1.0), glm::dvec3(3.4, 0, 0));
    EXPECT_TRUE(hasEnvmap(planFrame(input, {})));
}

TEST(ReflectorPlanner, ReflectorSeenOnlyInAMirrorGetsItsEnvmap) {
    FrameInput input = chromeScene();
    // The camera looks at a mirror in z = −4 facing +Z; the ball is behind the camera, so only the mirror
    // shows it.
    input.camera.position = {0.0, 0.0, 2.0};
    input.camera.target = {0.0, 0.0, -4.0};
    input.reflectors[0].world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 4));
    Mirror mirror;
    mirror.name = "Mirror";
    mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -4)), glm::radians(90.0),
                               glm::dvec3(1, 0, 0));
    mirror.size = {6.0, 6.0};
    input.mirrors.push_back(mirror);
    FramePlan plan = planFrame(input, {}, {320, 240});
    ASSERT_TRUE(hasEnvmap(plan));
    for (const auto& p : plan.passes) {
        if (p.kind == PassKind::Envmap) {
            EXPECT_EQ(p.details.seenIn, std::vector<std::string>{"Mirror"}) << p.reason();
        }
    }

    // The reason says how deep the mirrors reflect inside the map.
    for (int depth : {0, 1, 3}) {
        input.reflectors[0].mirrorDepth = depth;
        for (const auto& p : planFrame(input, {}, {320, 240}).passes) {
            if (p.kind != PassKind::Envmap)
                continue;
            EXPECT_EQ(p.details.mapMirrorDepth, depth) << p.reason();
        }
    }

    // Turned away from the mirror's reflected view (the mirror now shows the scene to the left).
    input.reflectors[0].world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 40, 4));
    plan = planFrame(input, {}, {320, 240});
    EXPECT_FALSE(hasEnvmap(plan));
    EXPECT_EQ(skipCode(plan, "Ball"), PlanReason::EnvmapOutOfSight);
}

TEST(ReflectorPlanner, OnChangeReusesTheMapUntilSomethingItSeesChanges) {
    FrameInput input = chromeScene();
    const PlannerState state = afterRendering(input);
    FramePlan plan = planFrame(input, state);
    EXPECT_FALSE(hasEnvmap(plan));
    EXPECT_EQ(skipCode(plan, "Ball"), PlanReason::EnvmapUnchanged);

    // The camera is not part of what the map sees.
    input.camera.position = {1.0, 1.0, 6.0};
    EXPECT_FALSE(hasEnvmap(planFrame(input, state)));

    // An object moves (an animation does this), a light changes, a material changes, the ball moves,
    // the map settings change: each needs a new map.
    auto rerenders = [&](auto change) {
        FrameInput changed = input;
        change(changed);
        const FramePlan p = planFrame(changed, state);
        return hasEnvmap(p);
    };
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].world[3].y += 0.1; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.lights[0].color = {1.0, 0.5, 0.5}; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.color = {1.0, 0.0, 0.0}; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.reflectors[0].world[3].x += 0.1; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.reflectors[0].map = ReflectorMap::TennisBall; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.reflectors[0].resolution = 128; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.settings.background = {1.0, 1.0, 1.0}; }));
    // Every material field a model file brings, the textures by identity (file or decoded image) and
    // their wrap modes.
    auto image = std::make_shared<const TextureImage>(checkerTexture(4));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.specularColor = {1.0, 0.5, 0.0}; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.texture.path = "/abs/a.png"; }));
    EXPECT_TRUE(rerenders([&](FrameInput& f) { f.items[0].material.texture.image = image; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.wrap[0] = TextureWrap::ClampToEdge; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.wrap[1] = TextureWrap::MirroredRepeat; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.emissionTexture.path = "/abs/e.png"; }));
    EXPECT_TRUE(rerenders([&](FrameInput& f) { f.items[0].material.emissionTexture.image = image; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.normalTexture.path = "/abs/n.png"; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.normalScale = 0.5; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.opacity = 0.5; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.alphaMode = AlphaMode::Mask; }));
    EXPECT_TRUE(rerenders([](FrameInput& f) { f.items[0].material.alphaCutoff = 0.3; }));
    // The reflector's own material is not seen by its map.
    EXPECT_FALSE(rerenders([](FrameInput& f) { f.reflectors[0].material.color = {1.0, 0.0, 0.0}; }));
    EXPECT_FALSE(rerenders([](FrameInput& f) { f.reflectors[0].reflectivity = 0.5; }));
}

TEST(ReflectorPlanner, OnceKeepsTheFirstMapAndAlwaysRendersEveryFrame) {
    FrameInput once = chromeScene(ReflectorUpdate::Once);
    EXPECT_TRUE(hasEnvmap(planFrame(once, {}))) << "the first frame has no map";
    PlannerState state = afterRendering(once);
    once.items[0].world[3].y += 1.0;
    FramePlan plan = planFrame(once, state);
    EXPECT_FALSE(hasEnvmap(plan));
    EXPECT_EQ(skipCode(plan, "Ball"), PlanReason::EnvmapReusedOnce);
    once.reflectors[0].map = ReflectorMap::DualParaboloid; // new textures: rendered once more
    EXPECT_TRUE(hasEnvmap(planFrame(once, state)));

    FrameInput always = chromeScene(ReflectorUpdate::Always);
    state = afterRendering(always);
    plan = planFrame(always, state);
    ASSERT_TRUE(hasEnvmap(plan));
    EXPECT_EQ(plan.passes[1].code, PlanReason::EnvmapAlways);
}

// The envmap pass of a plan; none when the plan draws no map.
const PlannedPass* envmapPass(const FramePlan& plan) {
    for (const auto& p : plan.passes)
        if (p.kind == PassKind::Envmap)
            return &p;
    return nullptr;
}

// Plans a frame and records what its map pass drew, as the renderer does; the faces it drew.
std::vector<int> playFrame(const FrameInput& input, PlannerState& state, FramePlan* planned = nullptr) {
    const FramePlan plan = planFrame(input, state);
    std::vector<int> drawn;
    if (!plan.envmaps.empty()) {
        for (const EnvmapFace& face : plan.envmaps[0].faces)
            drawn.push_back(face.index);
        recordEnvmap(plan.envmaps[0], state);
    }
    if (planned)
        *planned = plan;
    return drawn;
}

TEST(ReflectorPlanner, TimeSlicedRedrawsOneOutOfDateFaceAFrameInTurn) {
    FrameInput input = chromeScene(ReflectorUpdate::TimeSliced);
    PlannerState state;
    // The first map is drawn whole, whatever the policy.
    EXPECT_EQ(playFrame(input, state), (std::vector{0, 1, 2, 3, 4, 5}));
    EXPECT_TRUE(playFrame(input, state).empty());

    // The box moves once: one face a frame, in GL's order, until every face shows the new scene.
    input.items[0].world[3].y += 0.5;
    for (int frame = 0; frame < 6; ++frame) {
        FramePlan plan;
        EXPECT_EQ(playFrame(input, state, &plan), std::vector{frame}) << "frame " << frame;
        const PlannedPass* pass = envmapPass(plan);
        ASSERT_NE(pass, nullptr);
        EXPECT_EQ(pass->code, PlanReason::EnvmapTimeSliced);
        EXPECT_EQ(pass->details.mapFaces, 6);
        EXPECT_EQ(pass->details.staleFaces, 5 - frame);
        if (frame == 0) {
            EXPECT_NE(pass->reason().find("only its +X face this frame"), std::string::npos)
                << pass->reason();
            EXPECT_NE(pass->reason().find("5 of the other 5 still show an older scene, the oldest drawn 1 "
                                          "map update ago"),
                      std::string::npos)
                << pass->reason();
        }
        if (frame == 5) {
            EXPECT_NE(pass->reason().find("the other 5 are up to date"), std::string::npos) << pass->reason();
        }
    }
    FramePlan rest;
    EXPECT_TRUE(playFrame(input, state, &rest).empty()) << "converged: nothing more to draw";
    EXPECT_EQ(skipCode(rest, "Ball"), PlanReason::EnvmapUnchanged);
    EXPECT_NE(rest.skipped.front().reason().find("(update time-sliced)"), std::string::npos);

    // Moving every frame: the faces still come round in turn, the one drawn longest ago first.
    std::vector<int> order;
    for (int frame = 0; frame < 9; ++frame) {
        input.items[0].world[3].x += 0.1;
        for (int face : playFrame(input, state))
            order.push_back(face);
    }
    EXPECT_EQ(order, (std::vector{0, 1, 2, 3, 4, 5, 0, 1, 2}));

    // Mid-slice (faces 3..5 older), the policy changes to on-change or once: the map is drawn whole, not
    // reused part done.
    for (ReflectorUpdate policy : {ReflectorUpdate::OnChange, ReflectorUpdate::Once}) {
        FrameInput switched = input;
        switched.reflectors[0].update = policy;
        FramePlan whole;
        PlannerState midSlice = state;
        EXPECT_EQ(playFrame(switched, midSlice, &whole), (std::vector{0, 1, 2, 3, 4, 5}))
            << names::fileName(names::kReflectorUpdates, policy);
        EXPECT_EQ(envmapPass(whole)->code, PlanReason::EnvmapChanged);
        EXPECT_TRUE(playFrame(switched, midSlice).empty()) << "then reused";
    }

    // A direct-fill map slices by its two parts.
    input.reflectors[0].map = ReflectorMap::DualParaboloid;
    input.reflectors[0].fill = ReflectorFill::Direct;
    EXPECT_EQ(playFrame(input, state), (std::vector{0, 1})) << "new settings: drawn whole";
    input.items[0].world[3].x += 0.1;
    FramePlan plan;
    EXPECT_EQ(playFrame(input, state, &plan), std::vector{0});
    ASSERT_NE(envmapPass(plan), nullptr);
    EXPECT_NE(envmapPass(plan)->reason().find("only its −Z half this frame, one of 2"), std::string::npos)
        << envmapPass(plan)->reason();
    EXPECT_EQ(playFrame(input, state), std::vector{1});
    EXPECT_TRUE(playFrame(input, state).empty());
}

TEST(ReflectorPlanner, CaptureLooksFromTheCentreOfTheReflectorsBounds) {
    FrameInput input = chromeScene();
    input.reflectors[0].world =
        glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)), glm::dvec3(0.5));
    const EnvmapCapture capture = envmapCapture(input, 0);
    EXPECT_NEAR(capture.centre.x, 1.0, 1e-6);
    EXPECT_NEAR(capture.centre.y, 2.0, 1e-6);
    EXPECT_NEAR(capture.centre.z, 3.0, 1e-6);
    // Nothing outside the ball is clipped by a cube face's near plane (corners reach near·√3).
    EXPECT_LT(capture.near * std::sqrt(3.0), 0.5);
    EXPECT_GT(capture.near, 0.0);
    // The far distance reaches the box at (2, 0, 0) ± 1.
    EXPECT_GE(capture.far, glm::length(glm::dvec3(3, 1, 1) - glm::dvec3(1, 2, 3)));
}

} // namespace
} // namespace speculum::render
