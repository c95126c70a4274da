// Texel solid-angle statistics: the quadrature is checked against the closed form for cube texels and
// against the whole sphere, and each map's largest/smallest ratio lands where its geometry says it must.
#include "render/envmap/SolidAngle.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace speculum::test {
namespace {

using namespace render::envmap;

constexpr double kPi = 3.14159265358979323846;

// Exact solid angle of the rectangle [x0,x1]×[y0,y1] on the plane at unit distance.
double rectangleSolidAngle(double x0, double y0, double x1, double y1) {
    auto f = [](double x, double y) { return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0)); };
    return f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0);
}

TEST(EnvMapSolidAngle, CubeTexelsMatchTheClosedForm) {
    const MapLayout layout = makeLayout(MapType::Cube, 32);
    for (int y = 0; y < 32; y += 5)
        for (int x = 0; x < 32; x += 3) {
            const double exact = rectangleSolidAngle(-1.0 + 2.0 * x / 32, -1.0 + 2.0 * y / 32,
                                                     -1.0 + 2.0 * (x + 1) / 32, -1.0 + 2.0 * (y + 1) / 32);
            EXPECT_NEAR(texelSolidAngle(layout, x, y), exact, 1e-9 * exact);
        }
}

TEST(EnvMapSolidAngle, UsedTexelsCoverTheWholeSphere) {
    for (MapType type : {MapType::Cube, MapType::DualParaboloid, MapType::TennisBall, MapType::Octahedral}) {
        const SolidAngleStats stats = solidAngleStats(type, 64);
        // Boundary texels straddle two components and count in both, so the sum exceeds 4π by about the
        // seam length times a texel width; never less.
        EXPECT_GE(stats.usedSolidAngle, 4.0 * kPi * (1.0 - 1e-9)) << mapTypeName(type);
        EXPECT_LT(stats.usedSolidAngle, 4.0 * kPi * 1.15) << mapTypeName(type);
    }
    EXPECT_NEAR(solidAngleStats(MapType::Cube, 64).usedSolidAngle, 4.0 * kPi, 1e-9);
    // One component: only the texels that straddle the square's edge reach past it, into the band.
    EXPECT_LT(solidAngleStats(MapType::Octahedral, 64).usedSolidAngle, 4.0 * kPi * 1.1);
}

TEST(EnvMapSolidAngle, RatiosFollowEachMapsGeometry) {
    for (int n : {64, 256}) {
        const SolidAngleStats cube = solidAngleStats(MapType::Cube, n);
        const SolidAngleStats paraboloid = solidAngleStats(MapType::DualParaboloid, n);
        const SolidAngleStats tennis = solidAngleStats(MapType::TennisBall, n);
        const SolidAngleStats octahedral = solidAngleStats(MapType::Octahedral, n);
        std::printf("%s\n%s\n%s\n%s\n", describe(cube).c_str(), describe(paraboloid).c_str(),
                    describe(tennis).c_str(), describe(octahedral).c_str());
        // Cube: centre density 1, corner 3^{-3/2}, so the ratio approaches 3√3 = 5.196 from below.
        EXPECT_LT(cube.ratio, 3.0 * std::sqrt(3.0));
        EXPECT_GT(cube.ratio, 3.0 * std::sqrt(3.0) * (1.0 - 8.0 / n));
        EXPECT_DOUBLE_EQ(cube.usedFraction, 1.0);
        // Paraboloid: density 4/(1+r²)², 4 at the centre, 1 on the rim; rim texels reach a little past it.
        EXPECT_GT(paraboloid.ratio, 4.0);
        EXPECT_LT(paraboloid.ratio, 4.0 * (1.0 + 12.0 / n));
        // Used: the two discs, a fraction π/4 of the inner square, which the guard band shrinks.
        const double inner = double(n - 2 * defaultGuard(MapType::DualParaboloid, n)) / n;
        EXPECT_NEAR(paraboloid.usedFraction, kPi / 4.0 * inner * inner, 4.0 / n);
        // Tennis ball: density ∝ cos(latitude), latitude ≤ 45° where used: ratio → √2.
        EXPECT_GT(tennis.ratio, std::sqrt(2.0));
        EXPECT_LT(tennis.ratio, std::sqrt(2.0) * (1.0 + 4.0 / n));
        EXPECT_GT(tennis.usedFraction, 0.85);
        // Octahedral: density 1/r³ from the vertices (r = 1) to the faces' centres (r = 1/√3): 3√3 again,
        // approached from below; every texel of the inner square used.
        EXPECT_LT(octahedral.ratio, 3.0 * std::sqrt(3.0));
        EXPECT_GT(octahedral.ratio, 3.0 * std::sqrt(3.0) * (1.0 - 8.0 / n));
        EXPECT_NEAR(octahedral.usedFraction, inner * inner, 4.0 / n);
        // The expected ordering, measured: the tennis ball spends its texels most evenly.
        EXPECT_LT(tennis.ratio, paraboloid.ratio);
        EXPECT_LT(paraboloid.ratio, cube.ratio);
    }
}

} // namespace
} // namespace speculum::test
