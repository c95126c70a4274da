#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/passes/MainPass.hpp"
#include "render/plan/FramePlan.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <vector>

namespace speculum::render::passes {

// The alpha of a reflection texture's pixels that show no surface: as far as a path can be (the half
// float's largest value), read by a rough mirror's blur (shaders/mirror.frag).
inline constexpr float kFarPathLength = 65504.0f;

class MirrorOcclusion;

// What the views of a space draw beyond its input as it is: an environment map face draws each view
// with the scene's meshes split for the view's (virtual) capture point, through the warp, and with the
// back faces the capture point cannot see culled.
class SpaceScenes {
public:
    virtual ~SpaceScenes() = default;
    // Makes `program` and the context ready to draw in view `view` (-1: the space's own) and returns the
    // scene drawn there.
    virtual const FrameInput& enter(int view, const gl::Program& program, MainPassContext& context) = 0;
    // Every pass that draws in view `view` (its reflection, the masks and surfaces of the mirrors seen in
    // it) has run.
    virtual void leave(int view) = 0;
};

// The space a set of mirror views is drawn in: the camera's (FramePlan::views, into the frame's buffers)
// or one face of the reflector's environment map (its EnvmapPlan::views, into the face). The mirror
// passes run against the space they were planned in, so one recipe draws the mirrors of both.
struct ViewSpace {
    // The scene as the space's own view sees it: the camera's, or the capture point's (no reflector).
    const FrameInput& input;
    const std::vector<MirrorView>& views;
    int face = -1; // the views of this map face (MirrorView::face) are the space's; -1: the camera's
    // The space's own view: camera-relative world → eye (the camera's rotation, a cube face's view), and
    // eye → clip. A mirror view's projection (MirrorView::projection) goes with the same rotation. Both
    // are the identity in a direct-fill component, which warps its views instead.
    glm::dmat4 rotation{1.0};
    glm::dmat4 projection{1.0};
    glm::ivec2 size{1, 1}; // the target's pixels (texels)
    // A face: the framebuffer that passes drawing into their own map (PassTarget::OwnMap) draw into, the
    // face's. 0 in the camera's space, whose map passes bind maps of their own.
    GLuint mapFramebuffer = 0;
    // Objects wholly outside a view's clip volume are not drawn (ViewSetup::cullOutside). Off in a
    // direct-fill component, whose clip space is no frustum; a cube face culls what lies outside its 90°
    // (with several reflectors, each map would otherwise draw every other one six times).
    bool frustum = true;
    // The target's own projection mirrors the image (a direct-fill component whose warp does): every
    // winding the plan declares (PassWrites::clockwise) is flipped once more.
    bool flipsWinding = false;
    bool preWeighted = false;   // the camera's stencil mirrors draw pre-weighted (FramePlan::preWeighted)
    bool ownViewCoarse = false; // the own view draws simplified items too (the map's, like every mirror's)
    // What the passes draw with: the scene (context.program), the masks and the surfaces.
    MainPassContext& context;
    const gl::Program& flatProgram;
    const gl::Program& mirrorProgram;
    // The camera's masks test whether their mirrors are hidden; null: every mirror view is drawn.
    MirrorOcclusion* occlusion = nullptr;
    SpaceScenes* scenes = nullptr; // null: every view draws `input` with the context as it is

    const MirrorView& view(int index) const { return views.at(static_cast<std::size_t>(index)); }
    // The scene view `index` draws (-1: the space's own), with `program` and the context ready for it.
    const FrameInput& enter(int index, const gl::Program& program) const {
        return scenes ? scenes->enter(index, program, context) : input;
    }
    void leave(int index) const {
        if (scenes)
            scenes->leave(index);
    }
};

// The view of `viewIndex` in the space (-1: its own). `clockwise`: the winding the pass drawing in it
// declares (PassWrites::clockwise).
ViewSetup viewSetup(const ViewSpace& space, int viewIndex, bool clockwise);

// Draws the scene as view `viewIndex` of the space sees it (-1: its own) into the bound target, winding
// as `clockwise` declares.
void drawSpaceView(const ViewSpace& space, int viewIndex, bool clockwise);

// Stencil technique, step 1: in the parent's view, marks the mirror's visible pixels (those of its parent's
// stencil level whose depth test passes) with the view's stencil level, and counts them with an occlusion
// query (none: 0). With `waitForQuery`, waits for its result and returns false (and marks nothing) if no
// pixel passed: the mirror is fully hidden. Then resets the colour and depth of the marked pixels, so the
// reflected scene can be drawn there. Without `waitForQuery`, always returns true: the query's result is
// for the caller to read later (see MirrorOcclusion).
// Texture technique: only counts the visible pixels.
bool drawMirrorMask(const ViewSpace& space, const MirrorView& view, const ViewSetup& parent, GLuint query,
                    bool waitForQuery);

// Step 3: the mirror's own surface over its reflection, in the parent's view (see shaders/mirror.frag);
// stencil views also step their pixels back to the parent's stencil level and restore the mirror's depth.
// A perfect stencil mirror (reflectivity 1) has no surface of its own to shade: the flat program only tints.
// `reflectionEncoded`: the texture holds the sRGB-encoded bytes a copying surface (surfaceCopiesReflection)
// writes as they are, read through nearest filtering with the decode skipped.
void drawMirrorSurface(const ViewSpace& space, const MirrorView& view, const ViewSetup& parent,
                       GLuint reflectionTexture, int reflectionLevels, bool reflectionEncoded = false);

// True when a texture mirror's surface is its reflection, texel for texel (shaders/mirror.frag's
// MIRROR_COPY): sharp, reflectivity 1, a white tint and no Fresnel, in a view of weight 1.
bool surfaceCopiesReflection(const Mirror& mirror, const glm::dvec3& viewWeight);

// Scissor to a view's pixels.
void scissorTo(const math::PixelRect& rect);

} // namespace speculum::render::passes
