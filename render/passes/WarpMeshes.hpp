#pragma once

#include "render/envmap/Layout.hpp"
#include "render/gl/GpuMesh.hpp"
#include "render/mesh/MeshData.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <unordered_map>

namespace speculum::render::passes {

// How finely the "direct" environment fill needs its meshes. The fill warps vertices, so a straight edge
// becomes a curve only at its vertices: between them the rasterizer draws the chord, and interpolates
// positions, normals and uvs linearly in map space rather than along the true curve. Both errors grow
// with the angle the edge spans as seen from the capture point (the chord's deviation ≈ θ²/8 radians
// in either map), not with its world length: a short edge beside the reflector can span 60°, a long one
// across the room 1°.
struct WarpTolerance {
    glm::dvec3 centre{0.0}; // the capture point, world space
    double maxAngle = 0.3;  // radians an edge may span
    double minLength = 0.0; // world units: shorter edges are never split (geometry at the capture point)
};

// The largest angle an edge may span in a dual-paraboloid or tennis-ball map: its chord may stray up to
// one of the map's largest texels, and the edge never spans more than kMaxWarpEdgeAngle, which bounds
// the error of the linear interpolation (its share of the error falls only linearly with the angle)
// in small maps.
double warpEdgeAngle(const envmap::MapLayout& layout);
inline constexpr double kMaxWarpEdgeAngle = 0.6; // radians, 34°: binds below n = 128

// Splits edges of `mesh` (placed by `world`) at their midpoints until every edge spans at most
// tolerance.maxAngle seen from tolerance.centre, or is shorter than tolerance.minLength. Whether an edge
// is split depends on its two end points only, so the two triangles sharing it always agree and no
// T-junction (crack) appears; a triangle with one, two or three split edges becomes two, three or four.
// Midpoints are shared through an edge table, normals renormalised, uvs, colours and tangents interpolated.
// Gives up (and returns the triangles split so far) past `maxTriangles`.
MeshData subdivideForWarp(const MeshData& mesh, const glm::dmat4& world, const WarpTolerance& tolerance,
                          std::size_t maxTriangles = 400000);

// A cache of subdivided copies, one per (mesh, world matrix, tolerance): a static scene's meshes are
// split once and reused by every later update, and their GPU copies with them (gl::MeshCache keys on
// the MeshData). A mesh that needs no split is returned as it is.
class WarpMeshes {
public:
    // Starts an update: entries not asked for since the previous begin() are dropped by purge().
    void begin() { ++m_generation; }
    // Detail::Coarse splits the mesh's simplified level where it has one (the copy then holds only it).
    MeshHandle get(const MeshHandle& mesh, const glm::dmat4& world, const WarpTolerance& tolerance,
                   gl::Detail detail = gl::Detail::Full);
    // Forgets copies of meshes nobody holds any more, and those the last update did not use (a moving
    // object leaves one behind per position).
    void purge();
    std::size_t size() const { return m_entries.size(); }

private:
    struct Entry {
        std::weak_ptr<const MeshData> owner;
        MeshHandle fine; // empty: the mesh itself
        glm::dmat4 world{1.0};
        WarpTolerance tolerance;
        std::uint64_t generation = 0;
    };
    std::unordered_map<std::uint64_t, Entry> m_entries;
    std::uint64_t m_generation = 0;
};

} // namespace speculum::render::passes
