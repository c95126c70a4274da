#pragma once

#include "render/envmap/Layout.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

// The transforms of pass 1, without GL: cube-face cameras and the "direct" vertex warps, whose GLSL twins
// live in shaders/envmap_warp.glsl. Positions are relative to the capture point ("reflector-relative").
namespace speculum::render::envmap {

// Camera of cube face `face` in the map frame: rows S, T, −M of GL's face frame, so NDC (x, y) are the
// face's (sc, tc) and the rendered image lands in the face exactly as GL samples it. A proper rotation:
// no face flips the winding.
glm::dmat4 cubeFaceView(int face);
// 90° square perspective.
glm::dmat4 cubeFaceProjection(double near, double far);
// reflector-relative world → clip of face `face`; mapFromWorld rotates world axes into the map frame.
glm::dmat4 cubeFaceViewProjection(int face, const glm::dmat3& mapFromWorld, double near, double far);

// Everything a direct warp into one component needs (the uEnvWarp* uniforms of envmap_warp.glsl).
//
// Clip coordinates have w = 1 and (x, y) = ndcScale · (nominal map coordinates in [−1, 1]²), so a
// direction lands on the texel the lookup reads (MapLayout: texture = offset + scale · uv), guard
// band included. z is chosen so that the fixed-function clipper does the work the mapping cannot:
// - paraboloid: z = −1 + 2ρ(s + γ) / ((1 + γ) far), with ρ = |p| and s = cosine of the angle to the
//   component's axis. Along any ray z grows with ρ (depth test = nearest first); the near plane z = −w
//   is the cone s = −γ, which passes through the texture's edge (γ from the guard band), so geometry
//   behind the component is clipped, geometry in its guard band is drawn; z ≤ 1 while ρ ≤ far.
// - tennis ball: z = −1 + λ ρ/far + κ b². A vertex with |b| ≥ b_c (between the texture edge B and the
//   atan branch cut at 4/3) gets z > 1 whatever its distance, so a triangle whose vertices sit on both
//   sides of the cut (its image would span the whole texture) is clipped by the far plane; inside the
//   texture (|b| ≤ B, ρ ≤ far) z stays in [−1, 1]. κ = 2 / b_c², λ = 2 − κ B². Triangles that cross the
//   cut with a vertex further inside, or cross a paraboloid's rim far from the band, still come out
//   wrong: scenes must be tessellated finely enough (straight edges map to curves anyway).
struct WarpParameters {
    MapType type = MapType::DualParaboloid;
    int component = 0;
    glm::dvec2 ndcScale{1.0};
    double far = 1.0;
    double rimSine = 0.0;      // γ (paraboloid)
    double depthScale = 0.0;   // λ (tennis ball)
    double cutCurvature = 0.0; // κ (tennis ball)
    double cutLimit = 0.0;     // b_c (tennis ball)
    // The warp shows the component mirrored (paraboloid component 1): the caller swaps glFrontFace.
    bool mirrored = false;
    // (ndcScale.x, ndcScale.y, γ or λ, 0 or κ): the uEnvWarpParams uniform.
    glm::dvec4 packed() const;
};

// layout: a dual-paraboloid or tennis-ball layout; far: the largest distance the map must see.
WarpParameters warpParameters(const MapLayout& layout, int component, double far);

// Clip coordinates of a reflector-relative position in the map frame: the C++ twin of envmapWarp().
glm::dvec4 warpVertex(const WarpParameters& warp, const glm::dvec3& position);

} // namespace speculum::render::envmap
