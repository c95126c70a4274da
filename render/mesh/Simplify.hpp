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

// Whether a mesh is big enough for reflected views to draw a simplified level of it.
inline bool wantsCoarseLevel(const MeshData& mesh) {
    return mesh.triangleCount() > kSimplifyAboveTriangles;
}

// A simplified triangle list over the mesh's own vertices (meshoptimizer's edge-collapse simplifier,
// which keeps the surface closed and seams where uvs or normals split a vertex), and the error it
// reached. Empty for a mesh at or below kSimplifyAboveTriangles, one with a non-finite position, or where
// simplifying would not remove at least a quarter of the triangles.
CoarseLevel simplifyMesh(const MeshData& mesh);

// The mesh's simplified level (mesh.coarse), built by the first call and kept: seconds for a
// multi-million-triangle mesh, so an interactive caller asks a worker thread and reads
// mesh.coarse.ready() meanwhile.
const CoarseLevel& coarseLevel(const MeshData& mesh);

} // namespace speculum::render
