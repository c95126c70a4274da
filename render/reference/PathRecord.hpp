#pragma once

#include "render/reference/IdBuffer.hpp"

#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace speculum::render::reference {

// What one light gave a shaded point (lighting.glsl's loop): Blinn-Phong's two terms, already multiplied
// by the material's weights, and how much of the light the shadow test let through.
struct LightTerm {
    int light = -1;           // index into FrameInput::lights
    double nDotL = 0.0;       // ≤ 0: the light is behind the surface and gives nothing
    double cone = 1.0;        // a spot light's falloff (1 for other lights)
    bool shadowed = false;    // the light casts shadows (the planner gave it a map): a shadow test ran
    double visibility = 1.0;  // the shadow test's answer: 1 lit, 0 in shadow, between for PCF's footprint
    glm::dvec3 diffuse{0.0};  // base · diffuse · radiance · n·l · visibility
    glm::dvec3 specular{0.0}; // specular · specularColor · radiance · (n·h)^shininess · visibility
};

// material.glsl's shadeMaterial() term by term: total = emitted + ambient + Σ diffuse + Σ specular.
struct ShadingTerms {
    glm::dvec3 normal{0.0}; // the normal lighting used: the interpolated one, bent by the normal map if any
    glm::dvec3 base{0.0};   // colour × texture × vertex colour
    glm::dvec3 emitted{0.0};
    glm::dvec3 ambient{0.0};
    std::vector<LightTerm> lights;
    glm::dvec3 total{0.0};
};

// One event along a traced path, in the order the path met them.
enum class PathEventKind {
    Mirror,     // a planar mirror's reflective side: its surface part, then the reflection followed
    Reflector,  // a curved reflector: the same
    Surface,    // an object, a mirror's back, or a reflector or mirror shown with its plain material
    Background, // the ray left the scene
    DepthLimit, // a mirror met beyond the depth: its reflection adds nothing
    LostBelow,  // a rough lobe sample went below the surface: its reflection adds nothing
};

std::string_view toString(PathEventKind kind);

struct PathVertex {
    PathEventKind kind = PathEventKind::Surface;
    PixelId hit;              // what the ray met (Background: nothing)
    glm::dvec3 from{0.0};     // world: where the ray started
    glm::dvec3 position{0.0}; // world: where it met the surface (from + a long way for the background)
    glm::dvec3 normal{0.0};   // unit interpolated normal at the hit, on the viewer's side (no normal map)
    glm::dvec3 incoming{0.0}; // unit direction of the ray that arrived
    glm::dvec3 outgoing{0.0}; // Mirror, Reflector: unit direction of the reflected ray followed
    glm::dvec3 mirrored{0.0}; // Mirror, Reflector: the perfect mirror direction (= outgoing when sharp)
    double distance = 0.0;    // world length of the segment from `from` to `position`
    int mirrorLevel = 0;      // planar reflections before this one (since the last reflector)
    int reflectorLevel = 0;   // curved-reflector bounces before this one
    // Mirror, Reflector: the reflectivity R used (Schlick's with fresnel), the surface's share 1 − R, the
    // mirror's tint, and for a rough one the lobe: roughness, and the sample's weight G2/G1.
    double reflectivity = 0.0;
    bool fresnel = false;
    glm::dvec3 tint{1.0};
    double roughness = 0.0;
    double lobeWeight = 1.0;
    // Surface (and the surface part of a Mirror or Reflector with R < 1): material.glsl's terms.
    ShadingTerms shading;
    bool shaded = false;
    glm::dvec3 colour{0.0}; // the radiance this vertex sent back along `incoming`
    // How much of this vertex's colour reaches the camera: the product of R · tint · lobe weight of the
    // reflections before it (1 at the first vertex). weight · colour is its share of the path's colour.
    glm::dvec3 weight{1.0};
};

// One path, camera first. `colour` is what it brought to the camera.
struct TracedPath {
    std::vector<PathVertex> vertices;
    glm::dvec3 colour{0.0};
};

// Fills each vertex's `weight` from the reflections before it.
void weighPath(TracedPath& path);

} // namespace speculum::render::reference
