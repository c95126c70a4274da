#pragma once

#include "render/envmap/CaptureMath.hpp"
#include "render/math/Mirror.hpp"
#include "render/math/ShadowFrustum.hpp"
#include "render/mesh/MeshData.hpp"
#include "render/plan/PlanReason.hpp"
#include "render/plan/RenderOptions.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace speculum::render {

// Prefilter: the reflector's GGX pre-filtered chain, convolved from its environment map (runs after Envmap,
// only when the map changed or the chain's sample count did).
// ScreenDepth: the camera's view depth and its pyramid of minima, which screen-space mirrors trace
// against (runs once, before the first of their Mirror passes, only when one is seen).
// ScreenColour: a copy of the camera's image with its pyramid of blurred levels, which a rough reflector's
// screen-space trace reads (runs just before that trace, only for a rough reflector traced in screen space).
enum class PassKind {
    Shadow,
    MirrorMask,
    Mirror,
    MirrorSurface,
    Envmap,
    Prefilter,
    Main,
    Guides,
    Composite,
    ScreenDepth,
    ReflectorTrace,
    ScreenColour
};

std::string_view toString(PassKind kind);

// What a pass draws into. The frame's own buffers are named here; the executor binds what the plan says.
enum class PassTarget {
    OwnMap,     // a map the pass owns: a light's shadow map, the reflector's environment map
    Linear,     // the frame's linear (half-float) colour buffer with its depth-stencil buffer
    Reflection, // a texture-technique mirror's reflection texture (PassWrites::slot)
    Output,     // the caller's target (RenderTarget)
};

std::string_view toString(PassTarget target);

// How a pass writes, declared by the planner so that the executor decides nothing: where, what it clears
// first, which pixels it may touch, which stencil level it draws through, which way its triangles face,
// and what it prepares for the passes after it.
struct PassWrites {
    PassTarget target = PassTarget::OwnMap;
    int slot = -1; // Reflection: which reflection texture (MirrorView::textureSlot)
    // Clears colour (to the background), depth and stencil (to 0) before drawing: within `scissor`, or
    // the whole target with clearWhole (a blurred reflection's lookups read around the mirror's pixels).
    bool clear = false;
    bool clearWhole = false;
    std::optional<math::PixelRect> scissor; // draws only these pixels (none: the whole target)
    int stencilEqual = -1;                  // ≥ 0: draws only where the stencil holds this level
    bool clockwise = false; // front faces wind clockwise: the view has an odd number of reflections
    // MirrorSurface of a blurred texture-technique mirror: builds the reflection texture's mip chain
    // before reading it; readSlot is the texture the surface reads (-1: none, a stencil mirror).
    bool mipmaps = false;
    // The mip chain is convolved level by level with a Gaussian kernel (GlossyFilter::Chain) rather than
    // box-filtered.
    bool convolveMips = false;
    int readSlot = -1;
};

// One pass the renderer will run, and why, and how it writes. The plan is never changed by running it:
// what ran, what execution found and what it cost are the FrameReport's.
struct PlannedPass {
    PassKind kind = PassKind::Main;
    std::string target;      // node name, or empty for the whole frame
    PlanReason code{};       // why it runs: every planned pass sets it
    ReasonDetails details{}; // what the sentence of `code` names
    int lightIndex = -1;     // shadow passes: index into FrameInput::lights
    int view = -1;           // mirror passes: index into FramePlan::views
    // Envmap, Prefilter, ScreenColour and ReflectorTrace passes: index into FrameInput::reflectors; Envmap
    // passes also name their map's plan (index into FramePlan::envmaps).
    int reflector = -1;
    int envmap = -1;
    // Shadow passes: the signature of what the map holds (shadowSignature), which the renderer records
    // once the map is drawn, so the next frame's planner can reuse it. Prefilter passes: the chain's
    // (prefilterKey), recorded the same way.
    std::uint64_t signature = 0;
    PassWrites writes;

    std::string reason() const { return formatReason(code, details); }
};

// An effect the scene has that got no pass this frame, and why.
struct SkippedEffect {
    std::string target;
    PlanReason code{}; // why it got none: every skip sets it
    ReasonDetails details{};
    int face = -1; // skips inside the environment map: index into EnvmapPlan::faces (-1: every face)

    std::string reason() const { return formatReason(code, details); }
};

// The scene seen in one mirror, possibly through other mirrors: everything the renderer needs to draw
// it, derived in double precision by the planner. The camera's views live in FramePlan::views, the
// environment map's in EnvmapPlan::views; both are planned by planMirrors' one planner.
struct MirrorView {
    int mirror = -1; // index into FrameInput::mirrors
    int parent = -1; // index into the same list of the view the mirror is seen in; -1: the space's own
    int depth = 1;   // 1: seen directly by the camera (or the capture point)
    int face = -1;   // map views: index into EnvmapPlan::faces; -1: the camera's
    glm::dmat4 reflection{1.0}; // world → reflected world: the parent's reflection × this mirror's
    // The projection with the oblique near plane on the mirror: the camera's (used with its rotation), or
    // the cube face's (used with EnvmapFace::view). Unused in a direct-fill component, which clips with:
    glm::dmat4 projection{1.0};
    glm::dvec4 clipPlane{0.0}; // the mirror's kept side in relative (camera- or capture-relative) drawn space
    glm::dvec3 eye{0.0};       // the virtual eye in (unreflected) world space: reflection⁻¹ · camera
    math::PixelRect rect;      // the pixels (texels) the mirror covers, within its parent's
    double pixelArea = 0.0;
    bool ownTarget = false;     // texture technique: rendered into a texture of its own
    int stencilLevel = 0;       // the stencil value of its pixels in the target it is drawn into
    int parentStencilLevel = 0; // the stencil value of the parent view's pixels, where the mirror appears
    int textureSlot = -1;       // own-target views: which render texture (one per nesting of texture views)
    // With FramePlan::preWeighted: what the camera's buffer keeps of this view's scene, the product of
    // reflectivity × tint of the stencil mirrors down to it; everything the view draws is multiplied by it
    // as it is written. 1 for views drawn into a texture (and without pre-weighting).
    glm::dvec3 weight{1.0};
    // How its reflection is filtered when the mirror is rough: the settings' filter, or the convolved chain
    // where the planner trades the footprint's taps for it (MirrorPlanner's glossyFilterFor).
    GlossyFilter glossyFilter = GlossyFilter::Footprint;
    // A screen-space mirror seen directly by the camera: its Mirror pass traces its reflection through the
    // camera's image into its reflection texture instead of drawing the scene reflected. Its passes run
    // after every other mirror's, so that the image holds them; it has no views inside it (what it
    // reflects of other mirrors is what the image shows of them).
    bool screenSpace = false;
};

// Where the reflector's environment map is captured from: the centre of the reflector's world bounds
// (a teapot's node origin is its base), with a near distance that clips nothing outside the reflector
// and a far distance that reaches every corner of the scene.
struct EnvmapCapture {
    glm::dvec3 centre{0.0};
    double near = 0.01;
    double far = 100.0;
};

// One face of the map's cube (cube maps and the resampled fill) or one component of the direct fill, as
// pass 1 draws it: mirrors are planned in each, seen from the capture point.
struct EnvmapFace {
    std::string label;   // "+X face", "−Z half", "part 1"
    int index = 0;       // the cube face (GL order +X −X +Y −Y +Z −Z) or the component
    bool warped = false; // a direct-fill component, drawn through `warp`; else a cube face
    glm::dmat4 view{1.0}; // capture-relative world → the face's view (envmap::cubeFaceView), or the map frame
    envmap::WarpParameters warp;
    int width = 1; // texels
    int height = 1;
};

// What the environment pass draws, planned with the frame: the capture point, the faces, and the mirror
// views in each face with their passes (in execution order, face by face) and skips, with reasons.
struct EnvmapPlan {
    std::string target; // the reflector's name
    int reflector = -1; // index into FrameInput::reflectors
    // Which bounce this drawing of the map is (Settings::reflectorBounces): 0 draws the other reflectors
    // with their plain material; bounce k draws them with their maps of bounce k − 1.
    int bounce = 0;
    EnvmapCapture capture;
    // What the renderer records once the map is drawn (envmapSignature, envmapSettingsKey).
    std::uint64_t signature = 0;
    std::uint64_t settingsKey = 0;
    std::vector<EnvmapFace> faces;
    std::vector<MirrorView> views;
    std::vector<PlannedPass> passes; // view: index into `views`
    std::vector<SkippedEffect> skipped;
};

// A light whose shadow map the main pass samples this frame, rendered now or reused: its frustum is
// computed once, here, and used by the signature, the allocation, the shadow pass and every lookup.
struct ShadowPlan {
    int light = -1; // index into FrameInput::lights
    // Texels per side (per cube face): the light's own, shrunk by a preview, within the GPU's limits and
    // below every size of its kind that failed to allocate (fitShadowMapSize).
    int mapSize = 0;
    int pcf = 1; // the lookup's filter width
    math::ShadowFrustum frustum;
    std::uint64_t signature = 0; // shadowSignature: what the map holds
    bool render = false;         // a Shadow pass draws it this frame; false: the map is reused
};

// The camera's colour buffer. Half float keeps radiance above 1 until the composite pass resolves it,
// so a stencil mirror's blend (reflection × weight + surface) sees the unclamped reflection it drew. 8-bit
// sRGB, encoded by the GPU as each fragment is written (and blended in linear light), is what a frame
// with no such blend needs: its composite is then a plain copy, with no shader run per pixel.
enum class CameraBuffer { HalfFloat, Srgb8 };

struct FramePlan {
    std::vector<PlannedPass> passes;
    CameraBuffer cameraBuffer = CameraBuffer::HalfFloat;
    // The 8-bit sRGB camera buffer is the output's own: every pass that writes the camera's colour buffer
    // (PassTarget::Linear) writes the output, and no composite pass is planned.
    bool cameraBufferIsOutput = false;
    // Stencil mirrors in the camera's buffer draw their reflections already weighted (MirrorView::weight)
    // and add their surfaces over them, instead of blending the surface onto the reflection they drew: an
    // 8-bit buffer then holds clamp(w·R) + S, within one 8-bit step of the half-float result. Planned where
    // every such weight is constant over the mirror (no Fresnel term).
    bool preWeighted = false;
    std::vector<SkippedEffect> skipped;
    // Lights (indices into FrameInput::lights) whose shadow map the main pass samples, rendered this
    // frame or reused; at most kMaxShadowedLights. shadows[k] plans shadowedLights[k], slot k.
    std::vector<int> shadowedLights;
    std::vector<ShadowPlan> shadows;
    std::vector<MirrorView> views;
    // The environment maps drawn this frame, in the order their Envmap passes run: bounce by bounce,
    // reflector by reflector within a bounce.
    std::vector<EnvmapPlan> envmaps;
    // Per item (by index into FrameInput::items): the mirrors' views and the environment map draw it at its
    // simplified level (MeshData::coarse). Empty when no reflected view draws a simplified mesh.
    std::vector<bool> coarseItems;
    // Big meshes a reflected view draws that have no simplified level yet: drawn whole this frame, and the
    // renderer has the level built (at once, or on the editor's worker thread). Each mesh once.
    std::vector<MeshHandle> coarseLevelsWanted;
    // Each reflector's map resolution (by index into FrameInput::reflectors): its own, within the GPU's
    // limits and below every size of its layout that failed to allocate (fitEnvmapResolution); 0 where no
    // map of its layout fits. The map is allocated, drawn and looked up at this resolution (plannedInput).
    std::vector<int> reflectorResolutions;
    // The pre-filter's lobe samples a texel where the plan lowered the scene's (PlanOptions::maxMapSeconds);
    // 0: the scene's own.
    int prefilterSamples = 0;
    // Levels of mirror nesting the camera's views go to: settings.mirrorDepth, less what a preview cuts.
    int mirrorDepth = 0;
    // The preview the frame is (RenderOptions::preview); what it gives up is among `skipped`.
    PreviewPolicy preview;
    // What the frame cannot do as the scene asks, found while planning: a map larger than the GPU holds, or
    // of a size that failed to allocate in an earlier frame, and the size planned instead. The renderer
    // reports them first among FrameReport::warnings.
    std::vector<std::string> warnings;

    // The shadow plan of a light, or nullptr if the main pass does not sample a map of it.
    const ShadowPlan* shadowOf(int lightIndex) const;
    // The planned resolution of reflector `index`'s map (0: none fits, or no such reflector).
    int reflectorResolution(int index) const;
};

} // namespace speculum::render
