#include "render/envmap/CaptureMath.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::render::envmap {

namespace {
constexpr double kPi = 3.14159265358979323846;
} // namespace

glm::dmat4 cubeFaceView(int face) {
    // The face frame from the mapping itself: major axis M = direction of the face centre, S and T the
    // directions in which u and v grow at the centre.
    const glm::dvec3 m = cubeDirection(face, {0.5, 0.5});
    const glm::dvec3 s = glm::normalize(cubeDirection(face, {1.0, 0.5}) - m * std::sqrt(2.0) * 0.5);
    const glm::dvec3 t = glm::normalize(cubeDirection(face, {0.5, 1.0}) - m * std::sqrt(2.0) * 0.5);
    glm::dmat4 view(1.0);
    for (int c = 0; c < 3; ++c) { // GLM is column-major: view[column][row]
        view[c][0] = s[c];
        view[c][1] = t[c];
        view[c][2] = -m[c];
    }
    return view;
}

glm::dmat4 cubeFaceProjection(double near, double far) {
    assert(near > 0.0 && far > near && "envmap::cubeFaceProjection(): need 0 < near < far");
    return glm::perspective(kPi / 2.0, 1.0, near, far);
}

glm::dmat4 cubeFaceViewProjection(int face, const glm::dmat3& mapFromWorld, double near, double far) {
    return cubeFaceProjection(near, far) * cubeFaceView(face) * glm::dmat4(mapFromWorld);
}

glm::dvec4 WarpParameters::packed() const {
    if (type == MapType::DualParaboloid)
        return {ndcScale.x, ndcScale.y, rimSine, 0.0};
    return {ndcScale.x, ndcScale.y, depthScale, cutCurvature};
}

WarpParameters warpParameters(const MapLayout& layout, int component, double far) {
    assert(layout.type != MapType::Cube && "envmap::warpParameters(): cube faces are not warped");
    assert(component >= 0 && component < 2 && far > 0.0 && "envmap::warpParameters(): bad component or far");
    WarpParameters w;
    w.type = layout.type;
    w.component = component;
    w.far = far;
    // NDC = 2·(offset + scale·uv) − 1 = scale·(2uv − 1), since 2·offset + scale = 1.
    w.ndcScale = layout.scale;
    if (layout.type == MapType::DualParaboloid) {
        // Texture edge at nominal radius R = 1/scale: the direction at angle θ = 2·atan(R) from the axis,
        // whose cosine is (1 − R²)/(1 + R²) = −γ.
        const double r = 1.0 / layout.scale.x;
        w.rimSine = (r * r - 1.0) / (r * r + 1.0);
        // Seen from the centre, +x right and +y up looking down −z is a GL camera; looking down +z it is
        // a mirror image.
        w.mirrored = component == 1;
    } else {
        const double edge = 1.0 / layout.scale.y; // B
        w.cutLimit = 0.5 * (edge + 4.0 / 3.0);
        w.cutCurvature = 2.0 / (w.cutLimit * w.cutLimit);
        w.depthScale = 2.0 - w.cutCurvature * edge * edge;
        w.mirrored = false; // (a, b) ↦ (x, y) is a rotation of the camera's view in both components
    }
    return w;
}

glm::dvec4 warpVertex(const WarpParameters& warp, const glm::dvec3& p) {
    const double rho = std::max(glm::length(p), 1e-300);
    const glm::dvec3 d = p / rho;
    if (warp.type == MapType::DualParaboloid) {
        const double s = warp.component == 0 ? -d.z : d.z;
        const double denom = std::max(1.0 + s, 1e-4); // only vertices the near plane clips come close
        const glm::dvec2 ndc = glm::dvec2(d.x, d.y) / denom * warp.ndcScale;
        const double z = -1.0 + 2.0 * rho * (s + warp.rimSine) / ((1.0 + warp.rimSine) * warp.far);
        return {ndc, z, 1.0};
    }
    const glm::dvec2 ab = tennisBallUv(warp.component, d) * 2.0 - 1.0;
    const double z = -1.0 + warp.depthScale * rho / warp.far + warp.cutCurvature * ab.y * ab.y;
    return {ab * warp.ndcScale, z, 1.0};
}

} // namespace speculum::render::envmap
