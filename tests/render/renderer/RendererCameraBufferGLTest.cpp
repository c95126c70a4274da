// The camera's colour buffer (FramePlan::cameraBuffer): an 8-bit output is drawn straight into an 8-bit
// sRGB buffer, whose composite is a copy (or none, when the output is that buffer), wherever no blend there
// needs radiance above 1 (stencil mirrors drawn pre-weighted included). The image must
// be the one the half-float buffer and its shader composite give, within 8-bit rounding, for the demos and
// for scenes made to tell the two apart; a frame that needs the half-float buffer keeps it, and float
// outputs (EXR stills) stay linear and unclamped.
#include "render/gl/Memory.hpp"
#include "render/gl/Objects.hpp"
#include "render/mesh/Primitives.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/GlTest.hpp"
#include "support/TestPaths.hpp"

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
    scene::Scene scene;
    scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const QString path =
        QString::fromStdString(speculum::testSourcePath("resources/scenes/")) + QString::fromStdString(name);
    EXPECT_TRUE(scene::openProject(scene, path, warnings)) << name;
    std::vector<scene::Warning> snapshotWarnings;
    return scene::snapshot(scene, 0.4, meshes, snapshotWarnings);
}

class CameraBufferTest : public GlTest {
protected:
    // An 8-bit target like a window's (plain RGBA8, colour only), or with `srgbDepthStencil` one like the
    // editor's viewport (sRGB with depth and stencil: RenderTarget::srgbDepthStencil), read back as the
    // bytes it stores.
    std::vector<unsigned char> drawTarget(const FrameInput& input, const RenderOptions& options,
                                          bool srgbDepthStencil, int width, int height) {
        gl::FramebufferBinding keep;
        gl::Texture color = gl::makeTexture();
        glBindTexture(GL_TEXTURE_2D, color.id());
        glTexImage2D(GL_TEXTURE_2D, 0, srgbDepthStencil ? GL_SRGB8_ALPHA8 : GL_RGBA8, width, height, 0,
                     GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glBindTexture(GL_TEXTURE_2D, 0);
        gl::Framebuffer framebuffer = gl::makeFramebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
        gl::Renderbuffer depthStencil = gl::makeRenderbuffer();
        if (srgbDepthStencil) {
            glBindRenderbuffer(GL_RENDERBUFFER, depthStencil.id());
            glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                      depthStencil.id());
        }
        EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        // Garbage a missed pixel, or a depth or stencil test that trusted the caller's buffers, would show.
        glClearColor(0.3f, 0.9f, 0.6f, 0.0f);
        glClearDepth(0.0);
        glClearStencil(0x55);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glClearDepth(1.0);
        glClearStencil(0);
        m_report =
            renderer().render(input, {framebuffer.id(), width, height, true, srgbDepthStencil}, options);
        std::vector<unsigned char> pixels(std::size_t(width) * std::size_t(height) * 4);
        glBindTexture(GL_TEXTURE_2D, color.id());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        return pixels;
    }

    std::vector<unsigned char> draw8(const FrameInput& input, const RenderOptions& options, int width = 320,
                                     int height = 180) {
        return drawTarget(input, options, false, width, height);
    }

    std::vector<unsigned char> drawSrgb(const FrameInput& input, const RenderOptions& options,
                                        int width = 320, int height = 180) {
        return drawTarget(input, options, true, width, height);
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

    static int largestDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
        int largest = 0;
        for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
            largest = std::max(largest, std::abs(int(a[i]) - int(b[i])));
        return a.size() == b.size() ? largest : 256;
    }

    bool skipped(const std::string& target, PlanReason code) const {
        return std::any_of(m_report.skipped.begin(), m_report.skipped.end(),
                           [&](const SkippedEffect& s) { return s.target == target && s.code == code; });
    }

    std::string skips() const {
        std::string text;
        for (const SkippedEffect& s : m_report.skipped)
            text += s.target + ": " + s.reason() + "\n";
        for (const PlannedPass& p : m_report.plan.passes)
            text += std::string(toString(p.kind)) + " " + p.target + ": " + p.reason() + "\n";
        return text;
    }

    FrameReport m_report;
};

TEST_F(CameraBufferTest, ASceneWithoutMirrorsIsTheSameImageInEightBitSrgb) {
    EXPECT_LE(compareWithHalfFloat(ballScene(), CameraBuffer::Srgb8, "ball"), 1);
    const PlannedPass& composite = m_report.plan.passes.back();
    EXPECT_EQ(composite.kind, PassKind::Composite);
    EXPECT_EQ(composite.code, PlanReason::CompositeCopiesSrgb) << composite.reason();
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

// A texture mirror whose surface is its reflection (sharp, reflectivity 1, white, no Fresnel) keeps the
// reflection in 8-bit sRGB, drawn with the camera buffer's own encoding, and copies it as stored: the same
// image within 8-bit rounding, and half the colour bytes of the half-float texture.
TEST_F(CameraBufferTest, ACopiedTextureMirrorKeepsItsReflectionInEightBitSrgb) {
    const FrameInput input = mirrorScene(MirrorTechnique::Texture, 1.0, glm::dvec3(1.0));
    EXPECT_LE(compareWithHalfFloat(input, CameraBuffer::Srgb8, "copied texture mirror"), 1);
    ASSERT_EQ(m_report.countRan(PassKind::Mirror), 1u) << skips();
    const std::size_t encodedBytes = m_report.memory.mirrors;
    bool said = false;
    for (const PassRun& run : m_report.ran)
        said = said || run.outcome.find("8-bit sRGB reflection texture") != std::string::npos;
    EXPECT_TRUE(said) << skips();

    RenderOptions exact;
    exact.halfFloatCameraBuffer = true;
    draw8(input, exact);
    const std::size_t halfFloatBytes = m_report.memory.mirrors;
    const int levels = 1 + int(std::floor(std::log2(320.0)));
    EXPECT_EQ(halfFloatBytes - encodedBytes, gl::mipChainTexels(320, 180, levels) * 4)
        << "4 bytes a texel instead of 8; the same depth and stencil";

    // Not where the surface does more than copy: a tinted mirror's reflection stays half float.
    draw8(mirrorScene(MirrorTechnique::Texture, 1.0, {0.9, 0.8, 1.0}), {});
    EXPECT_EQ(m_report.plan.cameraBuffer, CameraBuffer::Srgb8);
    EXPECT_EQ(m_report.memory.mirrors, halfFloatBytes);
    for (const PassRun& run : m_report.ran)
        EXPECT_EQ(run.outcome.find("8-bit sRGB"), std::string::npos) << run.outcome;
}

// A stencil mirror that keeps part of its reflection (reflectivity, tint) draws it pre-weighted, so the
// 8-bit buffer holds it: the ball's highlight, above 1, is weighted before it is clamped, as in half float.
TEST_F(CameraBufferTest, ATintedStencilMirrorIsDrawnPreWeightedInEightBitSrgb) {
    const FrameInput input = mirrorScene(MirrorTechnique::Stencil, 0.5, {1.0, 0.9, 0.8});
    EXPECT_LE(compareWithHalfFloat(input, CameraBuffer::Srgb8, "tinted stencil mirror"), 1);
    EXPECT_TRUE(m_report.plan.preWeighted);
    EXPECT_EQ(m_report.countRan(PassKind::Mirror), 1u) << skips();

    // Two facing stencil mirrors, three reflections deep, each with its own weight: a perfect, tinted one
    // (nothing of its surface is added) and one that keeps 60 % of what it reflects.
    FrameInput facing = mirrorScene(MirrorTechnique::Stencil, 1.0, {1.0, 0.8, 0.6});
    facing.settings.mirrorDepth = 3;
    Mirror back = facing.mirrors[0];
    back.name = "Back mirror";
    back.world = glm::rotate(glm::translate(glm::dmat4(1.0), {0.0, 0.0, 4.0}), glm::radians(-90.0),
                             glm::dvec3(1.0, 0.0, 0.0));
    back.reflectivity = 0.6;
    back.tint = {0.7, 0.9, 1.0};
    facing.mirrors.push_back(back);
    facing.camera.position = {0.4, 0.3, 3.0};
    facing.camera.target = {0.0, 0.0, -1.5};
    EXPECT_LE(compareWithHalfFloat(facing, CameraBuffer::Srgb8, "facing stencil mirrors"), 1);
    EXPECT_TRUE(m_report.plan.preWeighted);
    EXPECT_GE(m_report.countRan(PassKind::Mirror), 2u) << skips();

    // Where both add their surfaces, a pixel seen through both would be rounded to 8 bits once per
    // surface: the half-float buffer stays, and says why.
    facing.mirrors[0].reflectivity = 0.7;
    EXPECT_EQ(compareWithHalfFloat(facing, CameraBuffer::HalfFloat, "facing stencil mirrors, both added"), 0);
    EXPECT_EQ(m_report.plan.passes.back().code, PlanReason::CompositeNestedBlend)
        << m_report.plan.passes.back().reason();
}

// The reflector's map draws the tinted mirror too, with the same stencil recipe, but never pre-weighted:
// what a pre-weighted frame set for its own mirrors must not reach the next frame's map. The frame after
// one drawn pre-weighted is the same image, its map drawn anew.
TEST_F(CameraBufferTest, APreWeightedFrameLeavesTheNextFramesMapAsItWas) {
    FrameInput input = mirrorScene(MirrorTechnique::Stencil, 0.5, {1.0, 0.9, 0.8});
    Reflector ball;
    ball.name = "Chrome ball";
    ball.mesh = std::make_shared<const MeshData>(makeSphere(32));
    ball.world = glm::scale(glm::translate(glm::dmat4(1.0), {1.1, 0.3, 0.2}), glm::dvec3(0.45));
    ball.update = ReflectorUpdate::Always;
    ball.resolution = 64;
    input.reflectors = {ball};
    RenderOptions exact;
    exact.halfFloatCameraBuffer = true;
    draw8(input, exact); // leaves the mirrors' programs as a frame that is not pre-weighted does
    const std::vector<unsigned char> first = draw8(input, {});
    ASSERT_TRUE(m_report.plan.preWeighted) << skips();
    ASSERT_FALSE(m_report.plan.envmaps.empty());
    EXPECT_GE(m_report.plan.envmaps[0].views.size(), 1u) << "the map sees the mirror";
    const std::vector<unsigned char> second = draw8(input, {});
    EXPECT_EQ(m_report.countRan(PassKind::Envmap), 1u);
    EXPECT_EQ(largestDifference(first, second), 0);
}

// With Fresnel the weight varies over the mirror: the half-float buffer stays, and the plan says why.
TEST_F(CameraBufferTest, AStencilMirrorWithFresnelKeepsTheHalfFloatBufferAndSaysWhy) {
    FrameInput input = mirrorScene(MirrorTechnique::Stencil, 0.5, {1.0, 0.9, 0.8});
    input.mirrors[0].fresnel = true;
    EXPECT_EQ(compareWithHalfFloat(input, CameraBuffer::HalfFloat, "Fresnel stencil mirror"), 0)
        << "the same path both times";
    const PlannedPass& composite = m_report.plan.passes.back();
    EXPECT_EQ(composite.code, PlanReason::CompositeFresnelBlend) << composite.reason();
    EXPECT_EQ(composite.details.node, "Wall mirror");
    // The sentence the composite shows in explain and the editor's Render Passes panel.
    EXPECT_EQ(composite.reason(),
              "resolves the half-float colour buffer into the 8-bit output with sRGB "
              "encoding: stencil mirror 'Wall mirror' blends onto the reflection it drew, "
              "with a Fresnel weight that varies over it");
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

// An sRGB output with its own depth and stencil takes the frame itself: no buffer of the renderer's and
// no copy, and the bytes are those the copy from the renderer's sRGB buffer gives.
TEST_F(CameraBufferTest, AnSrgbOutputWithDepthAndStencilIsDrawnIntoWithNoComposite) {
    struct Case {
        const char* label;
        FrameInput input;
    };
    const std::vector<Case> cases = {
        {"ball", ballScene()},
        {"texture mirror", mirrorScene(MirrorTechnique::Texture, 0.6, {0.9, 0.8, 1.0})},
        {"perfect stencil mirror", mirrorScene(MirrorTechnique::Stencil, 1.0, glm::dvec3(1.0))},
        {"chrome demo", demo("chrome.speculum.json")},
        {"mirrors demo", demo("mirrors.speculum.json")},
    };
    for (const Case& c : cases) {
        const std::vector<unsigned char> copied = draw8(c.input, {});
        const CameraBuffer copiedBuffer = m_report.plan.cameraBuffer;
        const std::vector<unsigned char> direct = drawSrgb(c.input, {});
        EXPECT_EQ(m_report.plan.cameraBuffer, copiedBuffer) << c.label;
        if (copiedBuffer != CameraBuffer::Srgb8)
            continue; // a frame that needs the half-float buffer: the next test
        EXPECT_TRUE(m_report.plan.cameraBufferIsOutput) << c.label;
        EXPECT_EQ(m_report.countRan(PassKind::Composite), 0u) << c.label << "\n" << skips();
        EXPECT_TRUE(skipped("output", PlanReason::CompositeNotNeeded)) << c.label << "\n" << skips();
        EXPECT_EQ(m_report.memory.main, 0u) << c.label << ": no colour buffer of the renderer's";
        EXPECT_EQ(largestDifference(direct, copied), 0) << c.label;
        for (std::size_t i = 3; i < direct.size(); i += 4)
            ASSERT_EQ(direct[i], 255) << c.label << ": every pixel written (pixel " << i / 4 << ")";
    }
}

// Where the output cannot be the camera's buffer (a preview drawn smaller, a frame that needs half float),
// the composite writes it as before, and the image is the plain 8-bit target's.
TEST_F(CameraBufferTest, AnSrgbOutputStillGetsTheCompositeWhereTheFrameNeedsOne) {
    FrameInput tinted = mirrorScene(MirrorTechnique::Stencil, 0.5, {1.0, 0.9, 0.8});
    tinted.mirrors[0].fresnel = true;
    const std::vector<unsigned char> plain = draw8(tinted, {});
    const std::vector<unsigned char> direct = drawSrgb(tinted, {});
    EXPECT_EQ(m_report.plan.cameraBuffer, CameraBuffer::HalfFloat);
    EXPECT_FALSE(m_report.plan.cameraBufferIsOutput);
    EXPECT_EQ(m_report.countRan(PassKind::Composite), 1u);
    EXPECT_EQ(largestDifference(direct, plain), 0) << "encoded by the composite, stored as it is";

    RenderOptions preview;
    preview.resolutionScale = 0.5;
    const FrameInput ball = ballScene();
    const std::vector<unsigned char> scaledPlain = draw8(ball, preview);
    const std::vector<unsigned char> scaled = drawSrgb(ball, preview);
    EXPECT_EQ(m_report.drawnWidth, 160);
    EXPECT_FALSE(m_report.plan.cameraBufferIsOutput) << "drawn smaller, then scaled up into the output";
    EXPECT_EQ(m_report.countRan(PassKind::Composite), 1u);
    EXPECT_EQ(largestDifference(scaled, scaledPlain), 0);
}

} // namespace
} // namespace speculum::test
