#pragma once

#include "scene/import/ModelImport.hpp"

#include <functional>

namespace speculum::scene::detail {

// Every part the node tree draws, with its world matrix (root.local first), depth first in file order.
void forEachPlacedPart(const ImportedModel& model,
                       const std::function<void(int part, const glm::dmat4& world)>& visit);

// The bounds of every placed part (unit scale included): exact, each vertex transformed.
render::Bounds placedBounds(const ImportedModel& model);

// A matrix as speculum's Transform (T · Rz·Ry·Rx · S, Euler degrees). False when the matrix has shear or
// is singular: then `out` is the closest such transform (scale from the column lengths, rotation from
// the orthonormalised columns).
bool decomposeTransform(const glm::dmat4& matrix, Transform& out);

// The double nearest to the shortest decimal that names the same float: model files hold floats, and a
// project file should say 0.06, not the 0.05999999865889549 that the float widens to.
double shortestFloat(double value);
glm::dvec3 shortestFloat(const glm::dvec3& value);

} // namespace speculum::scene::detail
