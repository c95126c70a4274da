#include "editor/view/ViewPresets.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace speculum::view {

namespace {

// The orbit keeps 2° away from the poles (ViewCamera::orbit); a top view sits just inside that, so a
// vertical drag from it moves at once instead of first catching up with the clamp.
constexpr double kPoleMarginDegrees = 2.0;

} // namespace

glm::dvec3 presetDirection(ViewPreset preset) {
    switch (preset) {
    case ViewPreset::Front:
        return {0.0, 0.0, -1.0};
    case ViewPreset::Back:
        return {0.0, 0.0, 1.0};
    case ViewPreset::Right:
        return {-1.0, 0.0, 0.0};
    case ViewPreset::Left:
        return {1.0, 0.0, 0.0};
    case ViewPreset::Top:
        return {0.0, -1.0, 0.0};
    case ViewPreset::Bottom:
        return {0.0, 1.0, 0.0};
    }
    return {0.0, 0.0, -1.0};
}

std::string_view presetName(ViewPreset preset) {
    switch (preset) {
    case ViewPreset::Front:
        return "front";
    case ViewPreset::Back:
        return "back";
    case ViewPreset::Right:
        return "right";
    case ViewPreset::Left:
        return "left";
    case ViewPreset::Top:
        return "top";
    case ViewPreset::Bottom:
        return "bottom";
    }
    return "front";
}

render::Camera presetView(const render::Camera& current, ViewPreset preset) {
    render::Camera camera = current;
    double distance = glm::length(current.position - current.target);
    if (!(distance > 1e-9) || !std::isfinite(distance)) {
        distance = 1.0;
    }
    glm::dvec3 toCamera = -presetDirection(preset);
    if (preset == ViewPreset::Top || preset == ViewPreset::Bottom) {
        // Tilted toward +Z by the margin: from there screen-up is −Z (Top) and +X stays on the right.
        const double a = glm::radians(kPoleMarginDegrees);
        toCamera = {0.0, toCamera.y * std::cos(a), std::sin(a)};
    }
    camera.up = {0.0, 1.0, 0.0};
    camera.position = current.target + toCamera * distance;
    return camera;
}

} // namespace speculum::view
