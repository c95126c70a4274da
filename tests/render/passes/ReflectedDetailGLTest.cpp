// Reflected views draw a mesh's simplified level (MeshData::coarse) where the plan says so, and the
// camera's own view always draws it whole. The mesh here is two boxes whose "simplified level" is made by
// hand to hold only the left one, so the image shows which list each view drew.
#include "render/mesh/Simplify.hpp"
#include "support/GlTest.hpp"
#include "support/SceneBuilder.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// Two unit boxes at x = −2 and x = +2; the coarse level keeps the first only.
MeshHandle twoBoxesCoarselyOne() {
    const MeshData box = makeBox();
    MeshData mesh;
    for (float x : {-2.0f, 2.0f}) {
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (std::size_t v = 0; v < box.positions.size(); ++v) {
            mesh.positions.push_back(box.positions[v] + glm::vec3(x, 0.0f, 0.0f));
            mesh.normals.push_back(box.normals[v]);
        }
        for (std::uint32_t index : box.indices)
            mesh.indices.push_back(base + index);
    }
    mesh.coarse.set(
        CoarseLevel{{mesh.indices.begin(), mesh.indices.begin() + std::ptrdiff_t(box.indices.size())}, 0.0f});
    return freezeMesh(std::move(mesh)); // moved: the hand-made level is kept
}

// The camera at (0, 0, 4) looks at a 10 × 6 perfect mirror at z = −4. The two boxes stand either behind
// the camera (seen only in the mirror) or in front of the mirror (seen directly, hiding their reflection).
FrameInput scene(MirrorTechnique technique, bool behindCamera) {
    FrameInput input;
    input.settings.background = {0.0, 0.0, 0.0};
    input.settings.ambient = 0.0;
    input.camera.position = {0.0, 0.0, 4.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.fovY = 60.0;
    input.camera.far = 60.0;
    Mirror m = mirror({0.0, 0.0, -4.0}, {0.0, 0.0, 1.0}, {10.0, 6.0});
    m.name = "Mirror";
    m.technique = technique;
    input.mirrors.push_back(m);
    const glm::dvec3 at = behindCamera ? glm::dvec3(0.0, 0.0, 9.0) : glm::dvec3(0.0, 0.0, -1.0);
    input.items.push_back(
        item("Boxes", twoBoxesCoarselyOne(), placed(at, glm::dvec3(0.6)), emissive({1, 1, 1})));
    return input;
}

// Lit pixels in the left and the right half of the image.
std::pair<int, int> litHalves(const Image& image) {
    int left = 0;
    int right = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4] > 0.5f)
                ++(x < image.width / 2 ? left : right);
    return {left, right};
}

class ReflectedDetail : public GlTest, public ::testing::WithParamInterface<MirrorTechnique> {};

TEST_P(ReflectedDetail, TheMirrorDrawsTheSimplifiedLevel) {
    const Image image = renderImage(scene(GetParam(), true), kWidth, kHeight);
    const auto [left, right] = litHalves(image);
    EXPECT_GT(left + right, 20) << "the kept box's reflection shows";
    EXPECT_TRUE(left == 0 || right == 0)
        << "only one box is in the simplified level: " << left << " / " << right;
    bool said = false;
    for (const auto& pass : lastReport().plan.passes)
        said = said ||
               (pass.kind == PassKind::Mirror && !pass.details.bigMeshes.empty() &&
                pass.details.bigMeshes[0].name == "Boxes" && pass.details.bigMeshes[0].simplifiedTriangles);
    EXPECT_TRUE(said) << "the mirror pass says it draws the mesh simplified";
}

TEST_P(ReflectedDetail, TurnedOffTheMirrorDrawsEveryTriangle) {
    FrameInput input = scene(GetParam(), true);
    input.settings.simplifyReflections = false;
    const auto [left, right] = litHalves(renderImage(input, kWidth, kHeight));
    EXPECT_GT(left, 20);
    EXPECT_GT(right, 20);
}

TEST_P(ReflectedDetail, TheCamerasOwnViewDrawsEveryTriangle) {
    const auto [left, right] = litHalves(renderImage(scene(GetParam(), false), kWidth, kHeight));
    EXPECT_GT(left, 20);
    EXPECT_GT(right, 20);
}

// The reflector's map, filled through the warp (whose split copies are made of the simplified level) and
// through cube faces: the ball shows the kept box only, and no GL error is raised.
class ReflectedDetailInTheMap : public GlTest, public ::testing::WithParamInterface<ReflectorFill> {};

TEST_P(ReflectedDetailInTheMap, TheBallReflectsTheSimplifiedLevel) {
    for (bool simplify : {true, false}) {
        FrameInput input = scene(MirrorTechnique::Stencil, true);
        input.mirrors.clear();
        input.settings.simplifyReflections = simplify;
        Reflector ball;
        ball.name = "Ball";
        ball.mesh = freezeMesh(makeSphere());
        ball.world = placed({0.0, 0.0, 0.0}, glm::dvec3(1.5));
        ball.map = ReflectorMap::DualParaboloid;
        ball.fill = GetParam();
        ball.resolution = 128;
        input.reflectors = {ball};
        const auto [left, right] = litHalves(renderImage(input, kWidth, kHeight));
        if (simplify) {
            EXPECT_GT(left + right, 3) << "the kept box shows in the ball";
            EXPECT_TRUE(left == 0 || right == 0) << left << " / " << right;
        } else {
            EXPECT_GT(left, 3);
            EXPECT_GT(right, 3);
        }
    }
}

// A mesh's simplified level is built only when a reflected view first needs it: by the frame itself by
// default (a still waits for it), or by whoever the renderer hands it to (the editor's worker), the frame
// drawing the mesh whole meanwhile.
class CoarseLevelOnDemand : public GlTest {
protected:
    static FrameInput withBigSphere(FrameInput input, const MeshHandle& big) {
        input.items.clear();
        input.items.push_back(
            item("Statue", big, placed({0.0, 0.0, 9.0}, glm::dvec3(1.0)), emissive({1, 1, 1})));
        return input;
    }
};

TEST_F(CoarseLevelOnDemand, AStillBuildsTheLevelItsMirrorNeedsAndDrawsWithIt) {
    const MeshHandle big = freezeMesh(makeSphere(256));
    ASSERT_GT(big->triangleCount(), kSimplifyAboveTriangles);
    FrameInput unreflected = withBigSphere(scene(MirrorTechnique::Stencil, true), big);
    unreflected.mirrors.clear();
    renderImage(unreflected, kWidth, kHeight);
    EXPECT_EQ(big->coarse.ready(), nullptr) << "nothing reflects the mesh: its level is never built";

    renderImage(withBigSphere(scene(MirrorTechnique::Stencil, true), big), kWidth, kHeight);
    ASSERT_NE(big->coarse.ready(), nullptr) << "the mirror needed it: built within the frame";
    EXPECT_EQ(lastReport().plan.coarseItems, (std::vector<bool>{true})) << "and drawn with at once";
    EXPECT_TRUE(lastReport().plan.coarseLevelsWanted.empty());
}

TEST_F(CoarseLevelOnDemand, WithARequestTheFrameDrawsTheMeshWholeUntilTheLevelIsReady) {
    const MeshHandle big = freezeMesh(makeSphere(256));
    std::vector<MeshHandle> asked;
    renderer().setCoarseLevelRequest([&](const std::vector<MeshHandle>& meshes) {
        asked.insert(asked.end(), meshes.begin(), meshes.end());
    });
    const FrameInput input = withBigSphere(scene(MirrorTechnique::Texture, true), big);
    const auto whole = litHalves(renderImage(input, kWidth, kHeight));
    EXPECT_EQ(asked, (std::vector<MeshHandle>{big}));
    EXPECT_EQ(big->coarse.ready(), nullptr) << "the frame did not build it itself";
    EXPECT_TRUE(lastReport().plan.coarseItems.empty());
    EXPECT_GT(whole.first + whole.second, 20) << "the reflection shows the mesh, whole";

    coarseLevel(*big); // what the request's worker does
    asked.clear();
    const auto simplified = litHalves(renderImage(input, kWidth, kHeight));
    EXPECT_TRUE(asked.empty()) << "a built level is not asked for again";
    EXPECT_EQ(lastReport().plan.coarseItems, (std::vector<bool>{true}));
    // The simplified sphere covers the same pixels within its error bound: an uploaded level, not garbage.
    const int wholePixels = whole.first + whole.second;
    const int simplifiedPixels = simplified.first + simplified.second;
    EXPECT_NEAR(simplifiedPixels, wholePixels, wholePixels / 20 + 2);
}

INSTANTIATE_TEST_SUITE_P(BothFills, ReflectedDetailInTheMap,
                         ::testing::Values(ReflectorFill::Direct, ReflectorFill::Resampled),
                         [](const ::testing::TestParamInfo<ReflectorFill>& info) {
                             return std::string(info.param == ReflectorFill::Direct ? "Direct" : "Resampled");
                         });

INSTANTIATE_TEST_SUITE_P(BothTechniques, ReflectedDetail,
                         ::testing::Values(MirrorTechnique::Stencil, MirrorTechnique::Texture),
                         [](const ::testing::TestParamInfo<MirrorTechnique>& info) {
                             return std::string(info.param == MirrorTechnique::Stencil ? "Stencil"
                                                                                       : "Texture");
                         });

} // namespace
} // namespace speculum::test
