#pragma once

#include "render/mesh/MeshData.hpp"

namespace speculum::render {

inline constexpr int kTeapotMinTessellation = 1;
inline constexpr int kTeapotMaxTessellation = 64;

// The Utah teapot tessellated from Newell's 32 bicubic Bezier patches: his original units and proportions
// (rim radius 1.5, height 3.15), Y up, base on y = 0, spout towards +X, handle towards -X.
//
// Every patch becomes tessellation x tessellation quads (clamped to 1..64), i.e. 32 * N^2 * 2 triangles
// and 32 * (N+1)^2 vertices; patches are not welded, so seams carry two vertices with equal positions.
// Normals are the analytic patch normals; where a patch edge collapses to a point (lid knob top, bottom
// centre) they are taken a tiny step inside the patch, which gives the tangent plane at the pole. The
// triangles touching those poles have zero area (two corners coincide); they are kept so that the count
// stays 32 * N^2 * 2 and each patch stays a regular grid. uvs are the patch parameters (0..1 per patch).
MeshData makeTeapot(int tessellation);

} // namespace speculum::render
