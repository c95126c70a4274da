// A mirror hidden behind an occluder gets no reflection pass, and a visible one does not stall the frame
// for its occlusion test: frame after frame, the image stays the one a fresh renderer draws, while a
// screen slides in front of the mirror and away again.
#include "render/plan/Planner.hpp"
#include "support/GlTest.hpp"
#include "support/SceneBuilder.hpp"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 160;
constexpr int kHeight = 120;

DrawItem box(const std::string& name, glm::dvec3 centre, glm::dvec3 half, glm::dvec3 color) {
    static const MeshHandle mesh = boxMesh();
    return item(name, mesh, placed(centre, half), emissive(color));
}

// A 4 × 3 mirror at z = −2 facing the camera at (0, 0, 4), a red cube in front of it, a green one behind
// the camera (seen only in the mirror), and a blue screen that either stands between the camera and the
// mirror, hiding all of it, or far off to the side.
FrameInput scene(MirrorTechnique technique, bool screenInFront) {
    FrameInput input;
    input.settings.background = {0.0, 0.0, 0.0};
    input.settings.ambient = 0.0;
    input.camera.position = {0.0, 0.0, 4.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.fovY = 60.0;
    input.camera.far = 30.0;
    Mirror mirror = test::mirror({0.0, 0.0, -2.0}, {0.0, 0.0, 1.0}, {4.0, 3.0});
    mirror.name = "Mirror";
    mirror.reflectivity = 0.8;
    mirror.technique = technique;
    mirror.material = emissive({0.2, 0.2, 0.2});
    mirror.hasMaterial = true;
    input.mirrors.push_back(mirror);
    input.items.push_back(box("Red", {1.0, 0.3, 0.0}, glm::dvec3(0.3), {1, 0, 0}));
    // Behind the camera: seen only in the mirror, far behind its surface.
    input.items.push_back(box("Green", {-1.0, -0.3, 7.0}, glm::dvec3(0.5), {0, 1, 0}));
    // 0.5 units in front of the camera, it covers the whole view.
    input.items.push_back(box("Screen", screenInFront ? glm::dvec3(0, 0, 3.5) : glm::dvec3(100, 0, 3.5),
                              {3, 3, 0.05}, {0, 0, 1}));
    return input;
}

bool ranMirrorPass(const FrameReport& report) {
    return report.countRan(PassKind::Mirror) > 0;
}

bool skippedAsOccluded(const std::vector<SkippedEffect>& skipped) {
    for (const SkippedEffect& skip : skipped)
        if (skip.target == "Mirror" &&
            (skip.code == PlanReason::MirrorOccluded || skip.code == PlanReason::MirrorOccludedInTile))
            return true;
    return false;
}

bool skippedAsOccluded(const FrameReport& report) {
    return skippedAsOccluded(report.skipped);
}

std::size_t countPlanned(const FramePlan& plan, PassKind kind, const std::string& target) {
    return static_cast<std::size_t>(
        std::count_if(plan.passes.begin(), plan.passes.end(),
                      [&](const PlannedPass& p) { return p.kind == kind && p.target == target; }));
}

float largestDifference(const Image& a, const Image& b) {
    float largest = 0.0f;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const glm::vec4 d = glm::abs(a.at(x, y) - b.at(x, y));
            largest = std::max({largest, d.r, d.g, d.b});
        }
    return largest;
}

class MirrorOcclusion : public GlTest, public ::testing::WithParamInterface<MirrorTechnique> {
protected:
    // The same frame from a renderer that has drawn nothing before.
    Image fresh(const FrameInput& input) {
        auto renderer = Renderer::create();
        EXPECT_TRUE(renderer.ok());
        auto still = renderStill(**renderer, input, {kWidth, kHeight, 1});
        EXPECT_TRUE(still.ok());
        return still.ok() ? std::move(still->image) : Image{};
    }
};

TEST_P(MirrorOcclusion, TheImageNeverDependsOnWhatEarlierFramesSaw) {
    const FrameInput open = scene(GetParam(), false);
    const FrameInput hidden = scene(GetParam(), true);
    const Image openImage = fresh(open);
    const Image hiddenImage = fresh(hidden);
    ASSERT_GT(largestDifference(openImage, hiddenImage), 0.5f) << "the screen changes the image";

    // First sight of the mirror: the frame waits for its test, and the reflection is drawn.
    Image image = renderImage(open, kWidth, kHeight);
    EXPECT_EQ(lastReport().occlusionWaits, 1);
    EXPECT_TRUE(ranMirrorPass(lastReport()));
    EXPECT_EQ(largestDifference(image, openImage), 0.0f);

    // Seen last frame: no wait, same image.
    image = renderImage(open, kWidth, kHeight);
    EXPECT_EQ(lastReport().occlusionWaits, 0);
    EXPECT_TRUE(ranMirrorPass(lastReport()));
    EXPECT_EQ(largestDifference(image, openImage), 0.0f);

    // The screen slides in: this frame still draws the reflection (it did not wait to learn that it is
    // hidden), and the reflection shows nowhere.
    image = renderImage(hidden, kWidth, kHeight);
    EXPECT_EQ(lastReport().occlusionWaits, 0);
    EXPECT_TRUE(ranMirrorPass(lastReport()));
    EXPECT_EQ(largestDifference(image, hiddenImage), 0.0f);

    // From the next frame on the hidden mirror costs nothing, and says why.
    for (int frame = 0; frame < 2; ++frame) {
        image = renderImage(hidden, kWidth, kHeight);
        EXPECT_EQ(lastReport().occlusionWaits, 1);
        EXPECT_FALSE(ranMirrorPass(lastReport()));
        EXPECT_TRUE(skippedAsOccluded(lastReport()));
        EXPECT_EQ(largestDifference(image, hiddenImage), 0.0f);
    }

    // The screen slides away: hidden last frame, so the frame waits, finds it visible, and reflects.
    image = renderImage(open, kWidth, kHeight);
    EXPECT_EQ(lastReport().occlusionWaits, 1);
    EXPECT_TRUE(ranMirrorPass(lastReport()));
    EXPECT_EQ(largestDifference(image, openImage), 0.0f);
}

// Running a frame never edits its plan: a mirror found hidden while drawing keeps its planned passes in
// the report's plan, exactly as the planner made them; what execution found is the report's own (the
// passes that ran, the mask's outcome, the skip).
TEST_P(MirrorOcclusion, TheReportKeepsThePlanAsPlannedWhenAMirrorTurnsOutHidden) {
    const FrameInput hidden = scene(GetParam(), true);
    renderImage(hidden, kWidth, kHeight); // first sight: the frame waits for the test, finds it hidden
    const FrameReport& report = lastReport();
    ASSERT_EQ(report.occlusionWaits, 1);

    // The plan still holds every pass planned for the mirror.
    EXPECT_EQ(countPlanned(report.plan, PassKind::MirrorMask, "Mirror"), 1u);
    EXPECT_EQ(countPlanned(report.plan, PassKind::Mirror, "Mirror"), 1u);
    EXPECT_EQ(countPlanned(report.plan, PassKind::MirrorSurface, "Mirror"), 1u);
    EXPECT_FALSE(skippedAsOccluded(report.plan.skipped)) << "execution's finding written into the plan";

    // Only the mask ran for it, and says what it waited for.
    EXPECT_EQ(report.countRan(PassKind::MirrorMask, "Mirror"), 1u);
    EXPECT_EQ(report.countRan(PassKind::Mirror, "Mirror"), 0u);
    EXPECT_EQ(report.countRan(PassKind::MirrorSurface, "Mirror"), 0u);
    EXPECT_EQ(report.countRan(PassKind::Main), 1u);
    for (const PassRun& run : report.ran) {
        if (report.planned(run).kind == PassKind::MirrorMask) {
            EXPECT_EQ(report.reason(run), report.planned(run).reason() + "; waited for its occlusion test");
        }
    }
    bool said = false;
    std::string skips;
    for (const SkippedEffect& skip : report.skipped) {
        said |= skip.target == "Mirror" && skip.code == PlanReason::MirrorOccluded;
        skips += skip.target + ": " + skip.reason() + "\n";
    }
    EXPECT_TRUE(said) << skips;

    // The plan is the planner's, pass for pass: the same input plans the same frame.
    const FramePlan planned = planFrame(hidden, PlannerState{}, PlanViewport{kWidth, kHeight});
    ASSERT_EQ(report.plan.passes.size(), planned.passes.size());
    for (std::size_t i = 0; i < planned.passes.size(); ++i) {
        SCOPED_TRACE("pass " + std::to_string(i));
        EXPECT_EQ(report.plan.passes[i].kind, planned.passes[i].kind);
        EXPECT_EQ(report.plan.passes[i].target, planned.passes[i].target);
        EXPECT_EQ(report.plan.passes[i].code, planned.passes[i].code);
        EXPECT_EQ(report.plan.passes[i].reason(), planned.passes[i].reason()) << "no outcome in the plan";
        EXPECT_EQ(report.plan.passes[i].view, planned.passes[i].view);
    }
    ASSERT_EQ(report.plan.skipped.size(), planned.skipped.size());
    for (std::size_t i = 0; i < planned.skipped.size(); ++i) {
        EXPECT_EQ(report.plan.skipped[i].target, planned.skipped[i].target);
        EXPECT_EQ(report.plan.skipped[i].code, planned.skipped[i].code);
        EXPECT_EQ(report.plan.skipped[i].reason(), planned.skipped[i].reason());
    }
    EXPECT_EQ(report.plan.views.size(), planned.views.size());
}

INSTANTIATE_TEST_SUITE_P(Techniques, MirrorOcclusion,
                         ::testing::Values(MirrorTechnique::Stencil, MirrorTechnique::Texture),
                         [](const auto& info) {
                             return std::string(info.param == MirrorTechnique::Stencil ? "stencil"
                                                                                       : "texture");
                         });

} // namespace
} // namespace speculum::test
