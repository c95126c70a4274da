#include "render/mesh/Simplify.hpp"

#include <algorithm>
#include <cmath>
#include <meshoptimizer.h>
#include <vector>

namespace speculum::render {

CoarseLevel simplifyMesh(const MeshData& mesh) {
    const std::size_t triangles = mesh.triangleCount();
    if (!wantsCoarseLevel(mesh) || mesh.positions.empty())
        return {};
    // meshoptimizer reads the positions as floats; a NaN or an infinity would poison its error metric,
    // and such a mesh (a hostile file) is better drawn whole.
    for (const glm::vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return {};
    const std::size_t target =
        std::max(kSimplifiedMinimumTriangles, static_cast<std::size_t>(double(triangles) * kSimplifiedShare));
    std::vector<std::uint32_t> indices(mesh.indices.size());
    float error = 0.0f;
    // The edge-collapse simplifier keeps the surface closed: 54 dB on the mirror's pixels of a 4 M-triangle
    // terrain's reflection. The sloppy one (vertex clustering) took 0.21 s instead of 4.5 s there, but left
    // single-pixel holes all over the reflection (37 dB), seen at once in the editor.
    const std::size_t kept =
        meshopt_simplify(indices.data(), mesh.indices.data(), mesh.indices.size(), &mesh.positions[0].x,
                         mesh.positions.size(), sizeof(glm::vec3), target * 3, kSimplifyMaxError, 0, &error);
    if (kept == 0 || kept / 3 > triangles * 3 / 4)
        return {}; // too little gained for a second index list
    indices.resize(kept);
    indices.shrink_to_fit();
    return CoarseLevel{std::move(indices), error};
}

const CoarseLevel& coarseLevel(const MeshData& mesh) {
    return mesh.coarse.ensure([&mesh] { return simplifyMesh(mesh); });
}

} // namespace speculum::render
