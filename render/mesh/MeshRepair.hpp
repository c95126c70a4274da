#pragma once

#include "base/Result.hpp"
#include "render/mesh/MeshData.hpp"

#include <cstddef>
#include <string>

namespace speculum::render {

// Meshes with more triangles (or vertices) than this are refused before anything is allocated for them.
inline constexpr std::size_t kMaxMeshTriangles = 50'000'000;
inline constexpr std::size_t kMaxMeshVertices = 3 * kMaxMeshTriangles;

// What repairMesh() changed. All counts are zero for a mesh that needed nothing.
struct RepairReport {
    std::size_t droppedTrailingIndices = 0; // index count not a multiple of 3
    std::size_t droppedOutOfRange = 0;      // triangles with an index >= vertex count
    std::size_t droppedNonFinite = 0;       // triangles with a NaN or infinite corner
    std::size_t droppedDegenerate = 0;      // repeated index or zero area
    std::size_t removedUnusedVertices = 0;  // vertices no kept triangle refers to
    std::size_t regeneratedNormals = 0;     // missing, non-finite or zero normals rebuilt from the faces
    std::size_t renormalizedNormals = 0;    // finite normals that were not unit length
    std::size_t fixedUvs = 0;               // non-finite uvs set to 0
    bool droppedUvs = false;                // uv array did not match the vertex count

    std::size_t droppedTriangles() const { return droppedOutOfRange + droppedNonFinite + droppedDegenerate; }
    bool clean() const;
    // One line for the user, e.g. "dropped 2 degenerate triangles; regenerated 8 normals", or
    // "no repairs needed".
    std::string summary() const;
};

// Makes an imported (or generated) mesh safe for the renderer and the tracer: drops triangles that are
// out of range, non-finite or degenerate, removes vertices nothing uses, rebuilds normals that are missing,
// non-finite or zero (area-weighted average of the adjacent faces) and normalises the rest. Fails with a
// user-facing message when no triangle survives or the mesh has more than `maxTriangles` triangles (or
// 3 * maxTriangles vertices); that check comes first, before anything is allocated.
base::Result<MeshData> repairMesh(MeshData mesh, RepairReport& report,
                                  std::size_t maxTriangles = kMaxMeshTriangles);

} // namespace speculum::render
