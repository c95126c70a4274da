#include "render/mesh/Primitives.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

namespace speculum::render {

MeshData makeSphere(int tessellation) {
    const int rings = std::clamp(tessellation, kSphereMinTessellation, kSphereMaxTessellation);
    const int segments = 2 * rings;
    const auto seg = static_cast<std::uint32_t>(segments);
    const auto columns = seg + 1; // inner rings duplicate the seam column so u can run 0..1

    // Layout: `segments` north-pole vertices (one per segment, so each gets the u of its segment), then
    // the inner rings 1..rings-1 with `columns` vertices each, then `segments` south-pole vertices.
    const auto inner = [&](std::uint32_t ring, std::uint32_t column) {
        return seg + (ring - 1) * columns + column;
    };
    const std::uint32_t south = seg + static_cast<std::uint32_t>(rings - 1) * columns;

    MeshData mesh;
    const std::size_t vertexCount = 2 * seg + static_cast<std::size_t>(rings - 1) * columns;
    mesh.positions.reserve(vertexCount);
    mesh.normals.reserve(vertexCount);
    mesh.uvs.reserve(vertexCount);
    const auto add = [&](const glm::dvec3& p, double u, double v) {
        mesh.positions.emplace_back(p);
        mesh.normals.emplace_back(glm::normalize(p));
        mesh.uvs.emplace_back(static_cast<float>(u), static_cast<float>(v));
    };

    // Ring i lies at polar angle theta = pi * i / rings from +Y; column j at azimuth phi = 2 pi j / segments,
    // measured from +X towards -Z. v = 1 - theta / pi.
    for (std::uint32_t j = 0; j < seg; ++j) {
        add({0.0, 1.0, 0.0}, (j + 0.5) / segments, 1.0);
    }
    for (int i = 1; i < rings; ++i) {
        const double theta = glm::pi<double>() * i / rings;
        for (std::uint32_t j = 0; j < columns; ++j) {
            const double phi = glm::two_pi<double>() * j / segments;
            const glm::dvec3 p(std::sin(theta) * std::cos(phi), std::cos(theta),
                               -std::sin(theta) * std::sin(phi));
            add(p, static_cast<double>(j) / segments, 1.0 - static_cast<double>(i) / rings);
        }
    }
    for (std::uint32_t j = 0; j < seg; ++j) {
        add({0.0, -1.0, 0.0}, (j + 0.5) / segments, 0.0);
    }

    // Triangle (a, a one ring down, a one column east) has normal d(theta) x d(phi), which points outward.
    mesh.indices.reserve(static_cast<std::size_t>(2 * segments) * (rings - 1) * 3);
    for (std::uint32_t j = 0; j < seg; ++j) {
        mesh.indices.insert(mesh.indices.end(), {j, inner(1, j), inner(1, j + 1)});
    }
    for (std::uint32_t i = 1; i + 1 < static_cast<std::uint32_t>(rings); ++i) {
        for (std::uint32_t j = 0; j < seg; ++j) {
            const std::uint32_t a = inner(i, j), b = inner(i + 1, j), c = a + 1, d = b + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, c, c, b, d});
        }
    }
    const auto last = static_cast<std::uint32_t>(rings - 1);
    for (std::uint32_t j = 0; j < seg; ++j) {
        mesh.indices.insert(mesh.indices.end(), {inner(last, j), south + j, inner(last, j + 1)});
    }
    return mesh;
}

MeshData makeBox() {
    struct Face {
        glm::vec3 normal, u,
            v; // u x v = normal, so corners in (u, v) order are counter-clockwise from outside
    };
    const std::array<Face, 6> faces = {{
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
        {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
        {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    }};
    const std::array<glm::vec2, 4> corners = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

    MeshData mesh;
    for (const Face& face : faces) {
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (const glm::vec2& uv : corners) {
            mesh.positions.push_back(face.normal + (2.0f * uv.x - 1.0f) * face.u +
                                     (2.0f * uv.y - 1.0f) * face.v);
            mesh.normals.push_back(face.normal);
            mesh.uvs.push_back(uv);
        }
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return mesh;
}

MeshData makePlane(int tessellation) {
    const int n = std::clamp(tessellation, 1, kPlaneMaxTessellation);
    const auto side = static_cast<std::uint32_t>(n + 1);

    MeshData mesh;
    const std::size_t vertexCount = static_cast<std::size_t>(side) * side;
    mesh.positions.reserve(vertexCount);
    mesh.normals.reserve(vertexCount);
    mesh.uvs.reserve(vertexCount);
    // Row k runs along +X at z = 1 - 2k/n, so k grows with v (towards -Z).
    for (std::uint32_t k = 0; k < side; ++k) {
        for (std::uint32_t i = 0; i < side; ++i) {
            const float s = static_cast<float>(i) / static_cast<float>(n);
            const float t = static_cast<float>(k) / static_cast<float>(n);
            mesh.positions.emplace_back(2.0f * s - 1.0f, 0.0f, 1.0f - 2.0f * t);
            mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
            mesh.uvs.emplace_back(s, t);
        }
    }
    mesh.indices.reserve(static_cast<std::size_t>(n) * n * 6u);
    // +X x -Z = +Y: a, a + east, a + north is counter-clockwise seen from above.
    for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(n); ++k) {
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
            const std::uint32_t a = k * side + i;
            const std::uint32_t b = a + 1;    // east
            const std::uint32_t c = a + side; // north (-Z)
            const std::uint32_t d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
        }
    }
    return mesh;
}

} // namespace speculum::render
