#include "render/passes/PassExecutors.hpp"

#include "render/passes/MirrorPasses.hpp"

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

void bindWrites(const PassWrites& writes, FrameExecution& frame) {
    resetPassState();
    if (writes.target != PassTarget::OwnMap) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebufferOf(writes, frame));
        const RenderTarget& size = writes.target == PassTarget::Output ? frame.outputTarget() : frame.target;
        glViewport(0, 0, size.width, size.height);
    }
    if (writes.clear) {
        if (writes.scissor && !writes.clearWhole)
            scissorTo(*writes.scissor);
        const glm::dvec3& background = frame.input.settings.background;
        // A reflection texture's alpha holds path lengths (shaders/material.glsl): none is as far as can be.
        const float alpha = writes.target == PassTarget::Reflection ? 65504.0f : 1.0f;
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
    glFrontFace(writes.clockwise ? GL_CW : GL_CCW);
}

PassResult runPass(const PlannedPass& pass, FrameExecution& frame) {
    switch (pass.kind) {
    case PassKind::Shadow:
        return runShadow(pass, frame);
    case PassKind::MirrorMask:
        return runMirrorMask(pass, frame);
    case PassKind::Mirror:
        return runMirror(pass, frame);
    case PassKind::MirrorSurface:
        return runMirrorSurface(pass, frame);
    case PassKind::Envmap:
        return runEnvmap(pass, frame);
    case PassKind::Prefilter:
        return runPrefilter(pass, frame);
    case PassKind::Main:
        return runMain(pass, frame);
    case PassKind::Composite:
        return runComposite(pass, frame);
    }
    return {false, {}};
}

} // namespace speculum::render::passes
