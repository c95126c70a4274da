// How each planned pass writes: the decisions the renderer used to make while running the plan (which
// buffer, what to clear, which pixels, which stencil level, which winding), made here once, GL-free, so
// the executor only carries them out and tests can check them without a context.
#include "render/plan/Planner.hpp"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace speculum::render {

namespace {

// An odd number of reflections turns counter-clockwise triangles clockwise.
bool mirrored(const MirrorView& view) {
    return glm::determinant(glm::dmat3(view.reflection)) < 0.0;
}

// Where the scene of `viewIndex` (-1: the camera's) is drawn: its own reflection texture, or the one its
// nearest texture-technique ancestor draws into, or the linear buffer.
void drawInto(const FramePlan& plan, int viewIndex, PassWrites& writes) {
    const int slot = viewIndex < 0 ? -1 : plan.views[static_cast<std::size_t>(viewIndex)].textureSlot;
    writes.target = slot < 0 ? PassTarget::Linear : PassTarget::Reflection;
    writes.slot = slot;
}

PassWrites cameraWrites(const FrameInput& input, const FramePlan& plan, const PlannedPass& pass) {
    PassWrites writes;
    switch (pass.kind) {
    case PassKind::Shadow:
    case PassKind::Envmap:
    case PassKind::Prefilter:
    case PassKind::ScreenDepth:  // its own depth texture and pyramid
    case PassKind::ScreenColour: // its own copy of the image and pyramid
        writes.target = PassTarget::OwnMap;
        break;
    case PassKind::Main:
        writes.target = PassTarget::Linear;
        writes.clear = true;
        break;
    case PassKind::Guides:         // over the camera's view, in its buffer, against its depth
    case PassKind::ReflectorTrace: // over the reflector the main pass drew, against its depth
        writes.target = PassTarget::Linear;
        break;
    case PassKind::Composite:
        writes.target = PassTarget::Output;
        break;
    case PassKind::MirrorMask:
    case PassKind::Mirror:
    case PassKind::MirrorSurface: {
        const MirrorView& view = plan.views[static_cast<std::size_t>(pass.view)];
        writes.scissor = view.rect;
        const bool blurred = input.mirrors[static_cast<std::size_t>(view.mirror)].roughness > 0.0;
        if (pass.kind == PassKind::MirrorMask) {
            drawInto(plan, view.parent, writes); // the mirror is marked where its parent's scene lies
            writes.clockwise =
                view.parent >= 0 && mirrored(plan.views[static_cast<std::size_t>(view.parent)]);
        } else if (pass.kind == PassKind::Mirror) {
            drawInto(plan, pass.view, writes);
            if (view.ownTarget) {
                // A fresh texture, cleared whole: blurred lookups read around the mirror, and a scissored
                // clear is slow on llvmpipe (Mesa clears a part of a buffer by drawing a quad through it;
                // the whole buffer is a fill). The reflection itself is still drawn in the mirror's pixels.
                writes.clear = true;
                writes.clearWhole = true;
            } else {
                writes.stencilEqual = view.stencilLevel; // inside the mask its MirrorMask marked
            }
            writes.clockwise = mirrored(view);
        } else {
            // The surface is drawn in the parent's (reflected) view, over the reflection it shows.
            drawInto(plan, view.parent, writes);
            writes.clockwise =
                view.parent >= 0 && mirrored(plan.views[static_cast<std::size_t>(view.parent)]);
            writes.mipmaps = view.ownTarget && blurred;
            writes.convolveMips = writes.mipmaps && view.glossyFilter == GlossyFilter::Chain;
            writes.readSlot = view.ownTarget ? view.textureSlot : -1;
        }
        break;
    }
    }
    return writes;
}

// The environment map's mirror passes draw into its faces, every mirror with the stencil technique; the
// capture draws whole faces (no scissor). Each pass draws through one stencil level: the mask marks the
// pixels of its parent's level one deeper, the reflection is drawn on those, and the surface, drawn over
// them, steps them back. A direct-fill component whose warp mirrors the image (EnvmapFace::warp.mirrored)
// flips the winding once more, on top of what is declared here, for the face's own view as for its
// mirrors'.
PassWrites envmapWrites(const EnvmapPlan& map, const PlannedPass& pass) {
    PassWrites writes;
    writes.target = PassTarget::OwnMap;
    const MirrorView& view = map.views[static_cast<std::size_t>(pass.view)];
    const bool parentMirrored =
        view.parent >= 0 && mirrored(map.views[static_cast<std::size_t>(view.parent)]);
    switch (pass.kind) {
    case PassKind::MirrorMask: // in the parent's view, on the parent's pixels
        writes.stencilEqual = view.parentStencilLevel;
        writes.clockwise = parentMirrored;
        break;
    case PassKind::Mirror: // in the mirror's own view, on the pixels its mask marked
        writes.stencilEqual = view.stencilLevel;
        writes.clockwise = mirrored(view);
        break;
    case PassKind::MirrorSurface: // in the parent's view, on the mirror's pixels, which it steps back
        writes.stencilEqual = view.stencilLevel;
        writes.clockwise = parentMirrored;
        break;
    case PassKind::Shadow: // not planned inside the map
    case PassKind::Envmap:
    case PassKind::Prefilter:
    case PassKind::Main:
    case PassKind::Guides:
    case PassKind::Composite:
    case PassKind::ScreenDepth:
    case PassKind::ScreenColour:
    case PassKind::ReflectorTrace:
        break;
    }
    return writes;
}

} // namespace

void declareWrites(const FrameInput& input, FramePlan& plan) {
    for (PlannedPass& pass : plan.passes)
        pass.writes = cameraWrites(input, plan, pass);
    for (EnvmapPlan& map : plan.envmaps)
        for (PlannedPass& pass : map.passes)
            if (pass.view >= 0)
                pass.writes = envmapWrites(map, pass);
}

} // namespace speculum::render
