#include "scene/model/SceneChecks.hpp"

#include "render/frame/SceneLimits.hpp"

#include <QLocale>
#include <QString>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace speculum::scene {

namespace {

using render::kMaxCoordinate;

double largestMagnitude(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// v / |v| without overflow or underflow: scaled by its largest component first. Zero stays zero.
glm::dvec3 direction(const glm::dvec3& v) {
    const double m = largestMagnitude(v);
    if (!(m > 0.0)) {
        return glm::dvec3(0.0);
    }
    return glm::normalize(v / m);
}

std::optional<FieldProblem> coordinates(const glm::dvec3& v, const char* field) {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(v[i]) || std::abs(v[i]) > kMaxCoordinate) {
            return FieldProblem{field, "coordinates must be within ±" + formatLimit(kMaxCoordinate) +
                                           ", got " + formatLimit(v[i])};
        }
    }
    return std::nullopt;
}

// Both within kMaxCoordinate: the difference is finite. Too close for the renderers' float maths to tell
// them apart is as bad as equal. `from` names the point the target must differ from.
std::optional<FieldProblem> targetDistance(const glm::dvec3& position, const glm::dvec3& target,
                                           const std::string& from) {
    const double distance = glm::length(target - position);
    const double minimum =
        std::max(render::kMinScale, 1e-6 * std::max(largestMagnitude(position), largestMagnitude(target)));
    if (!(distance >= minimum)) {
        return FieldProblem{"target", distance == 0.0 ? "must differ from " + from
                                                      : "must differ from " + from + " by at least " +
                                                            formatLimit(minimum) + ", got a distance of " +
                                                            formatLimit(distance)};
    }
    return std::nullopt;
}

} // namespace

std::string formatLimit(double value) {
    return QString::number(value, 'g', QLocale::FloatingPointShortest).toStdString();
}

std::optional<FieldProblem> cameraProblem(const CameraData& c) {
    if (auto p = coordinates(c.position, "position")) {
        return p;
    }
    if (auto p = coordinates(c.target, "target")) {
        return p;
    }
    if (auto p = coordinates(c.up, "up")) {
        return p;
    }
    if (!(c.fovY > 0.0 && c.fovY < 180.0)) {
        return FieldProblem{"fovY",
                            "must be between 0 and 180 degrees (exclusive), got " + formatLimit(c.fovY)};
    }
    if (!(c.near > 0.0)) {
        return FieldProblem{"near", "must be greater than 0, got " + formatLimit(c.near)};
    }
    // A tiny near plane spends the depth buffer's precision next to the eye: everything else collapses
    // onto the far plane and disappears.
    if (c.near < render::kMinNear || c.near > kMaxCoordinate) {
        return FieldProblem{"near", "must be in " + formatLimit(render::kMinNear) + ".." +
                                        formatLimit(kMaxCoordinate) + ", got " + formatLimit(c.near)};
    }
    if (!(c.far > c.near)) {
        return FieldProblem{"far", "must be greater than near (" + formatLimit(c.near) + "), got " +
                                       formatLimit(c.far)};
    }
    if (!std::isfinite(c.far) || c.far / c.near > render::kMaxFarNearRatio) {
        return FieldProblem{"far", "must be at most " + formatLimit(render::kMaxFarNearRatio) +
                                       " times near (" + formatLimit(c.near) +
                                       ") for the depth buffer's precision, got " + formatLimit(c.far)};
    }
    if (auto p = targetDistance(c.position, c.target, "the camera position")) {
        return p;
    }
    const glm::dvec3 view = c.target - c.position;
    if (largestMagnitude(c.up) < render::kMinScale) {
        return FieldProblem{"up", largestMagnitude(c.up) == 0.0
                                      ? std::string("must be non-zero")
                                      : "must be at least " + formatLimit(render::kMinScale) + " long"};
    }
    // The sine of the angle between unit vectors: a scale-free test of "parallel".
    if (glm::length(glm::cross(direction(view), direction(c.up))) <= 1e-6) {
        return FieldProblem{"up", "must not be parallel to the view direction (from position to target)"};
    }
    return std::nullopt;
}

std::optional<FieldProblem> editorViewProblem(const EditorView& view) {
    if (auto p = coordinates(view.position, "position")) {
        return p;
    }
    if (auto p = coordinates(view.target, "target")) {
        return p;
    }
    return targetDistance(view.position, view.target, "the view position");
}

} // namespace speculum::scene
