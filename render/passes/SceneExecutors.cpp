// The passes of the camera's own view: the scene into the linear buffer, and its composite into the target.
#include "render/math/Projection.hpp"
#include "render/passes/MirrorPasses.hpp"
#include "render/passes/PassExecutors.hpp"

#include <string>

namespace speculum::render::passes {

PassResult runMain(const PlannedPass& pass, FrameExecution& frame) {
    const ViewSpace camera = cameraSpace(frame);
    bindWrites(pass.writes, frame, camera);
    drawSpaceView(camera, -1, pass.writes.clockwise);
    return {};
}

// The guides over the camera's view, in its buffer, tested against the depth its passes left there.
PassResult runGuides(const PlannedPass& pass, FrameExecution& frame) {
    if (!frame.guides || frame.guides->empty())
        return {false, {}};
    bindWrites(pass.writes, frame);
    const GuidesView view{frame.projection,
                          math::viewRotation(frame.input.camera),
                          frame.input.camera.position,
                          frame.input.camera.near,
                          {frame.target.width, frame.target.height},
                          double(frame.target.width) / double(frame.outputTarget().width)};
    if (base::Status drawn = frame.resources.guides.draw(*frame.guides, view); !drawn) {
        frame.warnings.push_back("the guides could not be drawn: " + drawn.error());
        return {false, {}};
    }
    return {};
}

namespace {

// The sRGB buffer already holds the output's bytes: a blit copies them (no shader runs). With
// GL_FRAMEBUFFER_SRGB off, a blit between an sRGB and a plain 8-bit buffer neither decodes nor encodes.
// A preview drawn smaller is scaled up bilinearly, between encoded values.
void copySrgbBuffer(FrameExecution& frame) {
    FrameResources& r = frame.resources;
    const RenderTarget& output = frame.outputTarget();
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, r.linear.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, output.framebuffer);
    const bool sameSize = frame.target.width == output.width && frame.target.height == output.height;
    glBlitFramebuffer(0, 0, frame.target.width, frame.target.height, 0, 0, output.width, output.height,
                      GL_COLOR_BUFFER_BIT, sameSize ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, output.framebuffer);
}

} // namespace

PassResult runComposite(const PlannedPass& pass, FrameExecution& frame) {
    FrameResources& r = frame.resources;
    if (frame.plan.cameraBuffer == CameraBuffer::Srgb8) {
        copySrgbBuffer(frame);
        return {};
    }
    bindWrites(pass.writes, frame);
    glDisable(GL_DEPTH_TEST); // a full-screen triangle: nothing to test against
    const RenderTarget& output = frame.outputTarget();
    // Linear-buffer pixels per output pixel: (1, 1) copies, less scales a preview up.
    const glm::vec2 sourceScale(float(frame.target.width) / float(output.width),
                                float(frame.target.height) / float(output.height));
    const bool scaled = sourceScale != glm::vec2(1.0f);
    r.compositeProgram.useWith(std::string("#define COMPOSITE_SCALED ") + (scaled ? "1" : "0") +
                               "\n#define COMPOSITE_ENCODE " + (output.encodeSrgb ? "1" : "0") + "\n");
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, r.linear.color());
    r.compositeProgram.set("uColor", 0);
    r.compositeProgram.set("uEncodeSrgb", output.encodeSrgb ? 1 : 0);
    r.compositeProgram.set("uSourceScale", sourceScale);
    glBindVertexArray(r.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return {};
}

} // namespace speculum::render::passes
