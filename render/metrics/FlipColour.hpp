#pragma once

#include <glm/vec3.hpp>

// The colour spaces FLIP measures in (render/metrics internal). All take and give CIE XYZ, linear sRGB
// (Rec. 709 primaries, D65 white) or the spaces built on them, as doubles.
namespace speculum::render::metrics::flipcolour {

glm::dvec3 linearRgbToXyz(const glm::dvec3& rgb);
glm::dvec3 xyzToLinearRgb(const glm::dvec3& xyz);

// YCxCz: the linearised CIELAB opponent space the contrast sensitivity filters work in (Y' = 116 Y/Yn − 16,
// Cx = 500 (X/Xn − Y/Yn), Cz = 200 (Y/Yn − Z/Zn)), linear in XYZ so that filtering it is meaningful.
glm::dvec3 xyzToYcxcz(const glm::dvec3& xyz);
glm::dvec3 ycxczToXyz(const glm::dvec3& ycxcz);

// CIELAB with the Hunt adjustment (a and b scaled by 0.01 L: colourfulness falls with lightness).
glm::dvec3 huntLab(const glm::dvec3& linearRgb);

// HyAB: |ΔL| + the Euclidean distance in a and b, the colour difference for large differences.
double hyab(const glm::dvec3& a, const glm::dvec3& b);

} // namespace speculum::render::metrics::flipcolour
