#pragma once

#include "render/frame/Field.hpp"
#include "render/frame/Material.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/mesh/MeshData.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>

namespace speculum::render {

enum class ReflectorMap { Cube, DualParaboloid, TennisBall, Octahedral };
// How the dual-paraboloid and tennis-ball maps are filled: warping the scene's vertices (the reference's
// method, needs fine tessellation) or resampling a cube map rendered first (exact up to the cube's
// resolution). The octahedral map is always resampled: a triangle cannot be warped across the
// octahedron's folds.
enum class ReflectorFill { Direct, Resampled };
// Whether the map's fill applies: the dual-paraboloid and tennis-ball maps.
constexpr bool warpable(ReflectorMap map) {
    return map == ReflectorMap::DualParaboloid || map == ReflectorMap::TennisBall;
}
// When the map is rendered again: every frame, when something it sees changed, or once.
enum class ReflectorUpdate { Always, OnChange, Once, TimeSliced };
enum class ParallaxShape { Sphere, Box };
// How the reflection is drawn: the map alone, or traced in the camera's image first (a reflector seen
// directly; a rough one as a cone read from the image's blurred pyramid), the map where the trace finds
// nothing.
enum class ReflectorTechnique { Map, ScreenSpace };
static_assert(int(ReflectorMap::Octahedral) + 1 == names::kReflectorMaps.size(), "one name per value");
static_assert(int(ReflectorFill::Resampled) + 1 == names::kReflectorFills.size(), "one name per value");
static_assert(int(ReflectorUpdate::TimeSliced) + 1 == names::kReflectorUpdates.size(), "one name per value");
static_assert(int(ParallaxShape::Box) + 1 == names::kParallaxShapes.size(), "one name per value");
static_assert(int(ReflectorTechnique::ScreenSpace) + 1 == names::kReflectorTechniques.size(),
              "one name per value");

// Parallax correction: a proxy of the environment around the capture point (the reflector's centre), in
// world axes and units relative to that point. Lookups intersect the reflected ray with it.
struct ParallaxParams {
    ParallaxShape shape = ParallaxShape::Sphere;
    double radius = 5.0;              // sphere
    glm::dvec3 min{-5.0, -5.0, -5.0}; // box, relative to the capture point
    glm::dvec3 max{5.0, 5.0, 5.0};

    bool operator==(const ParallaxParams&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

template <typename Visit>
void ParallaxParams::fields(Visit&& visit) {
    constexpr auto sphere = [](const ParallaxParams& p) { return p.shape == ParallaxShape::Sphere; };
    constexpr auto box = [](const ParallaxParams& p) { return p.shape == ParallaxShape::Box; };
    visit(field(&ParallaxParams::shape, {.name = "shape",
                                         .label = "Proxy shape",
                                         .meaning = "A sphere or a box around the reflector's centre",
                                         .type = FieldType::Choice,
                                         .noun = "parallax shape",
                                         .choices = names::kParallaxShapes}));
    visit(field(&ParallaxParams::radius,
                {.name = "radius",
                 .label = "Proxy radius",
                 .meaning = "Radius of the proxy sphere around the reflector's centre",
                 .min = kMinScale,
                 .max = kMaxCoordinate,
                 .unit = " u"},
                sphere));
    visit(field(
        &ParallaxParams::min,
        {.name = "min",
         .label = "Proxy box min",
         .meaning = "The box's lower corner relative to the reflector's centre: every component below 0",
         .type = FieldType::Vector3,
         .min = -kMaxCoordinate,
         .max = kMaxCoordinate,
         .unit = " u",
         .noun = "coordinates"},
        box));
    visit(field(
        &ParallaxParams::max,
        {.name = "max",
         .label = "Proxy box max",
         .meaning = "The box's upper corner relative to the reflector's centre: every component above 0",
         .type = FieldType::Vector3,
         .min = -kMaxCoordinate,
         .max = kMaxCoordinate,
         .unit = " u",
         .noun = "coordinates"},
        box));
}

// What is wrong with a proxy beyond its single fields (a box that does not contain the capture point), as
// {field name, message}, or nothing.
std::optional<std::pair<std::string_view, std::string>> parallaxProblem(const ParallaxParams& proxy);

// The curved reflector as the scene holds it; its surface is its node's mesh.
struct ReflectorParams {
    ReflectorMap map = ReflectorMap::Cube;
    int resolution = 256;
    double reflectivity = 1.0; // at normal incidence when fresnel is on
    bool fresnel = false;
    ReflectorFill fill = ReflectorFill::Resampled; // the warpable maps only
    std::optional<ParallaxParams> parallax;        // none: lookups treat everything as infinitely far
    ReflectorUpdate update = ReflectorUpdate::OnChange;
    int mirrorDepth = 1;    // planar-mirror levels inside the environment map
    double roughness = 0.0; // 0..1, GGX roughness of the reflection as for a mirror's
    ReflectorTechnique technique = ReflectorTechnique::Map;

    bool operator==(const ReflectorParams&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

template <typename Visit>
void ReflectorParams::fields(Visit&& visit) {
    constexpr auto nonLinear = [](const ReflectorParams& r) { return warpable(r.map); };
    // What only the lookups read (not what the map draws) says .drawnInMaps = false.
    visit(field(&ReflectorParams::map,
                {.name = "map",
                 .label = "Environment map",
                 .meaning = "The map's layout: a cube, two paraboloids, a tennis ball, or an octahedron",
                 .type = FieldType::Choice,
                 .noun = "reflector map",
                 .choices = names::kReflectorMaps}));
    visit(field(&ReflectorParams::resolution,
                {.name = "resolution",
                 .label = "Resolution",
                 .meaning =
                     "Texels per cube face side, per paraboloid side, of the tennis ball's short side, or of "
                     "the octahedral square's side",
                 .type = FieldType::Integer,
                 .min = kMinEnvironmentMapSize,
                 .max = kMaxEnvironmentMapSize,
                 .unit = " px",
                 .decimals = 0,
                 .step = 32}));
    visit(field(&ReflectorParams::reflectivity,
                {.name = "reflectivity",
                 .label = "Reflectivity",
                 .meaning = "How much of the reflection shows; 1 = perfect mirror",
                 .min = 0,
                 .max = 1,
                 .slider = true,
                 .drawnInMaps = false}));
    visit(field(&ReflectorParams::fresnel,
                {.name = "fresnel",
                 .label = "Fresnel",
                 .meaning = "Schlick: the reflectivity applies at normal incidence and rises to 1 at grazing "
                            "angles",
                 .type = FieldType::Bool,
                 .drawnInMaps = false}));
    visit(
        field(&ReflectorParams::fill,
              {.name = "fill",
               .label = "Fill",
               .meaning = "How dual-paraboloid and tennis-ball maps are filled; the cube and octahedral maps "
                          "ignore it",
               .type = FieldType::Choice,
               .noun = "reflector fill",
               .choices = names::kReflectorFills,
               .write = FieldWrite::Everywhere},
              nonLinear));
    visit(
        field(&ReflectorParams::parallax,
              {.name = "parallax",
               .label = "Parallax proxy",
               .meaning = "Corrects the map's lookups for the distance to what it shows: each reflected ray "
                          "is intersected with this sphere or box around the reflector's centre (world "
                          "axes); absent, everything is treated as infinitely far away",
               .type = FieldType::Object,
               .drawnInMaps = false}));
    visit(field(&ReflectorParams::update,
                {.name = "update",
                 .label = "Update",
                 .meaning = "When the map is drawn again: every frame, when something "
                            "it sees changes, once, or time-sliced: one face (one part of a "
                            "direct fill) a frame, in turn, while any shows an older scene",
                 .type = FieldType::Choice,
                 .noun = "reflector update",
                 .choices = names::kReflectorUpdates,
                 .drawnInMaps = false}));
    visit(field(&ReflectorParams::mirrorDepth,
                {.name = "mirrorDepth",
                 .label = "Mirror depth in the map",
                 .meaning =
                     "How many levels of planar mirrors reflect inside the environment map, mirrors seen "
                     "in mirrors included; 0 shows only their surface's share (1 − reflectivity)",
                 .type = FieldType::Integer,
                 .min = 0,
                 .max = kMaxMirrorDepth}));
    visit(field(&ReflectorParams::roughness,
                {.name = "roughness",
                 .label = "Roughness",
                 .meaning = "GGX microfacet roughness (α = roughness²): 0 is a perfect mirror; rougher looks "
                            "up a pre-filtered level of the map",
                 .min = 0,
                 .max = 1,
                 .slider = true,
                 .drawnInMaps = false}));
    visit(field(&ReflectorParams::technique,
                {.name = "technique",
                 .label = "Technique",
                 .meaning = "The environment map alone, or traced in the camera's image first (screen "
                            "space: what the image shows has no parallax error), the map where the trace "
                            "finds nothing. Sharp reflectors seen directly only",
                 .type = FieldType::Choice,
                 .noun = "reflector technique",
                 .choices = names::kReflectorTechniques,
                 .write = FieldWrite::UnlessDefault,
                 .drawnInMaps = false,
                 .sweepName = "reflectorTechnique"}));
}

// The reflector of the frame: its parameters, where it is, its surface and material.
struct Reflector : ReflectorParams {
    std::string name;
    glm::dmat4 world{1.0};
    MeshHandle mesh;
    Material material;
};

} // namespace speculum::render
