#include "editor/ui/AxisGizmo.hpp"

#include <QPainter>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace speculum::ui {

namespace {

const QColor kColors[3] = {QColor(230, 75, 75), QColor(110, 200, 80), QColor(80, 135, 240)};
const char* const kLabels[3] = {"X", "Y", "Z"};
constexpr double kMargin = 14.0;

glm::dvec3 unit(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double l = glm::length(v);
    return l > 1e-12 && std::isfinite(l) ? v / l : fallback;
}

} // namespace

AxisGizmoLayout axisGizmoLayout(const render::Camera& camera, QSizeF size) {
    AxisGizmoLayout layout;
    layout.center =
        QPointF(size.width() - kMargin - kAxisGizmoRadius - 8.0, kMargin + kAxisGizmoRadius + 8.0);
    const glm::dvec3 forward = unit(camera.target - camera.position, {0.0, 0.0, -1.0});
    const glm::dvec3 right = unit(glm::cross(forward, camera.up), {1.0, 0.0, 0.0});
    const glm::dvec3 up = glm::cross(right, forward);
    for (int i = 0; i < 6; ++i) {
        glm::dvec3 e(0.0);
        e[i % 3] = i < 3 ? 1.0 : -1.0;
        AxisGizmoEnd& end = layout.ends[std::size_t(i)];
        end.axis = i % 3;
        end.positive = i < 3;
        end.tip = layout.center + QPointF(glm::dot(e, right), -glm::dot(e, up)) * kAxisGizmoRadius;
        end.depth = glm::dot(e, forward);
    }
    std::stable_sort(layout.ends.begin(), layout.ends.end(),
                     [](const AxisGizmoEnd& a, const AxisGizmoEnd& b) { return a.depth > b.depth; });
    return layout;
}

void paintAxisGizmo(QPainter& painter, const render::Camera& camera, QSizeF size) {
    const AxisGizmoLayout layout = axisGizmoLayout(camera, size);
    painter.save();
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 50));
    painter.drawEllipse(layout.center, kAxisGizmoRadius + 12.0, kAxisGizmoRadius + 12.0);
    QFont font = painter.font();
    font.setBold(true);
    font.setPixelSize(11);
    painter.setFont(font);
    for (const AxisGizmoEnd& end : layout.ends) {
        const QColor color = kColors[end.axis];
        if (end.positive) {
            painter.setPen(QPen(color, 2.5, Qt::SolidLine, Qt::RoundCap));
            painter.drawLine(layout.center, end.tip);
            painter.setPen(Qt::NoPen);
            painter.setBrush(color);
            painter.drawEllipse(end.tip, 8.0, 8.0);
            painter.setPen(QColor(20, 20, 20));
            painter.drawText(QRectF(end.tip - QPointF(8, 8), QSizeF(16, 16)), Qt::AlignCenter,
                             QString::fromLatin1(kLabels[end.axis]));
        } else {
            QColor dim = color;
            dim.setAlpha(110);
            painter.setPen(QPen(color, 1.2));
            painter.setBrush(dim);
            painter.drawEllipse(end.tip, 6.0, 6.0);
        }
    }
    painter.restore();
}

void paintPivot(QPainter& painter, QPointF at) {
    painter.save();
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(0, 0, 0, 150), 3.0));
    painter.drawEllipse(at, 5.0, 5.0);
    painter.setPen(QPen(QColor(255, 255, 255, 210), 1.3));
    painter.drawEllipse(at, 5.0, 5.0);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 210));
    painter.drawEllipse(at, 1.5, 1.5);
    painter.restore();
}

} // namespace speculum::ui
