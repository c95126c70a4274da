#include "editor/ui/CameraGizmo.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace speculum::ui {

namespace {

// A dark halo under a light line: readable over a bright floor and a dark background alike. Behind the
// scene a faint trace of both stays, so the camera can be found when an object hides it.
constexpr glm::vec4 kHalo(0.0f, 0.0f, 0.0f, 0.47f), kLine(0.92f, 0.92f, 0.92f, 0.86f);
constexpr float kHaloWidth = 3.0f, kLineWidth = 1.3f, kHiddenOpacity = 0.3f;

} // namespace

std::vector<std::pair<glm::dvec3, glm::dvec3>>
cameraGizmoSegments(const render::Camera& sceneCamera, const render::Camera& viewCamera, double aspect) {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> segments;
    const glm::dvec3 eye = sceneCamera.position;
    const glm::dvec3 toTarget = sceneCamera.target - eye;
    const double distance = glm::length(toTarget);
    if (!(distance > 1e-9) || !std::isfinite(distance) ||
        glm::length(viewCamera.position - eye) < 1e-6 * std::max(distance, 1.0)) {
        return segments;
    }
    const glm::dvec3 forward = toTarget / distance;
    glm::dvec3 right = glm::cross(forward, sceneCamera.up);
    if (glm::length(right) < 1e-9) {
        return segments;
    }
    right = glm::normalize(right);
    const glm::dvec3 up = glm::cross(right, forward);
    const double depth = std::clamp(distance * 0.2, 0.3, 2.0);
    const double halfH = depth * std::tan(glm::radians(sceneCamera.fovY) * 0.5);
    const double halfW = halfH * std::max(aspect, 1e-3);
    const glm::dvec3 c = eye + forward * depth;
    const glm::dvec3 corners[4] = {c - right * halfW - up * halfH, c + right * halfW - up * halfH,
                                   c + right * halfW + up * halfH, c - right * halfW + up * halfH};
    for (int i = 0; i < 4; ++i) {
        segments.emplace_back(eye, corners[i]);
        segments.emplace_back(corners[i], corners[(i + 1) % 4]);
    }
    // The up triangle over the top edge (corners 2 and 3).
    const glm::dvec3 apex = c + up * (halfH * 1.6);
    segments.emplace_back(corners[3] + right * (halfW * 0.4), apex);
    segments.emplace_back(apex, corners[2] - right * (halfW * 0.4));
    return segments;
}

void addCameraGizmoGuides(const render::Camera& sceneCamera, const render::Camera& viewCamera, double aspect,
                          std::vector<render::GuideLine>& guides) {
    const auto segments = cameraGizmoSegments(sceneCamera, viewCamera, aspect);
    for (const auto& style : {std::pair{kHalo, kHaloWidth}, std::pair{kLine, kLineWidth}}) {
        for (const auto& [from, to] : segments) {
            guides.push_back({from, to, style.first, style.second, kHiddenOpacity});
        }
    }
}

} // namespace speculum::ui
