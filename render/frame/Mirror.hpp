#pragma once

#include "render/frame/Field.hpp"
#include "render/frame/Material.hpp"
#include "render/frame/SceneLimits.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>

namespace speculum::render {

// ScreenSpace: the reflection is traced through the camera's own image and depth, as game engines'
// screen-space reflections are; what the image does not hold shows the background.
enum class MirrorTechnique { Stencil, Texture, ScreenSpace };
static_assert(int(MirrorTechnique::ScreenSpace) + 1 == names::kMirrorTechniques.size(), "one name per value");

// A planar mirror as the scene holds it: a rectangle centred at its node's origin in the local XZ plane,
// the reflective side towards local +Y.
struct MirrorParams {
    glm::dvec2 size{1.0, 1.0}; // local X and Z extents of the rectangle
    double reflectivity = 1.0; // at normal incidence when fresnel is on
    MirrorTechnique technique = MirrorTechnique::Stencil;
    glm::dvec3 tint{1.0, 1.0, 1.0}; // multiplies the reflected light
    bool fresnel = false;           // Schlick: reflectivity rises towards 1 at grazing angles
    // 0..1: GGX (Trowbridge–Reitz) microfacet roughness, α = roughness²; 0 is a perfect mirror.
    double roughness = 0.0;
#ifdef SPECULUM_FIELD_PROBE
    // A field only the field-declaration test's own build has (tests/editor/document): added here and in
    // fields() below and nowhere else, it must be read, written, shown, hashed and swept.
    double probe = 0.5;
#endif

    bool operator==(const MirrorParams&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

template <typename Visit>
void MirrorParams::fields(Visit&& visit) {
    visit(field(&MirrorParams::size, {.name = "size",
                                      .label = "Size",
                                      .meaning = "Extents along the node's local X and Z",
                                      .type = FieldType::Vector2,
                                      .min = kMinScale,
                                      .max = kMaxCoordinate,
                                      .unit = " u",
                                      .noun = "extents"}));
    visit(field(&MirrorParams::reflectivity,
                {.name = "reflectivity",
                 .label = "Reflectivity",
                 .meaning = "How much of the reflection shows through the mirror's own material; 1 = perfect "
                            "mirror",
                 .min = 0,
                 .max = 1,
                 .slider = true}));
    visit(field(&MirrorParams::technique,
                {.name = "technique",
                 .label = "Technique",
                 .meaning = "How the reflection is drawn: through the stencil buffer, "
                            "into a texture, or traced in the camera's image "
                            "(screen space)",
                 .type = FieldType::Choice,
                 .noun = "mirror technique",
                 .choices = names::kMirrorTechniques,
                 .drawnInMaps = false}));
    visit(field(
        &MirrorParams::tint,
        {.name = "tint", .label = "Tint", .meaning = "Multiplies the reflection", .type = FieldType::Color}));
    visit(field(&MirrorParams::fresnel,
                {.name = "fresnel",
                 .label = "Fresnel",
                 .meaning = "Schlick: the reflectivity applies at normal incidence and rises to 1 at grazing "
                            "angles",
                 .type = FieldType::Bool}));
    visit(
        field(&MirrorParams::roughness,
              {.name = "roughness",
               .label = "Roughness",
               .meaning = "GGX microfacet roughness (α = roughness²): 0 is a perfect mirror; a rough mirror "
                          "is drawn with the texture technique",
               .min = 0,
               .max = 1,
               .formerName = "blur",
               .slider = true,
               .drawnInMaps = false}));
#ifdef SPECULUM_FIELD_PROBE
    static constexpr double kProbeValues[] = {0.25, 0.75};
    visit(field(&MirrorParams::probe, {.name = "probe",
                                       .label = "Probe",
                                       .meaning = "A setting of the field-declaration test's build",
                                       .min = 0,
                                       .max = 1,
                                       .slider = true,
                                       .sweep = kProbeValues}));
#endif
}

// A mirror of the frame: its parameters, where it is, and its own material (a tinted or textured mirror).
struct Mirror : MirrorParams {
    std::string name;
    glm::dmat4 world{1.0};
    Material material;
    bool hasMaterial = false;
};

} // namespace speculum::render
