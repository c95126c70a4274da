#include "render/math/ShadowFrustum.hpp"

#include "render/math/Projection.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::render::math {

namespace {

// A world-space bounding sphere of each shadow caster.
struct Sphere {
    glm::dvec3 center;
    double radius;
};

std::vector<Sphere> casterSpheres(const FrameInput& input) {
    std::vector<Sphere> spheres;
    for (const DrawItem& item : input.items) {
        if (!item.castsShadows || !item.mesh)
            continue;
        const Box box = worldBounds(computeBounds(*item.mesh), item.world);
        spheres.push_back({box.center(), 0.5 * glm::length(box.max - box.min)});
    }
    for (const Reflector& reflector : input.reflectors) {
        if (!reflector.mesh)
            continue;
        const Box box = worldBounds(computeBounds(*reflector.mesh), reflector.world);
        spheres.push_back({box.center(), 0.5 * glm::length(box.max - box.min)});
    }
    return spheres;
}

// Does a sphere (relative to the light) reach into the 90° pyramid of cube face `face`?
bool sphereTouchesFace(const glm::dvec3& c, double r, int face) {
    const int axis = face / 2;
    const double sign = (face % 2 == 0) ? 1.0 : -1.0;
    const double along = sign * c[axis];
    const double slack = r * std::sqrt(2.0);
    if (along + r <= 0.0)
        return false;
    for (int other = 0; other < 3; ++other) {
        if (other == axis)
            continue;
        if (along - c[other] < -slack || along + c[other] < -slack)
            return false;
    }
    return true;
}

glm::dvec3 anyPerpendicular(const glm::dvec3& d) {
    return std::abs(d.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
}

} // namespace

const std::array<glm::dmat4, 6>& cubeFaceViews() {
    static const std::array<glm::dmat4, 6> views = {
        glm::lookAt(glm::dvec3(0), glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0)),
        glm::lookAt(glm::dvec3(0), glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0)),
        glm::lookAt(glm::dvec3(0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)),
        glm::lookAt(glm::dvec3(0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1)),
        glm::lookAt(glm::dvec3(0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0)),
        glm::lookAt(glm::dvec3(0), glm::dvec3(0, 0, -1), glm::dvec3(0, -1, 0)),
    };
    return views;
}

std::optional<ShadowFrustum> shadowFrustum(const FrameInput& input, const Light& light, int mapSize) {
    const Box scene = sceneBounds(input);
    if (scene.empty())
        return std::nullopt;
    const auto corners = scene.corners();
    ShadowFrustum f;
    mapSize = std::max(mapSize, 1);

    if (light.type == LightType::Directional) {
        const glm::dvec3 dir = glm::normalize(light.direction);
        const glm::dvec3 center = scene.center();
        const double radius = 0.5 * glm::length(scene.max - scene.min) + 1e-3;
        const glm::dmat4 view = glm::lookAt(center - dir * (radius * 2.0), center, anyPerpendicular(dir));
        // Fit tightly in light space around the scene box so every receiver is inside the map.
        Box lightBox;
        for (const glm::dvec3& c : corners)
            lightBox.add(glm::dvec3(view * glm::dvec4(c, 1.0)));
        const double pad = 1e-3 * radius;
        const double extent =
            std::max(lightBox.max.x - lightBox.min.x, lightBox.max.y - lightBox.min.y) + 2 * pad;
        const glm::dvec2 mid{(lightBox.min.x + lightBox.max.x) * 0.5,
                             (lightBox.min.y + lightBox.max.y) * 0.5};
        const glm::dmat4 projection =
            glm::ortho(mid.x - extent / 2, mid.x + extent / 2, mid.y - extent / 2, mid.y + extent / 2,
                       -lightBox.max.z - pad, -lightBox.min.z + pad);
        f.viewProjection[0] = projection * view;
        f.near = -lightBox.max.z - pad;
        f.far = -lightBox.min.z + pad;
        f.texelSize = extent / mapSize;
        return f;
    }

    // Point and spot: near/far from the distance to the scene box.
    double farthest = 0.0;
    for (const glm::dvec3& c : corners)
        farthest = std::max(farthest, glm::length(c - light.position));
    f.far = std::max(farthest * 1.01, 1e-3);
    f.near = std::clamp(f.far * 1e-3, 1e-4, 0.05);
    f.perspective = true;
    const glm::dmat4 translate = glm::translate(glm::dmat4(1.0), -light.position);

    if (light.type == LightType::Spot) {
        const glm::dvec3 dir = glm::normalize(light.direction);
        const double fov = std::clamp(2.0 * light.spotAngle + 2.0, 1.0, 170.0);
        const glm::dmat4 view = glm::lookAt(light.position, light.position + dir, anyPerpendicular(dir));
        f.viewProjection[0] = perspective(fov, 1.0, f.near, f.far) * view;
        f.texelSize = 2.0 * std::tan(glm::radians(fov) * 0.5) / mapSize;
        return f;
    }

    f.cube = true;
    const glm::dmat4 projection = perspective(90.0, 1.0, f.near, f.far);
    for (int face = 0; face < 6; ++face)
        f.viewProjection[face] = projection * cubeFaceViews()[face] * translate;
    f.texelSize = 2.0 / mapSize;
    for (const Sphere& s : casterSpheres(input))
        for (int face = 0; face < 6; ++face)
            if (sphereTouchesFace(s.center - light.position, s.radius, face))
                f.faceMask |= 1u << face;
    return f;
}

} // namespace speculum::render::math
