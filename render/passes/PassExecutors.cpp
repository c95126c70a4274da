#include "render/passes/PassExecutors.hpp"

#include "render/gl/Objects.hpp"
#include "render/image/ColorSpace.hpp"
#include "render/math/Projection.hpp"

#include <cassert>

namespace speculum::render::passes {

namespace {

GLuint framebufferOf(const PassWrites& writes, const FrameExecution& frame) {
    switch (writes.target) {
    case PassTarget::OwnMap: // the pass binds its own
        return 0;
    case PassTarget::Linear:
        return frame.plan.cameraBufferIsOutput ? frame.outputTarget().framebuffer
                                               : frame.resources.linear.framebuffer();
    case PassTarget::Reflection:
        return frame.resources.reflectionTextures.at(static_cast<std::size_t>(writes.slot)).framebuffer();
    case PassTarget::Output:
        return frame.outputTarget().framebuffer;
    }
    return 0;
}

} // namespace

void resetPassState() {
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilMask(0xFF);
    glFrontFace(GL_CCW);
}

ViewSpace cameraSpace(FrameExecution& frame) {
    FrameResources& r = frame.resources;
    return ViewSpace{.input = frame.input,
                     .views = frame.plan.views,
                     .rotation = math::viewRotation(frame.input.camera),
                     .projection = frame.projection,
                     .size = {frame.target.width, frame.target.height},
                     .preWeighted = frame.plan.preWeighted,
                     .context = frame.context,
                     .flatProgram = r.flatProgram,
                     .mirrorProgram = r.mirrorProgram,
                     .occlusion = &r.occlusion};
}

void bindWrites(const PassWrites& writes, FrameExecution& frame, const ViewSpace& space) {
    resetPassState();
    if (writes.target != PassTarget::OwnMap) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebufferOf(writes, frame));
        const RenderTarget& size = writes.target == PassTarget::Output ? frame.outputTarget() : frame.target;
        glViewport(0, 0, size.width, size.height);
    } else if (space.mapFramebuffer) {
        glBindFramebuffer(GL_FRAMEBUFFER, space.mapFramebuffer);
        glViewport(0, 0, space.size.x, space.size.y);
    }
    if (writes.clear) {
        if (writes.scissor && !writes.clearWhole)
            scissorTo(*writes.scissor);
        const glm::dvec3& background = frame.input.settings.background;
        // A reflection texture's alpha holds path lengths (shaders/material.glsl): none is as far as can be.
        const float alpha = writes.target == PassTarget::Reflection ? kFarPathLength : 1.0f;
        glClearColor(float(background.r), float(background.g), float(background.b), alpha);
        glClearStencil(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    }
    if (writes.scissor)
        scissorTo(*writes.scissor);
    if (writes.stencilEqual >= 0) {
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_EQUAL, writes.stencilEqual, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    }
    glFrontFace(writes.clockwise != space.flipsWinding ? GL_CW : GL_CCW);
}

void bindWrites(const PassWrites& writes, FrameExecution& frame) {
    bindWrites(writes, frame, cameraSpace(frame));
}

namespace {

bool isMirrorPass(PassKind kind) {
    return kind == PassKind::MirrorMask || kind == PassKind::Mirror || kind == PassKind::MirrorSurface;
}

} // namespace

PassResult runPass(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space) {
    // A map face's space holds its mirror views alone; every other pass draws the frame or a map of its
    // own, in the camera's.
    assert((space.face < 0 || isMirrorPass(pass.kind)) && "runPass(): only mirror passes run in a map face");
    // No default: a pass kind without an executor does not compile (-Wswitch).
    switch (pass.kind) {
    case PassKind::Shadow:
        return runShadow(pass, frame);
    case PassKind::MirrorMask:
        return runMirrorMask(pass, frame, space);
    case PassKind::Mirror:
        return runMirror(pass, frame, space);
    case PassKind::MirrorSurface:
        return runMirrorSurface(pass, frame, space);
    case PassKind::Envmap:
        return runEnvmap(pass, frame);
    case PassKind::Prefilter:
        return runPrefilter(pass, frame);
    case PassKind::Main:
        return runMain(pass, frame);
    case PassKind::Guides:
        return runGuides(pass, frame);
    case PassKind::Composite:
        return runComposite(pass, frame);
    case PassKind::ScreenDepth:
        return runScreenDepth(pass, frame);
    case PassKind::ReflectorTrace:
        return runReflectorTrace(pass, frame);
    case PassKind::ScreenColour:
        return runScreenColour(pass, frame);
    }
    assert(false && "runPass(): not a pass kind");
    return {false, {}};
}

PassResult runPass(const PlannedPass& pass, FrameExecution& frame) {
    return runPass(pass, frame, cameraSpace(frame));
}

namespace {

bool hasAttachment(GLenum attachment) {
    GLint type = GL_NONE;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    return type != GL_NONE;
}

} // namespace

PixelProbe probePixel(const PassWrites& writes, FrameExecution& frame, glm::ivec2 outputPixel) {
    PixelProbe probe;
    if (writes.target == PassTarget::OwnMap)
        return probe;
    // The output holds the target's pixels; every other buffer the drawn size's (fewer in a preview).
    const RenderTarget& output = frame.outputTarget();
    const bool isOutput = writes.target == PassTarget::Output;
    const RenderTarget& size = isOutput ? output : frame.target;
    const glm::ivec2 pixel = isOutput ? outputPixel
                                      : glm::ivec2(int(outputPixel.x * double(size.width) / output.width),
                                                   int(outputPixel.y * double(size.height) / output.height));
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.width || pixel.y >= size.height)
        return probe;
    gl::FramebufferBinding keep;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebufferOf(writes, frame));
    if (glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return probe;
    const GLint x = pixel.x, y = size.height - 1 - pixel.y; // GL rows count from the bottom
    probe.x = x;
    probe.y = y;
    float rgba[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, rgba);
    GLint encoding = GL_LINEAR;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &encoding);
    for (int c = 0; c < 3; ++c)
        probe.colour[c] = encoding == GL_SRGB ? srgbToLinear(rgba[c]) : rgba[c];
    probe.colour.a = rgba[3];
    if (hasAttachment(GL_STENCIL_ATTACHMENT)) {
        GLubyte stencil = 0;
        glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
        probe.stencil = stencil;
    }
    if (hasAttachment(GL_DEPTH_ATTACHMENT)) {
        float depth = 0.0f;
        glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
        probe.depth = depth;
    }
    probe.readable = true;
    return probe;
}

} // namespace speculum::render::passes
