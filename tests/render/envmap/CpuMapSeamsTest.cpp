// Lookups are continuous across every seam: pairs of directions straddling a seam are looked up in maps
// filled from a smooth environment and compared with a high-resolution cube map. Across a seam the lookup
// may change no more than the environment itself does (within a small tolerance); counter-examples
// (no guard band, no seamless cube filtering) show that the check catches a real seam.
#include "Seams.hpp"
#include "render/envmap/CpuMap.hpp"
#include "support/Directions.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>

namespace speculum::test {
namespace {

using namespace render::envmap;

constexpr double kPi = 3.14159265358979323846;
constexpr int kResolution = 64;
constexpr int kReferenceResolution = 512;

// A smooth environment with gradients in every direction; |∇| ≤ 1.9 per radian in each channel.
glm::dvec3 environment(const glm::dvec3& d) {
    return 0.5 + 0.5 * glm::dvec3(std::sin(3.0 * d.x + 1.3 * d.y + 0.2),
                                  std::sin(2.5 * d.y - 2.0 * d.z + 0.4),
                                  std::cos(2.0 * d.x + 3.0 * d.z - d.y));
}
constexpr double kMaxGradient = 1.9;

double maxAbs(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Largest angle a texel of the map spans at its nominal square (the cube's at a face centre).
double texelAngle(const MapLayout& layout) {
    switch (layout.type) {
    case MapType::Cube:
        return 2.0 / layout.width;
    case MapType::DualParaboloid:
        return 4.0 / (layout.width - 2.0 * layout.guard);
    case MapType::TennisBall:
        return (kPi / 2.0) / (layout.width - 2.0 * layout.guard);
    case MapType::Octahedral: // √6 rad per unit of p at the faces' centres, p = 2·uv
        return 2.0 * std::sqrt(6.0) / (layout.width - 2.0 * layout.guard);
    }
    return 0.0;
}

struct SeamReport {
    double worstExcess = -1.0; // max over pairs of |ΔL| − |ΔR|
    const char* worstSeam = "";
    double worstError = 0.0; // max |L − R| at the seam points
    const char* worstErrorSeam = "";
    int straddling = 0; // pairs whose two directions use different components
};

// Looks up each pair (seam point ∓ offset·across) in `map` and in the reference.
SeamReport measure(const CpuMap& map, const CpuMap& reference, const std::vector<SeamPoint>& seams,
                   double offset, bool seamlessCube = true) {
    SeamReport r;
    for (const SeamPoint& s : seams) {
        const glm::dvec3 d1 = glm::normalize(s.point - offset * s.across);
        const glm::dvec3 d2 = glm::normalize(s.point + offset * s.across);
        const double lookupStep = maxAbs(map.lookup(d1, seamlessCube) - map.lookup(d2, seamlessCube));
        const double referenceStep = maxAbs(reference.lookup(d1) - reference.lookup(d2));
        if (lookupStep - referenceStep > r.worstExcess) {
            r.worstExcess = lookupStep - referenceStep;
            r.worstSeam = s.seam;
        }
        const double error = maxAbs(map.lookup(s.point, seamlessCube) - reference.lookup(s.point));
        if (error > r.worstError) {
            r.worstError = error;
            r.worstErrorSeam = s.seam;
        }
        // The pair crosses a seam of the texture: its two directions land in different components, or far
        // apart in one (on either side of an octahedral square's folded side, or of its corner).
        const MapCoord c1 = toMap(map.layout().type, d1), c2 = toMap(map.layout().type, d2);
        r.straddling +=
            c1.component != c2.component || glm::length(c1.uv - c2.uv) > 10.0 / map.layout().width;
    }
    return r;
}

class EnvMapSeams : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_reference = std::make_unique<CpuMap>(
            CpuMap::fill(makeLayout(MapType::Cube, kReferenceResolution), environment));
    }
    static void TearDownTestSuite() { s_reference.reset(); }

    // Tolerance: a tenth of what the environment changes over one texel. A real seam (an edge texel
    // clamped, a hemisphere left empty) jumps by about half a texel's change or far more; bilinear
    // filtering of the same smooth function from two components differs by O(texel²).
    static double tolerance(const MapLayout& layout) { return 0.1 * kMaxGradient * texelAngle(layout); }

    // `errorBound`: the largest error of the map's lookups at the seam points themselves.
    static void expectSeamless(const CpuMap& map, const std::vector<SeamPoint>& seams,
                               double errorBound = 0.01) {
        const double texel = texelAngle(map.layout());
        for (double fraction : {0.02, 0.3, 1.0}) {
            const SeamReport r = measure(map, *s_reference, seams, fraction * texel);
            EXPECT_LE(r.worstExcess, tolerance(map.layout()))
                << mapTypeName(map.layout().type) << " at " << r.worstSeam << ", offset " << fraction
                << " texel";
            EXPECT_GT(r.straddling, int(seams.size()) / 2) << "the pairs must cross the seams";
            // And continuous around the right value: bilinear error of this environment is ≤ 0.01 here.
            EXPECT_LT(r.worstError, errorBound)
                << mapTypeName(map.layout().type) << " at " << r.worstErrorSeam;
            std::printf(
                "%-16s offset %.2f texel: worst excess %.2e (tolerance %.2e) at %s, worst error %.2e at %s\n",
                std::string(mapTypeName(map.layout().type)).c_str(), fraction, r.worstExcess,
                tolerance(map.layout()), r.worstSeam, r.worstError, r.worstErrorSeam);
        }
    }

    static inline std::unique_ptr<CpuMap> s_reference;
};

TEST_F(EnvMapSeams, CubeIsContinuousAcrossEdgesAndCorners) {
    expectSeamless(CpuMap::fill(makeLayout(MapType::Cube, kResolution), environment), cubeSeams());
}

TEST_F(EnvMapSeams, DualParaboloidIsContinuousAcrossTheEquator) {
    expectSeamless(CpuMap::fill(makeLayout(MapType::DualParaboloid, kResolution), environment),
                   paraboloidSeams());
}

TEST_F(EnvMapSeams, TennisBallIsContinuousAcrossItsSeamCutsAndPoles) {
    const std::vector<SeamPoint> seams = tennisBallSeams();
    expectSeamless(CpuMap::fill(makeLayout(MapType::TennisBall, kResolution), environment), seams);
}

// At the resolution whose n² texels match the cube's 6n² at kResolution (n·√6): at kResolution itself its
// texels are √6 times wider. The mapping bends along the octahedron's edges, which run inside the texture
// and along its folded sides (the direction's z goes with |1 − u| across a side): bilinear filtering across
// a bend errs to first order in the texel, not the second order of a smooth map's, so the error at those
// points may reach about twice the smooth maps' 0.01 (measured: 0.013, at the sides). The seams themselves
// are judged as for every map, by the excess over the reference's change across them.
TEST_F(EnvMapSeams, OctahedralIsContinuousAcrossItsFoldsAndCorners) {
    const int n = int(std::lround(kResolution * std::sqrt(6.0)));
    expectSeamless(CpuMap::fill(makeLayout(MapType::Octahedral, n), environment), octahedralSeams(), 0.02);
}

TEST_F(EnvMapSeams, TheCheckCatchesRealSeams) {
    const double fraction = 0.02;
    // A cube filtered face by face (no GL_TEXTURE_CUBE_MAP_SEAMLESS).
    const CpuMap cube = CpuMap::fill(makeLayout(MapType::Cube, kResolution), environment);
    const SeamReport cubeReport =
        measure(cube, *s_reference, cubeSeams(), fraction * texelAngle(cube.layout()), false);
    EXPECT_GT(cubeReport.worstExcess, 3.0 * tolerance(cube.layout()));
    // Tennis-ball components without a guard band: the seam at |y| = √2/2 is the texture's edge.
    const CpuMap tennis = CpuMap::fill(makeLayout(MapType::TennisBall, kResolution, 0), environment);
    const SeamReport tennisReport =
        measure(tennis, *s_reference, tennisBallSeams(), fraction * texelAngle(tennis.layout()));
    EXPECT_GT(tennisReport.worstExcess, 3.0 * tolerance(tennis.layout()));
    // Paraboloids whose texels past the rim were never drawn.
    const CpuMap paraboloid =
        CpuMap::fill(makeLayout(MapType::DualParaboloid, kResolution, 0), environment, false);
    const SeamReport paraboloidReport =
        measure(paraboloid, *s_reference, paraboloidSeams(), fraction * texelAngle(paraboloid.layout()));
    EXPECT_GT(paraboloidReport.worstExcess, 3.0 * tolerance(paraboloid.layout()));
    // An octahedral map without its folded band: clamping at the square's sides.
    const CpuMap octahedral = CpuMap::fill(
        makeLayout(MapType::Octahedral, int(std::lround(kResolution * std::sqrt(6.0))), 0), environment);
    const SeamReport octahedralReport =
        measure(octahedral, *s_reference, octahedralSeams(), fraction * texelAngle(octahedral.layout()));
    EXPECT_GT(octahedralReport.worstExcess, 3.0 * tolerance(octahedral.layout()));
    std::printf(
        "counter-examples, worst excess: cube %.2e, tennis-ball %.2e, paraboloid %.2e, octahedral %.2e\n",
        cubeReport.worstExcess, tennisReport.worstExcess, paraboloidReport.worstExcess,
        octahedralReport.worstExcess);
}

} // namespace
} // namespace speculum::test
