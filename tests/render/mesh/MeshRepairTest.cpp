#include "render/mesh/MeshRepair.hpp"

#include "render/mesh/Primitives.hpp"
#include "support/MeshChecks.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace speculum::render {
namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

// Two triangles sharing an edge (a unit square in the XY plane facing +Z), normals and uvs included.
MeshData square() {
    MeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.normals.assign(4, glm::vec3(0, 0, 1));
    mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

TEST(MeshRepair, CleanMeshIsUntouched) {
    RepairReport report;
    const auto result = repairMesh(square(), report);
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_TRUE(report.clean());
    EXPECT_EQ(report.summary(), "no repairs needed");
    EXPECT_EQ(result->positions, square().positions);
    EXPECT_EQ(result->indices, square().indices);
    EXPECT_EQ(result->uvs, square().uvs);
}

TEST(MeshRepair, DropsTrianglesWithNonFiniteCorners) {
    MeshData mesh = square();
    mesh.positions.push_back({kNaN, 0, 0});
    mesh.positions.push_back({0, kInf, 0});
    mesh.normals.resize(6, glm::vec3(0, 0, 1));
    mesh.uvs.resize(6);
    mesh.indices.insert(mesh.indices.end(), {0, 4, 1, 2, 5, 3});
    RepairReport report;
    const auto result = repairMesh(mesh, report);
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(report.droppedNonFinite, 2u);
    EXPECT_EQ(report.removedUnusedVertices, 2u);
    EXPECT_EQ(result->triangleCount(), 2u);
    EXPECT_EQ(result->vertexCount(), 4u); // the bad vertices are gone, so bounds stay finite
    test::expectWellFormed(*result);
    const Bounds b = computeBounds(*result);
    EXPECT_EQ(b.max, glm::vec3(1, 1, 0));
    EXPECT_NE(report.summary().find("non-finite"), std::string::npos) << report.summary();
}

TEST(MeshRepair, DropsOutOfRangeIndicesAndTrailingIndices) {
    MeshData mesh = square();
    mesh.indices.insert(mesh.indices.end(), {0, 1, 99, 2, 3});
    RepairReport report;
    const auto result = repairMesh(mesh, report);
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(report.droppedOutOfRange, 1u);
    EXPECT_EQ(report.droppedTrailingIndices, 2u);
    EXPECT_EQ(result->indices, square().indices);
}

TEST(MeshRepair, DropsDegenerateTriangles) {
    MeshData mesh = square();
    mesh.positions.push_back({2, 0, 0}); // collinear with 0 and 1
    mesh.positions.push_back({1, 1, 0}); // same position as vertex 2, different index
    mesh.normals.resize(6, glm::vec3(0, 0, 1));
    mesh.uvs.resize(6);
    mesh.indices.insert(mesh.indices.end(), {
                                                0, 0, 1, // repeated index
                                                0, 1, 4, // zero area, collinear
                                                2, 5, 3, // zero area, coincident corners
                                            });
    RepairReport report;
    const auto result = repairMesh(mesh, report);
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(report.droppedDegenerate, 3u);
    EXPECT_EQ(result->triangleCount(), 2u);
    EXPECT_EQ(report.removedUnusedVertices, 2u);
}

TEST(MeshRepair, RegeneratesMissingNormalsAreaWeighted) {
    MeshData mesh;
    // Vertex 0 is shared by a small triangle facing +Z (area 0.5) and a big one facing +X (area 4.5).
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 3, 0}, {0, 0, 3}};
    mesh.indices = {0, 1, 2, 0, 3, 4};
    RepairReport report;
    const auto result = repairMesh(mesh, report);
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(report.regeneratedNormals, 5u);
    test::expectWellFormed(*result);
    const glm::vec3 expected = glm::normalize(glm::vec3(9, 0, 1));
    EXPECT_NEAR(glm::distance(result->normals[0], expected), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(result->normals[1], glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(result->normals[3], glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
}

TEST(MeshRepair, RegeneratedBoxNormalsMatchTheFaces) {
    const MeshData box = makeBox();
    MeshData bare = box;
    bare.normals.clear();
    RepairReport report;
    const auto result = repairMesh(bare, report);
    ASSERT_TRUE(result.ok()) << result.error();
    ASSERT_EQ(result->vertexCount(), box.vertexCount());
    for (std::size_t v = 0; v < box.vertexCount(); ++v) {
        EXPECT_NEAR(glm::distance(result->normals[v], box.normals[v]), 0.0f, 1e-6f) << v;
    }
}

TEST(MeshRepair, FixesOnlyTheBadNormals) {
    MeshData mesh = square();
    mesh.normals[0] = {kNaN, 0, 0};
    mesh.normals[1] = {0, 0, 0};
    mesh.normals[2] = {0, 0, 5};                          // finite but not unit: renormalised
    mesh.normals[3] = glm::normalize(glm::vec3(0, 1, 1)); // deliberate smoothing: kept as is
    RepairReport report;
    const auto result = repairMesh(mesh, report);
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(report.regeneratedNormals, 2u);
    EXPECT_EQ(report.renormalizedNormals, 1u);
    EXPECT_EQ(result->normals[0], glm::vec3(0, 0, 1));
    EXPECT_EQ(result->normals[1], glm::vec3(0, 0, 1));
    EXPECT_EQ(result->normals[2], glm::vec3(0, 0, 1));
    EXPECT_NEAR(glm::distance(result->normals[3], glm::normalize(glm::vec3(0, 1, 1))), 0.0f, 1e-6f);
}

TEST(MeshRepair, UvsThatDoNotFitAreDroppedAndNonFiniteOnesReset) {
    MeshData mismatched = square();
    mismatched.uvs.pop_back();
    RepairReport report;
    auto result = repairMesh(mismatched, report);
    ASSERT_TRUE(result.ok());
    EXPECT_TRUE(report.droppedUvs);
    EXPECT_TRUE(result->uvs.empty());

    MeshData nan = square();
    nan.uvs[2] = {kNaN, 0.5f};
    result = repairMesh(nan, report);
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(report.fixedUvs, 1u);
    EXPECT_EQ(result->uvs[2], glm::vec2(0.0f));
}

TEST(MeshRepair, ColoursAndTangentsTravelWithTheirVertices) {
    // Vertex 1 is used by nothing once the degenerate triangle goes: the others are renumbered, and their
    // colours and tangents must follow them.
    MeshData mesh;
    mesh.positions = {{0, 0, 0}, {5, 5, 5}, {1, 0, 0}, {1, 1, 0}};
    mesh.normals.assign(4, glm::vec3(0, 0, 1));
    mesh.colors = {{1, 0, 0, 1}, {0, 0, 0, 0}, {0, 1, 0, 1}, {0, 0, 1, 0.5f}};
    mesh.tangents = {{1, 0, 0, 1}, {0, 0, 0, 0}, {0, 1, 0, -1}, {kNaN, 0, 0, 1}};
    mesh.indices = {0, 2, 3, 1, 1, 1};
    RepairReport report;
    auto result = repairMesh(mesh, report);
    ASSERT_TRUE(result.ok()) << result.error();
    ASSERT_EQ(result->positions.size(), 3u);
    ASSERT_EQ(result->colors.size(), 3u);
    ASSERT_EQ(result->tangents.size(), 3u);
    EXPECT_EQ(result->colors[0], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(result->colors[1], glm::vec4(0, 1, 0, 1));
    EXPECT_EQ(result->colors[2], glm::vec4(0, 0, 1, 0.5f));
    EXPECT_EQ(result->tangents[1], glm::vec4(0, 1, 0, -1));
    // A non-finite tangent becomes one without direction (the shaders then keep the plain normal).
    EXPECT_EQ(result->tangents[2], glm::vec4(0, 0, 0, 1));

    // A non-finite colour would poison its pixels: white instead. Arrays that do not fit are dropped.
    MeshData bad = square();
    bad.colors = {{kInf, 0, 0, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}};
    bad.tangents = {{1, 0, 0, 1}};
    result = repairMesh(bad, report);
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(result->colors[0], glm::vec4(1.0f));
    EXPECT_TRUE(result->tangents.empty());
}

TEST(MeshRepair, FailsClearlyWhenNothingIsLeft) {
    RepairReport report;
    const auto empty = repairMesh(MeshData{}, report);
    ASSERT_FALSE(empty.ok());
    EXPECT_NE(empty.error().find("no usable triangles"), std::string::npos) << empty.error();

    MeshData allBad;
    allBad.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {kNaN, 0, 0}};
    allBad.indices = {0, 1, 2, 0, 1, 3, 0, 1, 7};
    const auto result = repairMesh(allBad, report);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().find("no usable triangles"), std::string::npos) << result.error();
    EXPECT_NE(result.error().find("3 dropped"), std::string::npos) << result.error();
}

TEST(MeshRepair, RefusesAbsurdSizesBeforeWork) {
    RepairReport report;
    const auto result = repairMesh(makeBox(), report, 11);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().find("too large"), std::string::npos) << result.error();
    EXPECT_TRUE(repairMesh(makeBox(), report, 12).ok());
    EXPECT_EQ(kMaxMeshTriangles, 50'000'000u);
}

} // namespace
} // namespace speculum::render
