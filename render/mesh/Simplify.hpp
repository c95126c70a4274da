#pragma once

#include "render/mesh/MeshData.hpp"

#include <cstddef>

namespace speculum::render {

// Meshes with more triangles than this get a simplified level for the views that may draw less detail
// (reflections in mirrors, the reflector's environment map): on a software rasteriser a multi-million
// triangle model is vertex-bound, and each reflected view would pay for every vertex again.
inline constexpr std::size_t kSimplifyAboveTriangles = 100'000;
// The simplified level keeps this share of the triangles (but at least kSimplifiedMinimumTriangles), and
// stops early where a further collapse would move the surface by more than kSimplifyMaxError of the
// mesh's size: the level is as coarse as that error allows, never coarser.
inline constexpr double kSimplifiedShare = 1.0 / 8.0;
inline constexpr std::size_t kSimplifiedMinimumTriangles = 20'000;
inline constexpr float kSimplifyMaxError = 0.005f;

// Sets mesh.coarse: a simplified triangle list over the mesh's own vertices (meshoptimizer's edge-collapse
// simplifier, which keeps the surface closed and seams where uvs or normals split a vertex), and the error
// it reached. Leaves it empty for a mesh at or below kSimplifyAboveTriangles, or where simplifying would not
// remove at least a quarter of the triangles.
void buildCoarseLevel(MeshData& mesh);

} // namespace speculum::render
