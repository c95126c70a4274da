#pragma once

#include "render/mesh/MeshData.hpp"

#include <unordered_map>

namespace speculum::render::passes {

// The "direct" environment fill warps vertices, so a straight edge becomes a curve only at its vertices:
// a long edge cuts across the map as a chord. This cache keeps, for each mesh, a copy whose triangles
// are split uniformly (no T-junctions) until no edge is longer than 1/16 of the mesh's bounding-box
// diagonal, which keeps a floor or a box face from showing the chord error.
class WarpMeshes {
public:
    // The subdivided copy (the mesh itself when it is already fine enough).
    MeshHandle get(const MeshHandle& mesh);
    // Forgets copies of meshes nobody holds any more.
    void purge();

private:
    struct Entry {
        std::weak_ptr<const MeshData> owner;
        MeshHandle fine;
    };
    std::unordered_map<const MeshData*, Entry> m_entries;
};

// Splits every triangle into 4^levels (each edge into 2^levels segments); normals renormalised.
MeshData subdivideUniformly(const MeshData& mesh, int levels);

} // namespace speculum::render::passes
