#pragma once

#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"

#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace speculum::render::math {

// A plane n·x + d = 0 with unit normal n; the positive side (n·x + d > 0) is the reflective side.
struct Plane {
    glm::dvec3 normal{0.0, 1.0, 0.0};
    double d = 0.0;

    double distance(const glm::dvec3& p) const { return glm::dot(normal, p) + d; }
};

// The plane of a mirror: its node's local XZ plane, facing local +Y. Fails when the transform collapses
// the rectangle (zero area), so there is no plane to reflect in.
base::Result<Plane> mirrorPlane(const glm::dmat4& world);

// The four world corners of a mirror rectangle, counter-clockwise seen from the reflective side.
std::array<glm::dvec3, 4> mirrorCorners(const Mirror& mirror);

// R = I − 2nnᵀ with the translation −2dn: reflects points through the plane. Requires a unit normal
// (|n| = 1 within 1e-9); a zero or non-unit normal is an error, never a silently wrong matrix.
base::Result<glm::dmat4> reflectionMatrix(const Plane& plane);

// Transforms a plane (as a 4-vector n, d) by a point transform M: the plane of M·x.
glm::dvec4 transformPlane(const glm::dvec4& plane, const glm::dmat4& m);

// Lengyel's oblique near-plane clipping: replaces the near plane of `projection` by `clipPlane` (in view
// space, keeping points with clipPlane·v ≥ 0) while keeping the rest of the original frustum inside the new
// one. The camera (the view-space origin) must lie strictly on the negative side, and the plane must not
// pass through the far corner of the frustum (where the scale 2/(C·Q) blows up); otherwise an error says
// which, and there is no matrix.
base::Result<glm::dmat4> obliqueProjection(const glm::dmat4& projection, const glm::dvec4& clipPlane);

// The part of a mirror's rectangle worth drawing in a view. `rectangle` maps the unit square [-1, 1]² of
// local XZ to the mirror's rectangle, `toClip` maps that square to the view's clip space. A GPU draws the
// rectangle from float vertices: a mirror 1e12 wide seen from a few metres has corners 5e11 away, whose
// float rounding (≈ 6e4) moves its plane by tens of kilometres, so objects in front of it are cut or lost.
// When the part inside the view frustum is under a thousandth of the rectangle along either side, this
// returns `rectangle` narrowed to that part's bounding box (a little larger, within the rectangle), so the
// drawn corners lie near what is seen; otherwise `rectangle` itself, which keeps the mirror's texture
// coordinates. Computed in double: clip-space positions are affine in the local ones, so the clipped
// polygon's local coordinates interpolate exactly.
glm::dmat4 visibleMirrorRectangle(const glm::dmat4& rectangle, const glm::dmat4& toClip);

// A rectangle of pixels [x0, x1) × [y0, y1), y up (GL window coordinates).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
};

struct ScreenCoverage {
    double pixelArea = 0.0; // area of the visible part, in pixels
    PixelRect rect;         // pixel bounds of the visible part (empty if none)
};

// Where a world-space polygon lands on a width × height target seen through `viewProjection`: clipped to
// the view frustum, to the kept side of `keepPlane` (the parent mirror's plane, or none), and to `bounds`.
ScreenCoverage screenCoverage(const std::vector<glm::dvec3>& polygon, const glm::dmat4& viewProjection,
                              int width, int height, const PixelRect& bounds,
                              const glm::dvec4* keepPlane = nullptr);

} // namespace speculum::render::math
