#include "editor/ui/Gizmo.hpp"

#include "editor/ui/ViewGrid.hpp"
#include "render/math/Projection.hpp"
#include "scene/model/NodeMath.hpp"

#include <QLineF>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace speculum::ui {

namespace {

glm::dvec3 unit(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double l = glm::length(v);
    return l > 1e-12 && std::isfinite(l) ? v / l : fallback;
}

double distanceToSegment(QPointF p, QPointF a, QPointF b) {
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return QLineF(p, a + ab * t).length();
}

} // namespace

ScreenProjection::ScreenProjection(const render::Camera& camera, QSizeF size)
    : m_camera(camera)
    , m_size(size) {
    const double aspect = size.width() / std::max(size.height(), 1.0);
    m_viewProjection = render::math::perspective(camera.fovY, aspect, camera.near, camera.far) *
                       render::math::viewRotation(camera) * render::math::cameraRelative(camera);
}

std::optional<QPointF> ScreenProjection::project(const glm::dvec3& world) const {
    const glm::dvec4 clip = m_viewProjection * glm::dvec4(world, 1.0);
    if (clip.w <= 1e-9) {
        return std::nullopt;
    }
    const double x = clip.x / clip.w, y = clip.y / clip.w;
    return QPointF((x * 0.5 + 0.5) * m_size.width(), (0.5 - y * 0.5) * m_size.height());
}

double ScreenProjection::worldPerPixel(const glm::dvec3& world) const {
    const glm::dvec3 forward = unit(m_camera.target - m_camera.position, {0, 0, -1});
    const double depth = std::max(glm::dot(world - m_camera.position, forward), m_camera.near);
    return 2.0 * depth * std::tan(glm::radians(m_camera.fovY) * 0.5) / std::max(m_size.height(), 1.0);
}

void Gizmo::setUp(HandleMode mode, const ScreenProjection& projection, const glm::dmat4& parentWorld,
                  const glm::dmat4& world) {
    m_mode = mode;
    m_projection = projection;
    m_parentWorld = parentWorld;
    m_origin = glm::dvec3(world[3]);
    m_valid = false;
    const auto origin = projection.project(m_origin);
    if (mode == HandleMode::Select || !origin) {
        return;
    }
    m_originPx = *origin;
    m_length = kHandlePixels * projection.worldPerPixel(m_origin);
    static const glm::dvec3 basis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i) {
        Axis& a = m_axes[std::size_t(i)];
        a.index = i;
        a.line.clear();
        if (mode == HandleMode::Move) {
            a.direction = unit(glm::dvec3(parentWorld[i]), basis[i]);
        } else if (mode == HandleMode::Scale) {
            a.direction = unit(glm::dvec3(world[i]), basis[i]);
        }
    }
    if (mode == HandleMode::Rotate) {
        // R = Rz·Ry·Rx: z turns about the parent's Z, y about Rz·Y, x about Rz·Ry·X (all in the parent's
        // orientation, scale removed).
        glm::dmat3 parentRotation;
        for (int i = 0; i < 3; ++i) {
            parentRotation[i] = unit(glm::dvec3(parentWorld[i]), basis[i]);
        }
        // The node's current Euler angles are implied by world; recover them from the rotation part.
        const glm::dmat3 local = glm::inverse(parentRotation) * glm::dmat3(world);
        glm::dmat3 r;
        for (int i = 0; i < 3; ++i) {
            r[i] = unit(local[i], basis[i]);
        }
        // R = Rz(c)·Ry(b)·Rx(a): r[0] = Rz·Ry·X, and Rz·Y is r[0]-independent: derive from the angles.
        const double b = std::asin(std::clamp(-r[0][2], -1.0, 1.0));
        const double c = std::atan2(r[0][1], r[0][0]);
        const glm::dvec3 zAxis(0, 0, 1);
        const glm::dvec3 yAxis(-std::sin(c), std::cos(c), 0);
        const glm::dvec3 xAxis(std::cos(b) * std::cos(c), std::cos(b) * std::sin(c), -std::sin(b));
        m_axes[0].direction = unit(parentRotation * xAxis, basis[0]);
        m_axes[1].direction = unit(parentRotation * yAxis, basis[1]);
        m_axes[2].direction = unit(parentRotation * zAxis, basis[2]);
        for (Axis& a : m_axes) {
            const glm::dvec3 u =
                unit(glm::cross(a.direction, std::abs(a.direction.y) < 0.9 ? basis[1] : basis[0]), basis[0]);
            const glm::dvec3 v = glm::cross(a.direction, u);
            for (int k = 0; k <= 64; ++k) {
                const double t = glm::two_pi<double>() * k / 64.0;
                if (auto p = projection.project(m_origin + (u * std::cos(t) + v * std::sin(t)) * m_length)) {
                    a.line.push_back(*p);
                }
            }
        }
    } else {
        for (Axis& a : m_axes) {
            if (auto tip = projection.project(m_origin + a.direction * m_length)) {
                a.line = {m_originPx, *tip};
            }
        }
    }
    m_valid = true;
}

int Gizmo::hitTest(QPointF point) const {
    if (!m_valid) {
        return -1;
    }
    // The centre of the scale handles scales evenly: the centre wins over the axes that start there.
    if (m_mode == HandleMode::Scale &&
        std::hypot(point.x() - m_originPx.x(), point.y() - m_originPx.y()) <= kCentrePixels) {
        return kUniformAxis;
    }
    int best = -1;
    double bestDistance = kHitPixels;
    for (const Axis& a : m_axes) {
        for (std::size_t k = 1; k < a.line.size(); ++k) {
            const double d = distanceToSegment(point, a.line[k - 1], a.line[k]);
            if (d < bestDistance) {
                bestDistance = d;
                best = a.index;
            }
        }
    }
    return best;
}

namespace {

// The double nearest to `value` written with 12 significant digits: a multiple of a step such as 0.1
// comes out of the arithmetic as 0.30000000000000004, which a file would then write out in full.
double shortDecimal(double value) {
    std::array<char, 32> text{};
    const auto written =
        std::to_chars(text.data(), text.data() + text.size(), value, std::chars_format::general, 12);
    double parsed = value;
    if (written.ec == std::errc{}) {
        std::from_chars(text.data(), written.ptr, parsed);
    }
    return parsed;
}

// `value` on a grid of `step` (nothing for a step that is not a positive finite number).
double onGrid(double value, double step) {
    return step > 0.0 && std::isfinite(step) ? shortDecimal(std::round(value / step) * step) : value;
}

// `value` to `digits` significant digits: what a drag can mean, without the noise of the pixels' maths.
double significant(double value, int digits) {
    if (value == 0.0 || !std::isfinite(value)) {
        return value;
    }
    return onGrid(value, std::pow(10.0, std::floor(std::log10(std::abs(value))) - (digits - 1)));
}

} // namespace

double Gizmo::gridStep() const {
    return groundGridSpacing(m_projection.camera());
}

scene::NodeData Gizmo::drag(const scene::NodeData& start, int axis, QPointF from, QPointF to,
                            const std::optional<SnapSteps>& snap) const {
    scene::NodeData out = start;
    if (!m_valid || axis < 0 || axis > kUniformAxis ||
        (axis == kUniformAxis && m_mode != HandleMode::Scale)) {
        return out;
    }
    if (axis == kUniformAxis) {
        // Right or up grows it, left or down shrinks it: one handle length doubles the size.
        const QPointF mouse = to - from;
        const double pixels = kHandlePixels;
        const double factor = std::max(1.0 + (mouse.x() - mouse.y()) / pixels, 0.01);
        for (int i = 0; i < 3; ++i) {
            out.transform.scale[i] = scaled(start.transform.scale[i], factor, snap);
        }
        return out;
    }
    const Axis& a = m_axes[std::size_t(axis)];
    const QPointF mouse = to - from;
    if (m_mode == HandleMode::Rotate) {
        const QPointF p0 = from - m_originPx, p1 = to - m_originPx;
        double delta = std::atan2(p1.y(), p1.x()) - std::atan2(p0.y(), p0.x());
        delta = std::remainder(delta, glm::two_pi<double>());
        // Screen y points down: a counter-clockwise turn on screen is a negative atan2 change. Seen from
        // the axis tip (axis towards the camera) that is a positive rotation.
        const glm::dvec3 toCamera = m_projection.camera().position - m_origin;
        const double sign = glm::dot(a.direction, toCamera) >= 0.0 ? -1.0 : 1.0;
        // Snapped: the rotate step; else hundredths of a degree, which no pixel of the drag can tell apart.
        out.transform.rotate[axis] =
            onGrid(start.transform.rotate[axis] + glm::degrees(delta) * sign, snap ? snap->rotate : 0.01);
        return out;
    }
    if (a.line.size() < 2) {
        return out;
    }
    const QPointF screenAxis = a.line[1] - a.line[0];
    const double len2 = QPointF::dotProduct(screenAxis, screenAxis);
    if (len2 < 1.0) {
        return out; // the axis points at the camera: no usable direction on screen
    }
    const double fraction = QPointF::dotProduct(mouse, screenAxis) / len2; // in handle lengths
    if (m_mode == HandleMode::Move) {
        const glm::dvec3 worldDelta = a.direction * (fraction * m_length);
        const glm::dvec3 moved =
            start.transform.translate + glm::dvec3(glm::inverse(m_parentWorld) * glm::dvec4(worldDelta, 0.0));
        // Snapped: on the move step's lines (the ground grid's by default); else on a grid a thousand times
        // finer than the ground grid (below a pixel).
        const double step = !snap ? gridStep() * 1e-3 : snap->move > 0.0 ? snap->move : gridStep();
        for (int i = 0; i < 3; ++i) {
            if (moved[i] != start.transform.translate[i]) { // what the drag changes, and nothing else
                out.transform.translate[i] = onGrid(moved[i], step);
            }
        }
    } else if (m_mode == HandleMode::Scale) {
        // One handle length outwards doubles the scale; the factor never reaches zero or flips sign.
        const double factor = std::max(1.0 + fraction, 0.01);
        out.transform.scale[axis] = scaled(start.transform.scale[axis], factor, snap);
    }
    return out;
}

double Gizmo::scaled(double scale, double factor, const std::optional<SnapSteps>& snap) {
    // Snapped: the factor in the scale steps (never 0); the result to 4 significant digits either way.
    const double f = snap ? std::max(onGrid(factor, snap->scale), snap->scale) : factor;
    return significant(scale * f, 4);
}

scene::NodeData followDrag(HandleMode mode, const scene::NodeData& leadStart, const scene::NodeData& leadNow,
                           const glm::dmat4& leadParentWorld, const scene::NodeData& start,
                           const glm::dmat4& parentWorld) {
    scene::NodeData out = start;
    if (mode == HandleMode::Move) {
        const glm::dvec3 worldDelta(
            leadParentWorld * glm::dvec4(leadNow.transform.translate - leadStart.transform.translate, 0.0));
        const glm::dvec3 local(glm::inverse(parentWorld) * glm::dvec4(worldDelta, 0.0));
        // A parent scaled to zero has no inverse: such a node cannot follow and stays where it is.
        if (std::isfinite(local.x) && std::isfinite(local.y) && std::isfinite(local.z)) {
            out.transform.translate = start.transform.translate + local;
        }
    } else if (mode == HandleMode::Rotate) {
        out.transform.rotate =
            start.transform.rotate + (leadNow.transform.rotate - leadStart.transform.rotate);
    } else if (mode == HandleMode::Scale) {
        for (int i = 0; i < 3; ++i) {
            if (leadStart.transform.scale[i] != 0.0) {
                out.transform.scale[i] =
                    start.transform.scale[i] * (leadNow.transform.scale[i] / leadStart.transform.scale[i]);
            }
        }
    }
    return out;
}

} // namespace speculum::ui
