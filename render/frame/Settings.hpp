#pragma once

#include "render/frame/Field.hpp"
#include "render/frame/SceneLimits.hpp"

#include <algorithm>
#include <glm/vec3.hpp>

namespace speculum::render {

// How the rasterizer approximates a rough (glossy) reflection; the exact answer is the tracer's.
// Mip: one lookup in the reflection's mip chain at a level set by the roughness alone (the cheap end).
// Footprint: planar mirrors sample their reflection texture over the GGX lobe's footprint, which grows with
// the distance from the mirror to what it reflects; the curved reflector reads the level of its
// GGX-convolved (pre-filtered) map chain that matches its roughness.
// Chain: planar mirrors convolve their reflection once into a mip chain of Gaussian-filtered levels and
// read it with two lookups at the level the lobe's footprint asks for (its stretch along the plane of
// incidence kept); the curved reflector reads its pre-filtered chain, as with Footprint.
enum class GlossyFilter { Mip, Footprint, Chain };
static_assert(int(GlossyFilter::Chain) + 1 == names::kGlossyFilters.size(), "one name per value");

// Where a screen-space mirror's ray that meets nothing in the camera's image takes its reflection from:
// the environment map of the first curved reflector with a mesh used as a probe (parallax-corrected when it
// has a proxy), and the background where there is no map; or the background alone.
enum class ScreenFallback { Map, Background };
static_assert(int(ScreenFallback::Background) + 1 == names::kScreenFallbacks.size(), "one name per value");
// The resolution a screen-space mirror is traced at: every pixel, or one ray for four pixels, scaled up.
enum class ScreenResolution { Full, Half };
static_assert(int(ScreenResolution::Half) + 1 == names::kScreenResolutions.size(), "one name per value");

// The scene's own settings (the project file's "settings").
struct Settings {
    glm::dvec3 background{0.1, 0.1, 0.12};
    int mirrorDepth = 3;
    double ambient = 0.2;
    // Reflected views and the environment map draw big meshes at their simplified level
    // (MeshData::coarse): an approximation the bench's reflected-detail family measures.
    bool simplifyReflections = true;
    // The chain: within 1 dB of 16 footprint taps against the tracer at roughness 0.1, 0.3 and 0.6, for
    // four lookups a pixel up to roughness 0.4 (GlossyAgreementGLTest).
    GlossyFilter glossyFilter = GlossyFilter::Chain;
    int glossyTaps = 16;       // lobe samples per pixel of a rough planar mirror (Footprint)
    int prefilterSamples = 64; // lobe samples per texel of the reflector's pre-filtered chain (Footprint)
    // Screen-space mirrors: the trace's steps through the camera's depth pyramid, and how far behind a
    // surface the image shows (a share of its view depth) a ray still counts as meeting it.
    int screenSteps = 64;
    double screenThickness = 0.03;
    ScreenFallback screenFallback = ScreenFallback::Map;
    ScreenResolution screenResolution = ScreenResolution::Full;
    // Curved reflectors seen in each other's maps: 0 draws the others with their plain material; bounce k
    // draws them with their maps of bounce k − 1.
    int reflectorBounces = 0;

    bool operator==(const Settings&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);

private:
    // The screen-space trace's and the reflectors' settings, in the order fields() visits them after the
    // rest.
    template <typename Visit>
    static void traceAndReflectorFields(Visit& visit);
};

template <typename Visit>
void Settings::fields(Visit&& visit) {
    visit(field(&Settings::background, {.name = "background",
                                        .label = "Background",
                                        .meaning = "The colour of everything no surface covers",
                                        .type = FieldType::Color}));
    visit(field(&Settings::mirrorDepth,
                {.name = "mirrorDepth",
                 .label = "Mirror depth",
                 .meaning = "How many levels of reflections of reflections planar mirrors show",
                 .type = FieldType::Integer,
                 .min = 0,
                 .max = kMaxMirrorDepth,
                 .drawnInMaps = false}));
    visit(field(&Settings::ambient, {.name = "ambient",
                                     .label = "Ambient",
                                     .meaning = "The light that reaches every surface from everywhere",
                                     .type = FieldType::Number,
                                     .min = 0,
                                     .max = 1,
                                     .slider = true}));
    visit(field(&Settings::simplifyReflections,
                {.name = "simplifyReflections",
                 .label = "Simplify reflections",
                 .meaning = "Reflections draw big meshes at their simplified level; off draws every triangle",
                 .type = FieldType::Bool,
                 .choices = names::kReflectedDetail,
                 .write = FieldWrite::UnlessDefault,
                 .sweepName = "reflectedDetail"}));
    visit(field(&Settings::glossyFilter,
                {.name = "glossyFilter",
                 .label = "Glossy filter",
                 .meaning = "How rough reflections are blurred: one mip level (cheap); the GGX lobe's "
                            "footprint on planar mirrors (taps per pixel); or a convolved chain read at the "
                            "footprint's level (four lookups, 12 taps of it above roughness 0.4). The "
                            "reflector reads its pre-filtered map with either of the last two",
                 .type = FieldType::Choice,
                 .noun = "glossy filter",
                 .choices = names::kGlossyFilters,
                 .write = FieldWrite::UnlessDefault,
                 .drawnInMaps = false}));
    visit(field(&Settings::glossyTaps,
                {.name = "glossyTaps",
                 .label = "Glossy taps",
                 .meaning = "Lobe samples per pixel of a rough planar mirror (footprint filter)",
                 .type = FieldType::Integer,
                 .min = kMinGlossyTaps,
                 .max = kMaxGlossyTaps,
                 .write = FieldWrite::UnlessDefault,
                 .drawnInMaps = false}));
    visit(field(&Settings::prefilterSamples,
                {.name = "prefilterSamples",
                 .label = "Pre-filter samples",
                 .meaning = "Lobe samples per texel of the rough reflector's pre-filtered map chain",
                 .type = FieldType::Integer,
                 .min = kMinPrefilterSamples,
                 .max = kMaxPrefilterSamples,
                 .write = FieldWrite::UnlessDefault,
                 .drawnInMaps = false}));
    traceAndReflectorFields(visit);
}

template <typename Visit>
void Settings::traceAndReflectorFields(Visit& visit) {
    visit(field(&Settings::screenSteps,
                {.name = "screenSteps",
                 .label = "Screen-space steps",
                 .meaning = "Steps a screen-space mirror's ray takes through the camera's depth pyramid "
                            "before it gives up and shows the background",
                 .type = FieldType::Integer,
                 .min = kMinScreenSteps,
                 .max = kMaxScreenSteps,
                 .write = FieldWrite::UnlessDefault,
                 .drawnInMaps = false}));
    visit(field(&Settings::screenThickness,
                {.name = "screenThickness",
                 .label = "Screen-space thickness",
                 .meaning = "How far behind what the image shows a screen-space ray still meets it, as a "
                            "share of its distance: thin, rays pass behind objects; thick, they stop at "
                            "silhouettes they should pass",
                 .min = kMinScreenThickness,
                 .max = kMaxScreenThickness,
                 .write = FieldWrite::UnlessDefault,
                 .drawnInMaps = false}));
    visit(field(&Settings::screenFallback,
                {.name = "screenFallback",
                 .label = "Screen-space fallback",
                 .meaning = "Where a screen-space mirror's ray that meets nothing in the image takes its "
                            "reflection from: the reflector's environment map (parallax-corrected when it "
                            "has a proxy), or the background",
                 .type = FieldType::Choice,
                 .noun = "screen-space fallback",
                 .choices = names::kScreenFallbacks,
                 .write = FieldWrite::UnlessDefault,
                 .drawnInMaps = false}));
    visit(field(&Settings::screenResolution,
                {.name = "screenResolution",
                 .label = "Screen-space resolution",
                 .meaning = "Trace every pixel of a screen-space mirror, or one ray for each two by two "
                            "pixels scaled up (a quarter of the cost, softer edges)",
                 .type = FieldType::Choice,
                 .noun = "screen-space resolution",
                 .choices = names::kScreenResolutions,
                 .write = FieldWrite::UnlessDefault,
                 .drawnInMaps = false}));
    visit(field(&Settings::reflectorBounces,
                {.name = "reflectorBounces",
                 .label = "Reflector bounces",
                 .meaning = "How often curved reflectors see each other: 0 shows the others in a reflector's "
                            "map with their plain material; each bounce draws them with the maps the bounce "
                            "before made",
                 .type = FieldType::Integer,
                 .min = 0,
                 .max = kMaxReflectorBounces,
                 .write = FieldWrite::UnlessDefault,
                 .sweepName = "bounces"}));
}

// The lobe samples a rough planar mirror takes per pixel, within the limits whatever the settings hold.
inline int glossyTapCount(const Settings& settings) {
    return std::clamp(settings.glossyTaps, kMinGlossyTaps, kMaxGlossyTaps);
}

// The camera the scene is drawn from (the project file's "camera"). Its rules across fields (a target
// away from the position, an up not along the view, far beyond near) are the scene model's checks.
struct Camera {
    glm::dvec3 position{0.0, 0.0, 1.0};
    glm::dvec3 target{0.0, 0.0, -3.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovY = 65.0; // degrees, vertical
    double near = 0.1;
    double far = 10.0;

    bool operator==(const Camera&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

template <typename Visit>
void Camera::fields(Visit&& visit) {
    const FieldSpec point{.type = FieldType::Vector3,
                          .min = -kMaxCoordinate,
                          .max = kMaxCoordinate,
                          .unit = " u",
                          .noun = "coordinates"};
    FieldSpec position = point, target = point;
    position.name = "position", position.label = "Position", position.meaning = "Where the camera is";
    target.name = "target", target.label = "Target", target.meaning = "The point the camera looks at";
    visit(field(&Camera::position, position));
    visit(field(&Camera::target, target));
    FieldSpec up = point;
    up.name = "up", up.label = "Up", up.unit = {};
    up.meaning = "The direction that is up in the picture (any length, not along the view)";
    visit(field(&Camera::up, up));
    visit(field(&Camera::fovY, {.name = "fovY",
                                .label = "Field of view",
                                .meaning = "The vertical field of view",
                                .type = FieldType::Number,
                                .min = 0,
                                .max = 180,
                                .minOpen = true,
                                .maxOpen = true,
                                .unit = "°",
                                .decimals = 1,
                                .step = 1}));
    visit(field(&Camera::near, {.name = "near",
                                .label = "Near",
                                .meaning = "The distance from the camera where drawing starts",
                                .type = FieldType::Number,
                                .min = kMinNear,
                                .max = kMaxCoordinate,
                                .unit = " u"}));
    visit(field(&Camera::far,
                {.name = "far",
                 .label = "Far",
                 .meaning = "The distance from the camera where drawing ends: beyond near, and at most a "
                            "million times near for the depth buffer's precision",
                 .type = FieldType::Number,
                 .min = 0,
                 .minOpen = true,
                 .unit = " u"}));
}

} // namespace speculum::render
