#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vector>

// Points on every seam of the four maps, each with a tangent direction that crosses the seam there.
namespace speculum::test {

inline constexpr double kSeamPi = 3.14159265358979323846;

// A point on a seam and a tangent direction that crosses it.
struct SeamPoint {
    glm::dvec3 point;
    glm::dvec3 across;
    const char* seam;
};

inline glm::dvec3 tangentPart(const glm::dvec3& v, const glm::dvec3& p) {
    return glm::normalize(v - glm::dot(v, p) * p);
}

inline std::vector<SeamPoint> cubeSeams() {
    std::vector<SeamPoint> out;
    const int steps = 40;
    for (int i = 1; i < steps; ++i) {
        const double t = -1.0 + 2.0 * i / steps;
        for (int axis = 0; axis < 3; ++axis) {
            const int a = (axis + 1) % 3; // the edge runs along `axis`, between faces ±a and ±b
            const int b = (axis + 2) % 3;
            for (double sa : {-1.0, 1.0})
                for (double sb : {-1.0, 1.0}) {
                    glm::dvec3 p(0.0);
                    p[axis] = t;
                    p[a] = sa;
                    p[b] = sb;
                    p = glm::normalize(p);
                    glm::dvec3 g(0.0); // gradient of sa·x_a − sb·x_b, zero on the edge
                    g[a] = sa;
                    g[b] = -sb;
                    out.push_back({p, tangentPart(g, p), "cube edge"});
                }
        }
    }
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
            for (double z : {-1.0, 1.0}) {
                const glm::dvec3 p = glm::normalize(glm::dvec3(x, y, z));
                for (int k = 0; k < 12; ++k) {
                    const double angle = 2.0 * kSeamPi * k / 12.0;
                    const glm::dvec3 u = tangentPart(glm::dvec3(x, 0, 0), p);
                    const glm::dvec3 v = glm::cross(p, u);
                    out.push_back({p, std::cos(angle) * u + std::sin(angle) * v, "cube corner"});
                }
            }
    return out;
}

inline std::vector<SeamPoint> paraboloidSeams() {
    std::vector<SeamPoint> out;
    for (int i = 0; i < 360; ++i) {
        const double phi = 2.0 * kSeamPi * (i + 0.37) / 360.0;
        out.push_back({{std::cos(phi), std::sin(phi), 0.0}, {0, 0, 1}, "paraboloid equator"});
    }
    return out;
}

inline std::vector<SeamPoint> tennisBallSeams() {
    std::vector<SeamPoint> out;
    const double s = std::sqrt(0.5);
    const int steps = 120;
    for (int i = 0; i <= steps; ++i) {
        const double t = 0.5 * kSeamPi * (-1.0 + 2.0 * i / steps);
        for (double sign : {-1.0, 1.0}) {
            const glm::dvec3 front(s * std::sin(t), sign * s, s * std::cos(t)); // z ≥ 0, |y| = √2/2
            out.push_back({front, tangentPart({0, 1, 0}, front), "tennis-ball seam (front)"});
            const glm::dvec3 back(sign * s, s * std::sin(t), -s * std::cos(t)); // z ≤ 0, |x| = √2/2
            out.push_back({back, tangentPart({1, 0, 0}, back), "tennis-ball seam (back)"});
        }
        // The atan branch cuts and the poles of each component's parametrisation.
        const glm::dvec3 cut0(0.0, std::sin(t), -std::cos(t));
        out.push_back({cut0, {1, 0, 0}, "component 0 branch cut"});
        const glm::dvec3 cut1(std::sin(t), 0.0, std::cos(t));
        out.push_back({cut1, {0, 1, 0}, "component 1 branch cut"});
    }
    for (const glm::dvec3& pole :
         {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0)})
        for (int k = 0; k < 16; ++k) {
            const double angle = 2.0 * kSeamPi * k / 16.0;
            const glm::dvec3 u = tangentPart(glm::dvec3(0, 0, 1), pole);
            const glm::dvec3 v = glm::cross(pole, u);
            out.push_back({pole, std::cos(angle) * u + std::sin(angle) * v, "pole"});
        }
    return out;
}

// The octahedral map's: the sides of its square (the lower half's meridians in the planes x = 0 and y = 0,
// each folded onto itself), the −Z pole (the four corners), and the equator, where the diamond meets the
// folded corners (a crease of the mapping, not an edge of the texture).
inline std::vector<SeamPoint> octahedralSeams() {
    std::vector<SeamPoint> out;
    const int steps = 40;
    for (int i = 1; i < steps; ++i) {
        const double theta = (-0.5 + double(i) / steps) * kSeamPi; // −90°..90° from −Z
        out.push_back({{0.0, std::sin(theta), -std::cos(theta)}, {1, 0, 0}, "side (x = 0)"});
        out.push_back({{std::sin(theta), 0.0, -std::cos(theta)}, {0, 1, 0}, "side (y = 0)"});
        const double phi = 2.0 * kSeamPi * i / steps;
        out.push_back({{std::cos(phi), std::sin(phi), 0.0}, {0, 0, 1}, "equator"});
    }
    const glm::dvec3 pole(0, 0, -1);
    for (int k = 0; k < 16; ++k) {
        const double angle = 2.0 * kSeamPi * k / 16.0;
        out.push_back({pole, {std::cos(angle), std::sin(angle), 0.0}, "−Z corner"});
    }
    return out;
}

} // namespace speculum::test
