#pragma once

// Geometric checks shared by the mesh and import tests: what a user would verify about a mesh by hand.

#include "render/mesh/MeshData.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <string>

namespace speculum::render::test {

inline bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline glm::dvec3 corner(const MeshData& mesh, std::size_t triangle, int k) {
    return glm::dvec3(mesh.positions[mesh.indices[triangle * 3 + k]]);
}

// Unnormalised face normal (twice the area): counter-clockwise triangles give an outward normal.
inline glm::dvec3 faceNormal(const MeshData& mesh, std::size_t triangle) {
    const glm::dvec3 a = corner(mesh, triangle, 0);
    return glm::cross(corner(mesh, triangle, 1) - a, corner(mesh, triangle, 2) - a);
}

// Divergence theorem: positive for a closed mesh wound counter-clockwise seen from outside.
inline double signedVolume(const MeshData& mesh) {
    double volume = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        volume += glm::dot(corner(mesh, t, 0), glm::cross(corner(mesh, t, 1), corner(mesh, t, 2))) / 6.0;
    }
    return volume;
}

// Every array has the right size, every index is in range, every value finite, every normal unit length.
inline void expectWellFormed(const MeshData& mesh) {
    ASSERT_GT(mesh.triangleCount(), 0u);
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_TRUE(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size());
    for (std::uint32_t index : mesh.indices) {
        ASSERT_LT(index, mesh.positions.size());
    }
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        ASSERT_TRUE(finite(mesh.positions[v])) << "vertex " << v;
        ASSERT_TRUE(finite(mesh.normals[v])) << "normal " << v;
        ASSERT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-4f) << "normal " << v;
    }
    for (const glm::vec2& uv : mesh.uvs) {
        ASSERT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y));
    }
}

// The same checks as expectWellFormed, as a value: what is wrong, or empty. For code that cannot report
// through GoogleTest (a child process).
inline std::string wellFormedProblem(const MeshData& mesh) {
    if (mesh.triangleCount() == 0 || mesh.indices.size() % 3 != 0)
        return "no whole triangles";
    if (mesh.normals.size() != mesh.positions.size() ||
        !(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size()))
        return "attribute arrays of different sizes";
    for (std::uint32_t index : mesh.indices)
        if (index >= mesh.positions.size())
            return "index " + std::to_string(index) + " out of range";
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        if (!finite(mesh.positions[v]) || !finite(mesh.normals[v]) ||
            std::abs(glm::length(mesh.normals[v]) - 1.0f) > 1e-4f)
            return "vertex " + std::to_string(v) + " has a non-finite position or a normal of wrong length";
    for (const glm::vec2& uv : mesh.uvs)
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
            return "non-finite uv";
    return {};
}

} // namespace speculum::render::test
