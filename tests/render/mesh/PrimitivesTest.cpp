#include "render/mesh/Primitives.hpp"

#include "render/mesh/MeshRepair.hpp"
#include "render/mesh/Teapot.hpp"
#include "support/MeshChecks.hpp"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

using test::faceNormal;
using test::signedVolume;

// A texture reads un-mirrored from outside when, on every triangle, the direction of growing u crossed
// with the direction of growing v points along the outward normal.
void expectTexturesUnmirrored(const MeshData& mesh) {
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::dvec3 n = faceNormal(mesh, t);
        if (glm::length(n) < 1e-12) {
            continue;
        }
        const std::uint32_t i0 = mesh.indices[t * 3], i1 = mesh.indices[t * 3 + 1],
                            i2 = mesh.indices[t * 3 + 2];
        const glm::dvec3 e1 = glm::dvec3(mesh.positions[i1] - mesh.positions[i0]);
        const glm::dvec3 e2 = glm::dvec3(mesh.positions[i2] - mesh.positions[i0]);
        const glm::dvec2 d1 = glm::dvec2(mesh.uvs[i1] - mesh.uvs[i0]);
        const glm::dvec2 d2 = glm::dvec2(mesh.uvs[i2] - mesh.uvs[i0]);
        const double det = d1.x * d2.y - d1.y * d2.x;
        ASSERT_NE(det, 0.0) << "triangle " << t;
        // Solve for the surface directions of du and dv (the tangent frame).
        const glm::dvec3 dpdu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::dvec3 dpdv = (e2 * d1.x - e1 * d2.x) / det;
        ASSERT_GT(glm::dot(glm::cross(dpdu, dpdv), n), 0.0) << "triangle " << t;
    }
}

void expectFacesOutwardFromOrigin(const MeshData& mesh) {
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::dvec3 centroid =
            (test::corner(mesh, t, 0) + test::corner(mesh, t, 1) + test::corner(mesh, t, 2)) / 3.0;
        ASSERT_GT(glm::dot(faceNormal(mesh, t), centroid), 0.0) << "triangle " << t;
    }
}

void expectCleanUnderRepair(const MeshData& mesh) {
    RepairReport report;
    const auto repaired = repairMesh(mesh, report);
    ASSERT_TRUE(repaired.ok()) << repaired.error();
    EXPECT_TRUE(report.clean()) << report.summary();
    EXPECT_EQ(repaired->triangleCount(), mesh.triangleCount());
}

TEST(Sphere, UnitRadiusAtOrigin) {
    const MeshData mesh = makeSphere(32);
    test::expectWellFormed(mesh);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        ASSERT_NEAR(glm::length(mesh.positions[v]), 1.0f, 1e-5f);
        ASSERT_NEAR(glm::distance(mesh.positions[v], mesh.normals[v]), 0.0f, 1e-5f); // normal = position
    }
    const Bounds b = computeBounds(mesh);
    EXPECT_NEAR(b.min.x, -1.0f, 1e-6f);
    EXPECT_NEAR(b.max.x, 1.0f, 1e-6f);
    EXPECT_NEAR(b.min.y, -1.0f, 1e-6f);
    EXPECT_NEAR(b.max.y, 1.0f, 1e-6f);
    EXPECT_NEAR(b.min.z, -1.0f, 1e-6f);
    EXPECT_NEAR(b.max.z, 1.0f, 1e-6f);
}

TEST(Sphere, WoundOutwardAndClosed) {
    for (int rings : {3, 8, 32, 100}) {
        SCOPED_TRACE("rings = " + std::to_string(rings));
        const MeshData mesh = makeSphere(rings);
        EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>(2 * (2 * rings) * (rings - 1)));
        expectFacesOutwardFromOrigin(mesh);
        // An inscribed polyhedron: a little less than 4/3 pi, converging as the rings grow.
        const double volume = signedVolume(mesh);
        const double exact = 4.0 / 3.0 * glm::pi<double>();
        EXPECT_LT(volume, exact);
        EXPECT_GT(volume, exact * (rings >= 32 ? 0.99 : 0.6));
        expectCleanUnderRepair(mesh);
    }
}

TEST(Sphere, TessellationIsClamped) {
    EXPECT_EQ(makeSphere(0).triangleCount(), makeSphere(kSphereMinTessellation).triangleCount());
    EXPECT_EQ(makeSphere(-3).triangleCount(), makeSphere(kSphereMinTessellation).triangleCount());
    EXPECT_EQ(makeSphere(100000).triangleCount(), makeSphere(kSphereMaxTessellation).triangleCount());
    EXPECT_EQ(makeSphere().triangleCount(), makeSphere(kSphereDefaultTessellation).triangleCount());
}

TEST(Sphere, UvsWrapOnceAndRunPoleToPole) {
    const MeshData mesh = makeSphere(16);
    expectTexturesUnmirrored(mesh);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec2 uv = mesh.uvs[v];
        ASSERT_GE(uv.x, 0.0f);
        ASSERT_LE(uv.x, 1.0f);
        // v = 0 at the south pole, 1 at the north pole.
        ASSERT_NEAR(uv.y, std::acos(-mesh.positions[v].y) / glm::pi<float>(), 1e-4f);
    }
}

TEST(Box, CubeWithFlatFaces) {
    const MeshData mesh = makeBox();
    test::expectWellFormed(mesh);
    EXPECT_EQ(mesh.vertexCount(), 24u);
    EXPECT_EQ(mesh.triangleCount(), 12u);
    const Bounds b = computeBounds(mesh);
    EXPECT_EQ(b.min, glm::vec3(-1.0f));
    EXPECT_EQ(b.max, glm::vec3(1.0f));
    EXPECT_NEAR(signedVolume(mesh), 8.0, 1e-9);
    expectFacesOutwardFromOrigin(mesh);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::dvec3 face = glm::normalize(faceNormal(mesh, t));
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 n = mesh.normals[mesh.indices[t * 3 + k]];
            ASSERT_NEAR(glm::distance(glm::dvec3(n), face), 0.0, 1e-9); // flat: vertex normal = face normal
            const glm::vec3 p = mesh.positions[mesh.indices[t * 3 + k]];
            ASSERT_FLOAT_EQ(glm::dot(p, n), 1.0f); // on the face plane
        }
    }
    expectTexturesUnmirrored(mesh);
    expectCleanUnderRepair(mesh);
}

TEST(Box, EveryFaceMapsTheWholeTexture) {
    const MeshData mesh = makeBox();
    for (std::size_t face = 0; face < 6; ++face) {
        glm::vec2 lo(1.0f), hi(0.0f);
        for (std::size_t k = 0; k < 4; ++k) {
            lo = glm::min(lo, mesh.uvs[face * 4 + k]);
            hi = glm::max(hi, mesh.uvs[face * 4 + k]);
        }
        EXPECT_EQ(lo, glm::vec2(0.0f)) << face;
        EXPECT_EQ(hi, glm::vec2(1.0f)) << face;
    }
}

TEST(Plane, UnitSquareFacingUp) {
    for (int n : {1, 5}) {
        SCOPED_TRACE("N = " + std::to_string(n));
        const MeshData mesh = makePlane(n);
        test::expectWellFormed(mesh);
        EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>(2 * n * n));
        const Bounds b = computeBounds(mesh);
        EXPECT_EQ(b.min, glm::vec3(-1.0f, 0.0f, -1.0f));
        EXPECT_EQ(b.max, glm::vec3(1.0f, 0.0f, 1.0f));
        double area = 0.0;
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const glm::dvec3 face = faceNormal(mesh, t);
            ASSERT_GT(face.y, 0.0); // counter-clockwise seen from +Y
            area += glm::length(face) / 2.0;
        }
        EXPECT_NEAR(area, 4.0, 1e-9);
        for (const glm::vec3& normal : mesh.normals) {
            ASSERT_EQ(normal, glm::vec3(0.0f, 1.0f, 0.0f));
        }
        expectTexturesUnmirrored(mesh);
        expectCleanUnderRepair(mesh);
    }
}

TEST(Plane, UvRunsAlongXAndMinusZ) {
    const MeshData mesh = makePlane(4);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        EXPECT_FLOAT_EQ(mesh.uvs[v].x, (p.x + 1.0f) / 2.0f);
        EXPECT_FLOAT_EQ(mesh.uvs[v].y, (1.0f - p.z) / 2.0f);
    }
    EXPECT_EQ(makePlane(0).triangleCount(), 2u);
}

TEST(Bounds, EmptyAndNonFinite) {
    MeshData mesh;
    const Bounds empty = computeBounds(mesh);
    EXPECT_EQ(empty.min, glm::vec3(0.0f));
    EXPECT_EQ(empty.max, glm::vec3(0.0f));
    mesh.positions = {{1, 2, 3}, {std::nanf(""), 0, 0}, {-1, 5, 0.5f}};
    const Bounds b = computeBounds(mesh);
    EXPECT_EQ(b.min, glm::vec3(-1.0f, 2.0f, 0.5f));
    EXPECT_EQ(b.max, glm::vec3(1.0f, 5.0f, 3.0f));
}

TEST(Closure, ClosedMeshesAreRecognised) {
    // Closed and consistently wound, though their vertices are duplicated for normals, uvs and seams.
    EXPECT_TRUE(isClosed(makeBox()));
    EXPECT_TRUE(isClosed(makeSphere(12)));
    // Open: a plane has a rim; the teapot has the gap under its lid and open spout and handle ends.
    EXPECT_FALSE(isClosed(makePlane(3)));
    EXPECT_FALSE(isClosed(makeTeapot(4)));
    // A box with one triangle turned round is closed but not consistently wound; with one missing, open.
    MeshData flipped = makeBox();
    std::swap(flipped.indices[0], flipped.indices[1]);
    EXPECT_FALSE(isClosed(flipped));
    MeshData holed = makeBox();
    holed.indices.resize(holed.indices.size() - 3);
    EXPECT_FALSE(isClosed(holed));
    EXPECT_FALSE(isClosed(MeshData{}));
    // Every triangle turned round: closed and consistent, but inside out, so seen from outside every face
    // is a back face.
    MeshData insideOut = makeSphere(12);
    for (std::size_t t = 0; t + 2 < insideOut.indices.size(); t += 3)
        std::swap(insideOut.indices[t], insideOut.indices[t + 1]);
    EXPECT_FALSE(isClosed(insideOut));
    // Moved far from the origin it is the same surface.
    MeshData far = makeBox();
    for (glm::vec3& p : far.positions)
        p += glm::vec3(1e4f, -2e4f, 3e4f);
    EXPECT_TRUE(isClosed(far));
}

TEST(MeshData, AFrozenMeshKnowsItsBoundsAndACopyForgetsThem) {
    MeshData box = makeBox();
    const MeshHandle frozen = freezeMesh(MeshData(box));
    ASSERT_NE(frozen->knownBounds.get(), nullptr);
    EXPECT_EQ(frozen->knownBounds.get()->min, glm::vec3(-1.0f));
    EXPECT_EQ(frozen->knownBounds.get()->max, glm::vec3(1.0f));
    // A copy that is then edited must measure itself again, not answer with the original's box.
    MeshData copy = *frozen;
    EXPECT_EQ(copy.knownBounds.get(), nullptr);
    copy.positions[0] = glm::vec3(5.0f, 0.0f, 0.0f);
    EXPECT_EQ(computeBounds(copy).max.x, 5.0f);
    EXPECT_EQ(computeBounds(*frozen).max.x, 1.0f);
}

} // namespace
} // namespace speculum::render
