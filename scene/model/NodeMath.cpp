#include "scene/model/NodeMath.hpp"

#include <cmath>
#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <numbers>

namespace speculum::scene {

glm::dmat4 rotationMatrix(const glm::dvec3& eulerDegrees) {
    const glm::dmat4 identity(1.0);
    const glm::dmat4 rx = glm::rotate(identity, glm::radians(eulerDegrees.x), glm::dvec3(1.0, 0.0, 0.0));
    const glm::dmat4 ry = glm::rotate(identity, glm::radians(eulerDegrees.y), glm::dvec3(0.0, 1.0, 0.0));
    const glm::dmat4 rz = glm::rotate(identity, glm::radians(eulerDegrees.z), glm::dvec3(0.0, 0.0, 1.0));
    return rz * ry * rx; // column vectors: the rightmost (X) acts first
}

glm::dmat4 localMatrix(const glm::dvec3& translate, const glm::dvec3& rotateDegrees,
                       const glm::dvec3& scale) {
    const glm::dmat4 t = glm::translate(glm::dmat4(1.0), translate);
    const glm::dmat4 s = glm::scale(glm::dmat4(1.0), scale);
    return t * rotationMatrix(rotateDegrees) * s;
}

glm::dmat4 localMatrix(const Transform& transform) {
    return localMatrix(transform.translate, transform.rotate, transform.scale);
}

namespace {

// Where t falls within one period, in (-1, 1): fmod keeps sin and cos accurate at large times, and a
// period that is not a positive finite number (or a time that is not finite) means no motion rather than
// sin(inf) = NaN.
double phase(double timeSeconds, double period) {
    if (!(period > 0.0) || !std::isfinite(period) || !std::isfinite(timeSeconds)) {
        return 0.0;
    }
    const double fraction = std::fmod(timeSeconds, period) / period;
    return std::isfinite(fraction) ? fraction : 0.0;
}

} // namespace

double bounceOffset(const BounceAnimation& bounce, double timeSeconds) {
    return bounce.height * std::abs(std::sin(std::numbers::pi * phase(timeSeconds, bounce.period)));
}

glm::dvec3 orbitPosition(const OrbitAnimation& orbit, double timeSeconds) {
    const double angle = 2.0 * std::numbers::pi * phase(timeSeconds, orbit.period);
    return orbit.center + orbit.radius * glm::dvec3(std::cos(angle), 0.0, std::sin(angle));
}

glm::dvec3 animatedTranslate(const NodeData& node, double timeSeconds) {
    glm::dvec3 translate = node.transform.translate;
    if (node.animation) {
        if (node.animation->orbit) {
            translate = orbitPosition(*node.animation->orbit, timeSeconds);
        }
        if (node.animation->bounce) {
            translate.y += bounceOffset(*node.animation->bounce, timeSeconds);
        }
    }
    return translate;
}

glm::dmat4 animatedLocalMatrix(const NodeData& node, double timeSeconds) {
    return localMatrix(animatedTranslate(node, timeSeconds), node.transform.rotate, node.transform.scale);
}

} // namespace speculum::scene
