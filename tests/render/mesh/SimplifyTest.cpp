// The simplified level of big meshes (MeshData::coarse), which reflected views and environment maps draw.
#include "render/mesh/Simplify.hpp"

#include "render/mesh/MeshData.hpp"
#include "render/mesh/Primitives.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <thread>
#include <vector>

namespace speculum::render {
namespace {

// A unit sphere of more than kSimplifyAboveTriangles triangles.
MeshData bigSphere() {
    MeshData sphere = makeSphere(256);
    EXPECT_GT(sphere.triangleCount(), kSimplifyAboveTriangles);
    return sphere;
}

TEST(Simplify, ABigMeshGetsACoarseLevelWithinItsErrorBound) {
    const MeshHandle mesh = freezeMesh(bigSphere());
    EXPECT_EQ(mesh->coarse.ready(), nullptr) << "freezing a mesh must not pay for a level nobody asked for";
    const CoarseLevel& coarse = coarseLevel(*mesh);
    EXPECT_EQ(mesh->coarse.ready(), &coarse) << "built once, then kept";
    ASSERT_FALSE(coarse.indices.empty());
    EXPECT_EQ(coarse.indices.size() % 3, 0u);
    EXPECT_LE(coarse.triangleCount(), mesh->triangleCount() * 3 / 4) << "too little gained to keep it";
    EXPECT_GE(coarse.triangleCount(), kSimplifiedMinimumTriangles / 2);
    EXPECT_LE(coarse.error, kSimplifyMaxError);
    for (std::uint32_t index : coarse.indices)
        ASSERT_LT(index, mesh->vertexCount());
    // Every triangle of the level lies on the sphere within the error bound: its centroid is at most the
    // allowed deviation (a share of the size, 2) plus the chord's own sag inside the unit sphere.
    double worst = 0.0;
    for (std::size_t t = 0; t < coarse.indices.size(); t += 3) {
        const glm::vec3 c = (mesh->positions[coarse.indices[t]] + mesh->positions[coarse.indices[t + 1]] +
                             mesh->positions[coarse.indices[t + 2]]) /
                            3.0f;
        worst = std::max(worst, 1.0 - double(glm::length(c)));
    }
    EXPECT_LT(worst, 0.05) << "a triangle of the simplified sphere strays far inside it";
}

TEST(Simplify, SmallMeshesAreAlwaysDrawnWhole) {
    EXPECT_TRUE(coarseLevel(*freezeMesh(makeSphere())).indices.empty());
    EXPECT_TRUE(coarseLevel(*freezeMesh(makeBox())).indices.empty());
    EXPECT_TRUE(coarseLevel(*freezeMesh(MeshData{})).indices.empty());
}

TEST(Simplify, NonFinitePositionsGetNoCoarseLevel) {
    MeshData sphere = bigSphere();
    sphere.positions[7].x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(coarseLevel(*freezeMesh(std::move(sphere))).indices.empty());
}

TEST(Simplify, ACopyDropsTheLevelAndAMoveKeepsIt) {
    const MeshHandle mesh = freezeMesh(bigSphere());
    ASSERT_FALSE(coarseLevel(*mesh).indices.empty());
    MeshData copy = *mesh;
    EXPECT_EQ(copy.coarse.ready(), nullptr) << "a copy may be edited: its original's level would be stale";
    // A copy edited and frozen gets a level of its own, over its own triangles.
    copy.indices.resize(copy.indices.size() / 6 * 3); // half the triangles
    const MeshHandle edited = freezeMesh(std::move(copy));
    for (std::uint32_t index : coarseLevel(*edited).indices)
        ASSERT_LT(index, edited->vertexCount());

    MeshData moved = bigSphere();
    moved.coarse.set(CoarseLevel{{0, 1, 2}, 0.25f});
    const MeshHandle kept = freezeMesh(std::move(moved));
    ASSERT_NE(kept->coarse.ready(), nullptr) << "a level that came with the mesh is kept";
    EXPECT_EQ(coarseLevel(*kept).indices, (std::vector<std::uint32_t>{0, 1, 2})) << "and not built again";
    EXPECT_EQ(coarseLevel(*kept).error, 0.25f);
}

TEST(Simplify, ThreadsAskingAtOnceShareOneBuild) {
    const MeshHandle mesh = freezeMesh(bigSphere());
    std::vector<const CoarseLevel*> seen(4, nullptr);
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < seen.size(); ++i)
        threads.emplace_back([&, i] { seen[i] = &coarseLevel(*mesh); });
    for (std::thread& thread : threads)
        thread.join();
    for (const CoarseLevel* level : seen)
        EXPECT_EQ(level, mesh->coarse.ready());
    EXPECT_FALSE(mesh->coarse.ready()->indices.empty());
}

} // namespace
} // namespace speculum::render
