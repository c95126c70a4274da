// RenderOptions::resolutionScale (adaptive resolution in the editor): a frame drawn at a fraction
// of the target's size and scaled up by the composite is the same picture, finite everywhere even with
// over-bright light, and fills the whole target; a scale of 1 (and any tile) draws every pixel exactly as
// before.
#include "render/gl/Objects.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Teapot.hpp"
#include "support/GlTest.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

namespace speculum::test {
namespace {

using namespace render;

FrameInput mirrorScene() {
    FrameInput input;
    input.settings.background = {0.1, 0.1, 0.12};
    input.camera.position = {0.0, 0.5, 2.0};
    input.camera.target = {0.0, -0.5, -3.0};
    auto teapot = std::make_shared<const MeshData>(makeTeapot(6));
    auto plane = std::make_shared<const MeshData>(makePlane(1));
    DrawItem pot{"Teapot",
                 glm::scale(glm::translate(glm::dmat4(1.0), {0.0, -1.0, -3.0}), glm::dvec3(0.25)),
                 teapot,
                 {},
                 true};
    pot.material.specular = 0.5;
    DrawItem table{"Table",
                   glm::scale(glm::translate(glm::dmat4(1.0), {0.0, -1.0, -3.0}), {2.0, 1.0, 2.0}),
                   plane,
                   {},
                   true};
    Light light;
    light.name = "Light";
    light.position = {0.0, 2.0, -2.0};
    light.shadows = render::ShadowParams{512, 3};
    Mirror mirror;
    mirror.name = "Mirror";
    // Upright behind the teapot, facing the camera (+Z).
    mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), {0.0, -0.3, -4.2}), glm::radians(90.0),
                               glm::dvec3(1.0, 0.0, 0.0));
    mirror.size = {2.0, 1.4};
    input.items = {pot, table};
    input.lights = {light};
    input.mirrors = {mirror};
    return input;
}

// An offscreen float target of its own (as the still renderer's), read back top row first.
class ScaledFrame : public GlTest {
protected:
    std::vector<float> draw(const FrameInput& input, int width, int height, const RenderOptions& options) {
        gl::FramebufferBinding keep;
        gl::Texture color = gl::makeTexture();
        glBindTexture(GL_TEXTURE_2D, color.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
        gl::Framebuffer framebuffer = gl::makeFramebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
        EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        // Garbage to start from: a pixel the composite missed would show it.
        glClearColor(123.0f, -7.0f, 55.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        m_report = renderer().render(input, {framebuffer.id(), width, height, false}, options);
        std::vector<float> pixels(std::size_t(width) * std::size_t(height) * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, pixels.data());
        return pixels;
    }

    FrameReport m_report;
};

double meanDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        sum += std::abs(double(a[i]) - double(b[i]));
    return sum / double(a.size());
}

TEST_F(ScaledFrame, AHalfResolutionFrameIsTheSamePictureScaledUp) {
    const FrameInput input = mirrorScene();
    const std::vector<float> full = draw(input, 320, 180, {});
    EXPECT_EQ(m_report.drawnWidth, 320);
    EXPECT_EQ(m_report.drawnHeight, 180);
    EXPECT_EQ(m_report.countRan(PassKind::Mirror), 1u) << "the mirror is drawn";

    RenderOptions half;
    half.resolutionScale = 0.5;
    const std::vector<float> scaled = draw(input, 320, 180, half);
    EXPECT_EQ(m_report.drawnWidth, 160);
    EXPECT_EQ(m_report.drawnHeight, 90);
    EXPECT_EQ(m_report.countRan(PassKind::Mirror), 1u) << "the mirror is drawn in the preview too";
    ASSERT_EQ(scaled.size(), full.size());
    for (float v : scaled)
        ASSERT_TRUE(std::isfinite(v));
    for (std::size_t i = 3; i < scaled.size(); i += 4)
        ASSERT_EQ(scaled[i], 1.0f) << "every pixel written (alpha 1), none left as the garbage under it";
    EXPECT_LT(meanDifference(full, scaled), 0.02) << "the same picture";
    EXPECT_GT(meanDifference(full, scaled), 0.0) << "at a lower resolution";

    // Back to full: exactly the first frame again (nothing of the preview stays behind).
    const std::vector<float> again = draw(input, 320, 180, {});
    EXPECT_EQ(meanDifference(full, again), 0.0);
}

TEST_F(ScaledFrame, TheScaleIsClampedAndATileIgnoresIt) {
    const FrameInput input = mirrorScene();
    RenderOptions tiny;
    tiny.resolutionScale = 0.001;
    draw(input, 320, 180, tiny);
    EXPECT_EQ(m_report.drawnWidth, 40) << "kMinResolutionScale: an eighth";
    EXPECT_EQ(m_report.drawnHeight, 23);

    RenderOptions odd;
    odd.resolutionScale = std::nan("");
    draw(input, 64, 36, odd);
    EXPECT_EQ(m_report.drawnWidth, 64) << "not a number: full size";

    RenderOptions tiled;
    tiled.resolutionScale = 0.5;
    tiled.tile = ImageTile{128, 72, 64, 0};
    draw(input, 64, 72, tiled);
    EXPECT_EQ(m_report.drawnWidth, 64) << "a tile is part of an exact image";
}

TEST_F(ScaledFrame, OverBrightLightStaysFiniteWhenScaledUp) {
    FrameInput input = mirrorScene();
    input.lights[0].intensity = 1e9;
    RenderOptions preview;
    preview.resolutionScale = 0.37;
    const std::vector<float> pixels = draw(input, 200, 120, preview);
    float brightest = 0.0f;
    for (float v : pixels) {
        ASSERT_TRUE(std::isfinite(v));
        brightest = std::max(brightest, v);
    }
    EXPECT_LE(brightest, 65504.0f);
    EXPECT_GT(brightest, 1000.0f) << "the light is over-bright";
}

} // namespace
} // namespace speculum::test
