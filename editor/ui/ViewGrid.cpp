#include "editor/ui/ViewGrid.hpp"

#include "render/math/Projection.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace speculum::ui {

namespace {

constexpr int kHalfLines = 30;     // lines each side of the centre: the grid spans 60 cells
constexpr int kPiecesPerLine = 24; // each line is cut into pieces so that it can fade along its length
constexpr double kMinorAlpha = 0.22, kMajorAlpha = 0.38, kAxisAlpha = 0.6;

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

} // namespace

ClipProjection::ClipProjection(const render::Camera& camera, QSizeF size)
    : m_near(camera.near)
    , m_size(size) {
    const double aspect = size.width() / std::max(size.height(), 1.0);
    m_viewProjection = render::math::perspective(camera.fovY, aspect, camera.near, camera.far) *
                       render::math::viewRotation(camera) * render::math::cameraRelative(camera);
}

QPointF ClipProjection::toWidget(const glm::dvec4& clip) const {
    const double x = clip.x / clip.w, y = clip.y / clip.w;
    return QPointF((x * 0.5 + 0.5) * m_size.width(), (0.5 - y * 0.5) * m_size.height());
}

std::optional<QPointF> ClipProjection::point(const glm::dvec3& p) const {
    const glm::dvec4 c = m_viewProjection * glm::dvec4(p, 1.0);
    if (c.w < m_near) {
        return std::nullopt;
    }
    return toWidget(c);
}

double groundGridSpacing(const render::Camera& camera) {
    const double distance = glm::length(camera.position - camera.target);
    // What the view is about: its distance to the target, or its height when it hovers over the ground
    // looking far away.
    const double scale = std::max({distance, std::abs(camera.position.y), 1e-6});
    return std::isfinite(scale) ? std::pow(10.0, std::floor(std::log10(scale / 2.0))) : 0.0;
}

GroundGrid groundGrid(const render::Camera& camera) {
    GroundGrid grid;
    const double spacing = groundGridSpacing(camera);
    if (!(spacing > 0.0)) {
        return grid;
    }
    grid.spacing = spacing;
    const double s = grid.spacing;
    const double extent = kHalfLines * s;
    // Centred under the camera, snapped to the grid so lines do not swim as the view moves.
    const double cx = std::round(camera.position.x / s) * s, cz = std::round(camera.position.z / s) * s;
    const double height = std::abs(camera.position.y);
    const double fadeDistance = std::max(extent * 0.9, 1e-9);

    auto addLine = [&](const glm::dvec3& from, const glm::dvec3& to, glm::vec3 color, double alpha) {
        for (int i = 0; i < kPiecesPerLine; ++i) {
            const glm::dvec3 a = from + (to - from) * (double(i) / kPiecesPerLine);
            const glm::dvec3 b = from + (to - from) * (double(i + 1) / kPiecesPerLine);
            const glm::dvec3 mid = (a + b) * 0.5;
            const double toEye = std::max(glm::length(mid - camera.position), 1e-9);
            // Fades out far away, and where the view grazes the ground (its height over the distance is the
            // sine of the angle under which the ground is seen there).
            const double fade = (1.0 - smoothstep(0.3 * fadeDistance, fadeDistance, toEye)) *
                                smoothstep(0.02, 0.25, height / toEye);
            const double faded = alpha * fade;
            if (faded < 0.02) {
                continue;
            }
            render::GuideLine line;
            line.from = a;
            line.to = b;
            line.color = glm::vec4(color, float(faded));
            grid.lines.push_back(line);
        }
    };
    const glm::vec3 grey(200 / 255.f, 200 / 255.f, 205 / 255.f), red(225 / 255.f, 70 / 255.f, 70 / 255.f),
        blue(70 / 255.f, 120 / 255.f, 235 / 255.f);
    for (int i = -kHalfLines; i <= kHalfLines; ++i) {
        const double x = cx + i * s, z = cz + i * s;
        const long long kx = std::llround(x / s), kz = std::llround(z / s);
        // Lines along Z at this x, and along X at this z.
        const bool xAxis = kz == 0, zAxis = kx == 0;
        addLine({x, 0.0, cz - extent}, {x, 0.0, cz + extent}, zAxis ? blue : grey,
                zAxis ? kAxisAlpha : (kx % 10 == 0 ? kMajorAlpha : kMinorAlpha));
        addLine({cx - extent, 0.0, z}, {cx + extent, 0.0, z}, xAxis ? red : grey,
                xAxis ? kAxisAlpha : (kz % 10 == 0 ? kMajorAlpha : kMinorAlpha));
    }
    return grid;
}

} // namespace speculum::ui
