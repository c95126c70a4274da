#include "editor/ui/CameraGizmo.hpp"

#include <QPainter>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace speculum::ui {

std::vector<QLineF> cameraGizmoLines(const render::Camera& sceneCamera, const ClipProjection& view,
                                     const render::Camera& viewCamera, double aspect) {
    std::vector<QLineF> lines;
    const glm::dvec3 eye = sceneCamera.position;
    const glm::dvec3 toTarget = sceneCamera.target - eye;
    const double distance = glm::length(toTarget);
    if (!(distance > 1e-9) || !std::isfinite(distance) ||
        glm::length(viewCamera.position - eye) < 1e-6 * std::max(distance, 1.0)) {
        return lines;
    }
    const glm::dvec3 forward = toTarget / distance;
    glm::dvec3 right = glm::cross(forward, sceneCamera.up);
    if (glm::length(right) < 1e-9) {
        return lines;
    }
    right = glm::normalize(right);
    const glm::dvec3 up = glm::cross(right, forward);
    const double depth = std::clamp(distance * 0.2, 0.3, 2.0);
    const double halfH = depth * std::tan(glm::radians(sceneCamera.fovY) * 0.5);
    const double halfW = halfH * std::max(aspect, 1e-3);
    const glm::dvec3 c = eye + forward * depth;
    const glm::dvec3 corners[4] = {c - right * halfW - up * halfH, c + right * halfW - up * halfH,
                                   c + right * halfW + up * halfH, c - right * halfW + up * halfH};
    auto add = [&](const glm::dvec3& a, const glm::dvec3& b) {
        if (auto line = view.segment(a, b)) {
            lines.push_back(*line);
        }
    };
    for (int i = 0; i < 4; ++i) {
        add(eye, corners[i]);
        add(corners[i], corners[(i + 1) % 4]);
    }
    // The up triangle over the top edge (corners 2 and 3).
    const glm::dvec3 apex = c + up * (halfH * 1.6);
    add(corners[3] + right * (halfW * 0.4), apex);
    add(apex, corners[2] - right * (halfW * 0.4));
    return lines;
}

void paintCameraGizmo(QPainter& painter, const render::Camera& sceneCamera, const render::Camera& viewCamera,
                      QSizeF size) {
    const ClipProjection view(viewCamera, size);
    const double aspect = size.width() / std::max(size.height(), 1.0);
    const std::vector<QLineF> lines = cameraGizmoLines(sceneCamera, view, viewCamera, aspect);
    if (lines.empty()) {
        return;
    }
    painter.save();
    painter.setBrush(Qt::NoBrush);
    // A dark halo under a light line: readable over a bright floor and a dark background alike.
    painter.setPen(QPen(QColor(0, 0, 0, 120), 3.0, Qt::SolidLine, Qt::RoundCap));
    painter.drawLines(lines.data(), int(lines.size()));
    painter.setPen(QPen(QColor(235, 235, 235, 220), 1.3, Qt::SolidLine, Qt::RoundCap));
    painter.drawLines(lines.data(), int(lines.size()));
    painter.restore();
}

} // namespace speculum::ui
