// The camera's and the mirrors' views cull the back faces of closed meshes they can never see inside
// (passes::hidesBackFaces), and draw the back faces of those a near plane cuts only thinly after their front
// faces (passes::drawsBackFacesLast). Neither may change the image: not for a mesh the camera stands in, one
// its near plane cuts, one that crosses a mirror's plane (the reflection's near plane), an inside-out
// one, a masked one or one mirrored by a negative scale.
#include "render/math/Projection.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/passes/EnvironmentFaces.hpp"
#include "render/passes/MainPass.hpp"
#include "render/passes/MirrorPasses.hpp"
#include "render/passes/ShadowMaps.hpp"
#include "render/plan/Planner.hpp"
#include "support/GlTest.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 240, kHeight = 160;

MeshHandle sphere() {
    static const MeshHandle mesh = std::make_shared<const MeshData>(makeSphere(16));
    return mesh;
}

MeshHandle box() {
    static const MeshHandle mesh = std::make_shared<const MeshData>(makeBox());
    return mesh;
}

MeshHandle insideOutSphere() {
    static const MeshHandle mesh = [] {
        MeshData m = makeSphere(16);
        for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3)
            std::swap(m.indices[t], m.indices[t + 1]);
        return std::make_shared<const MeshData>(std::move(m));
    }();
    return mesh;
}

DrawItem item(const std::string& name, const MeshHandle& mesh, glm::dvec3 at, glm::dvec3 scale,
              glm::dvec3 color) {
    DrawItem d{name, glm::scale(glm::translate(glm::dmat4(1.0), at), scale), mesh, {}, true};
    d.material.color = color;
    d.material.specular = 0.4;
    return d;
}

Mirror mirror(const std::string& name, const glm::dmat4& world, glm::dvec2 size, MirrorTechnique technique) {
    Mirror m;
    m.name = name;
    m.world = world;
    m.size = size;
    m.reflectivity = 0.8;
    m.technique = technique;
    return m;
}

// Closed meshes in every situation: above a floor mirror, resting on it, half through it, cut by the camera's
// near plane, inside out, mirrored, masked, and a room-sized box the camera stands in, all reflected in a
// floor and a wall mirror.
FrameInput scene(MirrorTechnique floorTechnique) {
    FrameInput input;
    input.settings.ambient = 0.2;
    input.camera.position = {0.3, 1.4, 3.0};
    input.camera.target = {0.0, 0.4, 0.0};
    input.camera.near = 0.3;
    input.camera.far = 40.0;
    input.items = {item("Above", sphere(), {-0.8, 0.6, 0.0}, glm::dvec3(0.5), {0.8, 0.2, 0.1}),
                   item("Resting", sphere(), {-0.1, 0.25, 0.9}, glm::dvec3(0.25), {0.9, 0.5, 0.1}),
                   item("Through the floor", sphere(), {0.7, 0.0, 0.3}, glm::dvec3(0.45), {0.2, 0.7, 0.2}),
                   item("At the eye", box(), {0.45, 1.35, 2.75}, glm::dvec3(0.2), {0.9, 0.8, 0.2}),
                   item("Inside out", insideOutSphere(), {0.0, 0.5, -1.0}, glm::dvec3(0.4), {0.2, 0.3, 0.9}),
                   item("Mirrored", box(), {-0.3, 0.3, 1.0}, glm::dvec3(-0.25, 0.25, 0.25), {0.7, 0.3, 0.8}),
                   item("Masked", sphere(), {1.2, 0.9, -0.6}, glm::dvec3(0.35), {0.9, 0.9, 0.9}),
                   item("Room", box(), {0.0, 2.0, 0.0}, glm::dvec3(6.0, 4.0, 6.0), {0.6, 0.6, 0.65})};
    input.items[6].material.alphaMode = AlphaMode::Mask; // a cut-out could open it: never culled
    input.mirrors = {mirror("Floor", glm::dmat4(1.0), {4.0, 4.0}, floorTechnique),
                     mirror("Wall",
                            glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 1.0, -1.9)),
                                        glm::radians(90.0), glm::dvec3(1, 0, 0)),
                            {2.0, 1.6}, MirrorTechnique::Stencil)};
    Light lamp;
    lamp.name = "Lamp";
    lamp.position = {1.0, 3.0, 1.5};
    lamp.intensity = 0.9;
    input.lights = {lamp};
    input.settings.mirrorDepth = 2;
    return input;
}

// What the main pass needs to ask which faces a view draws, without drawing.
struct DrawContext {
    gl::Program program;
    gl::MeshCache meshes;
    gl::TextureCache textures;
    passes::ShadowMaps shadows;
    const std::vector<ShadowPlan> shadowPlans;
    passes::MeshFacts facts;
    passes::MainPassContext context{program, meshes, textures, shadows, shadowPlans, 0, 0, box()};
    DrawContext() { context.meshFacts = &facts; }

    // The camera's space of the plan, seen through `projection` (viewSetup asks nothing else of it).
    passes::ViewSpace cameraSpace(const FrameInput& input, const FramePlan& plan,
                                  const glm::dmat4& projection) {
        return {.input = input,
                .views = plan.views,
                .rotation = math::viewRotation(input.camera),
                .projection = projection,
                .size = {kWidth, kHeight},
                .preWeighted = plan.preWeighted,
                .context = context,
                .flatProgram = program,
                .mirrorProgram = program};
    }
};

class BackFaceCulling : public GlTest {
protected:
    // The largest difference of any channel between the still drawn with every face in order and the one
    // drawn with back faces culled or drawn last; -1 when either failed.
    double largestDifference(const FrameInput& input) {
        StillSettings settings{kWidth, kHeight, 1};
        settings.cullHiddenBackFaces = false;
        auto every = renderStill(renderer(), input, settings);
        settings.cullHiddenBackFaces = true;
        auto culled = renderStill(renderer(), input, settings);
        if (!every.ok() || !culled.ok())
            return -1.0;
        for (const std::string& warning : culled->firstSample.warnings)
            ADD_FAILURE() << warning;
        double largest = 0.0;
        for (std::size_t i = 0; i < every->image.rgba.size(); ++i)
            largest = std::max(largest, double(std::abs(every->image.rgba[i] - culled->image.rgba[i])));
        return largest;
    }
};

TEST_F(BackFaceCulling, NeverChangesTheImage) {
    for (MirrorTechnique technique : {MirrorTechnique::Stencil, MirrorTechnique::Texture}) {
        SCOPED_TRACE(technique == MirrorTechnique::Stencil ? "stencil floor" : "texture floor");
        EXPECT_EQ(largestDifference(scene(technique)), 0.0);
    }
}

// A sphere the camera's near plane cuts a thin cap off: through the hole, its inside (back faces, drawn
// after the front faces) hides the backdrop behind it, exactly as when every face is drawn in order.
TEST_F(BackFaceCulling, BackFacesDrawnLastShowThroughTheCut) {
    FrameInput input;
    input.settings.ambient = 0.3;
    input.camera.position = {0.0, 0.5, 3.0};
    input.camera.target = {0.0, 0.5, 0.0};
    input.camera.near = 0.3;
    input.camera.far = 40.0;
    const double radius = 0.3, cut = 0.005;
    const double centre = input.camera.position.z - (input.camera.near + radius - cut);
    input.items = {item("Cut open", sphere(), {0.0, 0.5, centre}, glm::dvec3(radius), {0.9, 0.5, 0.1}),
                   item("Backdrop", box(), {0.0, 0.5, -2.0}, glm::dvec3(3.0, 3.0, 0.1), {0.1, 0.3, 0.9})};
    Light lamp;
    lamp.name = "Lamp";
    lamp.position = {1.0, 3.0, 3.0};
    input.lights = {lamp};

    DrawContext draw;
    const FramePlan plan = planFrame(input, {}, PlanViewport{kWidth, kHeight});
    const glm::dmat4 projection =
        math::perspective(input.camera.fovY, double(kWidth) / kHeight, input.camera.near, input.camera.far);
    const passes::ViewSetup camera = passes::viewSetup(draw.cameraSpace(input, plan, projection), -1, false);
    EXPECT_TRUE(passes::drawsBackFacesLast(input.items[0], input, camera, draw.context));
    EXPECT_FALSE(passes::hidesBackFaces(input.items[0], input, camera, draw.context));

    EXPECT_EQ(largestDifference(input), 0.0);
}

// Which items a view culls: the ones it can never see a back face of, and no other.
TEST_F(BackFaceCulling, OnlyClosedOpaqueMeshesWhollyBeyondTheNearPlane) {
    const FrameInput input = scene(MirrorTechnique::Texture);
    DrawContext draw;
    passes::MainPassContext& context = draw.context;

    const FramePlan plan = planFrame(input, {}, PlanViewport{kWidth, kHeight});
    const glm::dmat4 projection =
        math::perspective(input.camera.fovY, double(kWidth) / kHeight, input.camera.near, input.camera.far);
    // The names of the items `view` treats so (hidesBackFaces or drawsBackFacesLast).
    using Question = bool (*)(const DrawItem&, const FrameInput&, const passes::ViewSetup&,
                              const passes::MainPassContext&);
    auto itemsWhere = [&](Question question, int view) {
        const passes::ViewSetup setup =
            passes::viewSetup(draw.cameraSpace(input, plan, projection), view, false);
        std::vector<std::string> names;
        for (const DrawItem& d : input.items)
            if (question(d, input, setup, context))
                names.push_back(d.name);
        return names;
    };
    auto culls = [&](int view) { return itemsWhere(passes::hidesBackFaces, view); };
    EXPECT_EQ(culls(-1), (std::vector<std::string>{"Above", "Resting", "Through the floor", "Mirrored"}));

    // Reflected in the floor, with the oblique near plane on the floor: the sphere through it is cut, and
    // so is the one resting on it (the reflection keeps only what lies a little beyond the plane).
    int floor = -1;
    for (std::size_t v = 0; v < plan.views.size(); ++v)
        if (plan.views[v].parent < 0 &&
            input.mirrors[static_cast<std::size_t>(plan.views[v].mirror)].name == "Floor")
            floor = static_cast<int>(v);
    ASSERT_GE(floor, 0);
    EXPECT_EQ(culls(floor), (std::vector<std::string>{"Above", "At the eye", "Mirrored"}));

    // Front faces first, back faces after them: the closed opaque meshes the near plane cuts only thinly.
    // In the floor's reflection, the sphere resting on it (its clip takes off a sliver); not the one half
    // through it nor the room box (the floor's plane cuts it deep), and in the camera's view neither the box
    // at the eye nor the room the camera stands in.
    auto backFacesLast = [&](int view) { return itemsWhere(passes::drawsBackFacesLast, view); };
    EXPECT_TRUE(backFacesLast(-1).empty());
    EXPECT_EQ(backFacesLast(floor), (std::vector<std::string>{"Resting"}));

    // Without the mesh facts nothing is culled.
    context.meshFacts = nullptr;
    EXPECT_TRUE(culls(-1).empty());
    EXPECT_TRUE(backFacesLast(floor).empty());
}

} // namespace
} // namespace speculum::test
