// Two mirrored balls facing each other against the exact tracer, which follows reflections between them:
// with reflectorBounces 0 each map shows the other ball with its plain (black) material; each bounce draws
// the maps again with the other's map of the bounce before, and the error on the balls' pixels falls. A
// reflector is never drawn into its own map, and hard placements (touching, one inside the other, tiny,
// far from the origin) draw no NaN.
#include "TiledRoom.hpp"
#include "render/frame/SceneNames.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/reference/Tracer.hpp"
#include "support/GlTest.hpp"

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kSize = 160;
constexpr int kSsaa = 2;
constexpr double kHalf = 8.0;

Reflector mirrorBall(const std::string& name, glm::dvec3 centre, double radius, glm::dvec3 colour = {}) {
    static const auto sphere = std::make_shared<const MeshData>(makeSphere(96));
    Reflector r;
    r.name = name;
    r.mesh = sphere;
    r.world = glm::scale(glm::translate(glm::dmat4(1.0), centre), glm::dvec3(radius));
    r.material = flatColour(colour);
    r.reflectivity = 1.0;
    r.resolution = 128;
    // The room is each ball's parallax proxy: the room's part of every reflection is then exact up to
    // the map's texels, and what is left is the other ball.
    r.parallax = ParallaxParams{.shape = ParallaxShape::Box};
    r.parallax->min = glm::dvec3(-kHalf) - centre;
    r.parallax->max = glm::dvec3(kHalf) - centre;
    return r;
}

// Two balls side by side in the tiled room, seen from the front: each shows the other on its inner side.
FrameInput facingBalls() {
    FrameInput input = tiledRoom(kHalf);
    input.camera.position = {0.0, 0.5, 3.4};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.fovY = 50.0;
    input.reflectors = {mirrorBall("Left", {-0.95, 0.0, 0.0}, 0.8),
                        mirrorBall("Right", {0.95, 0.0, 0.0}, 0.8)};
    return input;
}

double luminance(const Image& image, int x, int y) {
    const glm::vec4 c = image.at(x, y);
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

class ReflectorBounces : public GlTest {
protected:
    void trace(const FrameInput& input) {
        auto traced = traceExact(input, kSize, kSsaa);
        ASSERT_TRUE(traced);
        m_exact = std::move(traced->image);
        m_ids = std::move(traced->ids);
        m_mask = reference::reflectorMask(m_ids);
    }

    double reflectorPsnr(const Image& image) {
        auto stats = metrics::compare(image, m_exact, &m_mask);
        EXPECT_TRUE(stats.ok()) << (stats.ok() ? "" : stats.error());
        return stats.ok() ? stats->psnr : 0.0;
    }

    Image m_exact;
    reference::IdBuffer m_ids;
    std::vector<std::uint8_t> m_mask;
};

TEST_F(ReflectorBounces, EachBounceLowersTheErrorOnFacingBalls) {
    FrameInput input = facingBalls();
    trace(input);
    std::vector<double> psnr;
    std::vector<Image> images;
    for (int bounces : {0, 1, 2}) {
        input.settings.reflectorBounces = bounces;
        images.push_back(renderImage(input, kSize, kSize, kSsaa));
        psnr.push_back(reflectorPsnr(images.back()));
    }
    std::printf("[ measured ] facing balls, PSNR on their pixels at bounces 0, 1, 2: %.2f %.2f %.2f dB\n",
                psnr[0], psnr[1], psnr[2]);
    EXPECT_GT(psnr[1], psnr[0] + 1.0) << "the first bounce shows the other ball's reflection";
    EXPECT_GT(psnr[2], psnr[1]) << "the second shows the first ball inside that";

    // Where the left ball shows the right one, bounce 0 draws its plain black material; from bounce 1 on,
    // what the exact image shows there: the right ball's own reflection of the room.
    int otherBall = 0, shownAtBounce1 = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const reference::PixelId id = m_ids.at(x, y);
            if (id.kind != reference::HitKind::Reflector || id.index != 0)
                continue;
            if (luminance(images[0], x, y) < 0.01 && luminance(m_exact, x, y) > 0.05) {
                ++otherBall;
                shownAtBounce1 += luminance(images[1], x, y) > 0.05 ? 1 : 0;
            }
        }
    EXPECT_GT(otherBall, kSize * kSize / 200) << "the right ball covers part of the left one's reflection";
    EXPECT_GT(shownAtBounce1, otherBall * 9 / 10) << shownAtBounce1 << " of " << otherBall;
}

// Every map type and fill draws the other ball with its map from the first bounce on: the direct fill's
// warp as well as the cube faces.
TEST_F(ReflectorBounces, EveryMapTypeShowsTheOtherBallFromTheFirstBounce) {
    FrameInput input = facingBalls();
    trace(input);
    const std::pair<ReflectorMap, ReflectorFill> methods[] = {
        {ReflectorMap::DualParaboloid, ReflectorFill::Direct},
        {ReflectorMap::TennisBall, ReflectorFill::Direct},
        {ReflectorMap::Octahedral, ReflectorFill::Resampled}};
    for (const auto& [map, fill] : methods) {
        for (Reflector& r : input.reflectors) {
            r.map = map;
            r.fill = fill;
        }
        std::vector<double> psnr;
        for (int bounces : {0, 1}) {
            input.settings.reflectorBounces = bounces;
            psnr.push_back(reflectorPsnr(renderImage(input, kSize, kSize, kSsaa)));
        }
        const std::string name = std::string(names::fileName(names::kReflectorMaps, map)) + " " +
                                 std::string(names::fileName(names::kReflectorFills, fill));
        std::printf("[ measured ] facing balls, %s: PSNR at bounces 0, 1: %.2f %.2f dB\n", name.c_str(),
                    psnr[0], psnr[1]);
        EXPECT_GT(psnr[1], psnr[0] + 1.0) << name;
    }
}

TEST_F(ReflectorBounces, AReflectorIsNeverInItsOwnMap) {
    // White balls in a black room: each reflects the other (white at bounce 0, its black room beyond),
    // never its own white surface, so the pixels of a lone ball stay black at every bounce.
    FrameInput input = tiledRoom(kHalf);
    for (DrawItem& tile : input.items)
        tile.material = flatColour(glm::dvec3(0.0));
    input.camera.position = {0.0, 0.5, 3.4};
    input.camera.target = {0.0, 0.0, 0.0};
    input.reflectors = {mirrorBall("Lone", {0.0, 0.0, 0.0}, 0.8, glm::dvec3(1.0))};
    input.reflectors[0].reflectivity = 0.5; // half its own white, half what it reflects
    input.settings.reflectorBounces = 2;
    const Image lone = renderImage(input, kSize, kSize);
    double brightest = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            brightest = std::max(brightest, luminance(lone, x, y));
    EXPECT_LT(brightest, 0.6) << "its surface's half and nothing of itself in its reflection";
    EXPECT_GT(brightest, 0.4);
}

TEST_F(ReflectorBounces, HardPlacementsDrawNoNan) {
    struct Case {
        const char* name;
        glm::dvec3 a, b;
        double ra, rb;
    };
    const Case cases[] = {{"touching", {-0.5, 0, 0}, {0.5, 0, 0}, 0.5, 0.5},
                          {"intersecting", {-0.2, 0, 0}, {0.2, 0, 0}, 0.5, 0.5},
                          {"one inside the other", {0, 0, 0}, {0.1, 0, 0}, 0.8, 0.2},
                          {"tiny", {0, 0, 0}, {3e-4, 0, 0}, 1e-4, 1e-4},
                          {"far from the origin", {1e5, 0, 0}, {1e5 + 1.5, 0, 0}, 0.5, 0.5}};
    for (const Case& c : cases) {
        FrameInput input = tiledRoom(kHalf);
        input.reflectors = {mirrorBall("A", c.a, c.ra), mirrorBall("B", c.b, c.rb)};
        input.reflectors[0].parallax.reset();
        input.reflectors[1].parallax.reset();
        input.reflectors[1].map = ReflectorMap::DualParaboloid;
        input.settings.reflectorBounces = kMaxReflectorBounces;
        const glm::dvec3 middle = (c.a + c.b) * 0.5;
        input.camera.position = middle + glm::dvec3(0.0, 0.0, 4.0 * std::max(c.ra, c.rb) + 1e-3);
        input.camera.target = middle;
        input.camera.near = 1e-3 * std::max(c.ra, c.rb);
        input.camera.far = 1e6;
        const Image image = renderImage(input, 64, 64);
        int bad = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const glm::vec4 p = image.at(x, y);
                bad += std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) ? 0 : 1;
            }
        EXPECT_EQ(bad, 0) << c.name;
    }
}

} // namespace
} // namespace speculum::test
