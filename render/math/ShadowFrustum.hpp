#pragma once

#include "render/frame/FrameInput.hpp"

#include <array>
#include <glm/mat4x4.hpp>
#include <optional>

namespace speculum::render::math {

// Where a light's shadow map looks. Point lights use a cube map (six 90° faces, in GL's cube-face
// order +X −X +Y −Y +Z −Z); spot lights a perspective map over their cone; directional lights an
// orthographic map fitted around every receiver so nothing in the scene lies outside the map border.
struct ShadowFrustum {
    bool cube = false;
    bool perspective = false;
    std::array<glm::dmat4, 6> viewProjection{}; // world space → light clip space; 2D maps use [0]
    double near = 0.0;
    double far = 0.0;
    // World size of one shadow texel: perspective maps at unit distance (scale by distance), ortho maps
    // everywhere. Used for the normal offset that keeps surfaces from shadowing themselves.
    double texelSize = 0.0;
    unsigned faceMask = 0; // cube maps: faces that hold at least one caster
};

// nullopt when the scene has nothing to receive a shadow.
std::optional<ShadowFrustum> shadowFrustum(const FrameInput& input, const Light& light, int mapSize);

// The view matrices of the six cube faces, looking from the origin (GL cube-map conventions).
const std::array<glm::dmat4, 6>& cubeFaceViews();

} // namespace speculum::render::math
