#pragma once

#include "render/mesh/MeshData.hpp"

#include <cstddef>

namespace speculum::scene::detail {

// Merges vertices whose every stream (position, normal, uv, colour) is bitwise identical
// (meshopt_generateVertexRemapMulti) and renumbers the triangles; what Assimp's JoinIdenticalVertices did,
// in linear time. Indices must all be < vertexCount (callers drop bad triangles first).
void weldVertices(render::MeshData& mesh);

// Per-vertex tangents for normal maps from the triangles' uv gradients (area-weighted accumulation,
// Gram-Schmidt against the normal, w = handedness). Needs uvs and unit normals; leaves `tangents` empty
// otherwise.
void computeTangents(render::MeshData& mesh);

} // namespace speculum::scene::detail
