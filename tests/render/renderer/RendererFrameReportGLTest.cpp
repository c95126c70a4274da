// What a frame reports about its own cost: the memory of the render targets it used, the GPU time of its
// passes, and, when asked not to reuse maps, a static scene rendering its shadow and environment maps on
// every frame.
#include "render/gl/GpuTimer.hpp"
#include "render/mesh/Primitives.hpp"
#include "support/GlTest.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// A floor, a box, a reflecting ball and a point light with shadows: every kind of map a frame can have.
FrameInput roomWithBall(int resolution) {
    FrameInput input;
    input.camera.position = {0.0, 1.5, 4.0};
    input.camera.target = {0.0, 0.5, 0.0};
    input.camera.far = 50.0;
    const auto plane = std::make_shared<const MeshData>(makePlane(1));
    const auto box = std::make_shared<const MeshData>(makeBox());
    input.items.push_back({"Floor", glm::scale(glm::dmat4(1.0), glm::dvec3(5.0)), plane, Material{}, true});
    input.items.push_back({"Box",
                           glm::translate(glm::dmat4(1.0), glm::dvec3(-1.5, 0.5, 0.0)) *
                               glm::scale(glm::dmat4(1.0), glm::dvec3(0.5)),
                           box, Material{}, true});
    Light light;
    light.name = "Lamp";
    light.position = {1.0, 3.0, 1.0};
    light.shadows = ShadowParams{};
    light.shadows->mapSize = 256;
    light.shadows->pcf = 3;
    input.lights.push_back(light);
    Reflector r;
    r.name = "Ball";
    r.mesh = std::make_shared<const MeshData>(makeSphere(32));
    r.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.8, 0.6, 0.0)) *
              glm::scale(glm::dmat4(1.0), glm::dvec3(0.6));
    r.map = ReflectorMap::Cube;
    r.resolution = resolution;
    input.reflectors = {r};
    return input;
}

FrameReport renderFrame(Renderer& renderer, const FrameInput& input, bool reuseMaps) {
    StillSettings settings{kWidth, kHeight, 1};
    settings.reuseMaps = reuseMaps;
    auto still = renderStill(renderer, input, settings);
    EXPECT_TRUE(still.ok()) << (still.ok() ? "" : still.error());
    return still.ok() ? still->firstSample : FrameReport{};
}

int countPasses(const FrameReport& report, PassKind kind) {
    return static_cast<int>(report.countRan(kind));
}

class FrameReportTest : public GlTest {};

TEST_F(FrameReportTest, StaticSceneRendersEveryMapAgainWhenAskedNotToReuse) {
    const FrameInput input = roomWithBall(64);
    renderFrame(renderer(), input, true);
    const FrameReport reused = renderFrame(renderer(), input, true);
    EXPECT_EQ(countPasses(reused, PassKind::Shadow), 0);
    EXPECT_EQ(countPasses(reused, PassKind::Envmap), 0);
    // A benchmark times what an animated scene pays: every map, every frame.
    for (int frame = 0; frame < 2; ++frame) {
        const FrameReport fresh = renderFrame(renderer(), input, false);
        EXPECT_EQ(countPasses(fresh, PassKind::Shadow), 1) << "frame " << frame;
        EXPECT_EQ(countPasses(fresh, PassKind::Envmap), 1) << "frame " << frame;
    }
}

TEST_F(FrameReportTest, MemoryCountsEachRenderTargetFromItsSizeAndFormat) {
    const FrameReport small = renderFrame(renderer(), roomWithBall(64), false);
    // The linear half-float colour buffer (8 bytes a pixel) and its depth-stencil buffer (4).
    EXPECT_EQ(small.memory.main, std::size_t(kWidth) * kHeight * 12);
    // A point light's cube of six 256² 24-bit depth faces (stored in 32 bits).
    EXPECT_EQ(small.memory.shadows, std::size_t(6) * 256 * 256 * 4);
    EXPECT_EQ(small.memory.mirrors, 0u) << "no texture-technique mirror";
    // Six half-float faces with their mip chains, and one face-sized depth buffer.
    std::size_t chain = 0;
    for (int n = 64; n >= 1; n /= 2)
        chain += std::size_t(n) * n;
    EXPECT_EQ(small.memory.envmap, 6 * chain * 8 + std::size_t(64) * 64 * 4);
    EXPECT_EQ(small.memory.total(),
              small.memory.main + small.memory.shadows + small.memory.envmap + small.memory.mirrors);

    // Twice the resolution, four times the map; nothing else changes.
    const FrameReport large = renderFrame(renderer(), roomWithBall(128), false);
    EXPECT_NEAR(double(large.memory.envmap) / double(small.memory.envmap), 4.0, 0.01);
    EXPECT_EQ(large.memory.main, small.memory.main);
    EXPECT_EQ(large.memory.shadows, small.memory.shadows);

    // A texture-technique mirror in view adds a mipmapped reflection texture of the frame's size.
    FrameInput withMirror = roomWithBall(64);
    Mirror mirror;
    mirror.name = "Mirror";
    mirror.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 1.0, -2.0)) *
                   glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1, 0, 0));
    mirror.size = {3.0, 2.0};
    mirror.technique = MirrorTechnique::Texture;
    withMirror.mirrors.push_back(mirror);
    const FrameReport mirrored = renderFrame(renderer(), withMirror, false);
    EXPECT_GE(mirrored.memory.mirrors, std::size_t(kWidth) * kHeight * 12);
}

// Each reflector's map counts; drawn at more than one bounce, each keeps its map of the bounce before in a
// second texture of the same size, which counts too. One reflector alone never bounces.
TEST_F(FrameReportTest, MemoryCountsEveryReflectorsMapsAndTheBounceBefore) {
    FrameInput one = roomWithBall(64);
    one.settings.reflectorBounces = 2;
    const std::size_t single = renderFrame(renderer(), one, false).memory.envmap;
    FrameInput two = roomWithBall(64);
    Reflector second = two.reflectors[0];
    second.name = "Second ball";
    second.world = glm::translate(glm::dmat4(1.0), glm::dvec3(-0.4, 0.6, 1.0)) *
                   glm::scale(glm::dmat4(1.0), glm::dvec3(0.4));
    two.reflectors.push_back(second);
    // A map's capture keeps one face-sized depth buffer beside its faces; a bounce's second map its own.
    const FrameReport plain = renderFrame(renderer(), two, false);
    EXPECT_EQ(plain.memory.envmap, 2 * single);
    two.settings.reflectorBounces = 1;
    const FrameReport bounced = renderFrame(renderer(), two, false);
    EXPECT_EQ(countPasses(bounced, PassKind::Envmap), 4);
    EXPECT_EQ(bounced.memory.envmap, 4 * single) << "each map and its bounce-before map";
    // Without bounces the second maps are freed again.
    two.settings.reflectorBounces = 0;
    EXPECT_EQ(renderFrame(renderer(), two, false).memory.envmap, 2 * single);
}

TEST_F(FrameReportTest, EveryPassThatRanHasAGpuTimeAndTheyAddUpToTheFrame) {
    FrameReport report;
    for (int frame = 0; frame < 2; ++frame) // the second frame reuses the timer's queries
        report = renderFrame(renderer(), roomWithBall(32), false);
    ASSERT_GE(report.ran.size(), 3u);
    double sum = 0.0;
    int previous = -1;
    for (const PassRun& run : report.ran) {
        // In the plan's order, each planned pass at most once.
        ASSERT_GT(run.pass, previous);
        ASSERT_LT(std::size_t(run.pass), report.plan.passes.size());
        previous = run.pass;
        EXPECT_GE(run.gpuMs, 0.0) << toString(report.planned(run).kind);
        EXPECT_GE(run.cpuMs, 0.0) << toString(report.planned(run).kind);
        sum += run.gpuMs;
    }
    EXPECT_NEAR(sum, report.gpuMs, 1e-6);
}

// Back-to-back passes share the timestamp between them; a pass after untimed work takes its own.
TEST_F(FrameReportTest, GpuTimerTakesOneTimestampPerPassBoundary) {
    gl::GpuTimer timer;
    for (int frame = 0; frame < 2; ++frame) {
        timer.begin(0);
        timer.end();
        timer.begin(1);
        timer.end();
        EXPECT_EQ(timer.queriesThisFrame(), 3u);
        timer.begin(3); // pass 2 skipped: nothing ran in between
        timer.end();
        EXPECT_EQ(timer.queriesThisFrame(), 4u);
        const std::vector<double> ms = timer.collect(4);
        ASSERT_EQ(ms.size(), 4u);
        EXPECT_GE(ms[0], 0.0);
        EXPECT_GE(ms[1], 0.0);
        EXPECT_EQ(ms[2], -1.0) << "a pass that did not run has no time";
        EXPECT_GE(ms[3], 0.0);
        EXPECT_EQ(timer.queriesThisFrame(), 0u);
    }
}

// Explaining a pixel reads back what each pass left there; a frame that is only drawn records nothing.
TEST_F(FrameReportTest, APixelIsProbedOnlyWhenAskedAndItsLastProbeIsTheStillsPixel) {
    const FrameInput input = roomWithBall(64);
    const FrameReport plain = renderFrame(renderer(), input, false);
    EXPECT_TRUE(plain.probes.empty());
    StillSettings settings{kWidth, kHeight, 1};
    settings.reuseMaps = false;
    const glm::ivec2 pixel(60, 30); // on the ball
    settings.probePixel = pixel;
    auto still = renderStill(renderer(), input, settings);
    ASSERT_TRUE(still.ok()) << still.error();
    const FrameReport& report = still->firstSample;
    ASSERT_EQ(report.probes.size(), report.ran.size()) << "one probe per pass that ran";
    // The maps' passes draw into maps of their own: nothing of the camera's size to read.
    for (const PixelProbe& probe : report.probes) {
        const PassKind kind = report.planned(report.ran[std::size_t(probe.run)]).kind;
        if (kind == PassKind::Shadow || kind == PassKind::Envmap) {
            EXPECT_FALSE(probe.readable);
        }
    }
    const PixelProbe& last = report.probes.back();
    ASSERT_TRUE(last.readable);
    const std::size_t p = (std::size_t(pixel.y) * kWidth + std::size_t(pixel.x)) * 4;
    for (int c = 0; c < 3; ++c)
        EXPECT_FLOAT_EQ(last.colour[c], still->image.rgba[p + std::size_t(c)]) << "channel " << c;
    // The pixels the still draws are the same with and without the probe.
    const auto unprobed = renderStill(renderer(), input, StillSettings{kWidth, kHeight, 1});
    ASSERT_TRUE(unprobed.ok());
    EXPECT_EQ(unprobed->image.rgba, still->image.rgba);
}

// A preview draws fewer pixels and scales them up in the composite: the frame's own buffers are read at the
// drawn pixel under the probed one, the output at the probed pixel itself.
TEST_F(FrameReportTest, APreviewIsProbedAtTheDrawnPixelAndTheOutputAtItsOwn) {
    StillSettings settings{kWidth, kHeight, 1};
    settings.reuseMaps = false;
    settings.preview.scale = 0.5;
    const glm::ivec2 pixel(61, 31);
    settings.probePixel = pixel;
    auto still = renderStill(renderer(), roomWithBall(64), settings);
    ASSERT_TRUE(still.ok()) << still.error();
    const FrameReport& report = still->firstSample;
    ASSERT_FALSE(report.probes.empty());
    const PixelProbe& last = report.probes.back();
    ASSERT_EQ(report.planned(report.ran[std::size_t(last.run)]).kind, PassKind::Composite);
    ASSERT_TRUE(last.readable);
    const std::size_t p = (std::size_t(pixel.y) * kWidth + std::size_t(pixel.x)) * 4;
    for (int c = 0; c < 3; ++c)
        EXPECT_FLOAT_EQ(last.colour[c], still->image.rgba[p + std::size_t(c)]) << "channel " << c;
}

} // namespace
} // namespace speculum::test
