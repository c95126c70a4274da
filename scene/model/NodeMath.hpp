#pragma once

#include "scene/model/SceneData.hpp"

#include <glm/mat4x4.hpp>

namespace speculum::scene {

// Transforms and animations of a node, all in double (CPU-side transforms are composed in double).

// XYZ Euler angles in degrees, applied X, then Y, then Z: R = Rz · Ry · Rx.
glm::dmat4 rotationMatrix(const glm::dvec3& eulerDegrees);

// T × R × S.
glm::dmat4 localMatrix(const glm::dvec3& translate, const glm::dvec3& rotateDegrees, const glm::dvec3& scale);
glm::dmat4 localMatrix(const Transform& transform);

// height · |sin(π t / period)|: a hop of `height` every `period` seconds, on the ground at t = 0.
double bounceOffset(const BounceAnimation& bounce, double timeSeconds);

// center + radius · (cos 2πt/T, 0, sin 2πt/T).
glm::dvec3 orbitPosition(const OrbitAnimation& orbit, double timeSeconds);

// The node's translate at that time: the orbit position if it orbits, else its transform's translate; then
// lifted by the bounce offset along the parent's +Y.
glm::dvec3 animatedTranslate(const NodeData& node, double timeSeconds);

// localMatrix with the animated translate.
glm::dmat4 animatedLocalMatrix(const NodeData& node, double timeSeconds);

} // namespace speculum::scene
