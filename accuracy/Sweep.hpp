#pragma once

#include "accuracy/Variation.hpp"
#include "render/frame/FrameInput.hpp"

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace speculum::accuracy {

// The families of settings the bench sweeps, one at a time around the scene's own settings.
enum class Family {
    Scene,           // the scene exactly as saved: the anchor every family is compared with
    Envmap,          // reflector map type (and fill, for the non-linear maps) × resolution
    Parallax,        // reflector parallax correction off / on
    MirrorTechnique, // every planar mirror with the stencil, then the texture technique
    MirrorDepth,     // settings.mirrorDepth 1 .. cap
    Shadows,         // PCF kernel of every shadowed light
    Tessellation,    // tessellation of the built-in teapots
    ReflectedDetail, // big meshes in reflections: drawn whole, then at their simplified level
    Glossy,          // rough surfaces at roughness 0.1, 0.3, 0.6: each raster approximation and quality
    ScreenSpace,     // every planar mirror traced in screen space (steps, thickness, resolution, fallback)
                     // beside the stencil and texture techniques
    Setting,         // a declared field with sweep values of its own (FieldSpec::sweep), one series each
    Bounces,         // settings.reflectorBounces 0 .. 3, where the scene has reflectors that see each other
    Update,          // every reflector's map redrawn every frame, then time-sliced, while the scene moves
};

// Stable names, used in file names, CSV and JSON: "envmap", "mirror-depth", ...
std::string familyName(Family family);
std::optional<Family> familyFromName(const std::string& name); // none for a name this version lacks

// Which exact image a configuration is measured against. The tracer does not depend on map type,
// resolution, fill, parallax or mirror technique, so those share the scene's reference; the settings it
// does depend on get a reference of their own (see referenceDescription).
enum class ReferenceKind {
    Scene,       // the scene as saved; shadows with each light's PCF footprint
    HardShadows, // exact hard shadows (one shadow ray): what every PCF kernel approximates
    DeepMirrors, // planar mirrors recursing to depth 16 (the file format's maximum)
    FineMesh,    // built-in teapots at tessellation 64 (the file format's maximum)
    // The scene with every rough surface at one of kGlossyRoughness, the GGX lobe integrated by the
    // tracer's importance sampling.
    RoughLow,
    RoughMid,
    RoughHigh,
    // The scene as it stands after the update family's played frames (SweepInput::playedFrames).
    Played,
};

// Frames the update family plays, 1/60 s apart (as the editor plays an animation), before the frame it
// measures: enough for a time-sliced cube map to go round its six faces twice.
inline constexpr int kPlayedFrames = 12;

// The roughness each Rough* reference (and the glossy family's rows against it) gives the rough surfaces.
inline constexpr double kGlossyRoughness[3] = {0.1, 0.3, 0.6};
std::optional<double> referenceRoughness(ReferenceKind kind); // none for the other kinds

std::string referenceName(ReferenceKind kind); // "scene", "hard-shadows", "deep-mirrors", "fine-mesh"
std::optional<ReferenceKind> referenceFromName(const std::string& name);
std::string referenceDescription(ReferenceKind kind);

struct Configuration {
    Family family = Family::Scene;
    std::string id;     // unique and safe as a file name: "envmap-cube-128"
    std::string label;  // short, for plot labels: "128", "pcf 5"
    std::string series; // points of one series are joined in the plots: "cube", "tennis-ball direct"
    Variation variation;
    ReferenceKind reference = ReferenceKind::Scene;
};

// What the sweep knows about the scene, derived from its frame.
struct SceneTraits {
    bool reflector = false;
    std::size_t reflectors = 0;                  // reflectors with a mesh
    bool moves = false;                          // the caller played frames in which the scene moves
    bool ownProxy = false;                       // the scene's reflector has a parallax proxy of its own
    std::optional<render::ParallaxParams> proxy; // what "parallax on" uses: its own, or sceneProxy()
    bool proxyMakesSense = false;                // own, or the scene's bounds enclose the reflector
    std::size_t mirrors = 0;
    std::size_t shadowedLights = 0;        // lights with shadows on
    std::optional<int> teapotTessellation; // of the (first) built-in teapot
    // Meshes big enough for a simplified level (MeshData::coarse) in a scene with something that reflects
    // them.
    std::size_t simplifiableMeshes = 0;
    std::size_t roughMirrors = 0; // planar mirrors with roughness above 0
    bool roughReflector = false;
};

SceneTraits sceneTraits(const render::FrameInput& scene, const std::optional<int>& teapotTessellation);

struct SweepOptions {
    bool quick = false;
};

// The configurations to measure: the scene's own first, then each family the scene calls for, varied one
// at a time around the scene's settings (a scene without a reflector gets no map rows, and so on). The
// scene's own value of each swept setting is always among the values.
std::vector<Configuration> planSweep(const render::FrameInput& scene, const SceneTraits& traits,
                                     const SweepOptions& options);

// The frame each reference traces: the scene, changed as the reference kind says.
render::FrameInput referenceInput(const render::FrameInput& scene, ReferenceKind kind,
                                  const TessellateTeapot& tessellate);

std::string mapName(render::ReflectorMap map);    // "cube", "dual-paraboloid", "tennis-ball"
std::string fillName(render::ReflectorFill fill); // "direct", "resampled"

} // namespace speculum::accuracy
