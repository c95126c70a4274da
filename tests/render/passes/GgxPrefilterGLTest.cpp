// The rough reflector end to end: the GGX pre-filtered chain (Footprint) and the mip-chain fallback (Mip)
// for every map layout. Roughness 0 draws the sharp image, bit for bit, with no Prefilter pass; a uniform
// environment stays uniform at any roughness but for the lobe's albedo (the filter conserves a constant,
// across the seams too);
// more samples a texel come closer to a many-sample reference; nothing is NaN or infinite.
#include "render/math/GgxAlbedoTable.hpp"
#include "render/mesh/Primitives.hpp"
#include "support/GlTest.hpp"

#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kSize = 96;
const ReflectorMap kMaps[] = {ReflectorMap::Cube, ReflectorMap::DualParaboloid, ReflectorMap::TennisBall,
                              ReflectorMap::Octahedral};

Material emissive(glm::dvec3 color) {
    Material m;
    m.color = {0.0, 0.0, 0.0};
    m.ambient = 0.0;
    m.diffuse = 0.0;
    m.emission = color;
    return m;
}

// A mirror ball filling most of the view; with `walls`, in a room of six emissive walls of different
// colours (sharp edges for the lobe to blur), else in the background colour alone.
FrameInput ball(ReflectorMap map, double roughness, GlossyFilter filter, bool walls) {
    FrameInput input;
    input.settings.background = {0.3, 0.5, 0.7};
    input.settings.ambient = 0.0;
    input.settings.glossyFilter = filter;
    input.camera.position = {0.0, 0.0, 3.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.fovY = 45.0;
    input.camera.far = 100.0;
    static const auto plane = std::make_shared<const MeshData>(makePlane(1));
    const glm::dvec3 colors[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};
    for (int wall = 0; walls && wall < 6; ++wall) {
        const int axis = wall / 2;
        glm::dvec3 n(0.0);
        n[axis] = wall % 2 == 0 ? 1.0 : -1.0;
        glm::dmat4 turn(1.0);
        if (axis == 0)
            turn = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0, 0, 1));
        else if (axis == 2)
            turn = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1, 0, 0));
        const glm::dmat4 world =
            glm::translate(glm::dmat4(1.0), n * 10.0) * turn * glm::scale(glm::dmat4(1.0), glm::dvec3(10.0));
        input.items.push_back({"Wall " + std::to_string(wall), world, plane, emissive(colors[wall]), false});
    }
    static const auto sphere = std::make_shared<const MeshData>(makeSphere(64));
    Reflector r;
    r.name = "Ball";
    r.mesh = sphere;
    r.material = emissive({0.0, 0.0, 0.0});
    r.map = map;
    r.resolution = 64;
    r.roughness = roughness;
    input.reflectors = {r};
    return input;
}

// Mean absolute difference over the pixels and channels.
double meanDifference(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        sum += std::abs(double(a.rgba[i]) - double(b.rgba[i]));
    return a.rgba.empty() ? 0.0 : sum / double(a.rgba.size());
}

class Prefilter : public GlTest {};

TEST_F(Prefilter, RoughnessZeroIsTheSharpImageWithoutAPrefilterPass) {
    for (ReflectorMap map : kMaps) {
        SCOPED_TRACE(std::string(names::fileName(names::kReflectorMaps, map)));
        const Image footprint = renderImage(ball(map, 0.0, GlossyFilter::Footprint, true), kSize, kSize);
        EXPECT_EQ(lastReport().countRan(PassKind::Prefilter), 0u);
        for (const PlannedPass& p : lastReport().plan.passes)
            EXPECT_NE(p.kind, PassKind::Prefilter);
        const Image mip = renderImage(ball(map, 0.0, GlossyFilter::Mip, true), kSize, kSize);
        EXPECT_EQ(lastReport().countRan(PassKind::Prefilter), 0u);
        EXPECT_EQ(footprint.rgba, mip.rgba) << "roughness 0 reads the map the same way in both filters";
        // A chain left from a rough frame changes nothing at roughness 0.
        const Image rough = renderImage(ball(map, 0.5, GlossyFilter::Footprint, true), kSize, kSize);
        EXPECT_EQ(lastReport().countRan(PassKind::Prefilter), 1u);
        EXPECT_GT(meanDifference(rough, footprint), 1e-3) << "roughness 0.5 blurs the walls' edges";
        const Image again = renderImage(ball(map, 0.0, GlossyFilter::Footprint, true), kSize, kSize);
        EXPECT_EQ(again.rgba, footprint.rgba);
    }
}

TEST_F(Prefilter, UniformEnvironmentStaysUniform) {
    const glm::dvec3 background =
        ball(ReflectorMap::Cube, 0.0, GlossyFilter::Footprint, false).settings.background;
    for (ReflectorMap map : kMaps)
        for (GlossyFilter filter : {GlossyFilter::Footprint, GlossyFilter::Mip})
            for (double roughness : {0.5, 1.0}) {
                SCOPED_TRACE(std::string(names::fileName(names::kReflectorMaps, map)) +
                             (filter == GlossyFilter::Mip ? " mip" : " footprint") + " roughness " +
                             std::to_string(roughness));
                const Image image = renderImage(ball(map, roughness, filter, false), kSize, kSize);
                // Stills keep the map while nothing it sees changes: the chain filtered at roughness 0.5
                // holds every level, and roughness 1 reuses it.
                const bool filters = filter == GlossyFilter::Footprint && roughness == 0.5;
                EXPECT_EQ(lastReport().countRan(PassKind::Prefilter), filters ? 1u : 0u);
                if (filter == GlossyFilter::Footprint && !filters) {
                    bool reused = false;
                    for (const SkippedEffect& skip : lastReport().skipped)
                        reused |= skip.code == PlanReason::PrefilterReused;
                    EXPECT_TRUE(reused);
                }
                ASSERT_EQ(image.rgba.size(), std::size_t(kSize) * kSize * 4);
                // Each pixel is the background's colour scaled by the lobe's albedo at its view angle
                // (masking and shadowing take the same share of every channel), never more than 1.
                double worst = 0.0, darkest = 1.0;
                for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
                    const double scale = double(image.rgba[i + 2]) / background.b;
                    darkest = std::min(darkest, scale);
                    for (int c = 0; c < 3; ++c)
                        worst = std::max(
                            worst, std::abs(double(image.rgba[i + std::size_t(c)]) - scale * background[c]));
                    EXPECT_LE(scale, 1.0 + 2e-3);
                }
                // Half-float storage of the map and the chain: about 1e-3 relative.
                EXPECT_LT(worst, 2e-3);
                EXPECT_GT(darkest, 0.2) << "no pixel far below the lobe's albedo";
                // The centre faces the camera: the albedo at normal incidence.
                const glm::vec4 centre = image.at(kSize / 2, kSize / 2);
                EXPECT_NEAR(centre.b / background.b, math::ggxAlbedoTable().at(1.0, roughness), 3e-3);
            }
}

TEST_F(Prefilter, MoreSamplesComeCloserToTheReference) {
    for (ReflectorMap map : kMaps) {
        SCOPED_TRACE(std::string(names::fileName(names::kReflectorMaps, map)));
        auto render = [&](int samples) {
            FrameInput input = ball(map, 0.3, GlossyFilter::Footprint, true);
            input.settings.prefilterSamples = samples;
            return renderImage(input, kSize, kSize);
        };
        const Image reference = render(1024);
        double previous = 1e30;
        for (int samples : {8, 32, 128}) {
            const double error = meanDifference(render(samples), reference);
            EXPECT_EQ(lastReport().countRan(PassKind::Envmap), 0u) << "a new sample count only filters again";
            EXPECT_EQ(lastReport().countRan(PassKind::Prefilter), 1u);
            EXPECT_LT(error, previous) << samples << " samples";
            previous = error;
        }
        EXPECT_LT(previous, 0.01);
    }
}

TEST_F(Prefilter, RoughnessOneIsFiniteEverywhere) {
    for (ReflectorMap map : kMaps)
        for (GlossyFilter filter : {GlossyFilter::Footprint, GlossyFilter::Mip}) {
            SCOPED_TRACE(std::string(names::fileName(names::kReflectorMaps, map)));
            // Close up: the ball covers the view, and its reflection vectors cross every seam of the map.
            FrameInput input = ball(map, 1.0, filter, true);
            input.camera.position = {0.3, 0.4, 1.6};
            const Image image = renderImage(input, kSize, kSize);
            ASSERT_FALSE(image.rgba.empty());
            std::size_t bad = 0;
            for (float v : image.rgba)
                bad += std::isfinite(v) ? 0 : 1;
            EXPECT_EQ(bad, 0u);
        }
}

} // namespace
} // namespace speculum::test
