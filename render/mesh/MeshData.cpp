#include "render/mesh/MeshData.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <unordered_map>

namespace speculum::render {

Bounds computeBounds(const MeshData& mesh) {
    if (const Bounds* known = mesh.knownBounds.get()) {
        return *known;
    }
    // Non-finite positions are skipped: one NaN would otherwise poison every min/max after it.
    bool any = false;
    Bounds bounds;
    for (const glm::vec3& p : mesh.positions) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            continue;
        }
        if (!any) {
            bounds.min = bounds.max = p;
            any = true;
            continue;
        }
        bounds.min = glm::min(bounds.min, p);
        bounds.max = glm::max(bounds.max, p);
    }
    return bounds; // an empty mesh gives the zero box at the origin
}

MeshHandle freezeMesh(MeshData&& mesh) {
    auto frozen = std::make_shared<MeshData>(std::move(mesh));
    frozen->knownBounds.set(computeBounds(*frozen));
    return frozen;
}

bool isClosed(const MeshData& mesh) {
    if (mesh.indices.empty() || mesh.indices.size() > kMaxClosureCheckIndices)
        return false;
    // Vertices by position, on a grid a millionth of the mesh's size: seam and pole copies computed by
    // different sines (0 against −2e-16, or −0) are one point. A near-miss that falls across a grid line
    // only makes a closed mesh count as open, which is the safe way to be wrong.
    const Bounds bounds = computeBounds(mesh);
    const double size = std::max(1e-30, double(glm::length(bounds.max - bounds.min)));
    const double cell = size * 1e-6;
    struct KeyHash {
        std::size_t operator()(const std::array<std::int64_t, 3>& k) const {
            return (std::size_t(k[0]) * 73856093u) ^ (std::size_t(k[1]) * 19349663u) ^
                   (std::size_t(k[2]) * 83492791u);
        }
    };
    std::unordered_map<std::array<std::int64_t, 3>, std::uint32_t, KeyHash> ids;
    std::vector<std::uint32_t> id(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3& p = mesh.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return false;
        // From the box's corner: at most a million cells along each axis, whatever the coordinates.
        const glm::dvec3 q = (glm::dvec3(p) - glm::dvec3(bounds.min)) / cell;
        const std::array<std::int64_t, 3> key{std::llround(q.x), std::llround(q.y), std::llround(q.z)};
        id[v] = ids.emplace(key, static_cast<std::uint32_t>(ids.size())).first->second;
    }
    for (std::uint32_t index : mesh.indices)
        if (index >= mesh.positions.size())
            return false;
    std::unordered_map<std::uint64_t, int> directed;
    directed.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = id[mesh.indices[t + e]], b = id[mesh.indices[t + (e + 1) % 3]];
            if (a == b)
                return false; // a degenerate triangle
            if (++directed[(std::uint64_t(a) << 32) | b] > 1)
                return false;
        }
    for (const auto& [edge, count] : directed)
        if (!directed.contains((edge << 32) | (edge >> 32)))
            return false;
    // Wound outwards: counter-clockwise seen from outside encloses a positive volume (the divergence
    // theorem over the triangles' signed tetrahedra from the box's corner). Inside out, every face seen
    // from outside is a back face.
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a = glm::dvec3(mesh.positions[mesh.indices[t]]) - glm::dvec3(bounds.min);
        const glm::dvec3 b = glm::dvec3(mesh.positions[mesh.indices[t + 1]]) - glm::dvec3(bounds.min);
        const glm::dvec3 c = glm::dvec3(mesh.positions[mesh.indices[t + 2]]) - glm::dvec3(bounds.min);
        volume += glm::dot(a, glm::cross(b, c));
    }
    return volume > 0.0;
}

} // namespace speculum::render
