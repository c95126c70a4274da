// The editor's guide lines (RenderOptions::guides) in the frame: drawn over the camera's view where nothing
// stands in front of them, faintly where a line asks for it, never inside a mirror's reflection, and
// planned as a pass of their own that stills and tiles never run. Both ways an 8-bit frame reaches its
// output are tried: drawn straight into a viewport-like sRGB target with depth, and through the
// renderer's own buffer and the composite.
#include "render/gl/Objects.hpp"
#include "render/math/Projection.hpp"
#include "render/mesh/Primitives.hpp"
#include "support/GlTest.hpp"

#include <algorithm>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 320, kHeight = 180;

// A red box at the origin on a dark background, seen straight on from z = 4.
FrameInput boxScene() {
    FrameInput input;
    input.settings.background = {0.02, 0.02, 0.03};
    input.camera.position = {0.0, 0.0, 4.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.far = 40.0;
    DrawItem box{"Box", glm::dmat4(1.0), std::make_shared<const MeshData>(makeBox()), {}, true};
    box.material.color = {0.8, 0.1, 0.1};
    Light light;
    light.name = "Light";
    light.position = {1.0, 2.0, 5.0};
    input.items = {box};
    input.lights = {light};
    return input;
}

GuideLine whiteLine(glm::dvec3 from, glm::dvec3 to, float hiddenOpacity = 0.0f) {
    return {from, to, glm::vec4(1.0f), 2.0f, hiddenOpacity};
}

struct Frame {
    std::vector<unsigned char> pixels;
    FrameReport report;

    // The pixel a world point falls on (GL window coordinates: row 0 at the bottom).
    const unsigned char* at(const FrameInput& input, glm::dvec3 point) const {
        const Camera& c = input.camera;
        const glm::dvec4 clip = math::perspective(c.fovY, double(kWidth) / kHeight, c.near, c.far) *
                                math::viewRotation(c) * math::cameraRelative(c) * glm::dvec4(point, 1.0);
        const int x = std::clamp(int((clip.x / clip.w * 0.5 + 0.5) * kWidth), 0, kWidth - 1);
        const int y = std::clamp(int((clip.y / clip.w * 0.5 + 0.5) * kHeight), 0, kHeight - 1);
        return &pixels[(std::size_t(y) * kWidth + std::size_t(x)) * 4];
    }
};

int difference(const unsigned char* a, const unsigned char* b) {
    int largest = 0;
    for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
    return largest;
}

class GuidesTest : public GlTest, public ::testing::WithParamInterface<bool> {
protected:
    // GetParam(): the target is like the editor's viewport (sRGB with depth and stencil, drawn into
    // straight); otherwise plain 8-bit colour, reached through the composite.
    Frame draw(const FrameInput& input, const RenderOptions& options) {
        const bool viewportLike = GetParam();
        gl::FramebufferBinding keep;
        gl::Texture color = gl::makeTexture();
        glBindTexture(GL_TEXTURE_2D, color.id());
        glTexImage2D(GL_TEXTURE_2D, 0, viewportLike ? GL_SRGB8_ALPHA8 : GL_RGBA8, kWidth, kHeight, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, nullptr);
        gl::Framebuffer framebuffer = gl::makeFramebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
        gl::Renderbuffer depthStencil = gl::makeRenderbuffer();
        if (viewportLike) {
            glBindRenderbuffer(GL_RENDERBUFFER, depthStencil.id());
            glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, kWidth, kHeight);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                      depthStencil.id());
        }
        Frame frame;
        frame.report =
            renderer().render(input, {framebuffer.id(), kWidth, kHeight, true, viewportLike}, options);
        frame.pixels.resize(std::size_t(kWidth) * kHeight * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glBindTexture(GL_TEXTURE_2D, color.id()); // the renderer binds textures of its own
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, frame.pixels.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        return frame;
    }

    static RenderOptions withGuides(std::vector<GuideLine> guides) {
        RenderOptions options;
        options.guides = std::move(guides);
        return options;
    }
};

TEST_P(GuidesTest, ALineBehindAnOpaqueObjectIsHiddenAndOneInFrontCrossesIt) {
    const FrameInput input = boxScene();
    const glm::dvec3 behind(0.0, 0.0, -2.0), inFront(0.0, 0.25, 1.0), beside(-2.5, 0.0, -2.0);
    const Frame plain = draw(input, {});
    const Frame guided = draw(input, withGuides({whiteLine({-4.0, 0.0, -2.0}, {4.0, 0.0, -2.0}),
                                                 whiteLine({-2.0, 0.25, 1.0}, {2.0, 0.25, 1.0})}));
    EXPECT_LE(difference(plain.at(input, behind), guided.at(input, behind)), 1)
        << "the line behind the box does not cross it";
    EXPECT_GT(difference(plain.at(input, beside), guided.at(input, beside)), 100)
        << "the same line shows beside the box";
    EXPECT_GT(difference(plain.at(input, inFront), guided.at(input, inFront)), 100)
        << "a line in front of the box crosses it";
    EXPECT_EQ(guided.report.countRan(PassKind::Guides), 1u);
    EXPECT_EQ(plain.report.countRan(PassKind::Guides), 0u) << "no guides, no pass";
}

TEST_P(GuidesTest, AHiddenLineThatAsksForItShowsFaintly) {
    const FrameInput input = boxScene();
    const glm::dvec3 behind(0.0, 0.0, -2.0), beside(-2.5, 0.0, -2.0);
    const Frame plain = draw(input, {});
    const Frame faint = draw(input, withGuides({whiteLine({-4.0, 0.0, -2.0}, {4.0, 0.0, -2.0}, 0.3f)}));
    const int hidden = difference(plain.at(input, behind), faint.at(input, behind));
    const int open = difference(plain.at(input, beside), faint.at(input, beside));
    EXPECT_GT(hidden, 5) << "a trace shows through the box";
    EXPECT_LT(hidden, open / 2) << "fainter than where nothing hides it";
}

TEST_P(GuidesTest, AGuideOnAFloorIsNotLostInItsDepth) {
    FrameInput input = boxScene();
    input.camera.position = {0.0, 2.0, 4.0};
    input.items[0].world = glm::scale(glm::dmat4(1.0), {8.0, 0.01, 8.0}) *
                           glm::translate(glm::dmat4(1.0), {0.0, -0.5, 0.0}); // top face at y = 0
    const Frame plain = draw(input, {});
    const Frame guided = draw(input, withGuides({whiteLine({-3.0, 0.0, 0.0}, {3.0, 0.0, 0.0})}));
    for (double x : {-1.5, 0.0, 1.5})
        EXPECT_GT(difference(plain.at(input, {x, 0.0, 0.0}), guided.at(input, {x, 0.0, 0.0})), 50) << x;
}

TEST_P(GuidesTest, GuidesAreNeverDrawnIntoAReflection) {
    FrameInput input = boxScene();
    Mirror mirror;
    mirror.name = "Wall mirror";
    mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), {0.0, 0.0, -2.0}), glm::radians(90.0),
                               glm::dvec3(1.0, 0.0, 0.0));
    mirror.size = {8.0, 5.0};
    input.mirrors = {mirror};
    // Behind the camera (seen only in the mirror), and behind the mirror (hidden by its surface).
    const std::vector<GuideLine> guides{whiteLine({-4.0, 0.3, 6.0}, {4.0, 0.3, 6.0}),
                                        whiteLine({-4.0, -0.3, -3.0}, {4.0, -0.3, -3.0})};
    const Frame plain = draw(input, {});
    const Frame guided = draw(input, withGuides(guides));
    ASSERT_EQ(plain.report.countRan(PassKind::Mirror), 1u);
    // Where the line behind the camera would show in the mirror: its mirror image lies at z = -10.
    for (double x : {-2.5, -1.5, 1.5, 2.5}) {
        EXPECT_LE(difference(plain.at(input, {x, 0.3, -10.0}), guided.at(input, {x, 0.3, -10.0})), 1) << x;
        EXPECT_LE(difference(plain.at(input, {x, -0.3, -3.0}), guided.at(input, {x, -0.3, -3.0})), 1) << x;
    }
}

TEST_P(GuidesTest, APreviewDrawnSmallerKeepsItsGuides) {
    const FrameInput input = boxScene();
    const glm::dvec3 beside(-2.5, 0.0, -2.0);
    RenderOptions options = withGuides({whiteLine({-4.0, 0.0, -2.0}, {4.0, 0.0, -2.0})});
    options.preview.scale = 0.5;
    const Frame plain = draw(input, {});
    const Frame preview = draw(input, options);
    EXPECT_EQ(preview.report.drawnWidth, kWidth / 2);
    EXPECT_GT(difference(plain.at(input, beside), preview.at(input, beside)), 40);
}

INSTANTIATE_TEST_SUITE_P(Targets, GuidesTest, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "ViewportLike" : "ThroughComposite"; });

class GuidesPlanTest : public GlTest {};

TEST_F(GuidesPlanTest, TheGuidesPassIsPlannedBeforeTheCompositeAndSaysWhatItDraws) {
    RenderOptions options;
    options.guides = {whiteLine({0, 0, 0}, {1, 0, 0}), whiteLine({0, 0, 0}, {0, 0, 1})};
    gl::Texture color = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, color.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl::Framebuffer framebuffer = gl::makeFramebuffer();
    {
        gl::FramebufferBinding keep;
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
    }
    const FrameReport report = renderer().render(boxScene(), {framebuffer.id(), 64, 64}, options);
    const auto& passes = report.plan.passes;
    ASSERT_GE(passes.size(), 2u);
    EXPECT_EQ(passes.back().kind, PassKind::Composite);
    const PlannedPass& guides = passes[passes.size() - 2];
    EXPECT_EQ(guides.kind, PassKind::Guides);
    EXPECT_EQ(guides.code, PlanReason::GuidesOverView);
    EXPECT_EQ(guides.details.lines, 2u);
    EXPECT_NE(guides.reason().find("2 lines"), std::string::npos) << guides.reason();

    // A still (drawn in tiles or whole) never carries guides.
    options.tile = ImageTile{128, 128, 64, 0};
    const FrameReport tile = renderer().render(boxScene(), {framebuffer.id(), 64, 64}, options);
    EXPECT_TRUE(std::none_of(tile.plan.passes.begin(), tile.plan.passes.end(),
                             [](const PlannedPass& p) { return p.kind == PassKind::Guides; }));
    EXPECT_EQ(tile.countRan(PassKind::Guides), 0u);
}

} // namespace
} // namespace speculum::test
