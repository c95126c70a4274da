#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/plan/FramePlan.hpp"
#include "render/plan/GpuLimits.hpp"
#include "render/plan/RenderOptions.hpp"

#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace speculum::render {

// What the renderer kept of one reflector's environment map, as far as planning is concerned.
struct ReflectorMapState {
    // The reflector the map was drawn for (its name): a reflector deleted before it leaves its record to
    // the next, which must not take the map for its own.
    std::string reflector;
    // The map, once rendered: the signature of what it saw (envmapSignature) and of the settings it was
    // made with (envmapSettingsKey).
    std::optional<std::uint64_t> signature;
    std::optional<std::uint64_t> settings;
    // Each face (or direct-fill component) of the map, by EnvmapFace::index: the signature of what it was
    // last drawn with, and the update it was drawn in; `updates` counts the map's updates. A time-sliced
    // map redraws the faces whose signature is not the scene's.
    std::vector<std::uint64_t> faceSignatures;
    std::vector<std::uint64_t> faceUpdates;
    std::uint64_t updates = 0;
    // The GGX pre-filtered chain, once filtered: prefilterKey of the map and samples it holds.
    std::optional<std::uint64_t> prefilterKey;
};

// What the renderer kept from earlier frames, as far as planning is concerned.
struct PlannerState {
    // Signature of the contents of each light's shadow map (by index into FrameInput::lights).
    std::unordered_map<int, std::uint64_t> shadowSignatures;
    // Each reflector's map, by index into FrameInput::reflectors (shorter: the rest have none).
    std::vector<ReflectorMapState> reflectorMaps;

    // The record of reflector `index` (an empty one where there is none).
    const ReflectorMapState& mapOf(int index) const;
    ReflectorMapState& mapOf(int index); // grows the list to hold it
};

inline constexpr int kMaxLights = 8;
inline constexpr int kMaxShadowedLights = 4;
// Mirror views in one frame, all depths together: facing mirrors at depth 16 stay bounded.
inline constexpr int kMaxMirrorViews = 64;
// Nesting levels the 8-bit stencil buffer can tell apart.
inline constexpr int kStencilLevels = 255;
// Geometry closer than this (world units) to a mirror's plane is not reflected: a constant world
// distance, not a depth bias, so it means the same near and far from the camera.
inline constexpr double kMirrorClipOffset = 1e-4;

// The target the frame is planned for: mirror coverage is measured in its pixels.
struct PlanViewport {
    int width = 1;
    int height = 1;
    glm::dvec2 jitterPixels{0.0};
    // The output holds 8-bit sRGB (a window's framebuffer): the camera's view may be drawn into an 8-bit
    // sRGB buffer when nothing blends onto radiance above 1 there (FramePlan::cameraBuffer).
    bool eightBitOutput = false;
    // The output itself can be that 8-bit sRGB buffer (RenderTarget::srgbDepthStencil, drawn at its size).
    bool outputTakesCameraBuffer = false;
};

// The camera's projection for this viewport (jittered) and its camera-relative view-projection.
glm::dmat4 cameraProjection(const FrameInput& input, const PlanViewport& viewport);

// Hash of everything a light's shadow map depends on: the light, its map settings, the frustum and
// every caster's mesh and transform. Equal signatures mean the old map can be reused.
std::uint64_t shadowSignature(const FrameInput& input, int lightIndex);
// The same, with the light's frustum already computed (math::shadowFrustum; any map size gives the same
// matrices and face mask, which is all the signature reads of it): the planner computes it once per light.
std::uint64_t shadowSignature(const FrameInput& input, int lightIndex, const math::ShadowFrustum& frustum);

// What a frame is planned within besides its scene, its target and what earlier frames left: the map sizes
// the GPU holds (its limits, and the sizes that failed to allocate before), and the preview it is.
struct PlanOptions {
    MapLimits maps;
    PreviewPolicy preview;
    // Guide lines the caller draws over the camera's view (RenderOptions::guides): a Guides pass draws them
    // after the mirrors, before the composite.
    std::size_t guideLines = 0;
    // A view that must stay interactive (the editor's): the reflector's map is drawn smaller and with
    // fewer pre-filter samples where drawing it would take longer than this on a software renderer
    // (MapCost), with a warning that says so. 0: drawn as the scene asks (stills, benchmarks).
    double maxMapSeconds = 0.0;
};

// The layout of a reflector's map type.
envmap::MapType mapTypeOf(ReflectorMap map);

// The pure planning step: which passes run this frame, in order, with the reason for each, which effects
// got no pass and why, and the size of every map, fitted to `options.maps` (with FramePlan::warnings where
// a size had to change). Needs no GL.
FramePlan planFrame(const FrameInput& input, const PlannerState& state, const PlanViewport& viewport = {},
                    const PlanOptions& options = {});

// The scene as `plan` draws it: `input` with each planned shadow map's size (ShadowPlan::mapSize), each
// reflector's resolution (FramePlan::reflectorResolutions) and the mirror depth (FramePlan::mirrorDepth)
// the planner chose; nothing where they are the scene's own. The planner plans this scene, and the
// renderer's executors draw it, so what they allocate and draw is what was planned.
std::optional<FrameInput> plannedInput(const FrameInput& input, const FramePlan& plan);

// How every pass of `plan` writes (PassWrites), from its kind and its view: the last step of planFrame,
// so the renderer binds, clears, scissors, stencils and winds each pass as the plan says. The
// environment map's own passes get their stencil level and winding (they draw into the map's faces).
void declareWrites(const FrameInput& input, FramePlan& plan);

// Where reflector `index`'s environment map is captured from (EnvmapCapture). Needs a reflector with a mesh.
EnvmapCapture envmapCapture(const FrameInput& input, int index);

// The faces (or direct-fill components) pass 1 draws for the reflector's map settings.
std::vector<EnvmapFace> envmapFaces(const Reflector& reflector, const EnvmapCapture& capture);

// Hash of the map's settings (type, resolution, fill): a change needs new textures and a new map.
std::uint64_t envmapSettingsKey(const Reflector& reflector);

// Hash of everything reflector `index`'s environment map sees, independent of the camera: the capture
// point, the map settings, background and ambient, every light, every object's mesh, transform and
// material, every mirror, every other reflector (with its map's settings, which bounces read).
// Animations change transforms, so they change it too. Equal signatures: the map can be reused.
std::uint64_t envmapSignature(const FrameInput& input, int index);

// Hash of what the reflector's GGX pre-filtered chain holds: the map it was filtered from (its signature and
// settings) and the samples a texel. Equal keys: the chain can be reused.
std::uint64_t prefilterKey(std::uint64_t envmapSignature, std::uint64_t envmapSettings, int samples);

// Records in `state` what map.reflector's map holds once `map` is drawn: the scene's signature in each face
// drawn, stamped with this update. A map drawn whole (its first, or after its settings changed) starts the
// record afresh. The envmap pass's executor calls it; tests play frames with it.
void recordEnvmap(const EnvmapPlan& map, PlannerState& state);

// Whether reflector `index`'s world bounds can be seen by the camera or in one of the mirror views planned
// in `plan` (its reflected frustum, with the oblique near plane, narrowed to the mirror's pixels).
// `seenIn` gets the mirror it is seen in, or nothing when it is seen directly.
bool reflectorVisible(const FrameInput& input, int index, const PlanViewport& viewport, const FramePlan& plan,
                      std::vector<std::string>* seenIn = nullptr);

// The reflector whose map screen-space mirrors read where their rays find nothing in the image
// (ScreenFallback::Map): the first with a mesh; -1 without one.
int probeReflector(const FrameInput& input);

// The environment-map part of planning: appends every reflector's Envmap passes to `plan`, bounce by bounce
// (or a skip with its reason), then the GGX pre-filter's pass (or a skip) of each rough one. `input` is the
// scene as planned (its reflectors at plan.reflectorResolutions, see plannedInput); a preview
// (plan.preview) holds the maps there are. `mirrors` holds the frame's mirror views, used for visibility.
void planReflectors(const FrameInput& input, const PlannerState& state, const PlanViewport& viewport,
                    const FramePlan& mirrors, FramePlan& plan);

// The reflectors traced in screen space first (ReflectorTechnique::ScreenSpace), after every mirror's
// passes: a sharp reflector seen directly gets the camera's depth pyramid (shared with the screen-space
// mirrors') and its trace pass; a rough one, or one seen only in mirrors, a skip that says why. Needs the
// mirror views in `plan` (plan.views) and the environment passes planned.
void planReflectorTraces(const FrameInput& input, const PlanViewport& viewport, FramePlan& plan);

// Tiled stills: makes `plan`, planned for the whole image `image`, draw only the pixels `tile` of it
// (GL window coordinates, y up) into a target of the tile's size. Every view's projection becomes the
// image's own restricted to the tile (math::tileProjection), its pixel rectangle (and every pass's
// scissor, PassWrites::scissor) is clipped to the tile and moved to the tile's origin, and the passes of
// mirror views without a pixel in the tile are dropped (they could only draw outside it). Whatever the
// planner decided (which mirrors are seen, to what depth, which cover under one pixel, whether the reflector
// is seen) was decided for the whole image, so every tile draws its pixels as an untiled frame would. Where a
// tile legitimately differs: the renderer's occlusion query sees only the tile, so a mirror hidden there is
// reported "fully occluded in this tile" (it has no pixel to draw in it either way); a blurred
// texture-technique mirror reads the mip chain of the tile's own reflection texture, so near tile borders its
// blur cannot reach past the tile; and float rounding of vertices in the tile's clip space can move an edge
// across a sample lying on it.
void restrictToTile(FramePlan& plan, const math::PixelRect& tile, const PlanViewport& image);

// The mirror part of planning: the views of every mirror seen directly or through other mirrors, and the
// passes that draw them, appended to `plan` in execution order (depth first).
void planMirrors(const FrameInput& input, const PlanViewport& viewport, FramePlan& plan);

// The same planner for an environment map: the mirror views (to map.reflector's own mirrorDepth, all
// with the stencil technique) seen from the capture point in each of map.faces, their passes and skips.
// Every view of a face is planned within that face: kMaxMirrorViews per face.
void planEnvmapMirrors(const FrameInput& input, EnvmapPlan& map);

} // namespace speculum::render
