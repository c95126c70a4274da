// The sentences of the plan's reasons: what every planned pass and every skip (the planner's and the
// executors') says, worded here from its code and the details it names.
#include "render/plan/PlanReason.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/frame/SceneNames.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace speculum::render {

namespace {

// What a mirror whose paths end (a depth limit or the view budget) looks like, in the tracer as well.
constexpr const char* kDrawnDark =
    "drawn dark: its reflection is not followed, so only its surface's share (1 − reflectivity) shows";

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string rounded(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f", value);
    return text;
}

bool inMap(const ReasonDetails& d) {
    return !d.mapFace.empty();
}

// "seen directly" or "seen in Left → Right (depth 3)", then the map's face (", in Ball's map, +X face").
std::string whereSeen(const ReasonDetails& d) {
    std::string where = "seen directly";
    if (!d.seenIn.empty()) {
        std::string chain;
        for (auto name = d.seenIn.rbegin(); name != d.seenIn.rend(); ++name)
            chain = chain.empty() ? *name : *name + " → " + chain;
        where = "seen in " + chain + " (depth " + std::to_string(d.seenIn.size() + 1) + ")";
    }
    return inMap(d) ? where + ", in " + d.mapFace : where;
}

// ", 1234 px" (texels in the map); nothing in a direct-fill component.
std::string areaCovered(const ReasonDetails& d) {
    return d.area ? ", " + rounded(*d.area) + (inMap(d) ? " texels" : " px") : std::string();
}

// The big meshes a reflected view draws simplified, or whole; nothing when it draws none.
std::string reflectedMeshes(const ReasonDetails& d) {
    std::string simplified;
    std::string whole;
    std::string building;
    std::size_t simplifiedCount = 0;
    for (const ReflectedMesh& mesh : d.bigMeshes) {
        const std::string full = std::to_string(mesh.triangles);
        if (mesh.simplifying) {
            building += (building.empty() ? "'" : ", '") + mesh.name + "' (" + full + " triangles)";
            continue;
        }
        if (!mesh.simplifiedTriangles) {
            whole += (whole.empty() ? "'" : ", '") + mesh.name + "' (" + full + " triangles)";
            continue;
        }
        ++simplifiedCount;
        char error[32];
        std::snprintf(error, sizeof error, "%.2g%%", mesh.simplificationError * 100.0);
        simplified += (simplified.empty() ? "'" : ", '") + mesh.name + "' " + full + " → " +
                      std::to_string(*mesh.simplifiedTriangles) + " triangles, within " + error +
                      " of its size";
    }
    std::string said;
    if (!simplified.empty())
        said += "; draws " + std::string(simplifiedCount == 1 ? "a big mesh" : "big meshes") +
                " simplified (" + simplified + ")";
    if (!building.empty())
        said += "; draws big meshes whole while their simplified level is built: " + building;
    if (!whole.empty())
        said += "; draws big meshes whole, settings.simplifyReflections is off: " + whole;
    return said;
}

std::string lightSentence(PlanReason code, const ReasonDetails& d) {
    switch (code) {
    case PlanReason::LightLimit:
        return "more than " + std::to_string(d.limit) + " lights: this light is ignored";
    case PlanReason::ShadowsOff:
        return "shadow pass not needed: shadows are off for this light";
    case PlanReason::NoShadowCasters:
        return "shadow pass not needed: nothing in the scene casts a shadow";
    case PlanReason::NoShadowReceivers:
        return "shadow pass not needed: nothing in the scene can receive a shadow";
    case PlanReason::ShadowedLightLimit:
        return "shadow pass skipped: at most " + std::to_string(d.limit) +
               " lights cast shadows; this one lights without them";
    case PlanReason::ShadowMapDoesNotFit:
        return "shadow pass skipped: no shadow map of its kind fits in GPU memory (see the warnings); this "
               "light lights without shadows";
    case PlanReason::ShadowMapReused:
        return "shadow map reused: light and casters unchanged since the last frame";
    case PlanReason::ShadowMapNotAllocated:
        return "no shadow this frame: its " + std::to_string(d.mapSize) +
               "² map could not be allocated (see the warnings)";
    default:
        break;
    }
    std::string sentence = "light casts shadows (" + std::to_string(d.mapSize) + "² map, PCF " +
                           std::to_string(d.pcf) + "×" + std::to_string(d.pcf) + ") from " +
                           plural(d.casters, "caster", "casters");
    if (d.cubeFacesWithCasters)
        sentence += "; " + std::to_string(*d.cubeFacesWithCasters) + " of 6 cube faces hold casters";
    return sentence + (code == PlanReason::ShadowFirstMap ? "; no map yet" : "; light or casters changed");
}

std::string mainSentence(PlanReason code, const ReasonDetails& d) {
    std::string sentence = "draws " + plural(d.objects, "object", "objects") + " lit by " +
                           plural(d.lights, "light", "lights") + " into the camera's colour buffer";
    if (d.preWeighted)
        sentence += "; stencil mirrors draw their reflections weighted and add their surfaces over them";
    if (code == PlanReason::MainIntoOutput)
        return sentence + " (8-bit sRGB: the output's own buffer, encoded as it is written)";
    if (code == PlanReason::MainSrgb)
        return sentence + " (8-bit sRGB, encoded as it is written)";
    return sentence + " (half float)";
}

std::string compositeSentence(PlanReason code, const ReasonDetails& d) {
    switch (code) {
    case PlanReason::CompositeToFloat:
        return "resolves the half-float colour buffer into the float output (linear)";
    case PlanReason::CompositeCopiesSrgb:
        return "copies the sRGB colour buffer to the output: no blend in it needs radiance above 1";
    case PlanReason::CompositeNotNeeded:
        return "composite pass not needed: the frame is drawn straight into the output, an 8-bit sRGB "
               "buffer, and no blend needs radiance above 1";
    case PlanReason::CompositeScreenSpace:
        return "resolves the half-float colour buffer into the 8-bit output with sRGB encoding: '" + d.node +
               "' is traced in screen space and reads the frame's colour in linear light, above 1 included";
    default:
        break;
    }
    const std::string blend =
        "resolves the half-float colour buffer into the 8-bit output with sRGB encoding: "
        "stencil mirror '" +
        d.node + "' blends onto the reflection it drew";
    if (code == PlanReason::CompositeFresnelBlend)
        return blend + ", with a Fresnel weight that varies over it";
    if (code == PlanReason::CompositeNestedBlend)
        return blend + " inside another stencil mirror's reflection";
    return blend;
}

std::string guidesSentence(PlanReason, const ReasonDetails& d) {
    return "draws the editor's guides (" + plural(d.lines, "line", "lines") +
           ": grid, camera) over the view, hidden where the scene is in front of them; never in a "
           "reflection or a still";
}

// Which approximation of a rough mirror's reflection its surface pass draws.
std::string glossyApproximation(const ReasonDetails& d) {
    if (d.roughness <= 0.0)
        return {};
    char value[16];
    std::snprintf(value, sizeof value, "%.2f", d.roughness);
    const std::string rough = "; rough (roughness " + std::string(value) + "): ";
    if (inMap(d))
        return rough + "drawn sharp, as every mirror inside the environment map";
    if (d.glossyChain)
        return rough +
               "its reflection's convolved chain, read four times a pixel at the level the GGX lobe's " +
               "footprint asks for" +
               (d.chainInstead.empty()
                    ? std::string()
                    : " instead of " + std::to_string(d.glossyTaps) + " taps a pixel: " + d.chainInstead +
                          "; up to roughness 0.3 the chain stays within 1 dB of "
                          "16 taps");
    if (d.glossyTaps == 0)
        return rough + "one mip level of its reflection, chosen by the roughness alone (the cheap filter)";
    return rough + "its reflection sampled over the GGX lobe's footprint, " + std::to_string(d.glossyTaps) +
           " taps a pixel, wider the farther what it reflects lies beyond the mirror";
}

std::string mirrorPassSentence(PlanReason code, const ReasonDetails& d) {
    switch (code) {
    case PlanReason::MirrorMaskStencil:
        return "marks the mirror's visible " + std::string(inMap(d) ? "texels" : "pixels") +
               " in the stencil buffer (" + whereSeen(d) + areaCovered(d) + ")";
    case PlanReason::MirrorMaskCount:
        return "counts the mirror's visible pixels, so a hidden mirror costs nothing (" + whereSeen(d) + ")";
    case PlanReason::MirrorSurface:
        return "blends the mirror's own surface over the reflection (reflectivity " +
               rounded(d.reflectivity * 100) + "%" + (inMap(d) ? ", in " + d.mapFace : std::string()) + ")" +
               glossyApproximation(d);
    case PlanReason::MirrorScreenTrace:
        return "traces the reflection through the camera's image against its depth pyramid, into the "
               "mirror's reflection texture (" +
               whereSeen(d) + areaCovered(d) +
               "); where a ray leaves the image or passes behind what it shows, " +
               (d.screenFallsBackToMap ? d.node + "'s environment map (settings.screenFallback)"
                                       : std::string("the background")) +
               " fades in";
    case PlanReason::ScreenDepthPyramid:
        return "draws the view depth of what the camera sees, and halves it level by level keeping the "
               "nearest, for the screen-space reflections to trace against (" +
               d.node + (d.screenSpaceMirrorsInDepth ? "; the screen-space mirrors' surfaces included" : "") +
               ")";
    default:
        break;
    }
    return std::string("draws the scene reflected in the mirror ") +
           (code == PlanReason::MirrorIntoTexture ? "into its reflection texture"
                                                  : "inside its stencil mask") +
           (d.roughStencil ? " (rough: the stencil technique leaves no image of the reflection to filter)"
                           : "") +
           (d.screenSpaceAsTexture ? " (screen space asked, but it is seen inside another mirror, whose "
                                     "reflected view the camera's image does not hold)"
                                   : "") +
           (d.area ? " with an oblique near plane on the mirror (" : " with a clip plane on the mirror (") +
           whereSeen(d) + areaCovered(d) + ")" + reflectedMeshes(d);
}

// Why a mirror gets no view where the planner sees it.
std::string whyNoView(PlanReason code, const ReasonDetails& d) {
    const std::string viewer = inMap(d) ? "the capture point" : "the camera";
    switch (code) {
    case PlanReason::MirrorSizeInvalid:
        return "the mirror's size is not a positive finite number";
    case PlanReason::MirrorEdgeOn:
        return viewer + " is on the mirror's plane, which it sees edge-on";
    case PlanReason::MirrorBehind:
        return viewer + " is behind the mirror (it sees its back)";
    case PlanReason::MirrorOutsideView:
        return "outside the view";
    case PlanReason::MirrorOutsideParent:
        return "outside the parent mirror's reflected view";
    case PlanReason::MirrorBelowPixel:
        return "covers less than one " + std::string(inMap(d) ? "texel" : "pixel") + " (" +
               rounded(d.area.value_or(0.0) * 100) + "% of one)";
    case PlanReason::MirrorDepthLimit:
        return "the mirror depth limit (" + std::to_string(d.limit) + ") is reached; " + kDrawnDark;
    case PlanReason::MirrorViewLimit:
        return std::string(inMap(d) ? "this face" : "the frame") + " already has " + std::to_string(d.limit) +
               " mirror views; " + kDrawnDark;
    case PlanReason::MirrorStencilTooDeep:
        return "the stencil buffer cannot nest deeper";
    case PlanReason::MirrorDepthZero:
        return std::string("mirrorDepth is 0; ") + kDrawnDark;
    default: // MirrorNoPlane, MirrorNoReflectionMatrix, MirrorNoObliqueProjection: the maths' own words
        return d.error;
    }
}

// A mirror that gets no view where the planner sees it: why, then where.
std::string mirrorSkipSentence(PlanReason code, const ReasonDetails& d) {
    return "no reflection: " + whyNoView(code, d) + " (" + whereSeen(d) + ")";
}

// A mirror without a reflection for a reason found outside the planner's view by view tests.
std::string mirrorDroppedSentence(PlanReason code, const ReasonDetails& d) {
    switch (code) {
    case PlanReason::MapMirrorDepthZero:
        return "no reflection in " + d.node + "'s map: the reflector's mirrorDepth is 0; " + kDrawnDark +
               " (every face)";
    case PlanReason::MirrorOccluded:
        return "no reflection: fully occluded: no pixel of it passed the depth test";
    case PlanReason::MirrorOccludedInTile:
        return "no reflection: fully occluded in this tile: no pixel of it passed the depth test";
    default: // MirrorNoTexture
        return "no reflection: its reflection texture: " + d.error;
    }
}

// "a cube map (6 faces of 256×256)", "a dual-paraboloid map (2 components of 256×256, direct: …)"
std::string mapLayout(const ReasonDetails& d) {
    const int n = d.resolution;
    const std::string size = std::to_string(n) + "×" + std::to_string(n);
    if (d.map == ReflectorMap::Cube)
        return "a cube map (6 faces of " + size + ")";
    if (d.map == ReflectorMap::Octahedral)
        return "an octahedral map (one " + size + " square, resampled from a " + size +
               " cube: 6 scene passes + 1 resampling pass)";
    return "a " + std::string(names::fileName(names::kReflectorMaps, d.map)) + " map (2 components of " +
           (d.map == ReflectorMap::TennisBall ? std::to_string(n) + "×" + std::to_string(3 * n) : size) +
           ", " +
           (d.fill == ReflectorFill::Direct
                ? std::string("direct: vertices warped, 2 scene passes")
                : "resampled from a " + size + " cube: 6 scene passes + 2 resampling passes") +
           ")";
}

// A time-sliced update's clause: the face it redraws and how out of date the others are.
std::string timeSlice(const ReasonDetails& d) {
    const int others = std::max(d.mapFaces - 1, 0);
    std::string clause = "update time-sliced: only its " + d.slicedFace + " this frame, one of " +
                         std::to_string(d.mapFaces) + " a frame in turn while any shows an older scene; ";
    if (d.staleFaces == 0)
        return clause + (others == 1 ? "the other is" : "the other " + std::to_string(others) + " are") +
               " up to date";
    return clause + std::to_string(d.staleFaces) + " of the other " + std::to_string(others) +
           " still show an older scene, the oldest drawn " + std::to_string(d.oldestSlice) +
           (d.oldestSlice == 1 ? " map update" : " map updates") + " ago";
}

// How the map draws the other reflectors: with their plain material, or with their maps of the bounce before.
std::string bounceClause(const ReasonDetails& d) {
    if (d.otherReflectors == 0)
        return {};
    const std::string others = d.otherReflectors == 1
                                   ? "the other reflector"
                                   : "the " + std::to_string(d.otherReflectors) + " other reflectors";
    if (d.bounces == 0)
        return "; " + others + " in it with " + (d.otherReflectors == 1 ? "its" : "their") +
               " plain material (reflectorBounces 0)";
    const std::string of = "bounce " + std::to_string(d.bounce) + " of " + std::to_string(d.bounces);
    if (d.bounce == 0)
        return "; " + of + ": " + others + " in it with " + (d.otherReflectors == 1 ? "its" : "their") +
               " plain material";
    return "; " + of + ": " + others + " in it with " + (d.otherReflectors == 1 ? "its map" : "their maps") +
           " of bounce " + std::to_string(d.bounce - 1) + " where drawn this frame, else as kept";
}

std::string envmapSentence(PlanReason code, const ReasonDetails& d) {
    switch (code) {
    case PlanReason::EnvmapOutOfSight:
        return "environment pass not needed: the reflector is outside the view and outside every mirror's "
               "reflected view";
    case PlanReason::EnvmapDoesNotFit:
        return "environment pass skipped: no map of its layout fits in GPU memory (see the warnings); the "
               "reflector is drawn without it";
    case PlanReason::EnvmapReusedOnce:
        return "environment map reused: update is \"once\" and the map was rendered";
    case PlanReason::EnvmapUnchanged:
        return "environment map reused: nothing it sees changed since it was rendered (update " +
               std::string(names::fileName(names::kReflectorUpdates, d.update)) + ")";
    case PlanReason::EnvmapNotAllocated:
        return "no environment map: none could be allocated (see the warnings)";
    case PlanReason::EnvmapOverCap:
        return "environment pass skipped: more than " + std::to_string(d.limit) +
               " reflectors need a map this frame, and the " + std::to_string(d.limit) +
               " nearest the camera get one; this one keeps the map it has, or without one its plain "
               "material";
    case PlanReason::BouncesUnused:
        return "no reflector bounces: reflectorBounces is " + std::to_string(d.asked) +
               ", but a reflector never appears in its own map and there is no other";
    case PlanReason::BouncesCapped:
        return "reflector bounces cut to " + std::to_string(d.limit) + " of the " + std::to_string(d.asked) +
               " asked: every bounce draws each map again, and a frame draws at most " +
               std::to_string(kMaxEnvmapPasses) + " maps";
    default:
        break;
    }
    // Mirrors in the map cost a scene draw per mirror view in each face or component they show in.
    std::string mirrors;
    if (d.mapMirrorDepth) {
        const int depth = *d.mapMirrorDepth;
        mirrors = depth == 0
                      ? "; its mirrors show only their surface's share in it, not their reflections (the "
                        "reflector's mirrorDepth is 0)"
                      : "; planar mirrors reflect in it up to " + std::to_string(depth) +
                            (depth == 1 ? " level" : " levels") + " deep (the reflector's mirrorDepth)";
    }
    const std::string where = !d.screenSpaceFallbackOf.empty()
                                  ? "not seen, but the screen-space mirrors " + d.screenSpaceFallbackOf +
                                        " fall back to its map where their rays leave the image"
                              : !d.seenInMapOf.empty()
                                  ? "not seen, but in " + d.seenInMapOf + "'s map, which bounces draw it in"
                              : d.seenIn.empty() ? "seen directly"
                                                 : "seen in " + d.seenIn.front();
    const std::string why = code == PlanReason::EnvmapFirstMap ? "no map yet"
                            : code == PlanReason::EnvmapAlways ? "update: always"
                            : code == PlanReason::EnvmapBounce ? "a bounce redraws every map it drew"
                            : code == PlanReason::EnvmapChanged
                                ? "something it sees changed (update on-change)"
                                : timeSlice(d);
    return "renders the scene around the reflector, lit and shadowed, from its centre into " + mapLayout(d) +
           mirrors + bounceClause(d) + "; the reflector is " + where + "; " + why + reflectedMeshes(d);
}

std::string reflectorTraceSentence(PlanReason code, const ReasonDetails& d) {
    switch (code) {
    case PlanReason::ScreenColourPyramid:
        return "copies the camera's image once every pass has drawn into it, and halves it level by level "
               "(a box filter): the blurred pyramid that " +
               d.node + "'s rough trace (roughness " + rounded(d.roughness * 100) +
               "%) reads where a ray meets the image, at the level as wide as the lobe is there";
    case PlanReason::ReflectorTraceNotSeenDirectly:
        return "screen-space trace not needed: the reflector is seen only in mirrors, whose reflected views "
               "the camera's image does not hold; it reads its map there";
    default:
        return "traces the reflector's reflection through the camera's image against its depth pyramid, "
               "over what the main pass drew of it: where a ray meets what the image shows, that replaces "
               "the map's lookup and its parallax error; elsewhere the map stays" +
               std::string(d.roughness > 0.0 ? " (rough: a cone, read from the image's blurred pyramid "
                                               "against the map's rough lookup)"
                                             : "");
    }
}

std::string prefilterSentence(PlanReason code, const ReasonDetails& d) {
    switch (code) {
    case PlanReason::PrefilterSharp:
        return "GGX pre-filter not needed: the reflector's roughness is 0 (a sharp reflection reads the map "
               "itself)";
    case PlanReason::PrefilterMipFilter:
        return "GGX pre-filter not needed: settings.glossyFilter is mip (the reflector reads its map's mip "
               "chain at LOD roughness × " +
               std::to_string(d.levels - 1) + ")";
    case PlanReason::PrefilterReused:
        return "GGX pre-filter reused: the map did not change: the chain is reused";
    case PlanReason::PrefilterNoMap:
        return "no GGX pre-filtered chain: the reflector has no map";
    default:
        break;
    }
    // Which levels of the chain the reflector's roughness reads between.
    const double at = d.roughness * (d.levels - 1);
    const int below = static_cast<int>(std::floor(at));
    char roughness[32];
    std::snprintf(roughness, sizeof roughness, "%.3g", d.roughness);
    const std::string reads =
        at == below ? "reads level " + std::to_string(below)
                    : "reads between levels " + std::to_string(below) + " and " + std::to_string(below + 1);
    const char* why = code == PlanReason::PrefilterMapRendered ? "the map is rendered this frame"
                      : code == PlanReason::PrefilterSettingsChanged
                          ? "the chain was filtered with other settings (prefilterSamples)"
                          : "no chain yet";
    return "convolves " + d.node + "'s map with the GGX lobe into " + std::to_string(d.levels) +
           " levels (roughness r_k = k/" + std::to_string(d.levels - 1) + "; " + roughness + " " + reads +
           "), " + std::to_string(d.samples) + " samples a texel; " + why;
}

std::string previewSentence(PlanReason code, const ReasonDetails& d) {
    switch (code) {
    case PlanReason::PreviewScaled: {
        char percent[16];
        std::snprintf(percent, sizeof percent, "%.0f%%", d.scale * 100.0);
        return std::string("preview: drawn at ") + percent +
               " of the output's width and height and scaled up to it";
    }
    case PlanReason::PreviewMirrorDepth:
        return "preview: mirrors nest " + plural(static_cast<std::size_t>(d.limit), "level", "levels") +
               " deep, not " + std::to_string(d.asked) + " (settings.mirrorDepth)";
    case PlanReason::PreviewShadowMapSize:
        return "preview: shadow map drawn at " + std::to_string(d.mapSize) + "², not " +
               std::to_string(d.asked) + "², while a handle is dragged";
    default:
        return "preview: environment map held while the view moves (update \"" +
               std::string(names::fileName(names::kReflectorUpdates, d.update)) + "\" applies again at rest)";
    }
}

using Sentence = std::string (*)(PlanReason, const ReasonDetails&);

struct CodeEntry {
    PlanReason code;
    std::string_view name;
    Sentence sentence;
};

// Every code, in the enum's order: its name and the function that words it.
constexpr std::array<CodeEntry, kPlanReasonCount> kCodes{{
    {PlanReason::LightLimit, "light-limit", lightSentence},
    {PlanReason::ShadowsOff, "shadows-off", lightSentence},
    {PlanReason::NoShadowCasters, "no-shadow-casters", lightSentence},
    {PlanReason::NoShadowReceivers, "no-shadow-receivers", lightSentence},
    {PlanReason::ShadowedLightLimit, "shadowed-light-limit", lightSentence},
    {PlanReason::ShadowMapDoesNotFit, "shadow-map-does-not-fit", lightSentence},
    {PlanReason::ShadowMapReused, "shadow-map-reused", lightSentence},
    {PlanReason::ShadowFirstMap, "shadow-first-map", lightSentence},
    {PlanReason::ShadowChanged, "shadow-changed", lightSentence},
    {PlanReason::ShadowMapNotAllocated, "shadow-map-not-allocated", lightSentence},
    {PlanReason::MainHalfFloat, "main-half-float", mainSentence},
    {PlanReason::MainSrgb, "main-srgb", mainSentence},
    {PlanReason::MainIntoOutput, "main-into-output", mainSentence},
    {PlanReason::CompositeToFloat, "composite-to-float", compositeSentence},
    {PlanReason::CompositeCopiesSrgb, "composite-copies-srgb", compositeSentence},
    {PlanReason::CompositeStencilBlend, "composite-stencil-blend", compositeSentence},
    {PlanReason::CompositeFresnelBlend, "composite-fresnel-blend", compositeSentence},
    {PlanReason::CompositeNestedBlend, "composite-nested-blend", compositeSentence},
    {PlanReason::CompositeNotNeeded, "composite-not-needed", compositeSentence},
    {PlanReason::CompositeScreenSpace, "composite-screen-space", compositeSentence},
    {PlanReason::GuidesOverView, "guides-over-view", guidesSentence},
    {PlanReason::MirrorMaskStencil, "mirror-mask-stencil", mirrorPassSentence},
    {PlanReason::MirrorMaskCount, "mirror-mask-count", mirrorPassSentence},
    {PlanReason::MirrorIntoTexture, "mirror-into-texture", mirrorPassSentence},
    {PlanReason::MirrorInStencil, "mirror-in-stencil", mirrorPassSentence},
    {PlanReason::MirrorSurface, "mirror-surface", mirrorPassSentence},
    {PlanReason::MirrorScreenTrace, "mirror-screen-trace", mirrorPassSentence},
    {PlanReason::ScreenDepthPyramid, "screen-depth-pyramid", mirrorPassSentence},
    {PlanReason::MirrorSizeInvalid, "mirror-size-invalid", mirrorSkipSentence},
    {PlanReason::MirrorNoPlane, "mirror-no-plane", mirrorSkipSentence},
    {PlanReason::MirrorEdgeOn, "mirror-edge-on", mirrorSkipSentence},
    {PlanReason::MirrorBehind, "mirror-behind", mirrorSkipSentence},
    {PlanReason::MirrorOutsideView, "mirror-outside-view", mirrorSkipSentence},
    {PlanReason::MirrorOutsideParent, "mirror-outside-parent", mirrorSkipSentence},
    {PlanReason::MirrorBelowPixel, "mirror-below-pixel", mirrorSkipSentence},
    {PlanReason::MirrorDepthLimit, "mirror-depth-limit", mirrorSkipSentence},
    {PlanReason::MirrorViewLimit, "mirror-view-limit", mirrorSkipSentence},
    {PlanReason::MirrorNoReflectionMatrix, "mirror-no-reflection-matrix", mirrorSkipSentence},
    {PlanReason::MirrorNoObliqueProjection, "mirror-no-oblique-projection", mirrorSkipSentence},
    {PlanReason::MirrorStencilTooDeep, "mirror-stencil-too-deep", mirrorSkipSentence},
    {PlanReason::MirrorDepthZero, "mirror-depth-zero", mirrorSkipSentence},
    {PlanReason::MapMirrorDepthZero, "map-mirror-depth-zero", mirrorDroppedSentence},
    {PlanReason::MirrorOccluded, "mirror-occluded", mirrorDroppedSentence},
    {PlanReason::MirrorOccludedInTile, "mirror-occluded-in-tile", mirrorDroppedSentence},
    {PlanReason::MirrorNoTexture, "mirror-no-texture", mirrorDroppedSentence},
    {PlanReason::EnvmapFirstMap, "envmap-first-map", envmapSentence},
    {PlanReason::EnvmapAlways, "envmap-always", envmapSentence},
    {PlanReason::EnvmapChanged, "envmap-changed", envmapSentence},
    {PlanReason::EnvmapTimeSliced, "envmap-time-sliced", envmapSentence},
    {PlanReason::EnvmapOutOfSight, "envmap-out-of-sight", envmapSentence},
    {PlanReason::EnvmapDoesNotFit, "envmap-does-not-fit", envmapSentence},
    {PlanReason::EnvmapReusedOnce, "envmap-reused-once", envmapSentence},
    {PlanReason::EnvmapUnchanged, "envmap-unchanged", envmapSentence},
    {PlanReason::EnvmapNotAllocated, "envmap-not-allocated", envmapSentence},
    {PlanReason::EnvmapBounce, "envmap-bounce", envmapSentence},
    {PlanReason::EnvmapOverCap, "envmap-over-cap", envmapSentence},
    {PlanReason::BouncesUnused, "bounces-unused", envmapSentence},
    {PlanReason::BouncesCapped, "bounces-capped", envmapSentence},
    {PlanReason::PrefilterFirstChain, "prefilter-first-chain", prefilterSentence},
    {PlanReason::PrefilterMapRendered, "prefilter-map-rendered", prefilterSentence},
    {PlanReason::PrefilterSettingsChanged, "prefilter-settings-changed", prefilterSentence},
    {PlanReason::PrefilterSharp, "prefilter-sharp", prefilterSentence},
    {PlanReason::PrefilterMipFilter, "prefilter-mip-filter", prefilterSentence},
    {PlanReason::PrefilterReused, "prefilter-reused", prefilterSentence},
    {PlanReason::PrefilterNoMap, "prefilter-no-map", prefilterSentence},
    {PlanReason::ReflectorScreenTrace, "reflector-screen-trace", reflectorTraceSentence},
    {PlanReason::ScreenColourPyramid, "screen-colour-pyramid", reflectorTraceSentence},
    {PlanReason::ReflectorTraceNotSeenDirectly, "reflector-trace-not-seen-directly", reflectorTraceSentence},
    {PlanReason::PreviewScaled, "preview-scaled", previewSentence},
    {PlanReason::PreviewMirrorDepth, "preview-mirror-depth", previewSentence},
    {PlanReason::PreviewShadowMapSize, "preview-shadow-map-size", previewSentence},
    {PlanReason::PreviewEnvmapHeld, "preview-envmap-held", previewSentence},
}};

constexpr bool inEnumOrder() {
    for (std::size_t i = 0; i < kCodes.size(); ++i)
        if (kCodes[i].code != static_cast<PlanReason>(i))
            return false;
    return true;
}
static_assert(inEnumOrder(), "kCodes lists every code once, at its enum value");

const CodeEntry& entryOf(PlanReason code) {
    return kCodes.at(static_cast<std::size_t>(code));
}

} // namespace

bool isPreview(PlanReason code) {
    return code >= PlanReason::PreviewScaled;
}

bool dropsWhatTheSceneAsks(PlanReason code) {
    switch (code) {
    case PlanReason::LightLimit:
    case PlanReason::ShadowedLightLimit:
    case PlanReason::ShadowMapDoesNotFit:
    case PlanReason::ShadowMapNotAllocated:
    case PlanReason::MirrorSizeInvalid:
    case PlanReason::MirrorNoPlane:
    case PlanReason::MirrorViewLimit:
    case PlanReason::MirrorNoReflectionMatrix:
    case PlanReason::MirrorNoObliqueProjection:
    case PlanReason::MirrorStencilTooDeep:
    case PlanReason::MirrorNoTexture:
    case PlanReason::EnvmapDoesNotFit:
    case PlanReason::EnvmapNotAllocated:
    case PlanReason::EnvmapOverCap:
    case PlanReason::BouncesCapped:
    case PlanReason::PrefilterNoMap:
        return true;
    case PlanReason::ShadowsOff:
    case PlanReason::NoShadowCasters:
    case PlanReason::NoShadowReceivers:
    case PlanReason::ShadowMapReused:
    case PlanReason::ShadowFirstMap:
    case PlanReason::ShadowChanged:
    case PlanReason::MainHalfFloat:
    case PlanReason::MainSrgb:
    case PlanReason::MainIntoOutput:
    case PlanReason::CompositeToFloat:
    case PlanReason::CompositeCopiesSrgb:
    case PlanReason::CompositeStencilBlend:
    case PlanReason::CompositeFresnelBlend:
    case PlanReason::CompositeNestedBlend:
    case PlanReason::CompositeNotNeeded:
    case PlanReason::CompositeScreenSpace:
    case PlanReason::GuidesOverView:
    case PlanReason::MirrorMaskStencil:
    case PlanReason::MirrorMaskCount:
    case PlanReason::MirrorIntoTexture:
    case PlanReason::MirrorInStencil:
    case PlanReason::MirrorSurface:
    case PlanReason::MirrorScreenTrace:
    case PlanReason::ScreenDepthPyramid:
    case PlanReason::MirrorEdgeOn:
    case PlanReason::MirrorBehind:
    case PlanReason::MirrorOutsideView:
    case PlanReason::MirrorOutsideParent:
    case PlanReason::MirrorBelowPixel:
    case PlanReason::MirrorDepthLimit:
    case PlanReason::MirrorDepthZero:
    case PlanReason::MapMirrorDepthZero:
    case PlanReason::MirrorOccluded:
    case PlanReason::MirrorOccludedInTile:
    case PlanReason::EnvmapFirstMap:
    case PlanReason::EnvmapAlways:
    case PlanReason::EnvmapChanged:
    case PlanReason::EnvmapTimeSliced:
    case PlanReason::EnvmapOutOfSight:
    case PlanReason::EnvmapReusedOnce:
    case PlanReason::EnvmapUnchanged:
    case PlanReason::EnvmapBounce:
    case PlanReason::BouncesUnused:
    case PlanReason::PrefilterFirstChain:
    case PlanReason::PrefilterMapRendered:
    case PlanReason::PrefilterSettingsChanged:
    case PlanReason::PrefilterSharp:
    case PlanReason::PrefilterMipFilter:
    case PlanReason::PrefilterReused:
    case PlanReason::ReflectorScreenTrace:
    case PlanReason::ScreenColourPyramid:
    case PlanReason::ReflectorTraceNotSeenDirectly:
    case PlanReason::PreviewScaled:
    case PlanReason::PreviewMirrorDepth:
    case PlanReason::PreviewShadowMapSize:
    case PlanReason::PreviewEnvmapHeld:
        return false;
    }
    return false;
}

std::string_view toString(PlanReason code) {
    return entryOf(code).name;
}

std::ostream& operator<<(std::ostream& out, PlanReason code) {
    return out << toString(code);
}

std::string formatReason(PlanReason code, const ReasonDetails& details) {
    return entryOf(code).sentence(code, details);
}

} // namespace speculum::render
