#pragma once

#include "render/mesh/MeshData.hpp"

namespace speculum::render {

// Built-in meshes (sizes: docs/scene-format.md, "mesh"). All are counter-clockwise seen from outside, with
// unit normals and one uv per vertex. Texture convention, shared with Assimp's importers: v = 0 is the bottom
// row of the image and v = 1 its top (OpenGL's convention), u runs left to right.

inline constexpr int kSphereDefaultTessellation = 32;
inline constexpr int kSphereMinTessellation = 3;
inline constexpr int kSphereMaxTessellation = 512;
inline constexpr int kPlaneMaxTessellation = 1024;

// UV sphere of radius 1 at the origin. `tessellation` is the number of rings (latitude bands, clamped to
// 3..512); there are twice as many segments around. u runs around the Y axis from +X towards -Z
// (counter-clockwise seen from above), v from 0 at the south pole (-Y) to 1 at the north pole (+Y).
// Seam and pole vertices are duplicated so the uvs stay continuous; the poles get one triangle per
// segment, so no triangle is degenerate: 2 * segments * (rings - 1) triangles.
MeshData makeSphere(int tessellation = kSphereDefaultTessellation);

// The cube [-1,1]^3 with flat per-face normals: 24 vertices, 12 triangles. Each face maps the whole
// texture (uv 0..1) and reads un-mirrored from outside, upright on the side faces (v along +Y); on the
// top face u is along +X and v along -Z, on the bottom face u along +X and v along +Z.
MeshData makeBox();

// The square [-1,1]^2 in the XZ plane (y = 0) facing +Y, split into tessellation x tessellation quads
// (clamped to 1..1024). uv = ((x + 1) / 2, (1 - z) / 2): u along +X, v along -Z, so seen from above with
// -Z pointing up the screen a texture appears upright and un-mirrored.
MeshData makePlane(int tessellation = 1);

} // namespace speculum::render
