#include "render/mesh/MeshData.hpp"

#include <cmath>
#include <glm/common.hpp>

namespace speculum::render {

Bounds computeBounds(const MeshData& mesh) {
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

} // namespace speculum::render
