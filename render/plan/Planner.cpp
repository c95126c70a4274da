#include "render/plan/Planner.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/frame/SceneNames.hpp"
#include "render/math/Projection.hpp"
#include "render/math/ShadowFrustum.hpp"
#include "render/mesh/Simplify.hpp"
#include "render/plan/FrameHashing.hpp"
#include "render/plan/MapCost.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <functional>
#include <optional>

namespace speculum::render {

std::string_view toString(PassKind kind) {
    switch (kind) {
    case PassKind::Shadow:
        return "shadow";
    case PassKind::MirrorMask:
        return "mirror-mask";
    case PassKind::Mirror:
        return "mirror";
    case PassKind::MirrorSurface:
        return "mirror-surface";
    case PassKind::Envmap:
        return "envmap";
    case PassKind::Prefilter:
        return "prefilter";
    case PassKind::Main:
        return "main";
    case PassKind::Guides:
        return "guides";
    case PassKind::Composite:
        return "composite";
    case PassKind::ScreenDepth:
        return "screen-depth";
    case PassKind::ScreenColour:
        return "screen-colour";
    case PassKind::ReflectorTrace:
        return "reflector-trace";
    }
    return "unknown";
}

std::string_view toString(PassTarget target) {
    switch (target) {
    case PassTarget::OwnMap:
        return "own-map";
    case PassTarget::Linear:
        return "linear";
    case PassTarget::Reflection:
        return "reflection";
    case PassTarget::Output:
        return "output";
    }
    return "unknown";
}

const ShadowPlan* FramePlan::shadowOf(int lightIndex) const {
    for (const ShadowPlan& shadow : shadows)
        if (shadow.light == lightIndex)
            return &shadow;
    return nullptr;
}

int FramePlan::reflectorResolution(int index) const {
    return index >= 0 && static_cast<std::size_t>(index) < reflectorResolutions.size()
               ? reflectorResolutions[static_cast<std::size_t>(index)]
               : 0;
}

const ReflectorMapState& PlannerState::mapOf(int index) const {
    static const ReflectorMapState none;
    return index >= 0 && static_cast<std::size_t>(index) < reflectorMaps.size()
               ? reflectorMaps[static_cast<std::size_t>(index)]
               : none;
}

ReflectorMapState& PlannerState::mapOf(int index) {
    const auto i = static_cast<std::size_t>(std::max(index, 0));
    if (reflectorMaps.size() <= i)
        reflectorMaps.resize(i + 1);
    return reflectorMaps[i];
}

namespace {

// A stencil mirror whose blend keeps the camera's colour buffer in half float: the composite's reason.
struct BlendingMirror {
    PlanReason code = PlanReason::CompositeStencilBlend;
    std::string name;
};

// Why the camera's colour buffer must keep radiance above 1 (none: it need not). A stencil mirror drawn
// there blends its surface onto the reflection it drew (reflection × weight + surface): a reflected
// highlight brighter than 1 must not be clamped before it is weighted. A perfect, untinted mirror's blend
// multiplies by one and changes nothing.
std::optional<BlendingMirror> blendOntoRadiance(const FrameInput& input,
                                                const std::vector<MirrorView>& views) {
    // A screen-space mirror reads the camera's colour as its reflection: in linear light, with highlights
    // above 1 kept, as a texture mirror's own view would hold them.
    for (const MirrorView& view : views)
        if (view.screenSpace)
            return BlendingMirror{PlanReason::CompositeScreenSpace,
                                  input.mirrors[static_cast<std::size_t>(view.mirror)].name};
    for (const MirrorView& view : views) {
        if (view.ownTarget || view.textureSlot >= 0)
            continue;
        const Mirror& mirror = input.mirrors[static_cast<std::size_t>(view.mirror)];
        if (mirror.reflectivity >= 1.0 && mirror.tint == glm::dvec3(1.0))
            continue;
        return BlendingMirror{PlanReason::CompositeStencilBlend, mirror.name};
    }
    return std::nullopt;
}

// Gives every view drawn into the camera's buffer the weight its scene is kept with (the stencil mirrors'
// reflectivity × tint, multiplied down the nesting), so that the 8-bit buffer can hold its stencil
// mirrors. Returns why it cannot, leaving every weight 1; none when the weights are set. It cannot where
// a Fresnel term makes a weight vary over the mirror, or where a stencil mirror that adds its surface is
// seen in another that does: each surface added rounds the pixel to 8 bits once more, and the image
// would no longer be within one step of the half-float one.
std::optional<BlendingMirror> preWeightStencilMirrors(const FrameInput& input, FramePlan& plan) {
    std::vector<int> surfacesAdded(plan.views.size(), 0); // stencil surfaces added, down to each view
    for (std::size_t v = 0; v < plan.views.size(); ++v) {
        const MirrorView& view = plan.views[v];
        if (view.ownTarget || view.textureSlot >= 0)
            continue;
        const Mirror& mirror = input.mirrors[static_cast<std::size_t>(view.mirror)];
        const bool addsSurface = !(mirror.reflectivity >= 1.0);
        if (mirror.fresnel && addsSurface)
            return BlendingMirror{PlanReason::CompositeFresnelBlend, mirror.name};
        const int above = view.parent < 0 ? 0 : surfacesAdded[static_cast<std::size_t>(view.parent)];
        surfacesAdded[v] = above + (addsSurface ? 1 : 0);
        if (surfacesAdded[v] > 1)
            return BlendingMirror{PlanReason::CompositeNestedBlend, mirror.name};
    }
    // Parents come before their children in plan.views.
    for (MirrorView& view : plan.views) {
        if (view.ownTarget || view.textureSlot >= 0)
            continue;
        const Mirror& mirror = input.mirrors[static_cast<std::size_t>(view.mirror)];
        const glm::dvec3 parent =
            view.parent < 0 ? glm::dvec3(1.0) : plan.views[static_cast<std::size_t>(view.parent)].weight;
        view.weight = parent * std::clamp(mirror.reflectivity, 0.0, 1.0) * mirror.tint;
    }
    return std::nullopt;
}

// Big meshes in reflected views: which items the mirror and environment passes draw at their simplified
// level, said in those passes' reasons (or, with settings.simplifyReflections off, that they draw them
// whole, and what that costs in triangles).
void planReflectedDetail(const FrameInput& input, FramePlan& plan) {
    const bool reflected = std::any_of(plan.passes.begin(), plan.passes.end(), [](const PlannedPass& p) {
        return p.kind == PassKind::Mirror || p.kind == PassKind::Envmap;
    });
    if (!reflected)
        return;
    std::vector<ReflectedMesh> bigMeshes;
    std::vector<bool> coarse(input.items.size(), false);
    for (std::size_t i = 0; i < input.items.size(); ++i) {
        const DrawItem& item = input.items[i];
        if (!item.mesh)
            continue;
        // A level may come with a mesh of any size (set before it was frozen); others are built for big
        // meshes only.
        const CoarseLevel* level = item.mesh->coarse.ready();
        if (!level && !wantsCoarseLevel(*item.mesh))
            continue;
        if (level && level->indices.empty())
            continue; // simplifying gained too little: drawn whole, like any small mesh
        ReflectedMesh big{item.name, item.mesh->triangleCount()};
        if (input.settings.simplifyReflections && level) {
            coarse[i] = true;
            big.simplifiedTriangles = level->triangleCount();
            big.simplificationError = double(level->error);
        } else if (input.settings.simplifyReflections) {
            big.simplifying = true;
            if (std::find(plan.coarseLevelsWanted.begin(), plan.coarseLevelsWanted.end(), item.mesh) ==
                plan.coarseLevelsWanted.end())
                plan.coarseLevelsWanted.push_back(item.mesh);
        }
        bigMeshes.push_back(std::move(big));
    }
    if (std::find(coarse.begin(), coarse.end(), true) != coarse.end())
        plan.coarseItems = std::move(coarse);
    for (PlannedPass& pass : plan.passes)
        if (pass.kind == PassKind::Mirror || pass.kind == PassKind::Envmap)
            pass.details.bigMeshes = bigMeshes;
}

std::string lightLabel(const Light& light, int index) {
    return light.name.empty() ? "light " + std::to_string(index) : light.name;
}

} // namespace

glm::dmat4 cameraProjection(const FrameInput& input, const PlanViewport& viewport) {
    const double aspect = double(std::max(viewport.width, 1)) / double(std::max(viewport.height, 1));
    const glm::dmat4 projection =
        math::perspective(input.camera.fovY, aspect, input.camera.near, input.camera.far);
    return math::jitter(projection, viewport.jitterPixels.x, viewport.jitterPixels.y,
                        std::max(viewport.width, 1), std::max(viewport.height, 1));
}

namespace {

// The one definition of the shadow signature, for a map of `mapSize` texels a side; `frustum` null: the
// scene has nothing to receive a shadow.
std::uint64_t hashShadow(const FrameInput& input, int lightIndex, const math::ShadowFrustum* frustum,
                         int mapSize) {
    const Light& light = input.lights.at(static_cast<std::size_t>(lightIndex));
    Hasher h;
    h.add(light.type);
    h.add(light.position);
    h.add(light.direction);
    h.add(light.spotAngle);
    h.add(mapSize);
    if (frustum) {
        for (const auto& m : frustum->viewProjection)
            h.add(m);
        h.add(frustum->faceMask);
    }
    for (const DrawItem& item : input.items) {
        if (!item.castsShadows || !item.mesh)
            continue;
        h.add(item.mesh.get());
        h.add(item.world);
        addShadowAlpha(h, item.material); // masked casters cut holes into their shadows
    }
    for (const Reflector& reflector : input.reflectors) {
        h.add(reflector.mesh.get());
        h.add(reflector.world);
    }
    return h.value;
}

} // namespace

std::uint64_t shadowSignature(const FrameInput& input, int lightIndex, const math::ShadowFrustum& frustum) {
    const Light& light = input.lights.at(static_cast<std::size_t>(lightIndex));
    return hashShadow(input, lightIndex, &frustum, light.shadows->mapSize);
}

std::uint64_t shadowSignature(const FrameInput& input, int lightIndex) {
    const Light& light = input.lights.at(static_cast<std::size_t>(lightIndex));
    const auto frustum = math::shadowFrustum(input, light, light.shadows->mapSize);
    return hashShadow(input, lightIndex, frustum ? &*frustum : nullptr, light.shadows->mapSize);
}

namespace {

// What a shadow map draws: the items that cast shadows, and the reflectors.
std::size_t countShadowCasters(const FrameInput& input) {
    std::size_t casters = 0;
    for (const DrawItem& item : input.items)
        if (item.castsShadows && item.mesh)
            ++casters;
    for (const Reflector& reflector : input.reflectors)
        if (reflector.mesh)
            ++casters;
    return casters;
}

// What a light's shadow pass says it draws: its map (at the size it is drawn at), its casters, and whether a
// map was drawn for it before.
void explainShadowPass(const Light& light, int mapSize, std::size_t casters,
                       const math::ShadowFrustum& frustum, bool firstMap, PlannedPass& pass) {
    pass.code = firstMap ? PlanReason::ShadowFirstMap : PlanReason::ShadowChanged;
    pass.details.mapSize = mapSize;
    pass.details.pcf = light.shadows->pcf;
    pass.details.casters = casters;
    if (frustum.cube)
        pass.details.cubeFacesWithCasters = std::popcount(frustum.faceMask);
}

// The size a preview draws a light's shadow map at (PreviewPolicy::redrawsShadows): a power of two less per
// halving of the preview's scale, never under kMinPreviewShadowMapSize nor above the light's own.
int previewShadowMapSize(int size, const PreviewPolicy& preview) {
    if (!preview.active() || !preview.redrawsShadows)
        return size;
    int shrunk = size;
    for (double s = preview.scale; s <= 0.5 && shrunk > kMinPreviewShadowMapSize; s *= 2.0)
        shrunk /= 2;
    return std::min(size, std::max(shrunk, kMinPreviewShadowMapSize));
}

// The size a light's map is drawn at (see fitShadowMapSize, previewShadowMapSize); 0 where none fits, the
// light then skipped. A preview's smaller map is said among the skips.
int plannedShadowMapSize(const Light& light, int index, const MapLimits& limits, FramePlan& plan) {
    const std::string name = lightLabel(light, index);
    const int own = light.shadows->mapSize;
    const int asked = previewShadowMapSize(own, plan.preview);
    const int size = fitShadowMapSize(light, index, asked, limits, plan.warnings);
    if (size == 0)
        plan.skipped.push_back({name, PlanReason::ShadowMapDoesNotFit});
    else if (asked < own)
        plan.skipped.push_back({name, PlanReason::PreviewShadowMapSize, {.mapSize = size, .asked = own}});
    return size;
}

// The shadow maps of the lights that cast shadows (at most kMaxShadowedLights), each redrawn only when its
// signature changed; every light without one is skipped with the reason.
void planShadows(const FrameInput& input, const PlannerState& state, const MapLimits& limits,
                 FramePlan& plan) {
    const std::size_t casters = countShadowCasters(input);
    int shadowSlots = 0;
    const int lightCount = static_cast<int>(input.lights.size());
    for (int i = 0; i < lightCount; ++i) {
        const Light& light = input.lights[static_cast<std::size_t>(i)];
        const std::string name = lightLabel(light, i);
        if (i >= kMaxLights) {
            plan.skipped.push_back({name, PlanReason::LightLimit, {.limit = kMaxLights}});
            continue;
        }
        if (!light.shadows.has_value()) {
            plan.skipped.push_back({name, PlanReason::ShadowsOff});
            continue;
        }
        if (casters == 0) {
            plan.skipped.push_back({name, PlanReason::NoShadowCasters});
            continue;
        }
        if (shadowSlots >= kMaxShadowedLights) {
            plan.skipped.push_back({name, PlanReason::ShadowedLightLimit, {.limit = kMaxShadowedLights}});
            continue;
        }
        const int mapSize = plannedShadowMapSize(light, i, limits, plan);
        if (mapSize == 0)
            continue;
        // The one frustum of this light's map this frame, at the size the map is drawn at: the signature,
        // the shadow pass and every lookup use it.
        const auto frustum = math::shadowFrustum(input, light, mapSize);
        if (!frustum) {
            plan.skipped.push_back({name, PlanReason::NoShadowReceivers});
            continue;
        }
        ++shadowSlots;
        plan.shadowedLights.push_back(i);
        const auto previous = state.shadowSignatures.find(i);
        const std::uint64_t signature = hashShadow(input, i, &*frustum, mapSize);
        const bool reused = previous != state.shadowSignatures.end() && previous->second == signature;
        plan.shadows.push_back({i, mapSize, light.shadows->pcf, *frustum, signature, !reused});
        if (reused) {
            plan.skipped.push_back({name, PlanReason::ShadowMapReused});
            continue;
        }
        PlannedPass pass;
        pass.kind = PassKind::Shadow;
        pass.target = name;
        explainShadowPass(light, mapSize, casters, *frustum, previous == state.shadowSignatures.end(), pass);
        pass.lightIndex = i;
        pass.signature = signature;
        plan.passes.push_back(std::move(pass));
    }
}

PlannedPass mainPass(const FrameInput& input) {
    PlannedPass main;
    main.kind = PassKind::Main;
    main.code = PlanReason::MainHalfFloat; // until planCameraBuffer chooses the buffer
    main.details.objects = input.items.size() + input.mirrors.size() + input.reflectors.size();
    main.details.lights = std::min<std::size_t>(input.lights.size(), kMaxLights);
    return main;
}

// The editor's guide lines, over the camera's view and the mirrors in it: after their passes, so that they
// test against the depth those leave (the mirrors' surfaces, not their reflections), and never inside one.
PlannedPass guidesPass(std::size_t lines) {
    PlannedPass guides;
    guides.kind = PassKind::Guides;
    guides.code = PlanReason::GuidesOverView;
    guides.details.lines = lines;
    return guides;
}

// The camera's colour buffer (8-bit sRGB where no blend needs radiance above 1, pre-weighting the stencil
// mirrors where that makes it so; half float otherwise), said in the main pass's reason, and the
// composite pass that brings it to the output unless it is the output's own buffer. Needs the mirror
// views and the main pass planned.
void planCameraBuffer(const FrameInput& input, const PlanViewport& viewport, FramePlan& plan) {
    std::optional<BlendingMirror> blend = blendOntoRadiance(input, plan.views);
    // The reflector's trace reads the camera's colour too, and adds to it a difference that may be
    // negative.
    const auto trace = std::find_if(plan.passes.begin(), plan.passes.end(),
                                    [](const PlannedPass& p) { return p.kind == PassKind::ReflectorTrace; });
    if (trace != plan.passes.end() && (!blend || blend->code != PlanReason::CompositeScreenSpace))
        blend = BlendingMirror{PlanReason::CompositeScreenSpace, trace->target};
    if (viewport.eightBitOutput && blend && blend->code != PlanReason::CompositeScreenSpace) {
        blend = preWeightStencilMirrors(input, plan);
        plan.preWeighted = !blend;
    }
    plan.cameraBuffer = viewport.eightBitOutput && !blend ? CameraBuffer::Srgb8 : CameraBuffer::HalfFloat;
    PlannedPass& mainPass = *std::find_if(plan.passes.begin(), plan.passes.end(),
                                          [](const PlannedPass& p) { return p.kind == PassKind::Main; });
    mainPass.details.preWeighted = plan.preWeighted;
    PlannedPass composite;
    composite.kind = PassKind::Composite;
    if (plan.cameraBuffer == CameraBuffer::Srgb8 && viewport.outputTakesCameraBuffer) {
        plan.cameraBufferIsOutput = true;
        mainPass.code = PlanReason::MainIntoOutput;
        plan.skipped.push_back({"output", PlanReason::CompositeNotNeeded});
    } else if (plan.cameraBuffer == CameraBuffer::Srgb8) {
        mainPass.code = PlanReason::MainSrgb;
        composite.code = PlanReason::CompositeCopiesSrgb;
    } else if (viewport.eightBitOutput) { // a blend keeps the buffer in half float
        mainPass.code = PlanReason::MainHalfFloat;
        composite.code = blend->code;
        composite.details.node = blend->name;
    } else {
        mainPass.code = PlanReason::MainHalfFloat;
        composite.code = PlanReason::CompositeToFloat;
    }
    if (!plan.cameraBufferIsOutput)
        plan.passes.push_back(std::move(composite));
}

// Levels of mirror nesting a preview leaves: `depth` less its cut, but never less than one level.
int previewMirrorDepth(int depth, const PreviewPolicy& preview) {
    if (!preview.active())
        return depth;
    return depth - std::clamp(preview.mirrorDepthCut, 0, std::max(0, depth - 1));
}

// What a preview gives up of the whole frame, among the skips: pixels, and levels of mirror nesting. (Its
// smaller shadow maps and the environment map it holds are said with those.)
void notePreview(const FrameInput& input, FramePlan& plan) {
    const PreviewPolicy& preview = plan.preview;
    if (!preview.active())
        return;
    if (preview.scale < 1.0)
        plan.skipped.push_back(
            {"output", PlanReason::PreviewScaled, {.scale = std::max(preview.scale, kMinResolutionScale)}});
    if (plan.mirrorDepth < input.settings.mirrorDepth && !input.mirrors.empty())
        plan.skipped.push_back({"",
                                PlanReason::PreviewMirrorDepth,
                                {.limit = plan.mirrorDepth, .asked = input.settings.mirrorDepth}});
}

// A capped map keeps at least this resolution before its samples are lowered (a rough reflection shows
// little of a finer map, and fewer samples are noise), and at least the least of each in the end.
constexpr int kCappedResolutionFirst = 256;
constexpr int kLeastCappedResolution = 64;
constexpr int kLeastCappedSamples = 8;

// Lowers the map's resolution (to kCappedResolutionFirst), then its pre-filter samples, then its
// resolution again, by halves, until drawing it fits within `seconds` or both reach their least.
void capMap(const Reflector& reflector, const Settings& settings, double seconds, int& resolution,
            int& samples) {
    const auto fits = [&] {
        return mapCost(reflector, resolution, settings, samples).softwareSeconds() <= seconds;
    };
    while (!fits() && resolution > kCappedResolutionFirst)
        resolution = std::max(kCappedResolutionFirst, resolution / 2);
    while (!fits() && samples > kLeastCappedSamples)
        samples = std::max(kLeastCappedSamples, samples / 2);
    while (!fits() && resolution > kLeastCappedResolution)
        resolution = std::max(kLeastCappedResolution, resolution / 2);
}

// What drawing reflector `index`'s map costs, said before the work: a map that would take minutes on a
// software renderer is warned of, with the estimate; where the view must stay interactive (maxSeconds,
// this map's share of the frame's) it is drawn smaller and with fewer pre-filter samples instead, and the
// warning says so.
void planMapCost(const FrameInput& input, int index, double maxSeconds, FramePlan& plan) {
    const Reflector& reflector = input.reflectors[static_cast<std::size_t>(index)];
    int& planned = plan.reflectorResolutions[static_cast<std::size_t>(index)];
    const int asked = planned;
    const int samples = input.settings.prefilterSamples;
    const MapCost full = mapCost(reflector, asked, input.settings, samples);
    const std::string name = "reflector \"" + reflector.name + "\"";
    const std::string what =
        "its " + std::to_string(asked) + "² " +
        std::string(names::fileName(names::kReflectorMaps, reflector.map)) + " map" +
        (full.prefilterSamples > 0.0 ? " pre-filtered with " + std::to_string(samples) + " samples a texel"
                                     : std::string());
    const std::string often =
        reflector.update == ReflectorUpdate::Always ? ", every frame (update: always)"
        : reflector.update == ReflectorUpdate::TimeSliced
            ? ", spread a face a frame over the frames after a change (update: time-sliced)"
            : ", whenever what it shows changes";
    if (maxSeconds > 0.0 && full.softwareSeconds() > maxSeconds) {
        int resolution = asked, fewer = samples;
        capMap(reflector, input.settings, maxSeconds, resolution, fewer);
        planned = resolution;
        if (fewer != samples)
            plan.prefilterSamples =
                plan.prefilterSamples > 0 ? std::min(plan.prefilterSamples, fewer) : fewer;
        plan.warnings.push_back(name + ": drawn at " + std::to_string(resolution) + "² with " +
                                std::to_string(fewer) + " pre-filter samples while editing; " + what +
                                " is " + costText(full) + often +
                                "; Export Still and `speculum render` draw it in full");
        return;
    }
    if (full.softwareSeconds() > kMapCostWarningSeconds) {
        plan.warnings.push_back(name + ": " + what + " is " + costText(full) + often +
                                "; a lower resolution or fewer pre-filter samples cost far less");
    }
}

} // namespace

std::optional<FrameInput> plannedInput(const FrameInput& input, const FramePlan& plan) {
    auto differs = [&](const ShadowPlan& shadow) {
        const Light& light = input.lights[static_cast<std::size_t>(shadow.light)];
        return light.shadows->mapSize != shadow.mapSize;
    };
    const bool shadows = std::any_of(plan.shadows.begin(), plan.shadows.end(), differs);
    bool reflector = false;
    for (std::size_t i = 0; i < input.reflectors.size(); ++i) {
        const int resolution = plan.reflectorResolution(static_cast<int>(i));
        reflector = reflector || (resolution > 0 && input.reflectors[i].resolution != resolution);
    }
    const bool mirrors = input.settings.mirrorDepth != plan.mirrorDepth;
    const bool samples =
        plan.prefilterSamples > 0 && plan.prefilterSamples != input.settings.prefilterSamples;
    if (!shadows && !reflector && !mirrors && !samples)
        return std::nullopt;
    FrameInput planned = input;
    for (const ShadowPlan& shadow : plan.shadows)
        planned.lights[static_cast<std::size_t>(shadow.light)].shadows->mapSize = shadow.mapSize;
    for (std::size_t i = 0; i < planned.reflectors.size(); ++i)
        if (const int resolution = plan.reflectorResolution(static_cast<int>(i)); resolution > 0)
            planned.reflectors[i].resolution = resolution;
    planned.settings.mirrorDepth = plan.mirrorDepth;
    if (samples)
        planned.settings.prefilterSamples = plan.prefilterSamples;
    return planned;
}

FramePlan planFrame(const FrameInput& input, const PlannerState& state, const PlanViewport& viewport,
                    const PlanOptions& options) {
    FramePlan plan;
    plan.preview = options.preview;
    planShadows(input, state, options.maps, plan);
    // An interactive view's time for maps is shared among the reflectors and the bounces each is drawn at.
    const int drawings = static_cast<int>(input.reflectors.size()) *
                         (1 + (input.reflectors.size() > 1
                                   ? std::clamp(input.settings.reflectorBounces, 0, kMaxReflectorBounces)
                                   : 0));
    const double mapSeconds = drawings == 0 ? 0.0 : options.maxMapSeconds / static_cast<double>(drawings);
    for (std::size_t i = 0; i < input.reflectors.size(); ++i) {
        plan.reflectorResolutions.push_back(
            fitEnvmapResolution(input.reflectors[i], options.maps, plan.warnings));
        planMapCost(input, static_cast<int>(i), mapSeconds, plan);
    }
    plan.mirrorDepth = previewMirrorDepth(input.settings.mirrorDepth, plan.preview);
    // The rest is planned for the scene as it is drawn: its map sizes and mirror depth as just planned.
    const std::optional<FrameInput> planned = plannedInput(input, plan);
    const FrameInput& scene = planned ? *planned : input;

    // Mirror views are planned first (their passes run after the main pass): the environment pass, which
    // runs before the main pass, is needed only if the reflector is seen directly or in one of them.
    FramePlan mirrors;
    planMirrors(scene, viewport, mirrors);
    planReflectors(scene, state, viewport, mirrors, plan);

    plan.passes.push_back(mainPass(scene));

    // The mirror passes keep their view indices: plan.views is empty until here.
    plan.views = std::move(mirrors.views);
    for (PlannedPass& pass : mirrors.passes)
        plan.passes.push_back(std::move(pass));
    for (SkippedEffect& skip : mirrors.skipped)
        plan.skipped.push_back(std::move(skip));

    planReflectorTraces(scene, viewport, plan);
    if (options.guideLines > 0)
        plan.passes.push_back(guidesPass(options.guideLines));
    planCameraBuffer(scene, viewport, plan);
    planReflectedDetail(scene, plan);
    notePreview(input, plan);
    declareWrites(scene, plan);
    return plan;
}

} // namespace speculum::render
