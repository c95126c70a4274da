// The direct fill's mesh subdivision: edges end up spanning at most the tolerance angle from the capture
// point, nothing cracks, nothing far away is split, the angle chosen for a map keeps its chords within
// a texel, and the cache gives a static scene the same meshes every update.
#include "render/passes/WarpMeshes.hpp"

#include "render/envmap/Layout.hpp"
#include "render/envmap/Mapping.hpp"
#include "render/mesh/Primitives.hpp"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <map>
#include <random>

namespace speculum::test {
namespace {

using namespace render;
using namespace render::passes;

double angle(const glm::dvec3& u, const glm::dvec3& v) {
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

glm::dvec3 placed(const glm::dmat4& world, const glm::vec3& p) {
    return glm::dvec3(world * glm::dvec4(glm::dvec3(p), 1.0));
}

// Largest angle any edge spans from the tolerance's centre, among edges longer than its minLength.
double widestEdge(const MeshData& mesh, const glm::dmat4& world, const WarpTolerance& t) {
    double widest = 0.0;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3)
        for (int e = 0; e < 3; ++e) {
            const glm::dvec3 a = placed(world, mesh.positions[mesh.indices[i + e]]) - t.centre;
            const glm::dvec3 b = placed(world, mesh.positions[mesh.indices[i + (e + 1) % 3]]) - t.centre;
            if (glm::length(a - b) > t.minLength)
                widest = std::max(widest, angle(a, b));
        }
    return widest;
}

glm::dvec3 vectorArea(const MeshData& mesh) {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[i]]), b(mesh.positions[mesh.indices[i + 1]]),
            c(mesh.positions[mesh.indices[i + 2]]);
        sum += 0.5 * glm::cross(b - a, c - a);
    }
    return sum;
}

double area(const MeshData& mesh) {
    double sum = 0.0;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[i]]), b(mesh.positions[mesh.indices[i + 1]]),
            c(mesh.positions[mesh.indices[i + 2]]);
        sum += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return sum;
}

TEST(WarpMeshes, NearEdgesAreSplitToTheToleranceAngle) {
    const MeshData box = makeBox();
    // A box beside the capture point: its faces span up to ~110° from there.
    const glm::dmat4 world = glm::translate(glm::dmat4(1.0), glm::dvec3(1.6, 0.2, -0.3));
    const WarpTolerance tolerance{glm::dvec3(0.0), 0.2, 1e-4};
    ASSERT_GT(widestEdge(box, world, tolerance), 1.0);
    const MeshData fine = subdivideForWarp(box, world, tolerance);
    EXPECT_GT(fine.triangleCount(), box.triangleCount());
    EXPECT_LE(widestEdge(fine, world, tolerance), 0.2);
    // Same surface, same winding: the total area and each face's vector area are unchanged.
    EXPECT_NEAR(area(fine), area(box), 1e-4);
    EXPECT_LT(glm::length(vectorArea(fine) - vectorArea(box)), 1e-4);
    for (const glm::vec3& n : fine.normals)
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    EXPECT_EQ(fine.uvs.size(), fine.positions.size());
}

TEST(WarpMeshes, VertexColoursAndTangentsAreSplitWithTheVertices) {
    // The direct fill draws the split copy: a model's colours and tangents must survive the split, or its
    // reflection in the environment map would turn white and lose its normal map.
    MeshData box = makeBox();
    for (const glm::vec3& p : box.positions)
        box.colors.emplace_back(0.5f * (p + glm::vec3(1.0f)), 1.0f);
    box.tangents.assign(box.positions.size(), glm::vec4(0, 0, 1, -1));
    const glm::dmat4 world = glm::translate(glm::dmat4(1.0), glm::dvec3(1.6, 0.2, -0.3));
    const MeshData fine = subdivideForWarp(box, world, WarpTolerance{glm::dvec3(0.0), 0.2, 1e-4});
    ASSERT_GT(fine.positions.size(), box.positions.size());
    ASSERT_EQ(fine.colors.size(), fine.positions.size());
    ASSERT_EQ(fine.tangents.size(), fine.positions.size());
    // The colours are linear in position: every midpoint's colour is its position's.
    for (std::size_t i = 0; i < fine.positions.size(); ++i) {
        const glm::vec3 expected = 0.5f * (fine.positions[i] + glm::vec3(1.0f));
        EXPECT_LT(glm::length(glm::vec3(fine.colors[i]) - expected), 1e-5f) << i;
        EXPECT_EQ(fine.tangents[i], glm::vec4(0, 0, 1, -1)) << i;
    }
    // A mesh without them gets none.
    EXPECT_TRUE(subdivideForWarp(makeBox(), world, WarpTolerance{glm::dvec3(0.0), 0.2, 1e-4}).colors.empty());
}

TEST(WarpMeshes, SplitMeshesHaveNoCracks) {
    // A closed box whose faces are split unevenly (the corner nearest the capture point much more): every
    // edge, by the positions of its end points, must still be shared by exactly two triangles running it
    // in opposite directions. A T-junction would leave an edge used once.
    const MeshData box = makeBox();
    const glm::dmat4 world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(1.3, 1.2, 1.1)),
                                         glm::radians(30.0), glm::dvec3(0.3, 1.0, 0.2));
    const MeshData fine = subdivideForWarp(box, world, {glm::dvec3(0.0), 0.12, 1e-4});
    ASSERT_GT(fine.triangleCount(), 100u);
    using Key = std::pair<std::array<float, 3>, std::array<float, 3>>;
    std::map<Key, int> directed;
    auto key = [&](std::uint32_t a, std::uint32_t b) {
        const glm::vec3 p = fine.positions[a], q = fine.positions[b];
        return Key{{p.x, p.y, p.z}, {q.x, q.y, q.z}};
    };
    for (std::size_t i = 0; i < fine.indices.size(); i += 3)
        for (int e = 0; e < 3; ++e)
            ++directed[key(fine.indices[i + e], fine.indices[i + (e + 1) % 3])];
    int unmatched = 0;
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1)
            ++unmatched;
    }
    EXPECT_EQ(unmatched, 0) << "of " << directed.size() << " directed edges";
}

TEST(WarpMeshes, FarAndShortEdgesAreLeftAlone) {
    const MeshData plane = makePlane(1);
    const WarpTolerance tolerance{glm::dvec3(0.0), 0.2, 0.05};
    // 100 units away a 2-unit plane spans about 1°: nothing to split.
    const glm::dmat4 far = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -100.0, 0.0));
    EXPECT_EQ(subdivideForWarp(plane, far, tolerance).triangleCount(), plane.triangleCount());
    // Through the capture point itself edges span 180° however short: minLength stops the splitting.
    const glm::dmat4 through = glm::scale(glm::dmat4(1.0), glm::dvec3(0.1));
    const MeshData fine = subdivideForWarp(plane, through, tolerance);
    EXPECT_LT(fine.triangleCount(), 200u);
    // The same plane nearer is split more than further away.
    const auto at = [&](double distance) {
        return subdivideForWarp(plane, glm::translate(glm::dmat4(1.0), glm::dvec3(0, -distance, 0)),
                                tolerance)
            .triangleCount();
    };
    EXPECT_GT(at(0.5), at(2.0));
    EXPECT_GT(at(2.0), at(8.0));
}

TEST(WarpMeshes, TriangleBudgetCoarsensEverywhereInsteadOfStopping) {
    const MeshData plane = makePlane(1);
    const glm::dmat4 world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -0.05, 0.0));
    const WarpTolerance tolerance{glm::dvec3(0.0), 0.01, 1e-6};
    const MeshData fine = subdivideForWarp(plane, world, tolerance, 5000);
    EXPECT_LE(fine.triangleCount(), 5000u);
    EXPECT_GT(fine.triangleCount(), 100u);
    EXPECT_NEAR(area(fine), area(plane), 1e-4);
}

// The deviation (radians) of a straight edge's chord in the map from the edge's true image, the great
// circle through its end points: its largest value over the chord.
double chordError(envmap::MapType type, const glm::dvec3& a, const glm::dvec3& b) {
    const envmap::MapCoord ca = envmap::toMap(type, a);
    if (envmap::mapComponent(type, b) != ca.component)
        return -1.0;
    const glm::dvec2 ub = envmap::mapUv(type, ca.component, b);
    const glm::dvec3 normal = glm::normalize(glm::cross(a, b));
    double worst = 0.0;
    for (int k = 1; k < 16; ++k) {
        const glm::dvec2 uv = glm::mix(ca.uv, ub, k / 16.0);
        const glm::dvec3 d = envmap::fromMap(type, ca.component, uv);
        worst = std::max(worst, std::abs(std::asin(std::clamp(glm::dot(d, normal), -1.0, 1.0))));
    }
    return worst;
}

TEST(WarpMeshes, EdgeAngleKeepsChordsWithinATexel) {
    std::mt19937 rng(7);
    std::normal_distribution<double> gauss;
    for (auto type : {envmap::MapType::DualParaboloid, envmap::MapType::TennisBall}) {
        double previous = 10.0;
        for (int n : {64, 128, 256, 512, 1024}) {
            const envmap::MapLayout layout = envmap::makeLayout(type, n);
            const double theta = warpEdgeAngle(layout);
            EXPECT_LE(theta, kMaxWarpEdgeAngle);
            EXPECT_LE(theta, previous) << "finer maps need finer meshes";
            previous = theta;
            const double inner = layout.width - 2.0 * layout.guard;
            const double texel = type == envmap::MapType::DualParaboloid ? 4.0 / inner : 1.5707963 / inner;
            double worst = 0.0;
            for (int i = 0; i < 4000; ++i) {
                const glm::dvec3 a = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
                const glm::dvec3 side =
                    glm::normalize(glm::cross(a, glm::dvec3(gauss(rng), gauss(rng), gauss(rng))));
                const glm::dvec3 b = std::cos(theta) * a + std::sin(theta) * side;
                worst = std::max(worst, chordError(type, a, b));
            }
            EXPECT_LT(worst, texel * 1.05) << envmap::mapTypeName(type) << " n=" << n;
        }
    }
}

TEST(WarpMeshes, CacheReusesCopiesWhileTheGeometryStaysPut) {
    const auto box = std::make_shared<const MeshData>(makeBox());
    const WarpTolerance tolerance{glm::dvec3(0.0), 0.2, 1e-4};
    const glm::dmat4 here = glm::translate(glm::dmat4(1.0), glm::dvec3(2.0, 0.0, 0.0));
    const glm::dmat4 there = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -2.0));
    WarpMeshes cache;
    cache.begin();
    const MeshHandle a = cache.get(box, here, tolerance);
    const MeshHandle b = cache.get(box, there, tolerance);
    EXPECT_NE(a, box);
    EXPECT_NE(a, b) << "one copy per placement";
    cache.purge();
    // The next update with nothing moved gets the very same copies (and so the same GPU buffers).
    cache.begin();
    EXPECT_EQ(cache.get(box, here, tolerance), a);
    EXPECT_EQ(cache.get(box, there, tolerance), b);
    cache.purge();
    EXPECT_EQ(cache.size(), 2u);
    // The box moves: its old copy is dropped after the update that no longer used it.
    cache.begin();
    const MeshHandle moved = cache.get(box, glm::translate(here, glm::dvec3(0.0, 0.5, 0.0)), tolerance);
    EXPECT_NE(moved, a);
    cache.purge();
    EXPECT_EQ(cache.size(), 1u);
    // A mesh that needs no split is returned as it is, and the cache does not keep it alive.
    cache.begin();
    const glm::dmat4 far = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -500.0));
    auto small = std::make_shared<const MeshData>(makeBox());
    EXPECT_EQ(cache.get(small, far, tolerance), small);
    const std::weak_ptr<const MeshData> weak = small;
    small.reset();
    EXPECT_TRUE(weak.expired());
    cache.purge();
    EXPECT_EQ(cache.size(), 0u);
}

} // namespace
} // namespace speculum::test
