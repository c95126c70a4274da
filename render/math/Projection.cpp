#include "render/math/Projection.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::render::math {

glm::dmat4 viewRotation(const Camera& camera) {
    glm::dvec3 forward = camera.target - camera.position;
    if (glm::length(forward) < 1e-12)
        forward = {0.0, 0.0, -1.0};
    glm::dvec3 up = camera.up;
    // An up vector parallel to the view direction would give a NaN basis: pick any perpendicular one.
    if (glm::length(glm::cross(glm::normalize(forward), up)) < 1e-9)
        up = std::abs(forward.y) < 0.9 * glm::length(forward) ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    return glm::lookAt(glm::dvec3(0.0), forward, up);
}

glm::dmat4 perspective(double fovYDegrees, double aspect, double near, double far) {
    return glm::perspective(glm::radians(fovYDegrees), aspect, near, far);
}

glm::dmat4 jitter(const glm::dmat4& projection, double dxPixels, double dyPixels, int width, int height) {
    glm::dmat4 shift(1.0);
    shift[3][0] = 2.0 * dxPixels / width;
    shift[3][1] = 2.0 * dyPixels / height;
    return shift * projection;
}

glm::dmat4 tileProjection(const glm::dmat4& projection, int x0, int y0, int tileWidth, int tileHeight,
                          int width, int height) {
    // Image NDC x maps to pixel (x + 1)·width/2; the tile's NDC is (pixel − x0)·2/tileWidth − 1. Applied to
    // clip coordinates (before the divide by w): x' = sx·x + ox·w.
    glm::dmat4 crop(1.0);
    crop[0][0] = double(width) / tileWidth;
    crop[1][1] = double(height) / tileHeight;
    crop[3][0] = double(width - 2 * x0 - tileWidth) / tileWidth;
    crop[3][1] = double(height - 2 * y0 - tileHeight) / tileHeight;
    return crop * projection;
}

glm::dmat4 cameraRelative(const Camera& camera) {
    return glm::translate(glm::dmat4(1.0), -camera.position);
}

void Box::add(const glm::dvec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Box::add(const Box& b) {
    if (!b.empty()) {
        add(b.min);
        add(b.max);
    }
}

std::array<glm::dvec3, 8> Box::corners() const {
    std::array<glm::dvec3, 8> c;
    for (int i = 0; i < 8; ++i)
        c[i] = {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    return c;
}

Box worldBounds(const Bounds& local, const glm::dmat4& world) {
    Box box;
    Box localBox{glm::dvec3(local.min), glm::dvec3(local.max)};
    for (const glm::dvec3& c : localBox.corners())
        box.add(glm::dvec3(world * glm::dvec4(c, 1.0)));
    return box;
}

Box sceneBounds(const FrameInput& input) {
    Box box;
    for (const DrawItem& item : input.items)
        if (item.mesh)
            box.add(worldBounds(computeBounds(*item.mesh), item.world));
    for (const Mirror& mirror : input.mirrors) {
        const Bounds rect{{-0.5f * float(mirror.size.x), 0.0f, -0.5f * float(mirror.size.y)},
                          {0.5f * float(mirror.size.x), 0.0f, 0.5f * float(mirror.size.y)}};
        box.add(worldBounds(rect, mirror.world));
    }
    for (const Reflector& reflector : input.reflectors)
        if (reflector.mesh)
            box.add(worldBounds(computeBounds(*reflector.mesh), reflector.world));
    return box;
}

} // namespace speculum::render::math
