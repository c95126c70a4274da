// The three passes of a planar mirror's view: its mask in the parent's view, the reflected scene, and the
// mirror's surface over it.
#include "render/io/Printable.hpp"
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
    if (pass.writes.target == PassTarget::Reflection) {
        gl::RenderTexture& texture =
            frame.resources.reflectionTextures.at(static_cast<std::size_t>(pass.writes.slot));
        if (Status made = texture.ensure(frame.target.width, frame.target.height, GL_RGBA16F, true); !made) {
            // No texture to draw the reflection into: the mirror's passes (and those of views inside it)
            // are skipped and reported, with the reason.
            const std::string why = "its reflection texture: " + made.error();
            frame.warnings.push_back("mirror " + quoted(pass.target) + ": no reflection, " + why);
            frame.hidden[static_cast<std::size_t>(pass.view)] = why;
            frame.skipped.push_back({pass.target, "no reflection: " + why});
            return {false, {}};
        }
    }
    bindWrites(pass.writes, frame);
    drawMainPass(frame.input, setupOf(pass.view, pass, frame), frame.context);
    return {};
}

PassResult runMirrorSurface(const PlannedPass& pass, FrameExecution& frame) {
    const MirrorView& view = viewOf(pass, frame);
    GLuint reflection = 0;
    int levels = 1;
    if (pass.writes.readSlot >= 0) {
        gl::RenderTexture& texture =
            frame.resources.reflectionTextures.at(static_cast<std::size_t>(pass.writes.readSlot));
        if (pass.writes.mipmaps)
            texture.generateMipmaps();
        reflection = texture.color();
        levels = texture.levels();
    }
    bindWrites(pass.writes, frame);
    MirrorOcclusion& occlusion = frame.resources.occlusion;
    const bool counts = occlusion.countsAtSurface(pass.view);
    if (counts)
        glBeginQuery(GL_ANY_SAMPLES_PASSED, occlusion.query(pass.view));
    drawMirrorSurface(frame.input, view, setupOf(view.parent, pass, frame), frame.resources.mirrorProgram,
                      frame.resources.flatProgram, frame.context, reflection, levels,
                      {frame.target.width, frame.target.height});
    if (counts) {
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        occlusion.leftForLater(pass.view);
    }
    return {};
}

} // namespace speculum::render::passes
