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
//
// Octahedral (1 component, n×n): the sphere projected onto the octahedron |x| + |y| + |z| = 1, p = d /
// (|x| + |y| + |z|); the upper half (z ≥ 0) keeps (p.x, p.y), the diamond |p.x| + |p.y| ≤ 1; the lower half
// is folded out over the diamond's edges into the square's four corners, (p.x, p.y) ↦ (sign(p.x)·(1 − |p.y|),
// sign(p.y)·(1 − |p.x|)); uv = p·½ + ½. One square texture and no component to choose; a texel's solid
// angle goes with 1/r³, r the distance to its point on the octahedron, so from the vertices (r = 1) to the
// faces' centres (r = 1/√3) it grows by 3√3, as a cube's does from a face's corner to its centre. Each side
// of the square is folded onto itself (the points (1, t) and (1, −t) are one direction), so past the square
// the mapping continues by that symmetry, (1 + e, t) ↦ (1 − e, −t), which is what fills the guard band.
namespace speculum::render::envmap {

enum class MapType { Cube = 0, DualParaboloid = 1, TennisBall = 2, Octahedral = 3 };

// "cube", "dual-paraboloid", "tennis-ball", "octahedral" (scene file names)
std::string_view mapTypeName(MapType type);
int componentCount(MapType type); // 6, 2, 2, 1

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

// --- octahedral ---
glm::dvec2 octahedralUv(const glm::dvec3& direction); // any direction
glm::dvec3 octahedralDirection(const glm::dvec2& uv); // unit vector; any uv (folded back into the square)

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
