#include "render/metrics/FlipColour.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace speculum::render::metrics::flipcolour {

namespace {

// IEC 61966-2-1 (sRGB): the rows give X, Y and Z of the linear R, G, B primaries at D65. glm's
// constructor takes columns, hence the transpose.
const glm::dmat3& toXyz() {
    static const glm::dmat3 matrix = glm::transpose(glm::dmat3(0.4124564, 0.3575761, 0.1804375, //
                                                               0.2126729, 0.7151522, 0.0721750, //
                                                               0.0193339, 0.1191920, 0.9503041));
    return matrix;
}

const glm::dmat3& fromXyz() {
    static const glm::dmat3 matrix = glm::inverse(toXyz());
    return matrix;
}

// The white point: the XYZ of linear RGB (1, 1, 1), so that white has a = b = 0 exactly.
const glm::dvec3& white() {
    static const glm::dvec3 point = toXyz() * glm::dvec3(1.0);
    return point;
}

double labCompand(double t) {
    constexpr double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

} // namespace

glm::dvec3 linearRgbToXyz(const glm::dvec3& rgb) {
    return toXyz() * rgb;
}
glm::dvec3 xyzToLinearRgb(const glm::dvec3& xyz) {
    return fromXyz() * xyz;
}

glm::dvec3 xyzToYcxcz(const glm::dvec3& xyz) {
    const glm::dvec3 n = xyz / white();
    return {116.0 * n.y - 16.0, 500.0 * (n.x - n.y), 200.0 * (n.y - n.z)};
}

glm::dvec3 ycxczToXyz(const glm::dvec3& ycxcz) {
    const double y = (ycxcz.x + 16.0) / 116.0;
    return glm::dvec3(y + ycxcz.y / 500.0, y, y - ycxcz.z / 200.0) * white();
}

glm::dvec3 huntLab(const glm::dvec3& linearRgb) {
    const glm::dvec3 n = linearRgbToXyz(linearRgb) / white();
    const double fx = labCompand(n.x), fy = labCompand(n.y), fz = labCompand(n.z);
    const double l = 116.0 * fy - 16.0;
    return {l, 0.01 * l * 500.0 * (fx - fy), 0.01 * l * 200.0 * (fy - fz)};
}

double hyab(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 d = a - b;
    return std::abs(d.x) + std::sqrt(d.y * d.y + d.z * d.z);
}

} // namespace speculum::render::metrics::flipcolour
