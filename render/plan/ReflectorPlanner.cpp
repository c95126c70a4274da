// Plans the curved reflectors' environment passes: whether each reflector can be seen at all (directly, in
// a planned mirror view, or in another reflector's map when they bounce), whether its map must be
// rendered again under its update policy, and the order of the maps bounce by bounce. The signature of
// what a map sees is camera-independent, so a camera moving around a static scene reuses the maps.
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

EnvmapCapture envmapCapture(const FrameInput& input, int index) {
    const Reflector& reflector = input.reflectors.at(static_cast<std::size_t>(index));
    const math::Box own = math::worldBounds(computeBounds(*reflector.mesh), reflector.world);
    EnvmapCapture capture;
    capture.centre = own.center();
    const glm::dvec3 half = (own.max - own.min) * 0.5;
    const double inner = std::min({half.x, half.y, half.z});
    const double outer = std::max(glm::length(half), 1e-6);
    // A cube face clips points up to near·√3 from the centre: keep that inside the reflector, which is not
    // drawn into its own map, so nothing around it is ever clipped (but what lies inside it: another
    // reflector touching or inside this one).
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
// roughness, which the map's stencil mirrors do not use, nor what only the reflector's lookups read), the
// other reflectors whole (a bounce draws them with their maps), and where everything is.
std::uint64_t envmapSignature(const FrameInput& input, int index) {
    const Reflector& reflector = input.reflectors.at(static_cast<std::size_t>(index));
    Hasher h;
    h.add(envmapSettingsKey(reflector));
    const EnvmapCapture capture = envmapCapture(input, index);
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
    for (std::size_t j = 0; j < input.reflectors.size(); ++j) {
        if (static_cast<int>(j) == index)
            continue;
        const Reflector& other = input.reflectors[j];
        h.add(j);
        h.add(other.world);
        h.add(static_cast<const void*>(other.mesh.get()));
        addFields(h, static_cast<const ReflectorParams&>(other), false);
        addMaterial(h, other.material);
    }
    return h.value;
}

bool reflectorVisible(const FrameInput& input, int index, const PlanViewport& viewport, const FramePlan& plan,
                      std::vector<std::string>* seenIn) {
    const Reflector& reflector = input.reflectors.at(static_cast<std::size_t>(index));
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

int probeReflector(const FrameInput& input) {
    for (std::size_t i = 0; i < input.reflectors.size(); ++i)
        if (input.reflectors[i].mesh)
            return static_cast<int>(i);
    return -1;
}

namespace {

const Reflector& reflectorAt(const FrameInput& input, int index) {
    return input.reflectors[static_cast<std::size_t>(index)];
}

// The screen-space mirrors whose rays that find nothing in the image read the probe reflector's map
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

// The GGX pre-filter of reflector `index`, seen (planReflectors). `captured`: the signature of the map
// its Envmap passes render this frame; empty when the map is reused. The chain is filtered only when the
// map was rendered again, or the sample count changed, and only when the lookup reads it: a pass nothing on
// screen needs never runs.
void planPrefilter(const FrameInput& input, int index, const ReflectorMapState& state,
                   std::optional<std::uint64_t> captured, FramePlan& plan) {
    const Reflector& reflector = reflectorAt(input, index);
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
        key = prefilterKey(state.signature.value_or(0), settings, samples);
        if (state.prefilterKey && *state.prefilterKey == key) {
            plan.skipped.push_back({name, PlanReason::PrefilterReused});
            return;
        }
        why = state.prefilterKey ? PlanReason::PrefilterSettingsChanged : PlanReason::PrefilterFirstChain;
    }
    PlannedPass pass;
    pass.kind = PassKind::Prefilter;
    pass.target = name;
    pass.reflector = index;
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
PlanReason timeSlicedUpdate(const ReflectorMapState& state, EnvmapPlan& map, ReasonDetails& slice) {
    auto signatureOf = [&](int index) {
        const auto i = static_cast<std::size_t>(index);
        return i < state.faceSignatures.size() ? std::optional(state.faceSignatures[i]) : std::nullopt;
    };
    auto updateOf = [&](int index) {
        const auto i = static_cast<std::size_t>(index);
        return i < state.faceUpdates.size() ? state.faceUpdates[i] : 0;
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
                                                state.updates + 1 - updateOf(face.index), 1u << 30)));
        }
    const EnvmapFace face = *chosen;
    map.faces = {face};
    return PlanReason::EnvmapTimeSliced;
}

// Whether every face of the map was last drawn with one signature: a whole map of one scene, not one a
// time-sliced update left part done (before its policy changed). A state with no record of faces holds a
// map drawn whole.
bool facesAgree(const ReflectorMapState& state, const EnvmapPlan& map) {
    if (state.faceSignatures.empty())
        return true;
    for (const EnvmapFace& face : map.faces) {
        const auto i = static_cast<std::size_t>(face.index);
        if (i >= state.faceSignatures.size() || state.faceSignatures[i] != state.signature)
            return false;
    }
    return true;
}

// Why the map is drawn this frame (or reused): its update policy against what the planner state holds.
// A time-sliced update leaves in map.faces only the face it draws; the other policies draw whole a map
// that one left part done.
PlanReason mapUpdate(const Reflector& reflector, const ReflectorMapState& state, bool preview,
                     EnvmapPlan& map, ReasonDetails& slice) {
    if (!state.signature || state.settings != map.settingsKey || state.reflector != map.target)
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
    return *state.signature == map.signature ? PlanReason::EnvmapUnchanged : PlanReason::EnvmapChanged;
}

// A reflector that needs a map this frame, and where it is seen.
struct Wanted {
    int index = -1;
    std::vector<std::string> seenIn;   // the mirror it is seen in; empty: seen directly
    std::string screenSpaceFallbackOf; // not seen, but read by these screen-space mirrors
    std::string seenInMapOf;           // not seen, but in this reflector's map, which bounces draw it in
};

// The reflectors whose maps something on screen needs: those seen directly or in a mirror, the probe where
// screen-space mirrors fall back to it, and, when reflectors bounce, every other one (each is in the maps of
// those seen). Skips say why the others get none.
std::vector<Wanted> wantedReflectors(const FrameInput& input, const PlanViewport& viewport,
                                     const FramePlan& mirrors, FramePlan& plan) {
    std::vector<Wanted> wanted;
    std::vector<int> unseen;
    const int probe = probeReflector(input);
    int withMeshes = 0;
    for (std::size_t i = 0; i < input.reflectors.size(); ++i) {
        if (!input.reflectors[i].mesh)
            continue;
        ++withMeshes;
        Wanted w{static_cast<int>(i)};
        if (reflectorVisible(input, w.index, viewport, mirrors, &w.seenIn))
            wanted.push_back(std::move(w));
        else if (w.index == probe &&
                 !(w.screenSpaceFallbackOf = screenSpaceFallbackOf(input, mirrors)).empty())
            wanted.push_back(std::move(w));
        else
            unseen.push_back(w.index);
    }
    const bool bounces = input.settings.reflectorBounces > 0 && withMeshes > 1 && !wanted.empty();
    for (const int i : unseen) {
        if (bounces)
            wanted.push_back({i, {}, {}, reflectorAt(input, wanted.front().index).name});
        else
            plan.skipped.push_back({reflectorAt(input, i).name, PlanReason::EnvmapOutOfSight});
    }
    std::sort(wanted.begin(), wanted.end(),
              [](const Wanted& a, const Wanted& b) { return a.index < b.index; });
    return wanted;
}

// Keeps at most kMaxReflectorMaps of `wanted`, the nearest the camera, and those whose map fits; the others
// get a skip that says why.
void capWanted(const FrameInput& input, const FramePlan& plan, std::vector<Wanted>& wanted,
               std::vector<SkippedEffect>& skipped) {
    if (wanted.size() > static_cast<std::size_t>(kMaxReflectorMaps)) {
        auto distance = [&](const Wanted& w) {
            const Reflector& r = reflectorAt(input, w.index);
            return glm::length(math::worldBounds(computeBounds(*r.mesh), r.world).center() -
                               input.camera.position);
        };
        std::stable_sort(wanted.begin(), wanted.end(),
                         [&](const Wanted& a, const Wanted& b) { return distance(a) < distance(b); });
        for (std::size_t k = kMaxReflectorMaps; k < wanted.size(); ++k)
            skipped.push_back({reflectorAt(input, wanted[k].index).name,
                               PlanReason::EnvmapOverCap,
                               {.limit = kMaxReflectorMaps}});
        wanted.resize(kMaxReflectorMaps);
        std::sort(wanted.begin(), wanted.end(),
                  [](const Wanted& a, const Wanted& b) { return a.index < b.index; });
    }
    std::erase_if(wanted, [&](const Wanted& w) {
        if (plan.reflectorResolution(w.index) > 0)
            return false;
        skipped.push_back({reflectorAt(input, w.index).name, PlanReason::EnvmapDoesNotFit});
        return true;
    });
}

// A map its update policy draws this frame: its plan and the pass that draws it (before bounces).
struct DrawnMap {
    EnvmapPlan map;
    PlannedPass pass;
};

// The map of `w` if its update policy draws it this frame; else a skip that says why it is kept.
std::optional<DrawnMap> drawnMap(const FrameInput& input, const PlannerState& state, const Wanted& w,
                                 FramePlan& plan) {
    const Reflector& reflector = reflectorAt(input, w.index);
    EnvmapPlan map;
    map.target = reflector.name;
    map.reflector = w.index;
    map.capture = envmapCapture(input, w.index);
    map.signature = envmapSignature(input, w.index);
    map.settingsKey = envmapSettingsKey(reflector);
    map.faces = envmapFaces(reflector, map.capture);
    ReasonDetails slice;
    const PlanReason why = mapUpdate(reflector, state.mapOf(w.index), plan.preview.active(), map, slice);
    if (why == PlanReason::EnvmapReusedOnce || why == PlanReason::EnvmapUnchanged ||
        why == PlanReason::PreviewEnvmapHeld) {
        plan.skipped.push_back({reflector.name, why, {.update = reflector.update}});
        return std::nullopt;
    }
    PlannedPass pass;
    pass.kind = PassKind::Envmap;
    pass.target = reflector.name;
    pass.reflector = w.index;
    pass.code = why;
    pass.details = std::move(slice);
    pass.details.seenIn = w.seenIn;
    pass.details.screenSpaceFallbackOf = w.screenSpaceFallbackOf;
    pass.details.seenInMapOf = w.seenInMapOf;
    pass.details.map = reflector.map;
    pass.details.fill = reflector.fill;
    pass.details.resolution = reflector.resolution;
    pass.details.otherReflectors = 0;
    for (std::size_t j = 0; j < input.reflectors.size(); ++j)
        pass.details.otherReflectors += static_cast<int>(j) != w.index && input.reflectors[j].mesh ? 1 : 0;
    // Mirrors in the map cost a scene draw per mirror view in each face or component they show in.
    if (!input.mirrors.empty())
        pass.details.mapMirrorDepth = std::clamp(reflector.mirrorDepth, 0, kStencilLevels);
    planEnvmapMirrors(input, map);
    return DrawnMap{std::move(map), std::move(pass)};
}

// The bounces the frame draws: the scene's, where there is another reflector to see, and within
// kMaxEnvmapPasses for `maps` maps drawn bounce by bounce; skips say where fewer are drawn than asked.
int plannedBounces(const FrameInput& input, int maps, FramePlan& plan) {
    const int asked = std::clamp(input.settings.reflectorBounces, 0, kMaxReflectorBounces);
    if (asked == 0 || maps == 0)
        return 0;
    const auto withMeshes = std::count_if(input.reflectors.begin(), input.reflectors.end(),
                                          [](const Reflector& r) { return r.mesh != nullptr; });
    if (withMeshes < 2) {
        plan.skipped.push_back({"", PlanReason::BouncesUnused, {.asked = asked}});
        return 0;
    }
    const int most = std::max(kMaxEnvmapPasses / std::max(maps, 1) - 1, 0);
    if (asked > most) {
        plan.skipped.push_back({"", PlanReason::BouncesCapped, {.limit = most, .asked = asked}});
        return most;
    }
    return asked;
}

// Appends the drawn maps' Envmap passes bounce by bounce. Maps drawn whole at every bounce read each
// other's maps of the bounce before; where only one such map is drawn (or a time-sliced map's one face),
// the others it reads do not change between bounces, so it is drawn once, at the last.
void appendBounces(std::vector<DrawnMap>& drawn, int bounces, FramePlan& plan) {
    const auto everyBounce = [&](const DrawnMap& d) { return d.pass.code != PlanReason::EnvmapTimeSliced; };
    const bool jacobi = bounces > 0 && std::count_if(drawn.begin(), drawn.end(), everyBounce) > 1;
    for (int b = 0; b <= bounces; ++b)
        for (DrawnMap& d : drawn) {
            if (b != bounces && !(jacobi && everyBounce(d)))
                continue;
            PlannedPass pass = d.pass;
            pass.envmap = static_cast<int>(plan.envmaps.size());
            pass.details.bounce = b;
            pass.details.bounces = bounces;
            if (b > 0 && jacobi && everyBounce(d))
                pass.code = PlanReason::EnvmapBounce;
            plan.passes.push_back(std::move(pass));
            plan.envmaps.push_back(d.map);
            plan.envmaps.back().bounce = b;
        }
}

} // namespace

void planReflectors(const FrameInput& input, const PlannerState& state, const PlanViewport& viewport,
                    const FramePlan& mirrors, FramePlan& plan) {
    std::vector<Wanted> wanted = wantedReflectors(input, viewport, mirrors, plan);
    capWanted(input, plan, wanted, plan.skipped);
    std::vector<DrawnMap> drawn;
    for (const Wanted& w : wanted)
        if (std::optional<DrawnMap> map = drawnMap(input, state, w, plan))
            drawn.push_back(std::move(*map));
    appendBounces(drawn, plannedBounces(input, static_cast<int>(drawn.size()), plan), plan);
    for (const Wanted& w : wanted) {
        const auto it = std::find_if(drawn.begin(), drawn.end(),
                                     [&](const DrawnMap& d) { return d.map.reflector == w.index; });
        planPrefilter(input, w.index, state.mapOf(w.index),
                      it != drawn.end() ? std::optional(it->map.signature) : std::nullopt, plan);
    }
}

void recordEnvmap(const EnvmapPlan& map, PlannerState& commits) {
    ReflectorMapState& state = commits.mapOf(map.reflector);
    const bool whole = state.settings != map.settingsKey || state.reflector != map.target;
    state.reflector = map.target;
    state.signature = map.signature;
    state.settings = map.settingsKey;
    if (whole) {
        state.faceSignatures.clear();
        state.faceUpdates.clear();
    }
    ++state.updates;
    for (const EnvmapFace& face : map.faces) {
        const auto i = static_cast<std::size_t>(face.index);
        if (state.faceSignatures.size() <= i) {
            state.faceSignatures.resize(i + 1, 0);
            state.faceUpdates.resize(i + 1, 0);
        }
        state.faceSignatures[i] = map.signature;
        state.faceUpdates[i] = state.updates;
    }
}

namespace {

// Reflector `index`'s screen-space trace (planReflectorTraces), with the depth pyramid the traces share
// unless an earlier one planned it (`pyramid`).
void planReflectorTrace(const FrameInput& input, int index, const PlanViewport& viewport, bool& pyramid,
                        FramePlan& plan) {
    const Reflector& reflector = reflectorAt(input, index);
    std::vector<std::string> seenIn;
    if (!reflectorVisible(input, index, viewport, plan, &seenIn))
        return; // its map is skipped as out of sight, and says so
    if (!seenIn.empty()) {
        plan.skipped.push_back({reflector.name, PlanReason::ReflectorTraceNotSeenDirectly});
        return;
    }
    // The mirrors' pyramid leaves the screen-space mirrors out (none of their reflections is drawn when
    // they trace); by now they are, and the reflector's rays meet them: a pyramid of its own then.
    const bool screenSpaceMirrors =
        std::any_of(plan.views.begin(), plan.views.end(), [](const MirrorView& v) { return v.screenSpace; });
    if (!pyramid) {
        PlannedPass depth;
        depth.kind = PassKind::ScreenDepth;
        depth.code = PlanReason::ScreenDepthPyramid;
        depth.details.node = "for " + reflector.name;
        depth.details.screenSpaceMirrorsInDepth = screenSpaceMirrors;
        plan.passes.push_back(std::move(depth));
        pyramid = true;
    }
    // A rough reflector's cone reads the image blurred: a pyramid of it, once everything is drawn.
    const double roughness = std::clamp(reflector.roughness, 0.0, 1.0);
    if (roughness > 0.0) {
        PlannedPass colour;
        colour.kind = PassKind::ScreenColour;
        colour.code = PlanReason::ScreenColourPyramid;
        colour.reflector = index;
        colour.details.node = reflector.name;
        colour.details.roughness = roughness;
        plan.passes.push_back(std::move(colour));
    }
    PlannedPass trace;
    trace.kind = PassKind::ReflectorTrace;
    trace.target = reflector.name;
    trace.reflector = index;
    trace.code = PlanReason::ReflectorScreenTrace;
    trace.details.roughness = roughness;
    plan.passes.push_back(std::move(trace));
}

} // namespace

void planReflectorTraces(const FrameInput& input, const PlanViewport& viewport, FramePlan& plan) {
    bool pyramid = false;
    for (std::size_t i = 0; i < input.reflectors.size(); ++i) {
        const Reflector& reflector = input.reflectors[i];
        if (reflector.mesh && reflector.technique == ReflectorTechnique::ScreenSpace &&
            plan.reflectorResolution(static_cast<int>(i)) > 0)
            planReflectorTrace(input, static_cast<int>(i), viewport, pyramid, plan);
    }
}

} // namespace speculum::render
