#include "render/envmap/CpuMap.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/common.hpp>

namespace speculum::render::envmap {

CpuMap CpuMap::fill(const MapLayout& layout, const Environment& environment, bool fillOutsideDomain) {
    CpuMap map;
    map.m_layout = layout;
    map.m_texels.resize(std::size_t(layout.components) * layout.width * layout.height);
    std::size_t i = 0;
    for (int c = 0; c < layout.components; ++c)
        for (int y = 0; y < layout.height; ++y)
            for (int x = 0; x < layout.width; ++x, ++i) {
                const glm::dvec3 d = fromMap(layout.type, c, layout.texelCentre(x, y));
                if (fillOutsideDomain || mapComponent(layout.type, d) == c)
                    map.m_texels[i] = glm::vec3(environment(d));
            }
    return map;
}

glm::dvec3 CpuMap::texel(int component, int x, int y) const {
    assert(component >= 0 && component < m_layout.components && x >= 0 && x < m_layout.width && y >= 0 &&
           y < m_layout.height && "CpuMap::texel(): out of range");
    return m_texels[(std::size_t(component) * m_layout.height + y) * m_layout.width + x];
}

glm::dvec3 CpuMap::tap(int component, int x, int y, bool seamlessCube) const {
    const int w = m_layout.width;
    const int h = m_layout.height;
    if (x >= 0 && x < w && y >= 0 && y < h)
        return texel(component, x, y);
    if (m_layout.type != MapType::Cube || !seamlessCube)
        return texel(component, std::clamp(x, 0, w - 1), std::clamp(y, 0, h - 1));
    // Seamless cube filtering: a tap past a face's edge reads the texel of the adjacent face that lies in
    // its direction (at a corner, GL averages the three faces; one of them is close enough here).
    const glm::dvec3 d = cubeDirection(component, glm::dvec2((x + 0.5) / w, (y + 0.5) / h));
    const int face = cubeFace(d);
    const glm::dvec2 uv = cubeUv(face, d);
    return texel(face, std::clamp(int(std::floor(uv.x * w)), 0, w - 1),
                 std::clamp(int(std::floor(uv.y * h)), 0, h - 1));
}

glm::dvec3 CpuMap::bilinear(int component, const glm::dvec2& textureUv, bool seamlessCube) const {
    const double fx = textureUv.x * m_layout.width - 0.5;
    const double fy = textureUv.y * m_layout.height - 0.5;
    const int x0 = int(std::floor(fx));
    const int y0 = int(std::floor(fy));
    const double tx = fx - x0;
    const double ty = fy - y0;
    const glm::dvec3 bottom =
        glm::mix(tap(component, x0, y0, seamlessCube), tap(component, x0 + 1, y0, seamlessCube), tx);
    const glm::dvec3 top =
        glm::mix(tap(component, x0, y0 + 1, seamlessCube), tap(component, x0 + 1, y0 + 1, seamlessCube), tx);
    return glm::mix(bottom, top, ty);
}

glm::dvec3 CpuMap::lookup(const glm::dvec3& direction, bool seamlessCube) const {
    const MapCoord coord = toMap(m_layout.type, direction);
    return bilinear(coord.component, m_layout.toTexture(coord.uv), seamlessCube);
}

} // namespace speculum::render::envmap
