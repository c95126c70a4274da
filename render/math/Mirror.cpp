#include "render/math/Mirror.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <sstream>

namespace speculum::render::math {

base::Result<Plane> mirrorPlane(const glm::dmat4& world) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(world[c][r]))
                return base::Error{
                    "the mirror's transform holds a value that is not a finite number, so it has no "
                    "plane"};
    const glm::dvec3 ex(world[0]), ey(world[1]), ez(world[2]);
    glm::dvec3 normal = glm::cross(ez, ex); // spans the rectangle whatever the local Y scale
    const double length = glm::length(normal);
    if (!(length > 1e-300) || !std::isfinite(length))
        return base::Error{"the mirror's transform collapses its rectangle to zero area, so it has no plane"};
    normal /= length;
    // A mirroring transform keeps the reflective side where local +Y goes.
    if (glm::dot(normal, ey) < 0.0)
        normal = -normal;
    const glm::dvec3 origin(world[3]);
    return Plane{normal, -glm::dot(normal, origin)};
}

std::array<glm::dvec3, 4> mirrorCorners(const Mirror& mirror) {
    const double hx = mirror.size.x * 0.5, hz = mirror.size.y * 0.5;
    const glm::dvec4 local[4] = {{-hx, 0, hz, 1}, {hx, 0, hz, 1}, {hx, 0, -hz, 1}, {-hx, 0, -hz, 1}};
    std::array<glm::dvec3, 4> corners;
    for (int i = 0; i < 4; ++i)
        corners[static_cast<std::size_t>(i)] = glm::dvec3(mirror.world * local[i]);
    return corners;
}

base::Result<glm::dmat4> reflectionMatrix(const Plane& plane) {
    const double length = glm::length(plane.normal);
    if (!std::isfinite(length) || !std::isfinite(plane.d))
        return base::Error{"mirror plane is not finite"};
    if (length < 1e-12)
        return base::Error{"mirror normal is zero"};
    if (std::abs(length - 1.0) > 1e-9) {
        std::ostringstream s;
        s << "mirror normal must be unit length, got length " << length;
        return base::Error{s.str()};
    }
    const glm::dvec3 n = plane.normal;
    glm::dmat4 r(1.0);
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row)
            r[col][row] -= 2.0 * n[row] * n[col];
    r[3] = glm::dvec4(-2.0 * plane.d * n, 1.0);
    return r;
}

glm::dvec4 transformPlane(const glm::dvec4& plane, const glm::dmat4& m) {
    // Planes transform by the inverse transpose of the point transform.
    return glm::transpose(glm::inverse(m)) * plane;
}

base::Result<glm::dmat4> obliqueProjection(const glm::dmat4& projection, const glm::dvec4& clipPlane) {
    const double scale = glm::length(glm::dvec3(clipPlane));
    if (!(scale > 0.0) || !std::isfinite(scale) || !std::isfinite(clipPlane.w))
        return base::Error{"clip plane has no normal"};
    const glm::dvec4 c = clipPlane / scale; // unit normal: the thresholds below are world distances
    if (c.w > -1e-9)
        return base::Error{c.w > 1e-9 ? "the camera is behind the mirror plane"
                                      : "the camera is on the mirror plane"};
    // Q: the corner of the view frustum on the far side of the plane, in view space.
    const glm::dmat4 inverse = glm::inverse(projection);
    const glm::dvec4 clipSpacePlane = glm::transpose(inverse) * c;
    const glm::dvec4 corner(clipSpacePlane.x >= 0.0 ? 1.0 : -1.0, clipSpacePlane.y >= 0.0 ? 1.0 : -1.0, 1.0,
                            1.0);
    const glm::dvec4 q = inverse * corner;
    const double cq = glm::dot(c, q);
    // M4·q = 1 by construction, so q.w > 0 for a perspective projection and q / q.w is the corner itself.
    const glm::dvec3 farCorner = glm::dvec3(q) / q.w;
    const double cornerDistance = cq / q.w; // world distance of the far corner beyond the plane
    if (!(cornerDistance > 1e-9 * std::max(1.0, glm::length(farCorner))))
        return base::Error{cornerDistance > -1e-9
                               ? "the mirror plane is seen edge-on: it passes through the far corner "
                                 "of the view, where the oblique scale 2/(C·Q) blows up"
                               : "nothing beyond the mirror plane is in view"};
    const glm::dvec4 row3(projection[0][3], projection[1][3], projection[2][3], projection[3][3]);
    const glm::dvec4 row2 = c * (2.0 / cq) - row3;
    glm::dmat4 result = projection;
    for (int col = 0; col < 4; ++col)
        result[col][2] = row2[col];
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            if (!std::isfinite(result[col][row]))
                return base::Error{"oblique projection is not finite"};
    return result;
}

namespace {

using Polygon = std::vector<glm::dvec4>;

// Sutherland–Hodgman against one homogeneous half-space f(v) ≥ 0.
template <typename F>
Polygon clip(const Polygon& in, F f) {
    Polygon out;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const glm::dvec4& a = in[i];
        const glm::dvec4& b = in[(i + 1) % in.size()];
        const double fa = f(a), fb = f(b);
        if (fa >= 0)
            out.push_back(a);
        if ((fa >= 0) != (fb >= 0))
            out.push_back(a + (b - a) * (fa / (fa - fb)));
    }
    return out;
}

} // namespace

glm::dmat4 visibleMirrorRectangle(const glm::dmat4& rectangle, const glm::dmat4& toClip) {
    struct Vertex {
        glm::dvec4 clip;
        glm::dvec2 local;
    };
    std::vector<Vertex> poly;
    for (const glm::dvec2& local :
         {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
        poly.push_back({toClip * glm::dvec4(local.x, 0.0, local.y, 1.0), local});
    for (const Vertex& v : poly)
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(v.clip[i]))
                return rectangle;
    // −w ≤ x, y, z ≤ w, one half-space at a time (Sutherland–Hodgman).
    for (int plane = 0; plane < 6 && !poly.empty(); ++plane) {
        const int axis = plane / 2;
        const double sign = plane % 2 ? -1.0 : 1.0;
        auto f = [&](const Vertex& v) { return v.clip.w + sign * v.clip[axis]; };
        std::vector<Vertex> out;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Vertex& a = poly[i];
            const Vertex& b = poly[(i + 1) % poly.size()];
            const double fa = f(a), fb = f(b);
            if (fa >= 0)
                out.push_back(a);
            if ((fa >= 0) != (fb >= 0)) {
                const double t = fa / (fa - fb);
                out.push_back({a.clip + (b.clip - a.clip) * t, a.local + (b.local - a.local) * t});
            }
        }
        poly = std::move(out);
    }
    if (poly.size() < 3)
        return rectangle; // nothing of it in view: drawn (and culled) as it is
    glm::dvec2 lo(1.0), hi(-1.0);
    for (const Vertex& v : poly) {
        lo = glm::min(lo, v.local);
        hi = glm::max(hi, v.local);
    }
    const glm::dvec2 extent = hi - lo; // of 2 for the whole rectangle
    if (!(extent.x < 2e-3 || extent.y < 2e-3))
        return rectangle;
    // A margin of a tenth of the part (and of 1e-9 of the rectangle, for a part seen edge-on), so the
    // frustum's edges, where rasterization decides pixel by pixel, lie well inside what is drawn.
    const glm::dvec2 margin = glm::max(extent, glm::dvec2(1e-9)) * 0.1;
    lo = glm::max(lo - margin, glm::dvec2(-1.0));
    hi = glm::min(hi + margin, glm::dvec2(1.0));
    const glm::dvec2 centre = (lo + hi) * 0.5, half = (hi - lo) * 0.5;
    glm::dmat4 part(1.0);
    part[0][0] = half.x;
    part[2][2] = half.y;
    part[3] = glm::dvec4(centre.x, 0.0, centre.y, 1.0);
    return rectangle * part;
}

ScreenCoverage screenCoverage(const std::vector<glm::dvec3>& polygon, const glm::dmat4& viewProjection,
                              int width, int height, const PixelRect& bounds, const glm::dvec4* keepPlane) {
    ScreenCoverage result;
    Polygon world;
    for (const glm::dvec3& p : polygon)
        world.emplace_back(p, 1.0);
    if (keepPlane)
        world = clip(world, [&](const glm::dvec4& v) { return glm::dot(*keepPlane, v); });
    Polygon poly;
    for (const glm::dvec4& v : world)
        poly.push_back(viewProjection * v);
    // The six frustum planes in clip space: −w ≤ x, y, z ≤ w.
    for (int axis = 0; axis < 3 && !poly.empty(); ++axis) {
        poly = clip(poly, [axis](const glm::dvec4& v) { return v.w + v[axis]; });
        if (!poly.empty())
            poly = clip(poly, [axis](const glm::dvec4& v) { return v.w - v[axis]; });
    }
    if (poly.size() < 3)
        return result;
    std::vector<glm::dvec2> pixels;
    for (const glm::dvec4& v : poly)
        pixels.emplace_back((v.x / v.w * 0.5 + 0.5) * width, (v.y / v.w * 0.5 + 0.5) * height);
    // Then to the bounds (the parent's pixels), as four more half-planes.
    auto clip2 = [&](auto f) {
        std::vector<glm::dvec2> out;
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            const glm::dvec2 a = pixels[i], b = pixels[(i + 1) % pixels.size()];
            const double fa = f(a), fb = f(b);
            if (fa >= 0)
                out.push_back(a);
            if ((fa >= 0) != (fb >= 0))
                out.push_back(a + (b - a) * (fa / (fa - fb)));
        }
        pixels = std::move(out);
    };
    clip2([&](glm::dvec2 p) { return p.x - bounds.x0; });
    if (!pixels.empty())
        clip2([&](glm::dvec2 p) { return bounds.x1 - p.x; });
    if (!pixels.empty())
        clip2([&](glm::dvec2 p) { return p.y - bounds.y0; });
    if (!pixels.empty())
        clip2([&](glm::dvec2 p) { return bounds.y1 - p.y; });
    if (pixels.size() < 3)
        return result;
    double area = 0.0;
    glm::dvec2 lo(1e300), hi(-1e300);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const glm::dvec2 a = pixels[i], b = pixels[(i + 1) % pixels.size()];
        area += a.x * b.y - b.x * a.y;
        lo = glm::min(lo, a);
        hi = glm::max(hi, a);
    }
    result.pixelArea = std::abs(area) * 0.5;
    result.rect = {std::max(bounds.x0, static_cast<int>(std::floor(lo.x))),
                   std::max(bounds.y0, static_cast<int>(std::floor(lo.y))),
                   std::min(bounds.x1, static_cast<int>(std::ceil(hi.x))),
                   std::min(bounds.y1, static_cast<int>(std::ceil(hi.y)))};
    return result;
}

} // namespace speculum::render::math
