// Pass-1 transforms: cube-face cameras put every direction where GL's cube sampling reads it, and the
// direct warps put every direction where the lookup reads it, with depth and clipping as derived.
#include "render/envmap/CaptureMath.hpp"

#include "support/Directions.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::test {
namespace {

using namespace render::envmap;

TEST(EnvMapCaptureMath, CubeFaceCamerasRenderWhatGlSamples) {
    const glm::dmat3 mapFromWorld =
        glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3))));
    for (int face = 0; face < 6; ++face) {
        const glm::dmat3 rotation(cubeFaceView(face));
        EXPECT_NEAR(glm::determinant(rotation), 1.0, 1e-12) << "face " << face << " must not mirror";
    }
    for (const glm::dvec3& d : randomDirections(3000)) {
        const glm::dvec3 world = glm::transpose(mapFromWorld) * d; // the world direction that maps to d
        const int face = cubeFace(d);
        const glm::dmat4 vp = cubeFaceViewProjection(face, mapFromWorld, 0.1, 50.0);
        // Depth is along the face's axis: anything between near·√3 and far is inside every face's frustum.
        for (double rho : {0.1 * std::sqrt(3.0), 1.0, 50.0}) {
            const glm::dvec4 clip = vp * glm::dvec4(rho * world, 1.0);
            const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
            const glm::dvec2 expected = cubeUv(face, d) * 2.0 - 1.0;
            ASSERT_NEAR(ndc.x, expected.x, 1e-9);
            ASSERT_NEAR(ndc.y, expected.y, 1e-9);
            ASSERT_GE(ndc.z, -1.0 - 1e-9);
            ASSERT_LE(ndc.z, 1.0 + 1e-9);
        }
    }
}

TEST(EnvMapCaptureMath, WarpsPutEachDirectionWhereTheLookupReadsIt) {
    for (MapType type : {MapType::DualParaboloid, MapType::TennisBall})
        for (int n : {64, 256}) {
            const MapLayout layout = makeLayout(type, n);
            for (const glm::dvec3& d : randomDirections(3000)) {
                const MapCoord c = toMap(type, d);
                const WarpParameters warp = warpParameters(layout, c.component, 20.0);
                const glm::dvec2 expected = layout.toTexture(c.uv) * 2.0 - 1.0;
                for (double rho : {0.01, 3.0, 19.9}) {
                    const glm::dvec4 clip = warpVertex(warp, rho * d);
                    ASSERT_EQ(clip.w, 1.0);
                    ASSERT_NEAR(clip.x, expected.x, 1e-12) << mapTypeName(type);
                    ASSERT_NEAR(clip.y, expected.y, 1e-12) << mapTypeName(type);
                    ASSERT_GE(clip.z, -1.0) << mapTypeName(type) << " drawn directions are not near-clipped";
                    ASSERT_LE(clip.z, 1.0) << mapTypeName(type) << " drawn directions are not far-clipped";
                }
            }
        }
}

TEST(EnvMapCaptureMath, ParaboloidNearPlaneIsTheGuardBandsEdge) {
    const MapLayout layout = makeLayout(MapType::DualParaboloid, 128);
    for (int component = 0; component < 2; ++component) {
        const WarpParameters warp = warpParameters(layout, component, 10.0);
        EXPECT_EQ(warp.mirrored, component == 1);
        // The direction that lands on the middle of the texture's right edge.
        const glm::dvec3 edge = fromMap(MapType::DualParaboloid, component, layout.toNominal({1.0, 0.5}));
        const glm::dvec4 onEdge = warpVertex(warp, 5.0 * edge);
        EXPECT_NEAR(onEdge.x, 1.0, 1e-12);
        EXPECT_NEAR(onEdge.z, -1.0, 1e-12);
        // A bit further from the axis: clipped; a bit closer: drawn.
        const glm::dvec3 axis(0, 0, component == 0 ? -1.0 : 1.0);
        EXPECT_LT(warpVertex(warp, 5.0 * glm::normalize(edge - 0.01 * axis)).z, -1.0);
        EXPECT_GT(warpVertex(warp, 5.0 * glm::normalize(edge + 0.01 * axis)).z, -1.0);
        // Depth grows with distance along every drawn ray.
        for (const glm::dvec3& d : randomDirections(500, component + 1)) {
            if (warpVertex(warp, d).z < -1.0)
                continue;
            EXPECT_LT(warpVertex(warp, 1.0 * d).z, warpVertex(warp, 1.01 * d).z);
        }
    }
}

TEST(EnvMapCaptureMath, TennisBallFarPlaneClipsAcrossTheBranchCut) {
    const MapLayout layout = makeLayout(MapType::TennisBall, 128);
    for (int component = 0; component < 2; ++component) {
        const WarpParameters warp = warpParameters(layout, component, 10.0);
        EXPECT_FALSE(warp.mirrored);
        EXPECT_GT(warp.cutLimit, 1.0 / layout.scale.y);
        EXPECT_LT(warp.cutLimit, 4.0 / 3.0);
        EXPECT_GT(warp.depthScale, 0.3); // depth keeps a useful share of [−1, 1]
        for (const glm::dvec3& d : randomDirections(4000, 11 + component)) {
            const double b = tennisBallUv(component, d).y * 2.0 - 1.0;
            for (double rho : {0.001, 1.0, 10.0}) {
                const double z = warpVertex(warp, rho * d).z;
                if (std::abs(b) >= warp.cutLimit) {
                    ASSERT_GT(z, 1.0) << "vertices near the cut are far-clipped";
                }
                if (std::abs(b) <= 1.0 / layout.scale.y) {
                    ASSERT_LE(z, 1.0 + 1e-12) << "vertices inside the texture are kept";
                }
                ASSERT_GE(z, -1.0);
            }
            // Depth grows with distance along each ray.
            EXPECT_LT(warpVertex(warp, 1.0 * d).z, warpVertex(warp, 2.0 * d).z);
        }
    }
}

TEST(EnvMapCaptureMath, MirroredFlagMatchesTheWarpsOrientation) {
    // Seen from the capture point, a GL camera has right × up = −(view direction). Compare the warp's
    // orientation with that at directions inside each component.
    for (MapType type : {MapType::DualParaboloid, MapType::TennisBall}) {
        const MapLayout layout = makeLayout(type, 64);
        for (const glm::dvec3& d : randomDirections(300, 17)) {
            const int c = mapComponent(type, d);
            const WarpParameters warp = warpParameters(layout, c, 10.0);
            const glm::dvec3 helper = std::abs(d.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
            const glm::dvec3 right = glm::normalize(glm::cross(d, helper));
            const glm::dvec3 up = glm::cross(right, d);
            ASSERT_NEAR(glm::dot(glm::cross(right, up), -d), 1.0, 1e-12);
            const double h = 1e-6;
            const glm::dvec2 dx =
                (glm::dvec2(warpVertex(warp, d + h * right)) - glm::dvec2(warpVertex(warp, d - h * right)));
            const glm::dvec2 dy =
                (glm::dvec2(warpVertex(warp, d + h * up)) - glm::dvec2(warpVertex(warp, d - h * up)));
            const double orientation = dx.x * dy.y - dx.y * dy.x;
            EXPECT_EQ(orientation < 0.0, warp.mirrored) << mapTypeName(type) << " component " << c;
        }
    }
}

} // namespace
} // namespace speculum::test
