#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/gl/GpuMesh.hpp"
#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"
#include "render/gl/RenderTexture.hpp"
#include "render/gl/TextureCache.hpp"
#include "render/passes/GuidesPass.hpp"
#include "render/passes/MainPass.hpp"
#include "render/passes/MirrorOcclusion.hpp"
#include "render/passes/MirrorPasses.hpp"
#include "render/passes/ReflectorPass.hpp"
#include "render/passes/ShadowMaps.hpp"
#include "render/plan/FramePlan.hpp"
#include "render/plan/FrameReport.hpp"
#include "render/plan/Planner.hpp"
#include "render/plan/RenderOptions.hpp"

#include <glm/mat4x4.hpp>
#include <optional>
#include <string>
#include <vector>

namespace speculum::render::passes {

// The GL objects the renderer keeps from frame to frame: programs, caches, maps and buffers.
struct FrameResources {
    gl::Program meshProgram;
    gl::Program shadowProgram; // depth only
    gl::Program flatProgram;   // mirror masks and background resets
    gl::Program mirrorProgram;
    gl::Program compositeProgram;
    gl::Program mipConvolveProgram;      // a rough mirror's convolved chain (MipConvolve.hpp)
    gl::Framebuffer convolveFramebuffer; // its levels, one at a time
    gl::MeshCache meshes;
    gl::TextureCache textures;
    ShadowMaps shadows;
    ReflectorPass reflector; // the curved reflectors' environment maps and surfaces
    GuidesPass guides;       // the editor's guide lines over the camera's view
    // The linear (half-float) colour buffer every frame is drawn into before the composite pass, with
    // the depth-stencil buffer the mirror passes nest in.
    gl::RenderTexture linear;
    std::vector<gl::RenderTexture> reflectionTextures; // texture-technique mirrors, one per nesting
    MirrorOcclusion occlusion;                         // the mirror masks' occlusion tests
    MeshFacts meshFacts;      // closed meshes, whose back faces the camera's and mirrors' views cull
    gl::VertexArray emptyVao; // core profile needs a VAO bound even for attribute-less draws
    gl::Texture dummyShadow2D;
    gl::Texture dummyShadowCube;
    gl::Texture ggxAlbedo; // math::ggxAlbedoTable, which the glossy shaders read (kGgxAlbedoUnit)
    // Screen-space mirrors: the camera's view depth with its pyramid of minima (R32F), the programs that
    // draw and reduce it, and the trace.
    gl::RenderTexture screenDepth;
    gl::RenderTexture screenHalf; // the half-resolution trace, before it is scaled up (RGBA16F)
    // The camera's colour copied for the reflector's trace, which draws into it (RGBA16F); then, for a
    // still's counts, where the trace draws its sources.
    gl::RenderTexture screenImage;
    gl::Program screenDepthProgram;
    gl::Program depthMinProgram;
    gl::Program screenTraceProgram;
    gl::Program reflectorTraceProgram;
    MeshHandle unitPlane;
};

// One frame being executed: the plan, what the passes share, and what running them found. The plan is
// read only; executors record into the fields below it.
struct FrameExecution {
    const FrameInput& input;
    const FramePlan& plan;
    const RenderTarget& target;
    glm::dmat4 projection; // the camera's (restricted to the tile for tiles)
    bool tile = false;     // a tile of a larger image: occlusion is judged within the tile
    FrameResources& resources;
    MainPassContext& context;
    // What the next frame's planner learns once a map is drawn (the plan's signatures).
    PlannerState& commits;
    std::vector<std::string>& warnings;
    // Per reflector (by index), whether its map could be allocated for this frame's settings; false: its
    // Envmap passes do not run.
    std::vector<bool> envmapAllocated;
    // Lights whose planned shadow map could not be allocated this frame: their Shadow pass does not run, and
    // they light without shadows.
    std::vector<int> shadowsMissing;
    // The caller's target, which only the composite writes: larger than `target` (the size every other
    // pass draws at) for a preview at a reduced resolution; null: `target` itself.
    const RenderTarget* output = nullptr;
    const RenderTarget& outputTarget() const { return output ? *output : target; }
    // The lines the Guides pass draws (RenderOptions::guides); null: none.
    const std::vector<GuideLine>* guides = nullptr;

    // Filled while running: why a view found no reflection (fully occluded, no texture), by view, as the
    // skip it reports; a view with one runs no more passes, nor do the views inside it.
    std::vector<std::optional<SkippedEffect>> hidden;
    std::vector<SkippedEffect> skipped;  // effects execution found it could not draw, in pass order
    bool screenDepthReady = false;       // the ScreenDepth pass drew the pyramid the traces read
    bool screenColourReady = false;      // the ScreenColour pass copied the image and blurred its pyramid
    bool countScreenSpace = false;       // RenderOptions::countScreenSpace
    bool showScreenSpaceSources = false; // RenderOptions::showScreenSpaceSources
};

// What running one pass found.
struct PassResult {
    bool ran = true;
    std::string outcome; // PassRun::outcome
};

// The space the camera's mirror views are drawn in: the frame's plan, its camera, its buffers.
ViewSpace cameraSpace(FrameExecution& frame);

// Binds what `writes` says the pass draws into (its own map: nothing to bind in the camera's space, the
// face in a map face's), with the viewport of the space's target, clears it (to the background, depth 1,
// stencil 0: in the scissor or, clearWhole, all of it), limits drawing to the scissor and the stencil
// level, and sets the winding. Every other piece of GL state starts from its default (resetPassState).
void bindWrites(const PassWrites& writes, FrameExecution& frame, const ViewSpace& space);
// In the camera's space.
void bindWrites(const PassWrites& writes, FrameExecution& frame);

// The GL state every pass starts from.
void resetPassState();

// The executors, one per pass kind (family files: MapExecutors, SceneExecutors, MirrorExecutors). The
// mirror passes draw in the space their views belong to.
PassResult runShadow(const PlannedPass& pass, FrameExecution& frame);
PassResult runEnvmap(const PlannedPass& pass, FrameExecution& frame);
PassResult runPrefilter(const PlannedPass& pass, FrameExecution& frame);
PassResult runMain(const PlannedPass& pass, FrameExecution& frame);
PassResult runComposite(const PlannedPass& pass, FrameExecution& frame);
PassResult runGuides(const PlannedPass& pass, FrameExecution& frame);
PassResult runMirrorMask(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space);
PassResult runMirror(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space);
PassResult runMirrorSurface(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space);
// The reflection texture (PassWrites::slot) a mirror's Mirror pass draws into, at the frame's size in
// `format`; false when it does not fit, the view (and those inside it) then skipped with the reason.
bool ensureReflectionTexture(const PlannedPass& pass, FrameExecution& frame, GLenum format);
// Screen-space mirrors (ScreenSpaceExecutors.cpp): the depth pyramid, and a mirror's trace, which its
// Mirror pass runs instead of drawing the scene reflected (MirrorView::screenSpace).
PassResult runScreenDepth(const PlannedPass& pass, FrameExecution& frame);
PassResult runScreenTrace(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space);
// The curved reflector traced in screen space (ReflectorTechnique::ScreenSpace): over what the main pass
// drew of it, the image replaces the map's lookup where the trace meets it.
PassResult runReflectorTrace(const PlannedPass& pass, FrameExecution& frame);
// A rough reflector's trace reads the image blurred: a copy of it (FrameResources::screenImage) with its
// mip chain, each level the box-filtered half of the one below.
PassResult runScreenColour(const PlannedPass& pass, FrameExecution& frame);
// The debug view (FrameExecution::showScreenSpaceSources): a screen-space mirror's pixels, over its surface
// just drawn in the bound target, in the colour of where their reflection comes from, traced again at
// full resolution.
void drawScreenSpaceSources(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space);

// Runs the pass with the executor of its kind, in `space`: the camera's for the frame's passes, a map
// face's for the mirror passes planned inside the environment map (EnvmapPlan::passes), the only kind a
// face holds.
PassResult runPass(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space);
// In the camera's space.
PassResult runPass(const PlannedPass& pass, FrameExecution& frame);

// What `writes` left at the pixel of the buffer it drew into that shows `outputPixel` of the output (x from
// the left, y from the top; scaled to the drawn size for the frame's own buffers in a preview): colour,
// stencil and depth, read back now (a GPU wait). Not readable for a pass into a map of its own.
PixelProbe probePixel(const PassWrites& writes, FrameExecution& frame, glm::ivec2 outputPixel);

} // namespace speculum::render::passes
