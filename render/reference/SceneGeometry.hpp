#pragma once

#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/reference/TextureSampler.hpp"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
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
    std::vector<glm::dvec3> normals;  // world space, unnormalised; empty if the mesh has none
    std::vector<glm::vec2> uvs;       // empty if the mesh has none
    std::vector<glm::vec4> colors;    // linear RGBA vertex colours; empty if the mesh has none (white)
    std::vector<glm::dvec4> tangents; // world xyz, w the handedness signed for `flipped`; empty if none
    std::vector<std::uint32_t> indices;
    // Objects whose material has an alpha mask: rays of every kind pass where the material's alpha
    // (opacity · texture alpha · vertex alpha) is below the cutoff, as mesh.frag and shadow.frag discard.
    struct AlphaMask {
        double opacity = 1.0;
        double cutoff = 0.5;
        const LinearTexture* texture = nullptr; // the base colour texture, or none
        TextureWrap wrapS = TextureWrap::Repeat;
        TextureWrap wrapT = TextureWrap::Repeat;
    };
    std::optional<AlphaMask> mask;

    // The material's alpha at barycentric (u, v) of triangle `triangle` (1 without a mask).
    double alpha(std::size_t triangle, double u, double v) const;
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
    glm::dvec4 color{1.0};   // interpolated vertex colour (white where the mesh has none)
    glm::dvec4 tangent{0.0}; // interpolated world tangent, w the handedness; w = 0 where the mesh has none
    bool frontFacing = true; // the ray met the front side (what gl_FrontFacing says)
};

// The Embree device and two scenes: everything (camera, mirror and reflection rays) and the shadow casters
// (shadow rays). Thread-safe for queries once built.
class SceneGeometry {
public:
    // `origin` is the world point that becomes (0,0,0): the camera position. `itemTextures` (one per item,
    // indices into `textures`) give masked materials their alpha; without them masks are ignored.
    static base::Result<std::unique_ptr<SceneGeometry>>
    build(const FrameInput& input, const glm::dvec3& origin, std::vector<std::string>& warnings,
          const TextureSet* textures = nullptr, const std::vector<MaterialTextures>* itemTextures = nullptr);
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
    // Surfaces intersected in double here instead of by Embree: the mirrors (up to kExactMirrors). Embree
    // holds a float copy of each triangle; a mirror 1e12 wide has corners whose rounding (≈ 6e4) tilts
    // and moves its plane by kilometres where the camera looks at it, so its hits (and the order of hits
    // in front of it) come out wrong.
    std::vector<int> m_exactSurface;
    static constexpr std::size_t kExactMirrors = 64;

    Hit makeHit(const Surface& s, std::size_t triangle, double u, double v, double t,
                const glm::dvec3& direction) const;
};

} // namespace speculum::render::reference
