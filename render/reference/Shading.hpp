#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/reference/PathRecord.hpp"
#include "render/reference/SceneGeometry.hpp"
#include "render/reference/TextureSampler.hpp"
#include "render/reference/Tracer.hpp"

#include <glm/vec3.hpp>
#include <vector>

namespace speculum::render::reference {

// A light as lighting.glsl receives it: camera-relative, unit direction, radiance, cone cosines, and
// the shadow map it would have (if the planner gives it one).
struct ShadingLight {
    LightType type = LightType::Point;
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0, -1.0, 0.0};
    glm::dvec3 radiance{1.0};
    double cosOuter = 0.0;
    double cosInner = 0.0;
    bool shadowed = false;
    // The shadow map's footprint (ShadowMode::PcfFootprint).
    bool cubeMap = false;
    bool perspectiveMap = false;
    double texelSize = 0.0; // world size of a texel, at unit distance for perspective maps
    int mapSize = 1024;
    int pcf = 1;
};

// Lights `input` the way the rasterizer does: the first kMaxLights lights, with the planner's choice of
// shadowed lights. `origin` is the world point that is (0,0,0) in the tracer (the camera).
std::vector<ShadingLight> shadingLights(const FrameInput& input, const glm::dvec3& origin);

// Blinn-Phong of material.glsl / lighting.glsl at one point.
class Shader {
public:
    Shader(const std::vector<ShadingLight>& lights, const SceneGeometry& geometry, const TextureSet& textures,
           double sceneAmbient, ShadowMode shadows)
        : m_lights(lights)
        , m_geometry(geometry)
        , m_textures(textures)
        , m_sceneAmbient(sceneAmbient)
        , m_shadows(shadows) {}

    // shadeMaterial() of material.glsl: emitted + base·(ambient·sceneAmbient + diffuse·Σ) +
    // specular·specularColor·Σ with base = color·texture·vertex colour, emitted = emission·emission
    // texture, and the normal bent by the normal map where the hit has a tangent. `viewDir` is the unit
    // direction from the point towards the (virtual) eye; `textures` index the texture set. `terms`, when
    // given, receives the result term by term (explaining a pixel); light indices are those of FrameInput.
    glm::dvec3 shade(const Material& material, const MaterialTextures& textures, const Hit& hit,
                     const glm::dvec3& viewDir, ShadingTerms* terms = nullptr) const;

    // Fraction of the light that reaches `hit` (1 for an unshadowed light).
    double visibility(const ShadingLight& light, const Hit& hit, const glm::dvec3& toLight,
                      double distanceToLight) const;

private:
    double pcfVisibility(const ShadingLight& light, const Hit& hit, const glm::dvec3& toLight,
                         double distanceToLight) const;

    const std::vector<ShadingLight>& m_lights;
    const SceneGeometry& m_geometry;
    const TextureSet& m_textures;
    double m_sceneAmbient;
    ShadowMode m_shadows;
};

} // namespace speculum::render::reference
