#pragma once

#include "render/FrameInput.hpp"
#include "render/Result.hpp"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace speculum::render::reference {

enum class SurfaceKind : std::uint8_t { Object, Mirror, Reflector };

// One triangle mesh of the frame in camera-relative world coordinates (double precision; Embree gets a
// float copy). Only valid triangles are kept: indices in range and finite positions.
struct Surface {
    SurfaceKind kind = SurfaceKind::Object;
    int index = 0; // into FrameInput::items or ::mirrors; 0 for the reflector
    bool castsShadows = false;
    bool flipped = false; // the world matrix mirrors (det < 0): CCW triangles face the other way
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals; // world space, unnormalised; empty if the mesh has none
    std::vector<glm::vec2> uvs;      // empty if the mesh has none
    std::vector<std::uint32_t> indices;
};

// Where a ray met a surface, with everything shading needs.
struct Hit {
    const Surface* surface = nullptr;
    double t = 0.0;
    glm::dvec3 position{0.0};        // camera-relative world
    glm::dvec3 outwardNormal{0.0};   // unit geometric normal of the triangle's front (CCW) side
    glm::dvec3 normal{0.0};          // unit shading normal, turned towards the ray's origin side
    glm::dvec3 geometricNormal{0.0}; // unit geometric normal on the ray's origin side
    glm::dvec2 uv{0.0};
    bool frontFacing = true; // the ray met the front side (what gl_FrontFacing says)
};

// The Embree device and two scenes: everything (camera, mirror and reflection rays) and the shadow casters
// (shadow rays). Thread-safe for queries once built.
class SceneGeometry {
public:
    // `origin` is the world point that becomes (0,0,0): the camera position.
    static Result<std::unique_ptr<SceneGeometry>> build(const FrameInput& input, const glm::dvec3& origin,
                                                        std::vector<std::string>& warnings);
    ~SceneGeometry();
    SceneGeometry(const SceneGeometry&) = delete;
    SceneGeometry& operator=(const SceneGeometry&) = delete;

    // The nearest hit with t in [tnear, tfar]; `direction` need not be unit (t is in its units).
    std::optional<Hit> intersect(const glm::dvec3& origin, const glm::dvec3& direction, double tnear,
                                 double tfar) const;
    // Whether any shadow caster lies on the segment origin + t·direction, t in [tnear, tfar].
    bool occluded(const glm::dvec3& origin, const glm::dvec3& direction, double tnear, double tfar) const;

    // A distance that lifts a ray's origin off the surface it leaves, larger than the float rounding of
    // Embree's copy of the geometry near `p`.
    static double offset(const glm::dvec3& p);

    const std::vector<Surface>& surfaces() const { return m_surfaces; }

private:
    SceneGeometry() = default;
    struct Embree;
    std::unique_ptr<Embree> m_embree;
    std::vector<Surface> m_surfaces;
    std::vector<int> m_allSurface;    // scene geometry id → surface index
    std::vector<int> m_shadowSurface; // shadow scene geometry id → surface index
};

} // namespace speculum::render::reference
