// Direction ↔ texture mappings of the four environment maps: round trips, the reference's conventions,
// the component rules and the Jacobians that pass 2 uses for explicit LOD.
#include "render/envmap/Mapping.hpp"

#include "render/envmap/Layout.hpp"
#include "support/Directions.hpp"

#include <gtest/gtest.h>

namespace speculum::test {
namespace {

using namespace render::envmap;

constexpr MapType kTypes[] = {MapType::Cube, MapType::DualParaboloid, MapType::TennisBall,
                              MapType::Octahedral};
constexpr double kPi = 3.14159265358979323846;

std::vector<glm::dvec3> allTestDirections() {
    std::vector<glm::dvec3> dirs = randomDirections(20000);
    const std::vector<glm::dvec3> special = specialDirections();
    dirs.insert(dirs.end(), special.begin(), special.end());
    return dirs;
}

TEST(EnvMapping, DirectionToTextureToDirectionRoundTrips) {
    const std::vector<glm::dvec3> dirs = allTestDirections();
    ASSERT_GT(dirs.size(), 25000u);
    for (MapType type : kTypes) {
        double worst = 0.0;
        for (const glm::dvec3& d : dirs) {
            const MapCoord c = toMap(type, d);
            ASSERT_GE(c.component, 0);
            ASSERT_LT(c.component, componentCount(type));
            // The chosen component always holds the direction inside its nominal
            // square (up to rounding: asin(√2/2)/(π/4) is 1 ± 1 ulp).
            ASSERT_GE(c.uv.x, -1e-15) << mapTypeName(type);
            ASSERT_LE(c.uv.x, 1.0 + 1e-15) << mapTypeName(type);
            ASSERT_GE(c.uv.y, -1e-15) << mapTypeName(type);
            ASSERT_LE(c.uv.y, 1.0 + 1e-15) << mapTypeName(type);
            const glm::dvec3 back = fromMap(type, c.component, c.uv);
            EXPECT_NEAR(glm::length(back), 1.0, 1e-12);
            worst = std::max(worst, angleBetween(d, back));
        }
        EXPECT_LT(worst, 1e-9) << mapTypeName(type);
    }
}

TEST(EnvMapping, TextureToDirectionToTextureRoundTripsInsideEachComponent) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (MapType type : kTypes)
        for (int component = 0; component < componentCount(type); ++component) {
            int inside = 0;
            for (int i = 0; i < 4000; ++i) {
                const glm::dvec2 uv(unit(rng), unit(rng));
                const glm::dvec3 d = fromMap(type, component, uv);
                if (mapComponent(type, d) != component)
                    continue; // looked up in the other component: its uv there is another point
                ++inside;
                const glm::dvec2 back = mapUv(type, component, d);
                EXPECT_LT(glm::length(back - uv), 1e-12) << mapTypeName(type) << " " << component;
            }
            EXPECT_GT(inside, 2000) << mapTypeName(type) << " " << component;
        }
}

TEST(EnvMapping, ForcedComponentIsContinuousIntoTheGuardBand) {
    // The guard band holds each component's own mapping continued past its domain; round trips there
    // hold too (away from the far pole and the branch cut, which no band reaches).
    for (MapType type : {MapType::DualParaboloid, MapType::TennisBall}) {
        const MapLayout layout = makeLayout(type, 64);
        for (int component = 0; component < 2; ++component)
            for (int y = 0; y < layout.height; ++y)
                for (int x = 0; x < layout.width; ++x) {
                    const glm::dvec2 uv = layout.texelCentre(x, y);
                    const glm::dvec2 back = mapUv(type, component, fromMap(type, component, uv));
                    ASSERT_LT(glm::length(back - uv), 1e-12) << mapTypeName(type) << " " << x << "," << y;
                }
    }
}

// The octahedral map's guard band is its own square folded over each side: a texel past a side shows the
// direction of the texel mirrored across the side's midpoint, and the directions run on continuously from
// the square into the band (neighbouring texels a texel's angle apart, not a jump across the sphere).
TEST(EnvMapping, OctahedralGuardBandContinuesAcrossEachFold) {
    const MapLayout layout = makeLayout(MapType::Octahedral, 64);
    ASSERT_GT(layout.guard, 0);
    const double texel = 1.0 / (layout.width - 2.0 * layout.guard); // nominal uv per texel
    for (int y = 0; y < layout.height; ++y)
        for (int x = 0; x < layout.width; ++x) {
            const glm::dvec2 uv = layout.texelCentre(x, y);
            const glm::dvec3 d = octahedralDirection(uv);
            ASSERT_NEAR(glm::length(d), 1.0, 1e-12);
            for (const glm::dvec2& step : {glm::dvec2(texel, 0.0), glm::dvec2(0.0, texel)}) {
                if (x + 1 >= layout.width || y + 1 >= layout.height)
                    continue;
                // At most √6 rad per unit of p (at the faces' centres), p = 2·uv: 4.9 texels' worth.
                EXPECT_LT(angleBetween(d, octahedralDirection(uv + step)), 6.0 * texel) << x << "," << y;
            }
            if (uv.x > 1.0 && uv.y >= 0.0 && uv.y <= 1.0) { // past the right side: (1 + e, t) is (1 − e, −t)
                const glm::dvec2 mirrored(2.0 - uv.x, 1.0 - uv.y);
                EXPECT_LT(angleBetween(d, octahedralDirection(mirrored)), 1e-12) << x << "," << y;
            }
        }
}

TEST(EnvMapping, OctahedralFollowsTheOctahedronAndItsFold) {
    auto near = [](glm::dvec2 a, glm::dvec2 b) { return glm::length(a - b) < 1e-12; };
    EXPECT_TRUE(near(octahedralUv({0, 0, 1}), {0.5, 0.5})); // +Z at the centre
    EXPECT_TRUE(near(octahedralUv({1, 0, 0}), {1.0, 0.5})); // the equator on the diamond
    EXPECT_TRUE(near(octahedralUv({-1, 0, 0}), {0.0, 0.5}));
    EXPECT_TRUE(near(octahedralUv({0, 1, 0}), {0.5, 1.0}));
    EXPECT_TRUE(near(octahedralUv({1, 1, 0}), {0.75, 0.75}));
    const glm::dvec2 south = octahedralUv({0, 0, -1}); // −Z in a corner
    EXPECT_TRUE(near(south, {1.0, 1.0})) << south.x << "," << south.y;
    for (const glm::dvec2& corner : {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, 1), glm::dvec2(1, 1)})
        EXPECT_LT(angleBetween(octahedralDirection(corner), {0, 0, -1}), 1e-12);
    // The lower half folded: (1, 0, −1) lands on the right side, which is folded onto itself.
    const glm::dvec2 side = octahedralUv({1, 0, -1});
    EXPECT_TRUE(near(side, {1.0, 0.75})) << side.x << "," << side.y;
    EXPECT_LT(angleBetween(octahedralDirection({1.0, 0.25}), glm::normalize(glm::dvec3(1, 0, -1))), 1e-12);
    EXPECT_EQ(componentCount(MapType::Octahedral), 1);
    EXPECT_EQ(mapTypeName(MapType::Octahedral), "octahedral");
}

TEST(EnvMapping, CubeFollowsGlFaceOrderAndAxes) {
    // GL spec §8.13: +X face has sc = −z, tc = −y; +Y has sc = +x, tc = +z; −Z has sc = −x, tc = −y.
    EXPECT_EQ(cubeFace({1, 0.2, -0.3}), 0);
    EXPECT_EQ(cubeFace({-1, 0.2, -0.3}), 1);
    EXPECT_EQ(cubeFace({0.1, 2, -0.3}), 2);
    EXPECT_EQ(cubeFace({0.1, -2, -0.3}), 3);
    EXPECT_EQ(cubeFace({0.1, 0.2, 3}), 4);
    EXPECT_EQ(cubeFace({0.1, 0.2, -3}), 5);
    const glm::dvec2 px = cubeUv(0, {2.0, 1.0, -0.5}); // sc = 0.25, tc = −0.5
    EXPECT_NEAR(px.x, 0.625, 1e-15);
    EXPECT_NEAR(px.y, 0.25, 1e-15);
    const glm::dvec2 py = cubeUv(2, {0.5, 1.0, 0.25});
    EXPECT_NEAR(py.x, 0.75, 1e-15);
    EXPECT_NEAR(py.y, 0.625, 1e-15);
    const glm::dvec2 nz = cubeUv(5, {0.5, 0.25, -1.0});
    EXPECT_NEAR(nz.x, 0.25, 1e-15);
    EXPECT_NEAR(nz.y, 0.375, 1e-15);
}

TEST(EnvMapping, ParaboloidFollowsTheReferenceSigns) {
    // Component 0 (the reference's component 1) for z < 0 with d = 1 − z; component 1 for z ≥ 0, d = 1 + z.
    EXPECT_EQ(paraboloidComponent({0, 0, -1}), 0);
    EXPECT_EQ(paraboloidComponent({0, 0, 1}), 1);
    EXPECT_EQ(paraboloidComponent({1, 0, 0}), 1); // the equator belongs to component 1 (z ≥ 0)
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.4, -0.8));
    const glm::dvec2 uv = paraboloidUv(0, d);
    EXPECT_NEAR(uv.x, d.x / (1.0 - d.z) * 0.5 + 0.5, 1e-15);
    EXPECT_NEAR(uv.y, d.y / (1.0 - d.z) * 0.5 + 0.5, 1e-15);
    const glm::dvec2 uv1 = paraboloidUv(1, {1, 0, 0});
    EXPECT_NEAR(uv1.x, 1.0, 1e-15); // the rim is the unit circle
    EXPECT_NEAR(uv1.y, 0.5, 1e-15);
}

TEST(EnvMapping, TennisBallFollowsTheReferenceEquationsAndRule) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.5, 0.3, 0.6));
    ASSERT_EQ(tennisBallComponent(d), 0);
    const glm::dvec2 uv = tennisBallUv(0, d);
    EXPECT_NEAR(uv.x, std::asin(d.y) / (kPi / 4) * 0.5 + 0.5, 1e-15);           // u holds a (n texels)
    EXPECT_NEAR(uv.y, std::atan2(d.x, d.z) / (3 * kPi / 4) * 0.5 + 0.5, 1e-15); // v holds b (3n texels)
    const glm::dvec3 e = glm::normalize(glm::dvec3(0.2, 0.9, -0.3));
    ASSERT_EQ(tennisBallComponent(e), 1);
    const glm::dvec2 uv2 = tennisBallUv(1, e);
    EXPECT_NEAR(uv2.x, std::asin(e.x) / (kPi / 4) * 0.5 + 0.5, 1e-15);
    EXPECT_NEAR(uv2.y, std::atan2(e.y, -e.z) / (3 * kPi / 4) * 0.5 + 0.5, 1e-15);
    // The six axes.
    EXPECT_EQ(tennisBallComponent({0, 0, 1}), 0);
    EXPECT_EQ(tennisBallComponent({1, 0, 0}), 0);
    EXPECT_EQ(tennisBallComponent({-1, 0, 0}), 0);
    EXPECT_EQ(tennisBallComponent({0, 1, 0}), 1);
    EXPECT_EQ(tennisBallComponent({0, -1, 0}), 1);
    EXPECT_EQ(tennisBallComponent({0, 0, -1}), 1);
    EXPECT_NEAR(tennisBallUv(0, {1, 0, 0}).y, 5.0 / 6.0, 1e-15);
    EXPECT_NEAR(tennisBallUv(0, {-1, 0, 0}).y, 1.0 / 6.0, 1e-15);
    // Each component covers half the sphere: count over uniform directions.
    int zero = 0;
    const std::vector<glm::dvec3> dirs = randomDirections(40000, 99);
    for (const glm::dvec3& r : dirs)
        zero += tennisBallComponent(r) == 0;
    EXPECT_NEAR(double(zero) / dirs.size(), 0.5, 0.01);
}

TEST(EnvMapping, PolesAndBranchCutsGiveFiniteCoordinates) {
    for (int component = 0; component < 2; ++component)
        for (const glm::dvec3& d : {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0),
                                    glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 0, 1)}) {
            const glm::dvec2 uv = tennisBallUv(component, d);
            EXPECT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y));
        }
    // Rounding past |sin| = 1 must not produce NaN (asin is clamped).
    const glm::dvec3 pole(1e-17, 1.0, 1e-17);
    EXPECT_FALSE(std::isnan(tennisBallUv(0, pole).x));
}

TEST(EnvMapping, JacobianMatchesFiniteDifferences) {
    const std::vector<glm::dvec3> dirs = randomDirections(2000, 5);
    for (MapType type : kTypes)
        for (const glm::dvec3& d : dirs) {
            const int c = mapComponent(type, d);
            const glm::dmat3x2 j = uvJacobian(type, c, d);
            // Two tangent directions at d.
            const glm::dvec3 helper = std::abs(d.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
            const glm::dvec3 t1 = glm::normalize(glm::cross(d, helper));
            const glm::dvec3 t2 = glm::cross(d, t1);
            for (const glm::dvec3& t : {t1, t2}) {
                const double h = 1e-6;
                const glm::dvec2 numeric =
                    (mapUv(type, c, d + h * t) - mapUv(type, c, d - h * t)) / (2.0 * h);
                const glm::dvec2 analytic = j * t;
                EXPECT_LT(glm::length(numeric - analytic), 1e-6 * (1.0 + glm::length(analytic)))
                    << mapTypeName(type);
            }
        }
}

TEST(EnvMapping, SolidAngleDensityMatchesTheInverseMapping) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.02, 0.98);
    for (MapType type : kTypes)
        for (int i = 0; i < 500; ++i) {
            const glm::dvec2 uv(unit(rng), unit(rng));
            const double h = 1e-6;
            const glm::dvec3 du =
                (fromMap(type, 0, uv + glm::dvec2(h, 0)) - fromMap(type, 0, uv - glm::dvec2(h, 0))) / (2 * h);
            const glm::dvec3 dv =
                (fromMap(type, 0, uv + glm::dvec2(0, h)) - fromMap(type, 0, uv - glm::dvec2(0, h))) / (2 * h);
            const double numeric = glm::length(glm::cross(du, dv));
            EXPECT_NEAR(solidAngleDensity(type, uv), numeric, 1e-6 * numeric) << mapTypeName(type);
        }
}

TEST(EnvMapping, LayoutPlacesTheNominalSquareInsideTheGuardBand) {
    const MapLayout tennis = makeLayout(MapType::TennisBall, 128);
    EXPECT_EQ(tennis.width, 128);
    EXPECT_EQ(tennis.height, 384);
    EXPECT_EQ(tennis.guard, 4);
    EXPECT_NEAR(tennis.toTexture({0, 0}).x * tennis.width, 4.0, 1e-12);
    EXPECT_NEAR(tennis.toTexture({1, 1}).y * tennis.height, 380.0, 1e-12);
    const glm::dvec2 round = tennis.toNominal(tennis.toTexture({0.3, 0.7}));
    EXPECT_NEAR(round.x, 0.3, 1e-15);
    EXPECT_NEAR(round.y, 0.7, 1e-15);
    const MapLayout cube = makeLayout(MapType::Cube, 128);
    EXPECT_EQ(cube.guard, 0);
    EXPECT_EQ(cube.components, 6);
    EXPECT_EQ(makeLayout(MapType::DualParaboloid, 512).guard, 16);
    const MapLayout octahedral = makeLayout(MapType::Octahedral, 128);
    EXPECT_EQ(octahedral.width, 128);
    EXPECT_EQ(octahedral.height, 128);
    EXPECT_EQ(octahedral.components, 1);
    EXPECT_EQ(octahedral.guard, 4);
    // The smallest resolution a project may ask for still leaves most of the map inside the bands.
    for (const MapType type : {MapType::DualParaboloid, MapType::TennisBall, MapType::Octahedral}) {
        const MapLayout smallest = makeLayout(type, 8);
        EXPECT_GE(smallest.guard, 1);
        EXPECT_LT(4 * smallest.guard, smallest.resolution);
    }
}

} // namespace
} // namespace speculum::test
