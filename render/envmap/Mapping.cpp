#include "render/envmap/Mapping.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace speculum::render::envmap {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kQuarterPi = kPi / 4.0;
constexpr double kThreeQuarterPi = 3.0 * kPi / 4.0;
constexpr double kHalfSqrt2 = 0.70710678118654752440;

// GL's cube face frames: sc = d·s / d·major, tc = d·t / d·major (OpenGL 4.6 core, §8.13).
struct FaceFrame {
    glm::dvec3 major, s, t;
};
constexpr std::array<FaceFrame, 6> kFaces{{
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},  // +X
    {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},  // −X
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    // +Y
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},  // −Y
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   // +Z
    {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}}, // −Z
}};

glm::dvec3 unit(const glm::dvec3& d) {
    const double length = glm::length(d);
    assert(length > 0.0 && std::isfinite(length) && "envmap::unit(): direction must be finite and non-zero");
    return d / length;
}

// asin with its argument clamped: rounding can push |sin| a hair past 1.
double safeAsin(double s) {
    return std::asin(std::clamp(s, -1.0, 1.0));
}

// atan2 that is 0 (not implementation-defined) where both arguments vanish: the poles of a tennis-ball
// component, which the component rule never selects but guard-band fills and tests do evaluate.
double safeAtan2(double y, double x) {
    return (y == 0.0 && x == 0.0) ? 0.0 : std::atan2(y, x);
}

void assertComponent(MapType type, int component) {
    assert(component >= 0 && component < componentCount(type) && "envmap::fromMap(): component out of range");
    (void)type;
    (void)component;
}

} // namespace

std::string_view mapTypeName(MapType type) {
    switch (type) {
    case MapType::Cube:
        return "cube";
    case MapType::DualParaboloid:
        return "dual-paraboloid";
    case MapType::TennisBall:
        return "tennis-ball";
    case MapType::Octahedral:
        return "octahedral";
    }
    return "?";
}

int componentCount(MapType type) {
    return type == MapType::Cube ? 6 : type == MapType::Octahedral ? 1 : 2;
}

// --- cube ---

int cubeFace(const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    // Ties go to x, then y, the order GL implementations use in practice; either face gives the same
    // direction on the shared edge.
    if (a.x >= a.y && a.x >= a.z)
        return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z)
        return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}

glm::dvec2 cubeUv(int face, const glm::dvec3& d) {
    assert(face >= 0 && face < 6 && "envmap::cubeUv(): face out of range");
    const FaceFrame& f = kFaces[static_cast<std::size_t>(face)];
    const double m = glm::dot(d, f.major);
    assert(m > 0.0 && "envmap::cubeUv(): direction is not in front of the face");
    return glm::dvec2(glm::dot(d, f.s) / m, glm::dot(d, f.t) / m) * 0.5 + 0.5;
}

glm::dvec3 cubeDirection(int face, const glm::dvec2& uv) {
    assert(face >= 0 && face < 6 && "envmap::cubeDirection(): face out of range");
    const FaceFrame& f = kFaces[static_cast<std::size_t>(face)];
    const glm::dvec2 st = uv * 2.0 - 1.0;
    return glm::normalize(f.major + st.x * f.s + st.y * f.t);
}

// --- dual paraboloid ---

int paraboloidComponent(const glm::dvec3& d) {
    return d.z < 0.0 ? 0 : 1;
}

glm::dvec2 paraboloidUv(int component, const glm::dvec3& direction) {
    const glm::dvec3 d = unit(direction);
    // d ≥ 1 in the chosen component; elsewhere it only vanishes at the far pole.
    const double denom = component == 0 ? 1.0 - d.z : 1.0 + d.z;
    assert(denom > 0.0 && "envmap::paraboloidUv(): the far pole has no place in this component");
    return glm::dvec2(d.x, d.y) / denom * 0.5 + 0.5;
}

glm::dvec3 paraboloidDirection(int component, const glm::dvec2& uv) {
    // Inverse stereographic projection; radius > 1 continues smoothly into the other hemisphere, which
    // is what fills the guard band.
    const glm::dvec2 p = uv * 2.0 - 1.0;
    const double r2 = glm::dot(p, p);
    const double z = (1.0 - r2) / (1.0 + r2);
    return glm::dvec3(2.0 * p.x, 2.0 * p.y, 0.0) / (1.0 + r2) + glm::dvec3(0, 0, component == 0 ? -z : z);
}

// --- tennis ball ---

int tennisBallComponent(const glm::dvec3& d) {
    const glm::dvec3 u = unit(d);
    return ((u.z >= 0.0 && std::abs(u.y) <= kHalfSqrt2) || (u.z <= 0.0 && std::abs(u.x) >= kHalfSqrt2)) ? 0
                                                                                                        : 1;
}

glm::dvec2 tennisBallUv(int component, const glm::dvec3& direction) {
    const glm::dvec3 d = unit(direction);
    const double a = component == 0 ? safeAsin(d.y) / kQuarterPi : safeAsin(d.x) / kQuarterPi;
    const double b =
        component == 0 ? safeAtan2(d.x, d.z) / kThreeQuarterPi : safeAtan2(d.y, -d.z) / kThreeQuarterPi;
    return glm::dvec2(a, b) * 0.5 + 0.5;
}

glm::dvec3 tennisBallDirection(int component, const glm::dvec2& uv) {
    const double latitude = (uv.x * 2.0 - 1.0) * kQuarterPi;
    const double longitude = (uv.y * 2.0 - 1.0) * kThreeQuarterPi;
    const double c = std::cos(latitude);
    const double s = std::sin(latitude);
    if (component == 0)
        return {c * std::sin(longitude), s, c * std::cos(longitude)};
    return {s, c * std::sin(longitude), -c * std::cos(longitude)};
}

// --- octahedral ---

namespace {

// sign() that is +1 at 0: the fold sends the diamond's axes to the square's side midpoints either way.
double foldSign(double v) {
    return v < 0.0 ? -1.0 : 1.0;
}

// The point p of the square ([-1, 1]²) where d lies, before the lower half is folded out.
glm::dvec2 octahedronPoint(const glm::dvec3& d) {
    return glm::dvec2(d.x, d.y) / (std::abs(d.x) + std::abs(d.y) + std::abs(d.z));
}

} // namespace

glm::dvec2 octahedralUv(const glm::dvec3& direction) {
    const glm::dvec3 d = unit(direction);
    glm::dvec2 p = octahedronPoint(d);
    if (d.z < 0.0)
        p = glm::dvec2(foldSign(p.x) * (1.0 - std::abs(p.y)), foldSign(p.y) * (1.0 - std::abs(p.x)));
    return p * 0.5 + 0.5;
}

glm::dvec3 octahedralDirection(const glm::dvec2& uv) {
    glm::dvec2 p = uv * 2.0 - 1.0;
    // Past a side, the square continues folded over it: (1 + e, t) is (1 − e, −t). A few folds at most
    // (the guard band is a fraction of the square).
    for (int i = 0; i < 4 && (std::abs(p.x) > 1.0 || std::abs(p.y) > 1.0); ++i) {
        if (std::abs(p.x) > 1.0)
            p = glm::dvec2(foldSign(p.x) * 2.0 - p.x, -p.y);
        if (std::abs(p.y) > 1.0)
            p = glm::dvec2(-p.x, foldSign(p.y) * 2.0 - p.y);
    }
    p = glm::clamp(p, -1.0, 1.0);
    const double z = 1.0 - std::abs(p.x) - std::abs(p.y);
    if (z < 0.0)
        p = glm::dvec2(foldSign(p.x) * (1.0 - std::abs(p.y)), foldSign(p.y) * (1.0 - std::abs(p.x)));
    return glm::normalize(glm::dvec3(p, z));
}

// --- any map ---

int mapComponent(MapType type, const glm::dvec3& direction) {
    switch (type) {
    case MapType::Cube:
        return cubeFace(direction);
    case MapType::DualParaboloid:
        return paraboloidComponent(direction);
    case MapType::TennisBall:
        return tennisBallComponent(direction);
    case MapType::Octahedral:
        return 0;
    }
    return 0;
}

glm::dvec2 mapUv(MapType type, int component, const glm::dvec3& direction) {
    assertComponent(type, component);
    switch (type) {
    case MapType::Cube:
        return cubeUv(component, direction);
    case MapType::DualParaboloid:
        return paraboloidUv(component, direction);
    case MapType::TennisBall:
        return tennisBallUv(component, direction);
    case MapType::Octahedral:
        return octahedralUv(direction);
    }
    return {};
}

MapCoord toMap(MapType type, const glm::dvec3& direction) {
    const int component = mapComponent(type, direction);
    return {component, mapUv(type, component, direction)};
}

glm::dvec3 fromMap(MapType type, int component, const glm::dvec2& uv) {
    assertComponent(type, component);
    switch (type) {
    case MapType::Cube:
        return cubeDirection(component, uv);
    case MapType::DualParaboloid:
        return paraboloidDirection(component, uv);
    case MapType::TennisBall:
        return tennisBallDirection(component, uv);
    case MapType::Octahedral:
        return octahedralDirection(uv);
    }
    return {};
}

glm::dmat3x2 uvJacobian(MapType type, int component, const glm::dvec3& direction) {
    assertComponent(type, component);
    const glm::dvec3 d = unit(direction);
    glm::dvec3 du{0.0}, dv{0.0}; // gradients of u and v
    switch (type) {
    case MapType::Cube: {
        const FaceFrame& f = kFaces[static_cast<std::size_t>(component)];
        const double m = glm::dot(d, f.major);
        du = 0.5 * (f.s / m - glm::dot(d, f.s) / (m * m) * f.major);
        dv = 0.5 * (f.t / m - glm::dot(d, f.t) / (m * m) * f.major);
        break;
    }
    case MapType::DualParaboloid: {
        const double sign = component == 0 ? 1.0 : -1.0; // d = 1 − z or 1 + z
        const double denom = 1.0 - sign * d.z;
        du = 0.5 * glm::dvec3(1.0 / denom, 0.0, sign * d.x / (denom * denom));
        dv = 0.5 * glm::dvec3(0.0, 1.0 / denom, sign * d.y / (denom * denom));
        break;
    }
    case MapType::TennisBall: {
        if (component == 0) {
            const double ring = d.x * d.x + d.z * d.z; // cos² latitude ≥ ½ where component 0 is chosen
            du = glm::dvec3(0.0, 0.5 / (std::sqrt(ring) * kQuarterPi), 0.0);
            dv = glm::dvec3(d.z, 0.0, -d.x) * (0.5 / (ring * kThreeQuarterPi));
        } else {
            const double ring = d.y * d.y + d.z * d.z;
            du = glm::dvec3(0.5 / (std::sqrt(ring) * kQuarterPi), 0.0, 0.0);
            dv = glm::dvec3(0.0, -d.z, d.y) * (0.5 / (ring * kThreeQuarterPi));
        }
        break;
    }
    case MapType::Octahedral: {
        // p = (x, y) / s with s = |x| + |y| + |z|: ∂p.x/∂d = (e_x − p.x · sign(d)) / s.
        const double s = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
        const glm::dvec3 signs(foldSign(d.x), foldSign(d.y), foldSign(d.z));
        const glm::dvec3 dpx = (glm::dvec3(1, 0, 0) - (d.x / s) * signs) / s;
        const glm::dvec3 dpy = (glm::dvec3(0, 1, 0) - (d.y / s) * signs) / s;
        if (d.z >= 0.0) {
            du = 0.5 * dpx;
            dv = 0.5 * dpy;
        } else { // folded: u = ½ sign(p.x)(1 − |p.y|) + ½, v = ½ sign(p.y)(1 − |p.x|) + ½
            const double sx = foldSign(d.x), sy = foldSign(d.y);
            du = -0.5 * sx * sy * dpy;
            dv = -0.5 * sy * sx * dpx;
        }
        break;
    }
    }
    glm::dmat3x2 j;
    for (int c = 0; c < 3; ++c)
        j[c] = glm::dvec2(du[c], dv[c]);
    return j;
}

double solidAngleDensity(MapType type, const glm::dvec2& uv) {
    const glm::dvec2 p = uv * 2.0 - 1.0; // dp = 2 du
    switch (type) {
    case MapType::Cube: {
        // dΩ = ds dt / (1 + s² + t²)^{3/2} on the plane at unit distance.
        const double q = 1.0 + glm::dot(p, p);
        return 4.0 / (q * std::sqrt(q));
    }
    case MapType::DualParaboloid: {
        // Stereographic: dΩ = 4 dp dq / (1 + r²)².
        const double q = 1.0 + glm::dot(p, p);
        return 16.0 / (q * q);
    }
    case MapType::TennisBall:
        // dΩ = cos(latitude) dlatitude dlongitude, latitude = p.x·π/4, longitude = p.y·3π/4.
        return std::cos(p.x * kQuarterPi) * (2.0 * kQuarterPi) * (2.0 * kThreeQuarterPi);
    case MapType::Octahedral: {
        // A face of the octahedron seen from its centre: dΩ = dA cos θ / r² with dA = √3 dp (the face over
        // its projection), cos θ = (1/√3) / r: dΩ = dp / r³, r the distance to the face's point. The fold
        // is an isometry, so a corner's density is that of the lower face's point it shows.
        const glm::dvec3 d = octahedralDirection(uv);
        const double r = 1.0 / (std::abs(d.x) + std::abs(d.y) + std::abs(d.z)); // |d| / s, d a unit vector
        return 4.0 / (r * r * r);
    }
    }
    return 0.0;
}

} // namespace speculum::render::envmap
