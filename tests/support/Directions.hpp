#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <random>
#include <vector>

namespace speculum::test {

// Angle between two directions, accurate for tiny angles too (acos is not).
inline double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ua = glm::normalize(a);
    const glm::dvec3 ub = glm::normalize(b);
    return 2.0 * std::asin(std::min(1.0, glm::length(ua - ub) * 0.5));
}

// Uniformly distributed unit vectors from a fixed seed.
inline std::vector<glm::dvec3> randomDirections(int count, unsigned seed = 12345) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    std::vector<glm::dvec3> out;
    out.reserve(std::size_t(count));
    while (int(out.size()) < count) {
        const glm::dvec3 d(normal(rng), normal(rng), normal(rng));
        if (glm::length(d) > 1e-6)
            out.push_back(glm::normalize(d));
    }
    return out;
}

// Directions on every special line of the three maps: axes, cube edges and corners, the paraboloid
// equator, the tennis-ball component boundary (y = ±√2/2 for z ≥ 0, x = ±√2/2 for z ≤ 0), the atan branch
// cuts (x = 0, z < 0 and y = 0, z > 0), and each of them nudged by tiny amounts to either side.
inline std::vector<glm::dvec3> specialDirections() {
    const double s = std::sqrt(0.5);
    const double pi = 3.14159265358979323846;
    std::vector<glm::dvec3> base;
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            glm::dvec3 d(0.0);
            d[axis] = sign;
            base.push_back(d);
        }
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
            for (double z : {-1.0, 1.0})
                base.push_back(glm::normalize(glm::dvec3(x, y, z)));
    const int steps = 48;
    for (int i = 0; i <= steps; ++i) {
        const double t = -1.0 + 2.0 * i / steps;          // along a cube edge
        const double phi = pi * (-1.0 + 2.0 * i / steps); // around a great circle
        const double half = 0.5 * pi * (-1.0 + 2.0 * i / steps);
        for (double a : {-1.0, 1.0})
            for (double b : {-1.0, 1.0}) {
                base.push_back(glm::normalize(glm::dvec3(a, b, t)));
                base.push_back(glm::normalize(glm::dvec3(a, t, b)));
                base.push_back(glm::normalize(glm::dvec3(t, a, b)));
            }
        base.push_back({std::cos(phi), std::sin(phi), 0.0}); // paraboloid equator
        for (double sign : {-1.0, 1.0}) {
            base.push_back({s * std::sin(half), sign * s, s * std::cos(half)});  // tennis seam, z ≥ 0
            base.push_back({sign * s, s * std::sin(half), -s * std::cos(half)}); // tennis seam, z ≤ 0
        }
        base.push_back({0.0, std::sin(half), -std::cos(half)}); // branch cut, comp. 0
        base.push_back({std::sin(half), 0.0, std::cos(half)});  // branch cut, comp. 1
    }
    std::vector<glm::dvec3> out;
    for (const glm::dvec3& d : base) {
        out.push_back(d);
        for (double eps : {1e-12, 1e-8})
            for (int axis = 0; axis < 3; ++axis)
                for (double sign : {-1.0, 1.0}) {
                    glm::dvec3 e = d;
                    e[axis] += sign * eps;
                    out.push_back(glm::normalize(e));
                }
    }
    return out;
}

} // namespace speculum::test
