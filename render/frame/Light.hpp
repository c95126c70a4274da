#pragma once

#include "render/frame/Field.hpp"
#include "render/frame/SceneLimits.hpp"

#include <glm/vec3.hpp>
#include <optional>
#include <string>

namespace speculum::render {

enum class LightType { Point, Directional, Spot };
static_assert(int(LightType::Spot) + 1 == names::kLightTypes.size(), "one name per value");

// A light's shadow map: present on a light that casts shadows.
struct ShadowParams {
    int mapSize = 1024; // texels per side, a power of two
    int pcf = 1;        // odd kernel width in texels; 1 = hard shadows

    bool operator==(const ShadowParams&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

template <typename Visit>
void ShadowParams::fields(Visit&& visit) {
    visit(field(&ShadowParams::mapSize, {.name = "mapSize",
                                         .label = "Shadow map size",
                                         .meaning = "Texels along each side of the shadow map",
                                         .type = FieldType::Integer,
                                         .min = kMinShadowMapSize,
                                         .max = kMaxShadowMapSize,
                                         .rule = FieldRule::PowerOfTwo,
                                         .unit = " px"}));
    visit(field(&ShadowParams::pcf, {.name = "pcf",
                                     .label = "Shadow softness (PCF)",
                                     .meaning = "Odd filter width in shadow-map texels; 1 = hard shadows",
                                     .type = FieldType::Integer,
                                     .min = kMinPcfWidth,
                                     .max = kMaxPcfWidth,
                                     .rule = FieldRule::Odd,
                                     .unit = " texels",
                                     .noun = "kernel width",
                                     .decimals = 0,
                                     .step = 2}));
}

// What a light is, as the scene holds it; where it is comes from its node.
struct LightParams {
    LightType type = LightType::Point;
    glm::dvec3 color{1.0};
    double intensity = 1.0;
    double spotAngle = 30.0;             // outer half angle, degrees
    double spotBlend = 0.15;             // fraction of the cone over which the edge fades
    std::optional<ShadowParams> shadows; // present: the light casts shadows

    bool operator==(const LightParams&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

template <typename Visit>
void LightParams::fields(Visit&& visit) {
    constexpr auto spot = [](const LightParams& l) { return l.type == LightType::Spot; };
    visit(field(&LightParams::type,
                {.name = "type",
                 .label = "Type",
                 .meaning = "Point (all around), directional (along the node's −Y, like the "
                            "sun) or spot (a cone along −Y)",
                 .type = FieldType::Choice,
                 .noun = "light type",
                 .choices = names::kLightTypes}));
    visit(field(
        &LightParams::color,
        {.name = "color", .label = "Colour", .meaning = "The light's colour", .type = FieldType::Color}));
    visit(field(&LightParams::intensity, {.name = "intensity",
                                          .label = "Intensity",
                                          .meaning = "Multiplies the colour",
                                          .min = 0,
                                          .max = kMaxIntensity,
                                          .slider = true,
                                          .softMax = 5.0}));
    visit(field(&LightParams::spotAngle,
                {.name = "spotAngle",
                 .label = "Spot angle",
                 .meaning = "Outer half angle of a spot's cone",
                 .min = 0,
                 .max = 90,
                 .minOpen = true,
                 .unit = "°",
                 .slider = true,
                 .softMin = 1,
                 .softMax = 90,
                 .decimals = 1,
                 .step = 1},
                spot));
    visit(field(&LightParams::spotBlend,
                {.name = "spotBlend",
                 .label = "Spot blend",
                 .meaning = "Fraction of a spot's cone over which its edge fades",
                 .min = 0,
                 .max = 1,
                 .slider = true},
                spot));
    visit(
        field(&LightParams::shadows, {.name = "shadows",
                                      .label = "Casts shadows",
                                      .meaning = "The light's shadow map; absent, the light casts no shadows",
                                      .type = FieldType::Object}));
}

// A light of the frame: its parameters, where it is and which way it points.
struct Light : LightParams {
    std::string name;
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0, -1.0, 0.0}; // unit; directional and spot lights
};

} // namespace speculum::render
