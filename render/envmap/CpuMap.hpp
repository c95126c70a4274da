#pragma once

#include "render/envmap/Layout.hpp"

#include <functional>
#include <glm/vec3.hpp>
#include <vector>

namespace speculum::render::envmap {

// An environment map held in memory, filled and filtered the way the GPU path does it: texel centres
// hold the environment in the direction the layout gives them (guard bands included, like the
// `resampled` fill), and lookups are bilinear: clamp-to-edge inside a 2D component, seamless across cube
// faces. Used to measure seams, and as the exact model the GL tests compare with.
class CpuMap {
public:
    using Environment = std::function<glm::dvec3(const glm::dvec3& direction)>;

    // fillOutsideDomain = false leaves texels whose centre the component rule never looks up in that
    // component at zero: a map whose guard band was never drawn (a counter-example for the tests).
    static CpuMap fill(const MapLayout& layout, const Environment& environment,
                       bool fillOutsideDomain = true);

    const MapLayout& layout() const { return m_layout; }
    glm::dvec3 texel(int component, int x, int y) const;

    // The filtered value seen in a direction (any length but zero). seamlessCube = false filters each
    // face on its own, with clamp-to-edge, as GL does without GL_TEXTURE_CUBE_MAP_SEAMLESS.
    glm::dvec3 lookup(const glm::dvec3& direction, bool seamlessCube = true) const;
    // Bilinear filtering of one component at a texture coordinate (guard band included).
    glm::dvec3 bilinear(int component, const glm::dvec2& textureUv, bool seamlessCube = true) const;

private:
    glm::dvec3 tap(int component, int x, int y, bool seamlessCube) const;

    MapLayout m_layout;
    std::vector<glm::vec3> m_texels; // component-major, then rows (y), then x
};

} // namespace speculum::render::envmap
