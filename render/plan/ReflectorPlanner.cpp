// Plans the curved reflector's environment pass: whether the reflector can be seen at all (directly or in
// a planned mirror view), and whether its map must be rendered again under its update policy. The
// signature of what the map sees is camera-independent, so a camera moving around a static scene reuses
// the map.
#include "render/envmap/Layout.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/FrameHashing.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace speculum::render {

envmap::MapType mapTypeOf(ReflectorMap map) {
    switch (map) {
    case ReflectorMap::Cube:
        return envmap::MapType::Cube;
    case ReflectorMap::DualParaboloid:
        return envmap::MapType::DualParaboloid;
    case ReflectorMap::TennisBall:
        return envmap::MapType::TennisBall;
    case ReflectorMap::Octahedral:
        return envmap::MapType::Octahedral;
    }
    return envmap::MapType::Cube;
}

namespace {

// True if all eight corners lie on the negative side of one of the planes (clip-space rows): the box is
// outside. Conservative: a box near a frustum edge may be reported inside.
bool boxOutside(const std::array<glm::dvec4, 8>& clip, const std::vector<glm::dvec4>& planes) {
    for (const glm::dvec4& plane : planes) {
        bool allOut = true;
        for (const glm::dvec4& c : clip)
            if (glm::dot(plane, c) >= 0.0) {
                allOut = false;
                break;
            }
        if (allOut)
            return true;
    }
    return false;
}

// The frustum planes of clip space, narrowed to a pixel rectangle of the viewport: dot(plane, clip) ≥ 0
// inside.
std::vector<glm::dvec4> clipPlanes(const math::PixelRect& rect, const PlanViewport& viewport) {
    const double x0 = 2.0 * rect.x0 / viewport.width - 1.0, x1 = 2.0 * rect.x1 / viewport.width - 1.0;
    const double y0 = 2.0 * rect.y0 / viewport.height - 1.0, y1 = 2.0 * rect.y1 / viewport.height - 1.0;
    return {{1, 0, 0, -x0}, {-1, 0, 0, x1}, {0, 1, 0, -y0}, {0, -1, 0, y1}, {0, 0, 1, 1}, {0, 0, -1, 1}};
}

} // namespace

EnvmapCapture envmapCapture(const FrameInput& input) {
    const Reflector& reflector = *input.reflector;
    const math::Box own = math::worldBounds(computeBounds(*reflector.mesh), reflector.world);
    EnvmapCapture capture;
    capture.centre = own.center();
    const glm::dvec3 half = (own.max - own.min) * 0.5;
    const double inner = std::min({half.x, half.y, half.z});
    const double outer = std::max(glm::length(half), 1e-6);
    // A cube face clips points up to near·√3 from the centre: keep that inside the reflector, which is not
    // drawn into its own map, so nothing around it is ever clipped.
    capture.near = std::max(inner * 0.5 / std::sqrt(3.0), outer * 1e-3);
    double far = 0.0;
    const math::Box scene = math::sceneBounds(input);
    if (!scene.empty())
        for (const glm::dvec3& c : scene.corners())
            far = std::max(far, glm::length(c - capture.centre));
    capture.far = std::max(far * 1.01, capture.near * 16.0);
    return capture;
}

std::vector<EnvmapFace> envmapFaces(const Reflector& reflector, const EnvmapCapture& capture) {
    std::vector<EnvmapFace> faces;
    if (!warpable(reflector.map) || reflector.fill == ReflectorFill::Resampled) {
        // Cube maps and the resampled fill (the octahedral map's only one) draw six faces of the
        // reflector's resolution.
        static const char* const names[6] = {"+X face", "−X face", "+Y face",
                                             "−Y face", "+Z face", "−Z face"};
        for (int f = 0; f < 6; ++f) {
            EnvmapFace face;
            face.label = names[f];
            face.index = f;
            face.view = envmap::cubeFaceView(f);
            face.width = face.height = reflector.resolution;
            faces.push_back(face);
        }
        return faces;
    }
    const envmap::MapType type = mapTypeOf(reflector.map);
    const envmap::MapLayout layout = envmap::makeLayout(type, reflector.resolution);
    for (int c = 0; c < 2; ++c) {
        EnvmapFace face;
        // Paraboloid component 0 looks down −Z (envmap/Mapping.cpp); the tennis ball's parts wrap round.
        face.label = type == envmap::MapType::DualParaboloid ? (c == 0 ? "−Z half" : "+Z half")
                                                             : (c == 0 ? "part 1" : "part 2");
        face.index = c;
        face.warped = true;
        face.warp = envmap::warpParameters(layout, c, capture.far);
        face.width = layout.width;
        face.height = layout.height;
        faces.push_back(face);
    }
    return faces;
}

std::uint64_t envmapSettingsKey(const Reflector& reflector) {
    Hasher h;
    h.add(reflector.map);
    h.add(reflector.resolution);
    h.add(warpable(reflector.map) ? reflector.fill : ReflectorFill::Resampled);
    return h.value;
}

// What the map draws: the declared fields of the scene's settings, lights, materials, mirrors and the
// reflector itself that an environment map draws (FieldSpec::drawnInMaps: not the mirrors' technique and
// roughness, which the map's stencil mirrors do not use, nor what only the reflector's lookups read), and
// where everything is.
std::uint64_t envmapSignature(const FrameInput& input) {
    const Reflector& reflector = *input.reflector;
    Hasher h;
    h.add(envmapSettingsKey(reflector));
    const EnvmapCapture capture = envmapCapture(input);
    h.add(capture.centre);
    h.add(capture.near);
    h.add(capture.far);
    // Not drawn into its own map, but its shadows fall on the scene the map sees.
    h.add(reflector.world);
    h.add(static_cast<const void*>(reflector.mesh.get()));
    addFields(h, static_cast<const ReflectorParams&>(reflector), true);
    addFields(h, input.settings, true);
    for (const Light& light : input.lights) {
        addFields(h, static_cast<const LightParams&>(light));
        h.add(light.position);
        h.add(light.direction);
    }
    for (const DrawItem& item : input.items) {
        h.add(static_cast<const void*>(item.mesh.get()));
        // A big mesh is drawn whole until its simplified level is built, then at that level.
        h.add(item.mesh && item.mesh->coarse.indices() != nullptr);
        h.add(item.world);
        h.add(item.castsShadows);
        addMaterial(h, item.material);
    }
    // The map's mirrors are drawn with the stencil technique and no blur (passes/MirrorPasses.cpp),
    // their surfaces with reflectivity, tint, Fresnel and material, as the main pass's stencil mirrors.
    for (const Mirror& mirror : input.mirrors) {
        h.add(mirror.world);
        addFields(h, static_cast<const MirrorParams&>(mirror), true);
        h.add(mirror.hasMaterial);
        addMaterial(h, mirror.material);
    }
    return h.value;
}

bool reflectorVisible(const FrameInput& input, const PlanViewport& viewport, const FramePlan& plan,
                      std::vector<std::string>* seenIn) {
    const Reflector& reflector = *input.reflector;
    const math::Box box = math::worldBounds(computeBounds(*reflector.mesh), reflector.world);
    const glm::dmat4 rotation = math::viewRotation(input.camera);
    const glm::dmat4 toCameraRelative = math::cameraRelative(input.camera);
    auto clipCorners = [&](const glm::dmat4& worldToClip) {
        std::array<glm::dvec4, 8> clip;
        const auto corners = box.corners();
        for (std::size_t i = 0; i < corners.size(); ++i)
            clip[i] = worldToClip * glm::dvec4(corners[i], 1.0);
        return clip;
    };
    const math::PixelRect whole{0, 0, viewport.width, viewport.height};
    if (!boxOutside(clipCorners(cameraProjection(input, viewport) * rotation * toCameraRelative),
                    clipPlanes(whole, viewport))) {
        if (seenIn)
            seenIn->clear();
        return true;
    }
    for (const MirrorView& view : plan.views) {
        // The reflected scene as this view draws it: world → reflected world → camera-relative → clip,
        // with the oblique near plane on the mirror and only the mirror's pixels.
        const glm::dmat4 worldToClip = view.projection * rotation * toCameraRelative * view.reflection;
        if (!boxOutside(clipCorners(worldToClip), clipPlanes(view.rect, viewport))) {
            if (seenIn)
                *seenIn = {input.mirrors[static_cast<std::size_t>(view.mirror)].name};
            return true;
        }
    }
    return false;
}

std::uint64_t prefilterKey(std::uint64_t envmapSignature, std::uint64_t envmapSettings, int samples) {
    Hasher h;
    h.add(envmapSignature);
    h.add(envmapSettings);
    h.add(samples);
    return h.value;
}

namespace {

// The screen-space mirrors whose rays that find nothing in the image read the reflector's map
// (settings.screenFallback), named for the plan ("A, B"); empty when none does.
std::string screenSpaceFallbackOf(const FrameInput& input, const FramePlan& mirrors) {
    if (input.settings.screenFallback != ScreenFallback::Map)
        return {};
    std::string names;
    for (const MirrorView& view : mirrors.views)
        if (view.screenSpace)
            names += (names.empty() ? "" : ", ") + input.mirrors[static_cast<std::size_t>(view.mirror)].name;
    return names;
}

// The GGX pre-filter of a visible reflector (planReflector). `captured`: the signature of the map the
// Envmap pass renders this frame; empty when the map is reused. The chain is filtered only when the map
// was rendered again, or the sample count changed, and only when the lookup reads it: a pass nothing on
// screen needs never runs.
void planPrefilter(const FrameInput& input, const PlannerState& state, std::optional<std::uint64_t> captured,
                   FramePlan& plan) {
    const Reflector& reflector = *input.reflector;
    const std::string name = reflector.name;
    if (!(reflector.roughness > 0.0)) {
        plan.skipped.push_back({name, PlanReason::PrefilterSharp});
        return;
    }
    const envmap::MapLayout layout = envmap::makeLayout(mapTypeOf(reflector.map), reflector.resolution);
    if (input.settings.glossyFilter == GlossyFilter::Mip) {
        const int levels = envmap::usableMipLevels(layout);
        plan.skipped.push_back({name, PlanReason::PrefilterMipFilter, {.levels = levels}});
        return;
    }
    const int samples = std::clamp(input.settings.prefilterSamples, 1, 4096);
    const std::uint64_t settings = envmapSettingsKey(reflector);
    PlanReason why = PlanReason::PrefilterMapRendered;
    std::uint64_t key = 0;
    if (captured) {
        key = prefilterKey(*captured, settings, samples);
    } else {
        key = prefilterKey(state.envmapSignature.value_or(0), settings, samples);
        if (state.prefilterKey && *state.prefilterKey == key) {
            plan.skipped.push_back({name, PlanReason::PrefilterReused});
            return;
        }
        why = state.prefilterKey ? PlanReason::PrefilterSettingsChanged : PlanReason::PrefilterFirstChain;
    }
    PlannedPass pass;
    pass.kind = PassKind::Prefilter;
    pass.target = name;
    pass.code = why;
    pass.details.node = name;
    pass.details.roughness = std::min(reflector.roughness, 1.0);
    pass.details.levels = envmap::prefilterLevels(layout);
    pass.details.samples = samples;
    pass.signature = key;
    plan.passes.push_back(std::move(pass));
}

// The time-sliced update: the face drawn longest ago among those whose signature is not the scene's
// (round robin while the scene keeps changing), alone in map.faces; EnvmapUnchanged if every face is
// up to date. `slice` says which face, and how out of date the others are: their age counts map updates,
// this one included (1: drawn by the update before it).
PlanReason timeSlicedUpdate(const PlannerState& state, EnvmapPlan& map, ReasonDetails& slice) {
    auto signatureOf = [&](int index) {
        const auto i = static_cast<std::size_t>(index);
        return i < state.envmapFaceSignatures.size() ? std::optional(state.envmapFaceSignatures[i])
                                                     : std::nullopt;
    };
    auto updateOf = [&](int index) {
        const auto i = static_cast<std::size_t>(index);
        return i < state.envmapFaceUpdates.size() ? state.envmapFaceUpdates[i] : 0;
    };
    const EnvmapFace* chosen = nullptr;
    for (const EnvmapFace& face : map.faces)
        if (signatureOf(face.index) != map.signature &&
            (!chosen || updateOf(face.index) < updateOf(chosen->index)))
            chosen = &face;
    if (!chosen)
        return PlanReason::EnvmapUnchanged;
    slice.slicedFace = chosen->label;
    slice.mapFaces = static_cast<int>(map.faces.size());
    for (const EnvmapFace& face : map.faces)
        if (&face != chosen && signatureOf(face.index) != map.signature) {
            ++slice.staleFaces;
            slice.oldestSlice =
                std::max(slice.oldestSlice, static_cast<int>(std::min<std::uint64_t>(
                                                state.envmapUpdates + 1 - updateOf(face.index), 1u << 30)));
        }
    const EnvmapFace face = *chosen;
    map.faces = {face};
    return PlanReason::EnvmapTimeSliced;
}

// Whether every face of the map was last drawn with one signature: a whole map of one scene, not one a
// time-sliced update left part done (before its policy changed). A state with no record of faces holds a
// map drawn whole.
bool facesAgree(const PlannerState& state, const EnvmapPlan& map) {
    if (state.envmapFaceSignatures.empty())
        return true;
    for (const EnvmapFace& face : map.faces) {
        const auto i = static_cast<std::size_t>(face.index);
        if (i >= state.envmapFaceSignatures.size() || state.envmapFaceSignatures[i] != state.envmapSignature)
            return false;
    }
    return true;
}

// Why the map is drawn this frame (or reused): its update policy against what the planner state holds.
// A time-sliced update leaves in map.faces only the face it draws; the other policies draw whole a map
// that one left part done.
PlanReason mapUpdate(const Reflector& reflector, const PlannerState& state, bool preview, EnvmapPlan& map,
                     ReasonDetails& slice) {
    if (!state.envmapSignature || state.envmapSettings != map.settingsKey)
        return PlanReason::EnvmapFirstMap; // drawn whole, whatever the policy
    if (preview && reflector.update != ReflectorUpdate::Once)
        return PlanReason::PreviewEnvmapHeld;
    if (reflector.update == ReflectorUpdate::TimeSliced)
        return timeSlicedUpdate(state, map, slice);
    if (reflector.update == ReflectorUpdate::Always || !facesAgree(state, map))
        return reflector.update == ReflectorUpdate::Always ? PlanReason::EnvmapAlways
                                                           : PlanReason::EnvmapChanged;
    if (reflector.update == ReflectorUpdate::Once)
        return PlanReason::EnvmapReusedOnce;
    return *state.envmapSignature == map.signature ? PlanReason::EnvmapUnchanged : PlanReason::EnvmapChanged;
}

} // namespace

void planReflector(const FrameInput& input, const PlannerState& state, const PlanViewport& viewport,
                   const FramePlan& mirrors, FramePlan& plan) {
    if (!input.reflector || !input.reflector->mesh)
        return;
    const Reflector& reflector = *input.reflector;
    std::vector<std::string> seenIn;
    std::string fallbackOf;
    if (!reflectorVisible(input, viewport, mirrors, &seenIn)) {
        fallbackOf = screenSpaceFallbackOf(input, mirrors);
        if (fallbackOf.empty()) {
            plan.skipped.push_back({reflector.name, PlanReason::EnvmapOutOfSight});
            return;
        }
    }
    if (plan.reflectorResolution == 0) {
        plan.skipped.push_back({reflector.name, PlanReason::EnvmapDoesNotFit});
        return;
    }
    EnvmapPlan map;
    map.target = reflector.name;
    map.capture = envmapCapture(input);
    map.signature = envmapSignature(input);
    map.settingsKey = envmapSettingsKey(reflector);
    map.faces = envmapFaces(reflector, map.capture);
    ReasonDetails slice;
    const PlanReason why = mapUpdate(reflector, state, plan.preview.active(), map, slice);
    if (why == PlanReason::EnvmapReusedOnce || why == PlanReason::EnvmapUnchanged ||
        why == PlanReason::PreviewEnvmapHeld) {
        plan.skipped.push_back({reflector.name, why, {.update = reflector.update}});
        planPrefilter(input, state, {}, plan);
        return;
    }
    PlannedPass pass;
    pass.kind = PassKind::Envmap;
    pass.target = reflector.name;
    pass.code = why;
    pass.details = std::move(slice);
    pass.details.seenIn = std::move(seenIn);
    pass.details.screenSpaceFallbackOf = std::move(fallbackOf);
    pass.details.map = reflector.map;
    pass.details.fill = reflector.fill;
    pass.details.resolution = reflector.resolution;
    // Mirrors in the map cost a scene draw per mirror view in each face or component they show in.
    if (!input.mirrors.empty())
        pass.details.mapMirrorDepth = std::clamp(reflector.mirrorDepth, 0, kStencilLevels);
    plan.passes.push_back(std::move(pass));

    planEnvmapMirrors(input, map);
    const std::uint64_t signature = map.signature;
    plan.envmap = std::move(map);
    planPrefilter(input, state, signature, plan);
}

void recordEnvmap(const EnvmapPlan& map, PlannerState& commits) {
    const bool whole = commits.envmapSettings != map.settingsKey;
    commits.envmapSignature = map.signature;
    commits.envmapSettings = map.settingsKey;
    if (whole) {
        commits.envmapFaceSignatures.clear();
        commits.envmapFaceUpdates.clear();
    }
    ++commits.envmapUpdates;
    for (const EnvmapFace& face : map.faces) {
        const auto i = static_cast<std::size_t>(face.index);
        if (commits.envmapFaceSignatures.size() <= i) {
            commits.envmapFaceSignatures.resize(i + 1, 0);
            commits.envmapFaceUpdates.resize(i + 1, 0);
        }
        commits.envmapFaceSignatures[i] = map.signature;
        commits.envmapFaceUpdates[i] = commits.envmapUpdates;
    }
}

void planReflectorTrace(const FrameInput& input, const PlanViewport& viewport, FramePlan& plan) {
    if (!input.reflector || !input.reflector->mesh ||
        input.reflector->technique != ReflectorTechnique::ScreenSpace || plan.reflectorResolution == 0)
        return;
    const Reflector& reflector = *input.reflector;
    std::vector<std::string> seenIn;
    if (!reflectorVisible(input, viewport, plan, &seenIn))
        return; // its map is skipped as out of sight, and says so
    if (!seenIn.empty()) {
        plan.skipped.push_back({reflector.name, PlanReason::ReflectorTraceNotSeenDirectly});
        return;
    }
    // The mirrors' pyramid leaves the screen-space mirrors out (none of their reflections is drawn when
    // they trace); by now they are, and the reflector's rays meet them: a pyramid of its own then.
    const bool screenSpaceMirrors =
        std::any_of(plan.views.begin(), plan.views.end(), [](const MirrorView& v) { return v.screenSpace; });
    PlannedPass pyramid;
    pyramid.kind = PassKind::ScreenDepth;
    pyramid.code = PlanReason::ScreenDepthPyramid;
    pyramid.details.node = "for " + reflector.name;
    pyramid.details.screenSpaceMirrorsInDepth = screenSpaceMirrors;
    plan.passes.push_back(std::move(pyramid));
    // A rough reflector's cone reads the image blurred: a pyramid of it, once everything is drawn.
    const double roughness = std::clamp(reflector.roughness, 0.0, 1.0);
    if (roughness > 0.0) {
        PlannedPass colour;
        colour.kind = PassKind::ScreenColour;
        colour.code = PlanReason::ScreenColourPyramid;
        colour.details.node = reflector.name;
        colour.details.roughness = roughness;
        plan.passes.push_back(std::move(colour));
    }
    PlannedPass trace;
    trace.kind = PassKind::ReflectorTrace;
    trace.target = reflector.name;
    trace.code = PlanReason::ReflectorScreenTrace;
    trace.details.roughness = roughness;
    plan.passes.push_back(std::move(trace));
}

} // namespace speculum::render
