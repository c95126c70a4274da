// The three passes of a planar mirror's view: its mask in the parent's view, the reflected scene, and the
// mirror's surface over it.
#include "base/Printable.hpp"
#include "render/passes/MirrorPasses.hpp"
#include "render/passes/PassExecutors.hpp"

namespace speculum::render::passes {

namespace {

const MirrorView& viewOf(const PlannedPass& pass, const FrameExecution& frame) {
    return frame.plan.views.at(static_cast<std::size_t>(pass.view));
}

// The view a mirror view's mask and surface are drawn in (the parent's), or its own, with the pass's
// declared winding.
ViewSetup setupOf(int view, const PlannedPass& pass, const FrameExecution& frame) {
    return viewSetup(frame.input, frame.plan, view, frame.projection,
                     {frame.target.width, frame.target.height}, pass.writes.clockwise);
}

// A reflection its surface copies into the camera's 8-bit sRGB buffer (surfaceCopiesReflection) is kept
// in 8-bit sRGB too: drawn with the same encoding as that buffer, then copied as stored, neither decoded
// nor encoded again (EXT_texture_sRGB_decode's skip, and sRGB writes off). Half the bytes of a half-float
// texture to clear and read, and the surface's encoding of each pixel is gone. The same bytes as before
// but where the half float's rounding moved a colour across an 8-bit step. Views inside it keep half
// float: what their stencil mirrors blend is not copied.
bool keptEncoded(const MirrorView& view, int viewIndex, const FrameExecution& frame) {
    if (!view.ownTarget || view.parent >= 0 || frame.plan.cameraBuffer != CameraBuffer::Srgb8 ||
        !surfaceCopiesReflection(frame.input.mirrors.at(static_cast<std::size_t>(view.mirror)),
                                 glm::dvec3(1.0)))
        return false;
    for (const MirrorView& other : frame.plan.views)
        if (other.parent == viewIndex)
            return false;
    return epoxy_has_gl_extension("GL_EXT_texture_sRGB_decode");
}

} // namespace

PassResult runMirrorMask(const PlannedPass& pass, FrameExecution& frame) {
    const MirrorView& view = viewOf(pass, frame);
    bindWrites(pass.writes, frame);
    MirrorOcclusion& occlusion = frame.resources.occlusion;
    const bool wait = occlusion.mustWait(pass.view);
    if (view.ownTarget && !wait) {
        // Nothing to mark, and no need to know now: the surface counts the pixels instead, so the
        // mirror's rectangle is rasterised once less.
        occlusion.countAtSurface(pass.view);
        return {true, "visible last frame, so its pixels are counted as its surface is drawn"};
    }
    const bool marked =
        drawMirrorMask(frame.input, view, setupOf(view.parent, pass, frame), frame.resources.flatProgram,
                       frame.context, occlusion.query(pass.view), wait);
    PassResult result;
    if (wait) {
        occlusion.waited(pass.view, marked);
        result.outcome = "waited for its occlusion test";
    } else {
        occlusion.leftForLater(pass.view);
        result.outcome = "visible last frame, so not waiting for its occlusion test";
    }
    if (!marked)
        frame.hidden[static_cast<std::size_t>(pass.view)] =
            frame.tile ? "fully occluded in this tile: no pixel of it passed the depth test"
                       : "fully occluded: no pixel of it passed the depth test";
    return result;
}

PassResult runMirror(const PlannedPass& pass, FrameExecution& frame) {
    PassResult result;
    if (pass.writes.target == PassTarget::Reflection) {
        gl::RenderTexture& texture =
            frame.resources.reflectionTextures.at(static_cast<std::size_t>(pass.writes.slot));
        const bool encoded = keptEncoded(viewOf(pass, frame), pass.view, frame);
        if (encoded)
            result.outcome = "8-bit sRGB reflection texture, which the mirror's surface copies as stored";
        if (base::Status made = texture.ensure(frame.target.width, frame.target.height,
                                               encoded ? GL_SRGB8_ALPHA8 : GL_RGBA16F, true);
            !made) {
            // No texture to draw the reflection into: the mirror's passes (and those of views inside it)
            // are skipped and reported, with the reason.
            const std::string why = "its reflection texture: " + made.error();
            frame.warnings.push_back("mirror " + base::quoted(pass.target) + ": no reflection, " + why);
            frame.hidden[static_cast<std::size_t>(pass.view)] = why;
            frame.skipped.push_back({pass.target, "no reflection: " + why});
            return {false, {}};
        }
    }
    bindWrites(pass.writes, frame);
    drawMainPass(frame.input, setupOf(pass.view, pass, frame), frame.context);
    return result;
}

PassResult runMirrorSurface(const PlannedPass& pass, FrameExecution& frame) {
    const MirrorView& view = viewOf(pass, frame);
    GLuint reflection = 0;
    int levels = 1;
    bool encoded = false;
    if (pass.writes.readSlot >= 0) {
        gl::RenderTexture& texture =
            frame.resources.reflectionTextures.at(static_cast<std::size_t>(pass.writes.readSlot));
        if (pass.writes.mipmaps)
            texture.generateMipmaps();
        reflection = texture.color();
        levels = texture.levels();
        encoded = texture.format() == GL_SRGB8_ALPHA8;
        if (encoded) {
            glBindTexture(GL_TEXTURE_2D, reflection);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SRGB_DECODE_EXT, GL_SKIP_DECODE_EXT);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glBindTexture(GL_TEXTURE_2D, 0);
        }
    }
    bindWrites(pass.writes, frame);
    if (encoded)
        glDisable(GL_FRAMEBUFFER_SRGB);
    MirrorOcclusion& occlusion = frame.resources.occlusion;
    const bool counts = occlusion.countsAtSurface(pass.view);
    if (counts)
        glBeginQuery(GL_ANY_SAMPLES_PASSED, occlusion.query(pass.view));
    drawMirrorSurface(frame.input, view, setupOf(view.parent, pass, frame), frame.resources.mirrorProgram,
                      frame.resources.flatProgram, frame.context, reflection, levels,
                      {frame.target.width, frame.target.height}, encoded);
    if (counts) {
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        occlusion.leftForLater(pass.view);
    }
    if (encoded)
        glEnable(GL_FRAMEBUFFER_SRGB);
    return {};
}

} // namespace speculum::render::passes
