#include "editor/view/ViewCamera.hpp"

#include "render/frame/SceneLimits.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtx/rotate_vector.hpp>

namespace speculum::view {

namespace {

// Far grows as the view backs away, but never past the depth range a scene file may hold (so a view
// made the scene camera still saves): kMaxFarNearRatio.
double cappedFar(double near, double far) {
    return std::min(far, near * render::kMaxFarNearRatio);
}

} // namespace

namespace {

glm::dvec3 safeNormalize(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double len = glm::length(v);
    return len > 1e-12 ? v / len : fallback;
}

} // namespace

void ViewCamera::reset(const render::Camera& sceneCamera) {
    m_camera = sceneCamera;
    m_baseDistance = std::max(glm::length(sceneCamera.position - sceneCamera.target), 1e-6);
    m_baseFar = sceneCamera.far;
}

void ViewCamera::orbit(double yawDegrees, double pitchDegrees) {
    const glm::dvec3 up = safeNormalize(m_camera.up, {0.0, 1.0, 0.0});
    glm::dvec3 offset = m_camera.position - m_camera.target;
    const double distance = glm::length(offset);
    if (distance < 1e-12) {
        return;
    }
    offset = glm::rotate(offset, glm::radians(-yawDegrees), up);

    // Clamp pitch so the angle between offset and up stays within [2°, 178°].
    const double current = std::acos(std::clamp(glm::dot(offset / distance, up), -1.0, 1.0));
    const double limit = glm::radians(2.0);
    const double wanted = std::clamp(current - glm::radians(pitchDegrees), limit, glm::pi<double>() - limit);
    // A positive turn about up × offset carries offset away from up (it increases the angle to up): turn
    // by wanted − current to land on `wanted`.
    const glm::dvec3 right = safeNormalize(glm::cross(up, offset), {1.0, 0.0, 0.0});
    offset = glm::rotate(offset, wanted - current, right);

    m_camera.position = m_camera.target + offset;
}

void ViewCamera::orbitByDrag(double dx, double dy, double viewHeight) {
    const double degreesPerPixel = 180.0 / std::max(viewHeight, 1.0);
    // Down (dy > 0) raises the camera: a positive pitch (see the header for three.js' rule).
    const double vertical = m_invertedVertical ? -dy : dy;
    orbit(dx * degreesPerPixel, vertical * degreesPerPixel);
}

void ViewCamera::place(const glm::dvec3& position, const glm::dvec3& target) {
    const double distance = glm::length(position - target);
    if (!(distance > 1e-12) || !std::isfinite(distance)) {
        return;
    }
    m_camera.position = position;
    m_camera.target = target;
    m_camera.far = cappedFar(m_camera.near, m_baseFar + std::max(0.0, distance - m_baseDistance));
}

void ViewCamera::place(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up) {
    place(position, target);
    const double upLength = glm::length(up);
    const glm::dvec3 forward = safeNormalize(m_camera.target - m_camera.position, {0.0, 0.0, -1.0});
    if (std::isfinite(upLength) && upLength > 1e-12 &&
        glm::length(glm::cross(forward, up / upLength)) > 1e-9) {
        m_camera.up = up / upLength;
    }
}

void ViewCamera::pan(double rightFraction, double upFraction) {
    const glm::dvec3 forward = m_camera.target - m_camera.position;
    const double distance = glm::length(forward);
    if (distance < 1e-12) {
        return;
    }
    const glm::dvec3 right = safeNormalize(glm::cross(forward, m_camera.up), {1.0, 0.0, 0.0});
    const glm::dvec3 up = glm::normalize(glm::cross(right, forward));
    const double visibleHeight = 2.0 * distance * std::tan(glm::radians(m_camera.fovY) * 0.5);
    const glm::dvec3 shift = (right * rightFraction + up * upFraction) * visibleHeight;
    m_camera.position += shift;
    m_camera.target += shift;
}

void ViewCamera::zoom(double factor) {
    const glm::dvec3 offset = m_camera.position - m_camera.target;
    const double distance = glm::length(offset);
    if (distance < 1e-12 || !(factor > 0.0)) {
        return;
    }
    const double newDistance = std::clamp(distance * factor, m_camera.near * 2.0, m_baseDistance * 1e3);
    m_camera.position = m_camera.target + offset * (newDistance / distance);
    // Backing away must not push the scene past the far plane.
    m_camera.far = cappedFar(m_camera.near, m_baseFar + std::max(0.0, newDistance - m_baseDistance));
}

void ViewCamera::frame(const glm::dvec3& center, double radius, double aspect) {
    if (!(radius > 0.0) || !std::isfinite(radius)) {
        radius = 1.0;
    }
    const glm::dvec3 forward = safeNormalize(m_camera.target - m_camera.position, {0.0, 0.0, -1.0});
    const double halfY = glm::radians(m_camera.fovY) * 0.5;
    const double halfX = std::atan(std::tan(halfY) * std::max(aspect, 1e-3));
    const double distance = std::max(radius / std::sin(std::min(halfX, halfY)) * 1.1, m_camera.near * 2.0);
    m_camera.target = center;
    m_camera.position = center - forward * distance;
    m_camera.far = cappedFar(m_camera.near, std::max(m_camera.far, distance + radius * 2.0));
    m_baseFar = std::max(m_baseFar, m_camera.far);
    m_baseDistance = std::max(m_baseDistance, distance);
}

} // namespace speculum::view
