#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/passes/MainPass.hpp"
#include "render/plan/FramePlan.hpp"

namespace speculum::render::passes {

// The view a mirror view is drawn from: its parent's, or the camera's for index −1.
// `clockwise`: the winding the pass drawing in it declares (PassWrites::clockwise).
ViewSetup viewSetup(const FrameInput& input, const FramePlan& plan, int viewIndex,
                    const glm::dmat4& cameraProjection, glm::ivec2 targetSize, bool clockwise);

// Stencil technique, step 1: in the parent's view, marks the mirror's visible pixels (those of its parent's
// stencil level whose depth test passes) with the view's stencil level, and counts them with an occlusion
// query. With `waitForQuery`, waits for its result and returns false (and marks nothing) if no pixel
// passed: the mirror is fully hidden. Then resets the colour and depth of the marked pixels, so the
// reflected scene can be drawn there. Without `waitForQuery`, always returns true: the query's result is
// for the caller to read later (see MirrorOcclusion).
// Texture technique: only counts the visible pixels.
bool drawMirrorMask(const FrameInput& input, const MirrorView& view, const ViewSetup& parent,
                    const gl::Program& maskProgram, const MainPassContext& context, GLuint query,
                    bool waitForQuery);

// Step 3: the mirror's own surface over its reflection, in the parent's view (see shaders/mirror.frag);
// stencil views also step their pixels back to the parent's stencil level and restore the mirror's depth.
// A perfect stencil mirror (reflectivity 1) has no surface of its own to shade: flatProgram only tints.
// `reflectionEncoded`: the texture holds the sRGB-encoded bytes a copying surface (surfaceCopiesReflection)
// writes as they are, read through nearest filtering with the decode skipped.
void drawMirrorSurface(const FrameInput& input, const MirrorView& view, const ViewSetup& parent,
                       const gl::Program& surfaceProgram, const gl::Program& flatProgram,
                       MainPassContext& context, GLuint reflectionTexture, int reflectionLevels,
                       glm::ivec2 targetSize, bool reflectionEncoded = false);

// True when a texture mirror's surface is its reflection, texel for texel (shaders/mirror.frag's
// MIRROR_COPY): sharp, reflectivity 1, a white tint and no Fresnel, in a view of weight 1.
bool surfaceCopiesReflection(const Mirror& mirror, const glm::dvec3& viewWeight);

// Scissor to a view's pixels.
void scissorTo(const math::PixelRect& rect);

} // namespace speculum::render::passes
