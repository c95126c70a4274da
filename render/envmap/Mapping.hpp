#pragma once

#include <glm/mat3x2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string_view>

// Direction ↔ texture mappings of the three environment maps, in double precision, in the map's own
// frame (origin at the capture point; the renderer chooses the axes, normally the world axes).
//
// Every mapping returns a *nominal* uv in [0,1]² per component, exactly as the reference equations
// write it; MapLayout (Layout.hpp) places that square inside the real texture with a guard band.
// Component indices are 0-based: component 0 is the reference's "component 1".
//
// Cube (6 components = GL faces +X −X +Y −Y +Z −Z): GL's cube-map face selection and (s, t) rule
// (OpenGL 4.6 core, §8.13 "Cube Map Texture Selection"), so uv are the texture coordinates GL itself samples.
//
// Dual paraboloid (2 components, n×n): component 0 for z < 0 with d = 1 − z, component 1 for z ≥ 0
// with d = 1 + z, uv = (x/d, y/d)·½ + ½. This is the reference's sign convention: component 0 looks
// down −z (like a GL camera) and component 1 down +z, and both store +x to the right and +y up, so
// component 1 is a mirror image (the renderer flips the front face when it warps into it). Within
// the chosen component d ≥ 1, so nothing divides by a small number. The map is the stereographic
// projection: |uv − ½|·2 = tan(θ/2) with θ the angle from the component's axis, rim at radius 1.
//
// Tennis ball (2 components, n wide × 3n tall): component 0 has a = asin(y)/(π/4),
// b = atan(x, z)/(3π/4); component 1 has a = asin(x)/(π/4), b = atan(y, −z)/(3π/4); uv = (a, b)·½ + ½.
// So u (the n-texel axis) holds a, a 90° span of latitude, and v (the 3n-texel axis) holds b, a 270°
// span of longitude: both axes then get 90°/n per texel on the component's equator, and a texel's
// solid angle only falls with cos(latitude) ≥ cos 45°. This matches the reference's pass-1 output
// vertex (a, b) → (x, y) on an n×3n target. The component rule is the reference's:
// component 0 iff (z ≥ 0 and |y| ≤ √2/2) or (z ≤ 0 and |x| ≥ √2/2); the chosen component never
// reaches its own atan branch cut (|b| ≤ 1 there) nor its own poles (|sin| ≤ √2/2).
namespace speculum::render::envmap {

enum class MapType { Cube = 0, DualParaboloid = 1, TennisBall = 2 };

std::string_view mapTypeName(MapType type); // "cube", "dual-paraboloid", "tennis-ball" (scene file names)
int componentCount(MapType type);           // 6, 2, 2

// A place in a map: which component (face) and the nominal uv in it.
struct MapCoord {
    int component = 0;
    glm::dvec2 uv{0.0};
};

// --- cube ---
int cubeFace(const glm::dvec3& direction);
glm::dvec2 cubeUv(int face, const glm::dvec3& direction); // extends past [0,1] off the face's pyramid
glm::dvec3 cubeDirection(int face, const glm::dvec2& uv); // unit vector; any uv (the face's plane)

// --- dual paraboloid ---
int paraboloidComponent(const glm::dvec3& direction);
glm::dvec2 paraboloidUv(int component, const glm::dvec3& direction); // any direction but the far pole
glm::dvec3 paraboloidDirection(int component, const glm::dvec2& uv); // unit vector; any uv

// --- tennis ball ---
int tennisBallComponent(const glm::dvec3& direction);
glm::dvec2 tennisBallUv(int component, const glm::dvec3& direction); // any direction (poles: b = 0)
glm::dvec3 tennisBallDirection(int component, const glm::dvec2& uv); // unit vector; any uv

// --- any map ---
// Directions need not be unit length (they are normalised); a zero vector is a programmer error.
int mapComponent(MapType type, const glm::dvec3& direction);
glm::dvec2 mapUv(MapType type, int component, const glm::dvec3& direction);
MapCoord toMap(MapType type, const glm::dvec3& direction);
glm::dvec3 fromMap(MapType type, int component, const glm::dvec2& uv);

// ∂uv/∂direction for a unit direction, in a given component (GLM: 3 columns of 2 rows, column j =
// ∂uv/∂direction[j]). What textureGrad needs: uv gradients from the continuous direction gradients, so
// the LOD does not jump where neighbouring pixels pick different components.
glm::dmat3x2 uvJacobian(MapType type, int component, const glm::dvec3& direction);

// Solid angle (steradians) per unit of nominal uv area at uv: |∂d/∂u × ∂d/∂v|.
double solidAngleDensity(MapType type, const glm::dvec2& uv);

} // namespace speculum::render::envmap
