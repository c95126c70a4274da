// The three passes of a planar mirror's view: its mask in the parent's view, the reflected scene, and the
// mirror's surface over it. They run in the space their views belong to: the camera's, or a face of the
// reflector's environment map.
#include "base/Printable.hpp"
#include "render/passes/MipConvolve.hpp"
#include "render/passes/MirrorPasses.hpp"
#include "render/passes/PassExecutors.hpp"

namespace speculum::render::passes {

namespace {

// A reflection its surface copies into the camera's 8-bit sRGB buffer (surfaceCopiesReflection) is kept
// in 8-bit sRGB too: drawn with the same encoding as that buffer, then copied as stored, neither decoded
// nor encoded again (EXT_texture_sRGB_decode's skip, and sRGB writes off). Half the bytes of a half-float
// texture to clear and read, and the surface's encoding of each pixel is gone. The same bytes as before
// but where the half float's rounding moved a colour across an 8-bit step. Views inside it keep half
// float: what their stencil mirrors blend is not copied.
bool keptEncoded(const MirrorView& view, int viewIndex, const ViewSpace& space, const FrameExecution& frame) {
    if (!view.ownTarget || view.parent >= 0 || frame.plan.cameraBuffer != CameraBuffer::Srgb8 ||
        !surfaceCopiesReflection(space.input.mirrors.at(static_cast<std::size_t>(view.mirror)),
                                 glm::dvec3(1.0)))
        return false;
    for (const MirrorView& other : space.views)
        if (other.parent == viewIndex)
            return false;
    return epoxy_has_gl_extension("GL_EXT_texture_sRGB_decode");
}

} // namespace

bool ensureReflectionTexture(const PlannedPass& pass, FrameExecution& frame, GLenum format) {
    gl::RenderTexture& texture =
        frame.resources.reflectionTextures.at(static_cast<std::size_t>(pass.writes.slot));
    const base::Status made = texture.ensure(frame.target.width, frame.target.height, format, true);
    if (made)
        return true;
    // No texture to draw the reflection into: the mirror's passes (and those of views inside it) are
    // skipped and reported, with the reason.
    frame.warnings.push_back("mirror " + base::quoted(pass.target) +
                             ": no reflection, its reflection texture: " + made.error());
    const SkippedEffect skip{pass.target, PlanReason::MirrorNoTexture, {.error = made.error()}};
    frame.hidden[static_cast<std::size_t>(pass.view)] = skip;
    frame.skipped.push_back(skip);
    return false;
}

PassResult runMirrorMask(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space) {
    const MirrorView& view = space.view(pass.view);
    bindWrites(pass.writes, frame, space);
    const ViewSetup parent = viewSetup(space, view.parent, pass.writes.clockwise);
    if (!space.occlusion) { // nothing tests whether the mirror is hidden: its reflection is drawn anyway
        drawMirrorMask(space, view, parent, 0, false);
        return {};
    }
    MirrorOcclusion& occlusion = *space.occlusion;
    const bool wait = occlusion.mustWait(pass.view);
    if (view.ownTarget && !wait) {
        // Nothing to mark, and no need to know now: the surface counts the pixels instead, so the
        // mirror's rectangle is rasterised once less.
        occlusion.countAtSurface(pass.view);
        return {true, "visible last frame, so its pixels are counted as its surface is drawn"};
    }
    const bool marked = drawMirrorMask(space, view, parent, occlusion.query(pass.view), wait);
    PassResult result;
    if (wait) {
        occlusion.waited(pass.view, marked);
        result.outcome = "waited for its occlusion test";
    } else {
        occlusion.leftForLater(pass.view);
        result.outcome = "visible last frame, so not waiting for its occlusion test";
    }
    if (!marked)
        frame.hidden[static_cast<std::size_t>(pass.view)] = SkippedEffect{
            pass.target, frame.tile ? PlanReason::MirrorOccludedInTile : PlanReason::MirrorOccluded};
    return result;
}

PassResult runMirror(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space) {
    if (space.view(pass.view).screenSpace)
        return runScreenTrace(pass, frame, space);
    PassResult result;
    if (pass.writes.target == PassTarget::Reflection) {
        const bool encoded = keptEncoded(space.view(pass.view), pass.view, space, frame);
        if (encoded)
            result.outcome = "8-bit sRGB reflection texture, which the mirror's surface copies as stored";
        if (!ensureReflectionTexture(pass, frame, encoded ? GL_SRGB8_ALPHA8 : GL_RGBA16F))
            return {false, {}};
    }
    bindWrites(pass.writes, frame, space);
    drawSpaceView(space, pass.view, pass.writes.clockwise);
    return result;
}

PassResult runMirrorSurface(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space) {
    const MirrorView& view = space.view(pass.view);
    GLuint reflection = 0;
    int levels = 1;
    bool encoded = false;
    if (pass.writes.readSlot >= 0) {
        gl::RenderTexture& texture =
            frame.resources.reflectionTextures.at(static_cast<std::size_t>(pass.writes.readSlot));
        if (pass.writes.convolveMips) {
            FrameResources& r = frame.resources;
            const glm::dvec3& background = frame.input.settings.background;
            // What the reflection pass cleared its texture to (bindWrites): the background, far away.
            const glm::vec4 outside(float(background.r), float(background.g), float(background.b),
                                    kFarPathLength);
            convolveMipChain(texture, r.mipConvolveProgram, r.convolveFramebuffer.id(), r.emptyVao.id(),
                             view.rect, outside);
        } else if (pass.writes.mipmaps) {
            texture.generateMipmaps();
        }
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
    bindWrites(pass.writes, frame, space);
    if (encoded)
        glDisable(GL_FRAMEBUFFER_SRGB);
    const bool counts = space.occlusion && space.occlusion->countsAtSurface(pass.view);
    if (counts)
        glBeginQuery(GL_ANY_SAMPLES_PASSED, space.occlusion->query(pass.view));
    drawMirrorSurface(space, view, viewSetup(space, view.parent, pass.writes.clockwise), reflection, levels,
                      encoded);
    if (counts) {
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        space.occlusion->leftForLater(pass.view);
    }
    if (encoded)
        glEnable(GL_FRAMEBUFFER_SRGB);
    if (view.screenSpace && frame.showScreenSpaceSources)
        drawScreenSpaceSources(pass, frame, space);
    // The last pass that draws in the view: what was made to draw it can go.
    space.leave(pass.view);
    return {};
}

} // namespace speculum::render::passes
