#include "render/mesh/Teapot.hpp"

#include "render/mesh/TeapotPatches.hpp"

#include <algorithm>
#include <array>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace speculum::render {
namespace {

using Controls = std::array<glm::dvec3, 16>;

// Newell's data is Z up; ours is Y up. (x, y, z) -> (x, z, -y) is a rotation about +X (det +1), so the
// spout stays on +X, the frame stays right-handed and cross products (normals, winding) are preserved.
glm::dvec3 toYUp(const glm::dvec3& p) {
    return {p.x, p.z, -p.y};
}

Controls patchControls(std::size_t patch) {
    Controls c;
    for (std::size_t k = 0; k < 16; ++k) {
        const auto& p = teapot::kControlPoints[teapot::kPatches[patch][k] - 1u];
        c[k] = toYUp(glm::dvec3(p[0], p[1], p[2]));
    }
    return c;
}

// Cubic Bernstein basis and its derivative at t.
std::array<double, 4> bernstein(double t) {
    const double s = 1.0 - t;
    return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}
std::array<double, 4> bernsteinDerivative(double t) {
    const double s = 1.0 - t;
    return {-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t};
}

// Row index (first of the 4x4) is the parameter `u`, column index is `v`.
glm::dvec3 evaluate(const Controls& c, const std::array<double, 4>& bu, const std::array<double, 4>& bv) {
    glm::dvec3 p(0.0);
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            p += bu[i] * bv[j] * c[i * 4 + j];
        }
    }
    return p;
}

// Outward normal at (u, v), unnormalised. In Newell's data u runs from top to bottom (rim towards base)
// and v runs clockwise seen from above, so dP/dv x dP/du points out of the surface for every patch.
glm::dvec3 normalAt(const Controls& c, double u, double v) {
    const glm::dvec3 du = evaluate(c, bernsteinDerivative(u), bernstein(v));
    const glm::dvec3 dv = evaluate(c, bernstein(u), bernsteinDerivative(v));
    return glm::cross(dv, du);
}

glm::dvec3 unitNormal(const Controls& c, double u, double v) {
    glm::dvec3 n = normalAt(c, u, v);
    // At the lid-knob top and the bottom centre a whole patch edge is one point, so dP/dv vanishes there
    // and the cross product is zero. Step a little towards the patch centre: the normal there converges
    // to the tangent plane of the pole (the axis direction) as the step shrinks. The threshold is relative
    // to the patch size, which is of order 1 in Newell's units.
    double step = 1e-4;
    while (glm::length(n) < 1e-10 && step < 0.5) {
        n = normalAt(c, u + (0.5 - u) * step, v + (0.5 - v) * step);
        step *= 10.0;
    }
    const double length = glm::length(n);
    return length > 0.0 ? n / length : glm::dvec3(0.0, 1.0, 0.0);
}

} // namespace

MeshData makeTeapot(int tessellation) {
    const int n = std::clamp(tessellation, kTeapotMinTessellation, kTeapotMaxTessellation);
    const auto side = static_cast<std::uint32_t>(n + 1);

    MeshData mesh;
    const std::size_t vertexCount = teapot::kPatchCount * side * side;
    mesh.positions.reserve(vertexCount);
    mesh.normals.reserve(vertexCount);
    mesh.uvs.reserve(vertexCount);
    mesh.indices.reserve(teapot::kPatchCount * static_cast<std::size_t>(n * n) * 6u);

    for (std::size_t patch = 0; patch < teapot::kPatchCount; ++patch) {
        const Controls c = patchControls(patch);
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (std::uint32_t i = 0; i < side; ++i) {
            const double u = static_cast<double>(i) / n;
            const auto bu = bernstein(u);
            for (std::uint32_t j = 0; j < side; ++j) {
                const double v = static_cast<double>(j) / n;
                mesh.positions.emplace_back(evaluate(c, bu, bernstein(v)));
                mesh.normals.emplace_back(unitNormal(c, u, v));
                mesh.uvs.emplace_back(static_cast<float>(u), static_cast<float>(v));
            }
        }
        // With a = (u, v), the triangle a, a + dv, a + du has normal dv x du: counter-clockwise from outside.
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
            for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(n); ++j) {
                const std::uint32_t a = base + i * side + j;
                const std::uint32_t b = a + 1;     // (u, v + dv)
                const std::uint32_t c2 = a + side; // (u + du, v)
                const std::uint32_t d = c2 + 1;    // (u + du, v + dv)
                mesh.indices.insert(mesh.indices.end(), {a, b, c2, b, d, c2});
            }
        }
    }
    return mesh;
}

} // namespace speculum::render
