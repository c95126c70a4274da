#include "render/passes/WarpMeshes.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace speculum::render::passes {

namespace {

constexpr double kEdgeFraction = 1.0 / 16.0; // of the bounding-box diagonal
constexpr int kMaxLevels = 5;                // 1024 triangles per original triangle at most
constexpr std::size_t kFineEnough = 200000;  // triangles: dense meshes are left as they are

int levelsFor(const MeshData& mesh) {
    if (mesh.triangleCount() == 0 || mesh.triangleCount() >= kFineEnough)
        return 0;
    const Bounds b = computeBounds(mesh);
    const double diagonal = glm::length(glm::dvec3(b.max) - glm::dvec3(b.min));
    double longest = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const glm::vec3 a = mesh.positions[mesh.indices[t + e]];
            const glm::vec3 c = mesh.positions[mesh.indices[t + (e + 1) % 3]];
            longest = std::max(longest, double(glm::length(a - c)));
        }
    if (!(diagonal > 0.0) || longest <= diagonal * kEdgeFraction)
        return 0;
    int levels = static_cast<int>(std::ceil(std::log2(longest / (diagonal * kEdgeFraction))));
    levels = std::clamp(levels, 0, kMaxLevels);
    // Keep the copy under the dense-mesh size.
    while (levels > 0 && (mesh.triangleCount() << (2 * levels)) > kFineEnough * 4)
        --levels;
    return levels;
}

} // namespace

MeshData subdivideUniformly(const MeshData& mesh, int levels) {
    const int k = 1 << levels;
    MeshData out;
    const bool hasUv = mesh.uvs.size() == mesh.positions.size();
    const std::size_t perTriangle = static_cast<std::size_t>((k + 1) * (k + 2) / 2);
    out.positions.reserve(mesh.triangleCount() * perTriangle);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        // Row i (0..k) from vertex 0 towards the edge 1-2, j (0..i) along the row towards vertex 2.
        for (int i = 0; i <= k; ++i)
            for (int j = 0; j <= i; ++j) {
                const float w1 = float(i - j) / float(k), w2 = float(j) / float(k), w0 = 1.0f - w1 - w2;
                out.positions.push_back(w0 * mesh.positions[i0] + w1 * mesh.positions[i1] +
                                        w2 * mesh.positions[i2]);
                glm::vec3 n = w0 * mesh.normals[i0] + w1 * mesh.normals[i1] + w2 * mesh.normals[i2];
                const float length = glm::length(n);
                out.normals.push_back(length > 0.0f ? n / length : mesh.normals[i0]);
                if (hasUv)
                    out.uvs.push_back(w0 * mesh.uvs[i0] + w1 * mesh.uvs[i1] + w2 * mesh.uvs[i2]);
            }
        auto at = [&](int i, int j) { return base + static_cast<std::uint32_t>(i * (i + 1) / 2 + j); };
        for (int i = 0; i < k; ++i)
            for (int j = 0; j <= i; ++j) {
                out.indices.insert(out.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                if (j < i)
                    out.indices.insert(out.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
    }
    return out;
}

MeshHandle WarpMeshes::get(const MeshHandle& mesh) {
    if (!mesh)
        return mesh;
    auto it = m_entries.find(mesh.get());
    if (it != m_entries.end() && !it->second.owner.expired())
        return it->second.fine ? it->second.fine : mesh;
    const int levels = levelsFor(*mesh);
    MeshHandle fine =
        levels == 0 ? mesh : std::make_shared<const MeshData>(subdivideUniformly(*mesh, levels));
    // A copy that is the mesh itself must not keep it alive: hold it weakly through the owner only.
    m_entries[mesh.get()] = {mesh, levels == 0 ? MeshHandle() : fine};
    return fine;
}

void WarpMeshes::purge() {
    for (auto it = m_entries.begin(); it != m_entries.end();)
        it = it->second.owner.expired() ? m_entries.erase(it) : std::next(it);
}

} // namespace speculum::render::passes
