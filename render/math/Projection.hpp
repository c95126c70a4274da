#pragma once

#include "render/frame/FrameInput.hpp"

#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace speculum::render::math {

// All matrices here are double precision; the renderer converts to float only after making them
// camera-relative, so that scenes far from the origin keep their precision.

// Rotation-only view matrix: the camera sits at the origin of camera-relative world space.
glm::dmat4 viewRotation(const Camera& camera);

// OpenGL perspective projection (clip z in [-w, w]) for a vertical field of view in degrees.
glm::dmat4 perspective(double fovYDegrees, double aspect, double near, double far);

// Shifts a projection by a sub-pixel offset (in pixels) for supersampling: the image moves by
// (dx, dy) pixels on a width × height target.
glm::dmat4 jitter(const glm::dmat4& projection, double dxPixels, double dyPixels, int width, int height);

// The part of `projection` that falls on the pixels [x0, x0 + tileWidth) × [y0, y0 + tileHeight) (GL
// window coordinates, y up) of a width × height image, spread over a whole target of the tile's size:
// pixel (x, y) of the image becomes pixel (x − x0, y − y0) of the tile. Only clip x and y change, so depth,
// near and far (also an oblique near plane) stay exactly those of the whole image.
glm::dmat4 tileProjection(const glm::dmat4& projection, int x0, int y0, int tileWidth, int tileHeight,
                          int width, int height);

// Translation that takes world space to camera-relative world space.
glm::dmat4 cameraRelative(const Camera& camera);

// Axis-aligned box in world space.
struct Box {
    glm::dvec3 min{1e300};
    glm::dvec3 max{-1e300};
    bool empty() const { return min.x > max.x; }
    void add(const glm::dvec3& p);
    void add(const Box& b);
    glm::dvec3 center() const { return (min + max) * 0.5; }
    std::array<glm::dvec3, 8> corners() const;
};

Box worldBounds(const Bounds& local, const glm::dmat4& world);

// The world-space box of everything that can receive or cast a shadow.
Box sceneBounds(const FrameInput& input);

} // namespace speculum::render::math
