#pragma once

#include "render/frame/Reflector.hpp"

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace speculum::render {

// Why a pass runs, or why an effect got none: one code per sentence the plan can show. Tools and tests
// compare codes (and `explain --json` prints toString's name); the sentence, formatReason's, is for people.
enum class PlanReason {
    // A light and its shadow map.
    LightLimit,            // skip: more than kMaxLights lights
    ShadowsOff,            // skip
    NoShadowCasters,       // skip
    NoShadowReceivers,     // skip
    ShadowedLightLimit,    // skip: more than kMaxShadowedLights lights cast shadows
    ShadowMapDoesNotFit,   // skip: no map of its kind fits in GPU memory
    ShadowMapReused,       // skip
    ShadowFirstMap,        // pass: the light has no map yet
    ShadowChanged,         // pass: the light or its casters changed
    ShadowMapNotAllocated, // skip while running: its planned map (details.mapSize) could not be allocated
    // The camera's colour buffer: the main pass (by its buffer) and the composite.
    MainHalfFloat,
    MainSrgb,
    MainIntoOutput, // the output's own 8-bit sRGB buffer
    CompositeToFloat,
    CompositeCopiesSrgb,
    CompositeStencilBlend, // a stencil mirror's blend needs radiance above 1
    CompositeFresnelBlend, // … and its Fresnel weight keeps it from being pre-weighted
    CompositeNestedBlend,  // … and it blends inside another stencil mirror's reflection
    CompositeNotNeeded,    // skip: the frame is drawn straight into the output
    CompositeScreenSpace,  // a screen-space mirror reads the frame's colour in linear light
    GuidesOverView,        // the editor's guide lines (details.lines), depth-tested against the view
    // A planar mirror's passes.
    MirrorMaskStencil, // marks its pixels in the stencil buffer
    MirrorMaskCount,   // counts its pixels (a texture-technique mirror)
    MirrorIntoTexture,
    MirrorInStencil,
    MirrorSurface,
    MirrorScreenTrace,  // a screen-space mirror's reflection, traced through the camera's image
    ScreenDepthPyramid, // the camera's view depth and its pyramid of minima (details.node: who traces it)
    // A planar mirror that gets no view where it is seen (directly, in mirrors, in a face of the map).
    MirrorSizeInvalid,
    MirrorNoPlane, // its transform leaves no plane (details.error)
    MirrorEdgeOn,
    MirrorBehind,
    MirrorOutsideView,
    MirrorOutsideParent, // outside the reflected view of the mirror it is seen in
    MirrorBelowPixel,
    MirrorDepthLimit,
    MirrorViewLimit,           // kMaxMirrorViews in the frame or the face
    MirrorNoReflectionMatrix,  // details.error
    MirrorNoObliqueProjection, // details.error
    MirrorStencilTooDeep,
    MirrorDepthZero,    // settings.mirrorDepth is 0
    MapMirrorDepthZero, // the reflector's mirrorDepth is 0: no mirror reflects in its map
    // A planar mirror found without a reflection while the frame runs (it, or a mirror it is seen in).
    MirrorOccluded,
    MirrorOccludedInTile,
    MirrorNoTexture, // its reflection texture could not be allocated (details.error)
    // The curved reflector's environment map.
    EnvmapFirstMap,   // pass: no map yet
    EnvmapAlways,     // pass: update "always"
    EnvmapChanged,    // pass: something it sees changed
    EnvmapTimeSliced, // pass: update "time-sliced", one face (details.slicedFace) of a map out of date
    EnvmapOutOfSight, // skip: the reflector is seen neither directly nor in a mirror
    EnvmapDoesNotFit, // skip: no map of its layout fits in GPU memory
    EnvmapReusedOnce,
    EnvmapUnchanged,
    EnvmapNotAllocated, // skip while running
    EnvmapBounce,       // pass: bounce details.bounce, the other reflectors drawn with their maps
    EnvmapOverCap,      // skip: more reflectors need a map than kMaxReflectorMaps; this one is farther
    BouncesUnused,      // skip: bounces asked with one reflector, which is never in its own map
    BouncesCapped,      // skip: fewer bounces (details.limit) than asked (details.asked), kMaxEnvmapPasses
    // The reflector's GGX pre-filtered chain.
    PrefilterFirstChain,      // pass: no chain yet
    PrefilterMapRendered,     // pass: the map is rendered this frame
    PrefilterSettingsChanged, // pass: the chain was filtered with another sample count
    PrefilterSharp,           // skip: roughness 0
    PrefilterMipFilter,       // skip: settings.glossyFilter is mip
    PrefilterReused,
    PrefilterNoMap, // skip while running: the map could not be allocated or drawn
    // The reflector traced in screen space first (ReflectorTechnique::ScreenSpace).
    ReflectorScreenTrace, // pass
    ScreenColourPyramid,  // the camera's image and its blurred pyramid, for a rough reflector's trace
    ReflectorTraceNotSeenDirectly, // skip: seen only in mirrors, whose views the image does not hold
    // What a preview (RenderOptions::preview) gives up, each a skip whose sentence starts "preview: ".
    PreviewScaled,        // details.scale of the output's width and height
    PreviewMirrorDepth,   // mirrors nest details.limit levels, not details.asked
    PreviewShadowMapSize, // a handle drag's shadow map: details.mapSize², not details.asked²
    PreviewEnvmapHeld,    // the map is kept while the view moves (details.update applies at rest)
};

inline constexpr std::size_t kPlanReasonCount = static_cast<std::size_t>(PlanReason::PreviewEnvmapHeld) + 1;

// Whether the code is one of a preview's skips (its name starts "preview-").
bool isPreview(PlanReason code);

// Whether a skip with this code drops something the scene asks for (a map that does not fit, a mirror
// past the view limit, a transform that leaves no plane): what the commands warn of. Skips that are the
// frame working as meant (nothing to draw, reused, out of sight, the scene's own settings such as a
// sharp reflector needing no pre-filter) and the passes' own codes are not.
bool dropsWhatTheSceneAsks(PlanReason code);

// The code's stable kebab-case name ("mirror-outside-view"): explain's JSON "code".
std::string_view toString(PlanReason code);

// Writes the code's name, as test failures and logs show it.
std::ostream& operator<<(std::ostream& out, PlanReason code);

// A big mesh that a mirror's or the environment map's pass draws at its simplified level, or whole.
struct ReflectedMesh {
    std::string name{};
    std::size_t triangles = 0;
    std::optional<std::size_t> simplifiedTriangles{}; // none: drawn whole
    double simplificationError = 0.0;                 // of the simplified mesh, as a fraction of its size
    // Drawn whole while its simplified level is being built (the level is built when a reflected view
    // first needs it; in the editor, on a worker thread).
    bool simplifying = false;
};

// What a reason's sentence names besides its code; each code reads only the fields its sentence needs.
struct ReasonDetails {
    // Where a mirror is seen (its views' passes and its skips), or the reflector (its map's pass).
    std::vector<std::string> seenIn{}; // the mirrors it is seen in, outermost first; empty: seen directly
    std::string
        mapFace{}; // the face of the map it is planned in ("Ball's map, +X face"); empty: the camera's
    // The pixels (texels in the map) a mirror covers. None: a component of a direct-fill map, which has no
    // pixels to count and draws its reflection with a clip plane instead of an oblique near plane.
    std::optional<double> area{};

    std::string node{};  // a node named besides the target: the reflector of a map, the mirror that blends
    std::string error{}; // the failure's own words
    int limit = 0;       // the limit reached: lights, shadowed lights, mirror depth, mirror views

    // A shadow pass.
    int mapSize = 0;
    int pcf = 1;
    std::size_t casters = 0;
    std::optional<int> cubeFacesWithCasters{}; // a point light's cube map; none: a 2D map

    // The main pass.
    std::size_t objects = 0;
    std::size_t lights = 0;
    bool preWeighted = false; // FramePlan::preWeighted

    // The guides pass: how many lines it draws.
    std::size_t lines = 0;

    // A mirror's passes.
    bool roughStencil = false; // a rough stencil mirror, drawn into a texture to be filtered
    double reflectivity = 1.0;
    double roughness = 0.0; // also the reflector's, for its pre-filter
    int glossyTaps = 0;     // a rough mirror's filter: taps a pixel over the GGX footprint; 0: one mip level
    bool glossyChain = false; // … or the convolved chain, four lookups a pixel
    std::string chainInstead; // why the planner chose the chain over the settings' taps; empty: they ask it
    // A screen-space mirror seen inside another mirror, drawn with the texture technique: the camera's
    // image holds nothing of that mirror's reflected view to trace.
    bool screenSpaceAsTexture = false;
    // A screen-space mirror's trace falls back to the reflector's map (named in `node`), not the background.
    bool screenFallsBackToMap = false;
    // A depth pyramid drawn after the screen-space mirrors, for the reflector's trace: it holds their
    // surfaces too, which the mirrors' own pyramid leaves out.
    bool screenSpaceMirrorsInDepth = false;

    // The environment map's pass.
    // Not seen, but the screen-space mirrors named here read it where their rays find nothing on screen.
    std::string screenSpaceFallbackOf{};
    ReflectorMap map = ReflectorMap::Cube;
    ReflectorFill fill = ReflectorFill::Resampled;
    int resolution = 0;
    std::optional<int> mapMirrorDepth{}; // how deep planar mirrors reflect in the map; none: no mirrors
    // Not seen, but in the map of the reflector named here, which draws it with its map (bounces).
    std::string seenInMapOf{};
    // The bounce this drawing of the map is, of how many (Settings::reflectorBounces as planned), and the
    // other reflectors it draws (0 with bounces: drawn with their plain material).
    int bounce = 0;
    int bounces = 0;
    int otherReflectors = 0;
    // A time-sliced update: the face (or direct-fill part) it redraws, how many faces the map has, how many
    // others still show an older scene, and how many updates ago the oldest of those was drawn.
    std::string slicedFace{};
    int mapFaces = 0;
    int staleFaces = 0;
    int oldestSlice = 0;

    // The pre-filtered chain (and the map's mip chain, for the mip filter).
    int levels = 0;
    int samples = 0;

    // A preview's skips: what the scene asks for where the preview draws less (mirror levels, shadow map
    // texels), its fraction of the output's width and height, and the reflector's update it holds.
    int asked = 0;
    double scale = 1.0;
    ReflectorUpdate update = ReflectorUpdate::OnChange;

    // Mirror and environment map passes: the big meshes they draw simplified, or whole.
    std::vector<ReflectedMesh> bigMeshes{};
};

// The sentence `explain`, the editor's Render Passes panel and the timing tools show for a code.
std::string formatReason(PlanReason code, const ReasonDetails& details);

} // namespace speculum::render
