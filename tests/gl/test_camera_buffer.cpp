// The camera's colour buffer (FramePlan::cameraBuffer): an 8-bit output is drawn straight into an 8-bit
// sRGB buffer, whose composite is a copy, wherever no blend there needs radiance above 1. The image must
// be the one the half-float buffer and its shader composite give, within 8-bit rounding, for the demos and
// for scenes made to tell the two apart; a frame that needs the half-float buffer keeps it, and float
// outputs (EXR stills) stay linear and unclamped.
#include "GlTest.hpp"
#include "editor/document/ProjectFile.hpp"
#include "editor/document/Snapshot.hpp"
#include "render/gl/Objects.hpp"
#include "render/mesh/Primitives.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

namespace speculum::test {
namespace {

using namespace render;

// A red ball on black: the one-ball benchmark scene.
FrameInput ballScene() {
    FrameInput input;
    input.settings.background = {0.0, 0.0, 0.0};
    input.camera.position = {0.0, 0.0, 3.0};
    input.camera.target = {0.0, 0.0, 0.0};
    DrawItem ball{"Ball", glm::dmat4(1.0), std::make_shared<const MeshData>(makeSphere(32)), {}, true};
    ball.material.color = {0.9, 0.1, 0.1};
    ball.material.specular = 0.8;
    Light light;
    light.name = "Light";
    light.position = {2.0, 3.0, 3.0};
    light.intensity = 4.0; // a highlight well above 1: clamped the same way on both paths
    input.items = {ball};
    input.lights = {light};
    return input;
}

// The ball before an upright mirror, of the technique and reflectivity given.
FrameInput mirrorScene(MirrorTechnique technique, double reflectivity, glm::dvec3 tint) {
    FrameInput input = ballScene();
    input.settings.background = {0.05, 0.05, 0.07};
    input.camera.position = {0.0, 0.3, 3.0};
    Mirror mirror;
    mirror.name = "Wall mirror";
    mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), {0.0, 0.0, -1.5}), glm::radians(90.0),
                               glm::dvec3(1.0, 0.0, 0.0));
    mirror.size = {5.0, 3.0}; // wider than the ball in front of it
    mirror.technique = technique;
    mirror.reflectivity = reflectivity;
    mirror.tint = tint;
    input.mirrors = {mirror};
    return input;
}

FrameInput demo(const std::string& name) {
    document::Scene scene;
    document::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const QString path = QString(SPECULUM_SOURCE_DIR) + "/resources/scenes/" + QString::fromStdString(name);
    EXPECT_TRUE(document::openProject(scene, path, warnings)) << name;
    return document::snapshot(scene, 0.4, meshes, warnings);
}

class CameraBufferTest : public GlTest {
protected:
    // An 8-bit target like a window's, read back as bytes.
    std::vector<unsigned char> draw8(const FrameInput& input, const RenderOptions& options, int width = 320,
                                     int height = 180) {
        gl::FramebufferBinding keep;
        gl::Texture color = gl::makeTexture();
        glBindTexture(GL_TEXTURE_2D, color.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glBindTexture(GL_TEXTURE_2D, 0);
        gl::Framebuffer framebuffer = gl::makeFramebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
        EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        glClearColor(0.3f, 0.9f, 0.6f, 0.0f); // garbage a missed pixel would show
        glClear(GL_COLOR_BUFFER_BIT);
        m_report = renderer().render(input, {framebuffer.id(), width, height, true}, options);
        std::vector<unsigned char> pixels(std::size_t(width) * std::size_t(height) * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        return pixels;
    }

    // Both paths of the same frame; returns the largest difference of any channel, in 8-bit steps.
    int compareWithHalfFloat(const FrameInput& input, CameraBuffer expected, const std::string& label) {
        RenderOptions exact;
        exact.halfFloatCameraBuffer = true;
        const std::vector<unsigned char> reference = draw8(input, exact);
        EXPECT_EQ(m_report.plan.cameraBuffer, CameraBuffer::HalfFloat) << label;
        const std::vector<unsigned char> cheap = draw8(input, {});
        EXPECT_EQ(m_report.plan.cameraBuffer, expected) << label;
        int largest = 0;
        for (std::size_t i = 0; i < cheap.size(); ++i)
            largest = std::max(largest, std::abs(int(cheap[i]) - int(reference[i])));
        for (std::size_t i = 3; i < cheap.size(); i += 4)
            EXPECT_EQ(cheap[i], 255) << label << ": every pixel written, alpha 1 (pixel " << i / 4 << ")";
        return largest;
    }

    std::string skips() const {
        std::string text;
        for (const SkippedEffect& s : m_report.skipped)
            text += s.target + ": " + s.reason + "\n";
        for (const PlannedPass& p : m_report.plan.passes)
            text += std::string(toString(p.kind)) + " " + p.target + ": " + p.reason + "\n";
        return text;
    }

    FrameReport m_report;
};

TEST_F(CameraBufferTest, ASceneWithoutMirrorsIsTheSameImageInEightBitSrgb) {
    EXPECT_LE(compareWithHalfFloat(ballScene(), CameraBuffer::Srgb8, "ball"), 1);
    const PlannedPass& composite = m_report.plan.passes.back();
    EXPECT_EQ(composite.kind, PassKind::Composite);
    EXPECT_NE(composite.reason.find("copies the sRGB colour buffer"), std::string::npos) << composite.reason;
}

TEST_F(CameraBufferTest, TextureMirrorsAndPerfectStencilMirrorsNeedNoHalfFloat) {
    EXPECT_LE(compareWithHalfFloat(mirrorScene(MirrorTechnique::Texture, 0.6, {0.9, 0.8, 1.0}),
                                   CameraBuffer::Srgb8, "texture mirror"),
              1);
    EXPECT_EQ(m_report.countRan(PassKind::Mirror), 1u) << skips();
    EXPECT_LE(compareWithHalfFloat(mirrorScene(MirrorTechnique::Stencil, 1.0, glm::dvec3(1.0)),
                                   CameraBuffer::Srgb8, "perfect stencil mirror"),
              1);
    EXPECT_EQ(m_report.countRan(PassKind::Mirror), 1u);
}

TEST_F(CameraBufferTest, ATintedStencilMirrorKeepsTheHalfFloatBufferAndSaysWhy) {
    const FrameInput input = mirrorScene(MirrorTechnique::Stencil, 0.5, {1.0, 0.9, 0.8});
    EXPECT_EQ(compareWithHalfFloat(input, CameraBuffer::HalfFloat, "tinted stencil mirror"), 0)
        << "the same path both times";
    const PlannedPass& composite = m_report.plan.passes.back();
    EXPECT_NE(composite.reason.find("stencil mirror 'Wall mirror' blends onto the reflection it drew"),
              std::string::npos)
        << composite.reason;
}

TEST_F(CameraBufferTest, TheDemosAreTheSameImageInEitherBuffer) {
    for (const char* name :
         {"teapot.speculum.json", "mirrors.speculum.json", "chrome.speculum.json", "models.speculum.json"}) {
        const FrameInput input = demo(name);
        RenderOptions exact;
        exact.halfFloatCameraBuffer = true;
        const std::vector<unsigned char> reference = draw8(input, exact);
        const std::vector<unsigned char> cheap = draw8(input, {});
        int largest = 0;
        for (std::size_t i = 0; i < cheap.size(); ++i)
            largest = std::max(largest, std::abs(int(cheap[i]) - int(reference[i])));
        EXPECT_LE(largest, 1) << name << " (drawn in "
                              << (m_report.plan.cameraBuffer == CameraBuffer::Srgb8 ? "sRGB" : "half float")
                              << ")";
    }
    // The chrome demo has no mirror: the cheap path.
    draw8(demo("chrome.speculum.json"), {});
    EXPECT_EQ(m_report.plan.cameraBuffer, CameraBuffer::Srgb8);
}

TEST_F(CameraBufferTest, APreviewScaledUpFromTheSrgbBufferFillsTheTarget) {
    const FrameInput input = mirrorScene(MirrorTechnique::Texture, 0.6, glm::dvec3(1.0));
    const std::vector<unsigned char> full = draw8(input, {});
    RenderOptions preview;
    preview.resolutionScale = 0.5;
    const std::vector<unsigned char> scaled = draw8(input, preview);
    EXPECT_EQ(m_report.plan.cameraBuffer, CameraBuffer::Srgb8);
    EXPECT_EQ(m_report.drawnWidth, 160);
    double sum = 0.0;
    for (std::size_t i = 0; i < full.size(); ++i) {
        if (i % 4 == 3) {
            ASSERT_EQ(scaled[i], 255) << "every pixel of the target written";
        }
        sum += std::abs(int(full[i]) - int(scaled[i]));
    }
    EXPECT_LT(sum / double(full.size()), 4.0) << "the same picture, at a lower resolution";
}

// Stills (PNG and EXR alike) are drawn into a float target: linear, unclamped, through the composite.
TEST_F(CameraBufferTest, FloatOutputsStayLinearAndUnclamped) {
    FrameInput input = ballScene();
    input.lights[0].intensity = 40.0;
    const Image still = renderImage(input, 96, 64);
    EXPECT_EQ(lastReport().plan.cameraBuffer, CameraBuffer::HalfFloat);
    float brightest = 0.0f;
    for (float v : still.rgba)
        brightest = std::max(brightest, v);
    EXPECT_GT(brightest, 1.5f) << "radiance above 1 survives into a float still";
}

} // namespace
} // namespace speculum::test
