#include "render/mesh/Teapot.hpp"

#include "render/mesh/MeshRepair.hpp"
#include "render/mesh/TeapotPatches.hpp"
#include "support/MeshChecks.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <set>

namespace speculum::render {
namespace {

using test::faceNormal;
using test::signedVolume;

// Extents of Newell's teapot surface in our Y-up frame, from the control data: handle back at x = -3,
// spout tip at x = 3.43408 (interior maximum of the spout's top curve), body radius 2 at the widest,
// knob top at 3.15, base at 0.
constexpr double kMinX = -3.0, kMaxX = 3.434075, kHeight = 3.15, kRadius = 2.0;

TEST(Teapot, ControlDataHasNewellsShape) {
    EXPECT_EQ(teapot::kPatches.size(), 32u);
    EXPECT_EQ(teapot::kControlPoints.size(), 306u);
    std::set<int> used;
    for (const auto& patch : teapot::kPatches) {
        for (auto index : patch) {
            ASSERT_GE(index, 1);
            ASSERT_LE(index, 306);
            used.insert(index);
        }
    }
    // Only the four +-0.002 points near the knob (205, 206, 216, 223) are unused in the published set.
    EXPECT_EQ(used.size(), 302u);
    for (int unused : {205, 206, 216, 223}) {
        EXPECT_EQ(used.count(unused), 0u) << unused;
    }
}

TEST(Teapot, CountsFollowTessellation) {
    for (int n : {1, 2, 6, 10, 16}) {
        const MeshData mesh = makeTeapot(n);
        EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>(32 * n * n * 2)) << "N = " << n;
        EXPECT_EQ(mesh.vertexCount(), static_cast<std::size_t>(32 * (n + 1) * (n + 1))) << "N = " << n;
        EXPECT_EQ(mesh.normals.size(), mesh.vertexCount());
        EXPECT_EQ(mesh.uvs.size(), mesh.vertexCount());
    }
    EXPECT_EQ(makeTeapot(0).triangleCount(), makeTeapot(1).triangleCount());
    EXPECT_EQ(makeTeapot(-5).triangleCount(), makeTeapot(1).triangleCount());
    EXPECT_EQ(makeTeapot(1000).triangleCount(), makeTeapot(kTeapotMaxTessellation).triangleCount());
}

TEST(Teapot, WellFormedAtEveryTessellation) {
    for (int n : {1, 3, 8, 24}) {
        SCOPED_TRACE("N = " + std::to_string(n));
        const MeshData mesh = makeTeapot(n);
        test::expectWellFormed(mesh);
        for (const glm::vec2& uv : mesh.uvs) {
            ASSERT_GE(uv.x, 0.0f);
            ASSERT_LE(uv.x, 1.0f);
            ASSERT_GE(uv.y, 0.0f);
            ASSERT_LE(uv.y, 1.0f);
        }
    }
}

TEST(Teapot, BoundsMatchNewellsProportions) {
    const Bounds fine = computeBounds(makeTeapot(64));
    EXPECT_FLOAT_EQ(fine.min.x, kMinX);
    EXPECT_NEAR(fine.max.x, kMaxX, 2e-4); // the spout maximum falls between grid lines
    EXPECT_FLOAT_EQ(fine.min.y, 0.0f);    // base on y = 0
    EXPECT_FLOAT_EQ(fine.max.y, kHeight);
    EXPECT_FLOAT_EQ(fine.min.z, -kRadius);
    EXPECT_FLOAT_EQ(fine.max.z, kRadius);

    // Coarse tessellations sample the same surface: never outside it, and the exact extents that lie on
    // patch corners are hit at every N.
    for (int n : {1, 4, 8}) {
        const Bounds b = computeBounds(makeTeapot(n));
        EXPECT_FLOAT_EQ(b.min.x, kMinX) << n;
        EXPECT_LE(b.max.x, kMaxX + 1e-5) << n;
        EXPECT_GT(b.max.x, 3.2) << n;
        EXPECT_FLOAT_EQ(b.min.y, 0.0f) << n;
        EXPECT_FLOAT_EQ(b.max.y, kHeight) << n;
        EXPECT_FLOAT_EQ(b.max.z, kRadius) << n;
    }
}

TEST(Teapot, SpoutPointsTowardsPlusXAndHandleTowardsMinusX) {
    const MeshData mesh = makeTeapot(16);
    const auto tip = std::max_element(mesh.positions.begin(), mesh.positions.end(),
                                      [](const glm::vec3& a, const glm::vec3& b) { return a.x < b.x; });
    // The spout tip is high up (its lip is at 2.4..2.51) and on the symmetry plane z = 0.
    EXPECT_GT(tip->y, 2.4f);
    EXPECT_LT(tip->y, 2.52f);
    EXPECT_NEAR(tip->z, 0.0f, 1e-5f);
    const auto back = std::min_element(mesh.positions.begin(), mesh.positions.end(),
                                       [](const glm::vec3& a, const glm::vec3& b) { return a.x < b.x; });
    // The handle's outermost point is at mid-height.
    EXPECT_GT(back->y, 1.3f);
    EXPECT_LT(back->y, 2.3f);
    // The teapot is symmetric about z = 0 (the data's x-z plane), which a wrong axis mapping would break.
    const Bounds b = computeBounds(mesh);
    EXPECT_FLOAT_EQ(b.min.z, -b.max.z);
}

TEST(Teapot, BaseSitsFlatOnZero) {
    const MeshData mesh = makeTeapot(8);
    std::size_t onGround = 0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        ASSERT_GE(p.y, 0.0f);
        if (p.y == 0.0f) {
            ++onGround;
            // The flat bottom disc has radius 1.425 and faces straight down.
            EXPECT_LE(std::hypot(p.x, p.z), 1.425f + 1e-5f);
            EXPECT_NEAR(mesh.normals[v].y, -1.0f, 1e-4f);
        }
    }
    EXPECT_GE(onGround, 4u * 9u);
}

TEST(Teapot, NormalsAreOutward) {
    for (int n : {4, 12, 24}) {
        SCOPED_TRACE("N = " + std::to_string(n));
        const MeshData mesh = makeTeapot(n);
        // Winding: the (open, self-intersecting) surface still encloses a positive volume when wound
        // counter-clockwise from outside; the teapot holds about 25.9 cubic Newell units.
        const double volume = signedVolume(mesh);
        EXPECT_GT(volume, 24.5);
        EXPECT_LT(volume, 26.0);

        // Vertex normals agree with the faces around them. Below N = 12 the triangles cut right across
        // the spout lip's tight curl, where no flat facet can agree with the smooth surface.
        const double agreement = n >= 12 ? 0.5 : -1.0;
        std::size_t degenerate = 0;
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const glm::dvec3 face = faceNormal(mesh, t);
            if (glm::length(face) < 1e-12) {
                ++degenerate; // the pole fans of lid and bottom; checked below
                continue;
            }
            const glm::dvec3 unit = glm::normalize(face);
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 vn(mesh.normals[mesh.indices[t * 3 + k]]);
                ASSERT_GT(glm::dot(unit, vn), agreement) << "triangle " << t << " corner " << k;
            }
        }
        // One collapsed triangle per quad along the knob top and the bottom centre: 8 patches * N.
        EXPECT_EQ(degenerate, static_cast<std::size_t>(8 * n));

        // Poles: the knob top faces up, the bottom centre faces down.
        std::size_t top = 0, bottom = 0;
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            const glm::vec3 p = mesh.positions[v];
            if (std::hypot(p.x, p.z) > 1e-6f) {
                continue;
            }
            if (std::abs(p.y - kHeight) < 1e-5) {
                ++top;
                EXPECT_GT(mesh.normals[v].y, 0.9999f);
            } else if (std::abs(p.y) < 1e-6) {
                ++bottom;
                EXPECT_LT(mesh.normals[v].y, -0.9999f);
            }
        }
        EXPECT_EQ(top, static_cast<std::size_t>(4 * (n + 1)));
        EXPECT_EQ(bottom, static_cast<std::size_t>(4 * (n + 1)));
    }
}

TEST(Teapot, OutwardAtKnownPlaces) {
    const MeshData mesh = makeTeapot(8);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        const glm::vec3 n = mesh.normals[v];
        // Widest point of the body, towards +X, -X (behind the handle root), +Z and -Z.
        // (The handle's lower end also touches the body at (-2, 0.9, 0); its normal runs along the handle.)
        const bool handle = p.x < -1.9f && std::abs(p.z) < 0.31f;
        if (!handle && std::abs(p.y - 0.9f) < 1e-5f && std::abs(std::hypot(p.x, p.z) - 2.0f) < 1e-5f) {
            EXPECT_GT(glm::dot(n, glm::normalize(glm::vec3(p.x, 0.0f, p.z))), 0.95f) << p.x << ' ' << p.z;
        }
        // The lid's top face at the knob's outer radius faces up.
        if (std::abs(p.y - 3.15f) < 1e-5f) {
            EXPECT_GT(n.y, 0.9f);
        }
    }
}

TEST(Teapot, RepairFindsNothingButThePoleFans) {
    const int n = 6;
    RepairReport report;
    const auto repaired = repairMesh(makeTeapot(n), report);
    ASSERT_TRUE(repaired.ok()) << repaired.error();
    EXPECT_EQ(report.droppedNonFinite, 0u);
    EXPECT_EQ(report.droppedOutOfRange, 0u);
    EXPECT_EQ(report.droppedDegenerate, static_cast<std::size_t>(8 * n));
    EXPECT_EQ(report.regeneratedNormals, 0u);
    EXPECT_EQ(report.renormalizedNormals, 0u);
}

} // namespace
} // namespace speculum::render
