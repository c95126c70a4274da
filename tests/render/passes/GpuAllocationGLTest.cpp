// GPU allocations that do not fit: a shadow map, environment map or render target the driver cannot
// allocate (GL_OUT_OF_MEMORY, an incomplete framebuffer) is drawn at the largest size that works, halving
// from the size asked for, with a warning naming the light or reflector and both sizes, and the plan
// (what `speculum explain` prints) says the size used. Real 8192² maps on this machine's driver, and a
// test limit (gl::setAllocationLimitForTesting) that makes any GPU refuse large allocations.
#include "render/gl/Allocation.hpp"
#include "render/gl/Objects.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/passes/EnvironmentCapture.hpp"
#include "support/GlTest.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

// Sets the test allocation limit for one scope and always clears it again.
struct AllocationLimit {
    explicit AllocationLimit(std::size_t bytes) { gl::setAllocationLimitForTesting(bytes); }
    ~AllocationLimit() { gl::setAllocationLimitForTesting(0); }
    AllocationLimit(const AllocationLimit&) = delete;
    AllocationLimit& operator=(const AllocationLimit&) = delete;
};

// A floor, a box casting a shadow on it, a point light "Lamp" above with a cube shadow map; optionally a
// reflector ball. Small, so that drawing even large maps stays quick.
FrameInput scene(int shadowMapSize, bool withReflector = false) {
    FrameInput input;
    input.settings.background = {0.2, 0.25, 0.3};
    input.camera.position = {0.0, 3.0, 5.0};
    input.camera.target = {0.0, 0.3, 0.0};
    input.camera.far = 30.0;
    DrawItem floor;
    floor.name = "Floor";
    floor.mesh = std::make_shared<const MeshData>(makePlane(1));
    floor.world = glm::scale(glm::dmat4(1.0), glm::dvec3(4.0, 1.0, 4.0));
    floor.material.color = {0.8, 0.8, 0.8};
    input.items.push_back(floor);
    DrawItem box;
    box.name = "Box";
    box.mesh = std::make_shared<const MeshData>(makeBox());
    box.world = glm::translate(glm::dmat4(1.0), glm::dvec3(-0.8, 0.5, 0.0)) *
                glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
    box.material.color = {0.8, 0.2, 0.1};
    input.items.push_back(box);
    Light lamp;
    lamp.name = "Lamp";
    lamp.type = LightType::Point;
    lamp.position = {0.5, 3.0, 0.5};
    lamp.intensity = 1.0;
    lamp.shadows = render::ShadowParams{shadowMapSize, 1};
    input.lights.push_back(lamp);
    if (withReflector) {
        Reflector ball;
        ball.name = "Ball";
        ball.mesh = std::make_shared<const MeshData>(makeSphere(24));
        ball.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.9, 0.6, 0.3)) *
                     glm::scale(glm::dmat4(1.0), glm::dvec3(0.6));
        ball.resolution = 64;
        input.reflectors = {ball};
    }
    return input;
}

bool mentions(const std::vector<std::string>& warnings, const std::string& what) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&](const std::string& w) { return w.find(what) != std::string::npos; });
}

// The first pass of this kind that ran: the plan keeps the passes execution dropped (a map or a texture
// that could not be allocated), the report's `ran` does not.
const PlannedPass* findPass(const FrameReport& report, PassKind kind) {
    for (const PassRun& run : report.ran)
        if (report.planned(run).kind == kind)
            return &report.planned(run);
    return nullptr;
}

double meanLuminance(const Image& image) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
        sum += 0.2126 * image.rgba[i] + 0.7152 * image.rgba[i + 1] + 0.0722 * image.rgba[i + 2];
    return sum / double(std::max<std::size_t>(1, image.rgba.size() / 4));
}

// Fraction of pixels whose colour differs by more than `tolerance` in any channel.
double differingFraction(const Image& a, const Image& b, float tolerance = 0.05f) {
    EXPECT_EQ(a.rgba.size(), b.rgba.size());
    std::size_t differ = 0, pixels = std::min(a.rgba.size(), b.rgba.size()) / 4;
    for (std::size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < 3; ++c)
            if (std::abs(a.rgba[p * 4 + c] - b.rgba[p * 4 + c]) > tolerance) {
                ++differ;
                break;
            }
    return pixels ? double(differ) / double(pixels) : 1.0;
}

// The size a warning says was used ("...; using 4096²" or "...; using 4096"), or -1.
int usedSize(const std::string& warning) {
    const auto at = warning.rfind("; using ");
    return at == std::string::npos ? -1 : std::atoi(warning.c_str() + at + 8);
}

// The case: on llvmpipe an 8192² cube of depth (1.5 GiB) is refused with GL_OUT_OF_MEMORY, and the
// scene came out entirely unlit while the plan claimed the map.
TEST_F(GlTest, PointLightShadowMapThatDoesNotFitIsDrawnSmallerAndTheSceneStaysLit) {
    const Image reference = renderImage(scene(1024), 96, 54);
    EXPECT_TRUE(lastReport().warnings.empty()) << ::testing::PrintToString(lastReport().warnings);
    const Image unlit = [&] {
        FrameInput dark = scene(1024);
        dark.lights.clear();
        return renderImage(dark, 96, 54);
    }();

    const auto start = std::chrono::steady_clock::now();
    const Image huge = renderImage(scene(8192), 96, 54);
    const double firstMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const FrameReport report = lastReport();
    const PlannedPass* shadow = findPass(report, PassKind::Shadow);
    ASSERT_NE(shadow, nullptr);
    int used = 8192;
    if (!report.warnings.empty()) {
        ASSERT_EQ(report.warnings.size(), 1u) << ::testing::PrintToString(report.warnings);
        const std::string& w = report.warnings[0];
        EXPECT_NE(w.find("light 'Lamp'"), std::string::npos) << w;
        EXPECT_NE(w.find("8192²"), std::string::npos) << w;
        used = usedSize(w);
        EXPECT_GE(used, 16) << w;
        EXPECT_LT(used, 8192) << w;
    }
    // The plan (explain) names the size drawn, not the one asked for.
    EXPECT_EQ(shadow->details.mapSize, used) << shadow->reason();
    std::printf("8192² point-light shadow map: drawn at %d² (first frame %.0f ms)\n", used, firstMs);

    // Lit, and shadowed like the 1024² map: only shadow edges may differ.
    const double lit = meanLuminance(reference), dark = meanLuminance(unlit);
    ASSERT_GT(lit, dark + 0.05);
    EXPECT_NEAR(meanLuminance(huge), lit, 0.1 * (lit - dark));
    EXPECT_LT(differingFraction(huge, reference), 0.03);

    // The failing size is remembered: the next frame goes straight to the size that worked and draws
    // the same image, with the same warning.
    const Image again = renderImage(scene(8192), 96, 54);
    EXPECT_EQ(lastReport().warnings, report.warnings);
    EXPECT_TRUE(std::equal(again.rgba.begin(), again.rgba.end(), huge.rgba.begin()));
}

// Any GPU: with a limit of 16 MiB per object, an 8192² cube (1.5 GiB) halves until a map fits: 1024² is
// 24 MiB, 512² is 6 MiB.
TEST_F(GlTest, ShadowMapFallsBackByHalvingToTheLargestSizeThatFits) {
    AllocationLimit limit(16u << 20);
    const Image fallback = renderImage(scene(8192), 96, 54);
    ASSERT_EQ(lastReport().warnings.size(), 1u) << ::testing::PrintToString(lastReport().warnings);
    EXPECT_EQ(lastReport().warnings[0], "light 'Lamp': the 8192² cube shadow map did not fit in GPU memory "
                                        "(over the test limit of 16777216 bytes); using 512²");
    const PlannedPass* shadow = findPass(lastReport(), PassKind::Shadow);
    ASSERT_NE(shadow, nullptr);
    EXPECT_EQ(shadow->details.mapSize, 512) << shadow->reason();
    EXPECT_EQ(lastReport().memory.shadows, 6u * 512 * 512 * 4);
    // The very image a 512² map asked for draws.
    const Image direct = renderImage(scene(512), 96, 54);
    EXPECT_TRUE(lastReport().warnings.empty()) << ::testing::PrintToString(lastReport().warnings);
    EXPECT_TRUE(std::equal(fallback.rgba.begin(), fallback.rgba.end(), direct.rgba.begin()));
}

// Not even the smallest map fits: the light lights without shadows, and says so.
TEST_F(GlTest, LightWhoseSmallestShadowMapDoesNotFitLightsWithoutShadows) {
    FrameInput input = scene(1024);
    input.lights[0].shadows.reset();
    const Image unshadowed = renderImage(input, 32, 18); // the meshes and the colour buffer, under no limit
    AllocationLimit limit(1000);                         // a 16² cube takes 6 KiB
    input.lights[0].shadows = ShadowParams{};
    const Image image = renderImage(input, 32, 18);
    ASSERT_EQ(lastReport().warnings.size(), 1u) << ::testing::PrintToString(lastReport().warnings);
    EXPECT_NE(
        lastReport().warnings[0].find("light 'Lamp': the 1024² cube shadow map did not fit in GPU memory"),
        std::string::npos)
        << lastReport().warnings[0];
    EXPECT_NE(lastReport().warnings[0].find("the light casts no shadows"), std::string::npos)
        << lastReport().warnings[0];
    EXPECT_EQ(findPass(lastReport(), PassKind::Shadow), nullptr);
    EXPECT_TRUE(std::equal(image.rgba.begin(), image.rgba.end(), unshadowed.rgba.begin()));
}

// The driver's own answer for 8192 maps, which are 3 GiB (cube) and 1 + 3 GiB (dual paraboloid and its
// intermediate cube) of half floats: either they work, or the failure is caught and named, never an
// unchecked map (on llvmpipe both are refused: GL_OUT_OF_MEMORY for the cubes).
TEST_F(GlTest, EnvironmentMapsTheDriverRefusesAreCaughtAndNamed) {
    for (envmap::MapType type : {envmap::MapType::Cube, envmap::MapType::DualParaboloid}) {
        bool sizeFailure = false;
        const auto start = std::chrono::steady_clock::now();
        auto capture =
            envmap::EnvironmentCapture::create({type, 8192, envmap::FillMethod::Resampled}, &sizeFailure);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (capture) {
            EXPECT_FALSE(sizeFailure);
            EXPECT_GT(capture->bytes(), std::size_t(3) << 30);
            std::printf("8192 map type %d: allocated (%.0f ms)\n", int(type), ms);
        } else {
            EXPECT_TRUE(sizeFailure) << capture.error();
            EXPECT_TRUE(capture.error().find("did not fit in GPU memory") != std::string::npos ||
                        capture.error().find("framebuffer incomplete") != std::string::npos)
                << capture.error();
            std::printf("8192 map type %d: %s (%.0f ms)\n", int(type), capture.error().c_str(), ms);
        }
    }
}

#ifdef SPECULUM_SLOW_ALLOCATION_TESTS
// The map's layouts at 8192: cube (3 GiB of half floats) and dual-paraboloid with its 8192² intermediate
// cube are refused on llvmpipe and drawn at 4096; the reflector is never dropped. Filling a 4096 map takes
// llvmpipe seconds (gigabytes of half floats and mip chains), so this runs with the slow tests.
TEST_F(GlTest, ReflectorWhoseMapDoesNotFitIsDrawnSmallerNotDropped) {
    struct Case {
        ReflectorMap map;
        ReflectorFill fill;
    };
    for (const Case& c : {Case{ReflectorMap::Cube, ReflectorFill::Resampled},
                          Case{ReflectorMap::DualParaboloid, ReflectorFill::Resampled}}) {
        SCOPED_TRACE(std::string(names::fileName(names::kReflectorMaps, c.map)));
        FrameInput input = scene(256, true);
        input.items.clear(); // the map shows the background only: cheap to fill even at 4096
        input.lights[0].shadows.reset();
        input.reflectors[0].map = c.map;
        input.reflectors[0].fill = c.fill;
        input.reflectors[0].resolution = 8192;
        const auto start = std::chrono::steady_clock::now();
        renderImage(input, 64, 36);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const FrameReport& report = lastReport();
        const PlannedPass* envmap = findPass(report, PassKind::Envmap);
        ASSERT_NE(envmap, nullptr) << "the reflector was dropped";
        EXPECT_GT(report.memory.envmap, 0u);
        int used = 8192;
        for (const std::string& w : report.warnings) {
            EXPECT_NE(w.find("reflector 'Ball': the 8192 "), std::string::npos) << w;
            used = usedSize(w);
        }
        EXPECT_LE(report.warnings.size(), 1u) << ::testing::PrintToString(report.warnings);
        EXPECT_EQ(envmap->details.resolution, used) << envmap->reason();
        std::printf("8192 %s reflector: drawn at %d (%.0f ms)\n",
                    std::string(names::fileName(names::kReflectorMaps, c.map)).c_str(), used, ms);
    }
}

#endif

// Any GPU, every layout and fill: with 4 MiB per object, each map halves until it fits and renders, the
// same image as asking for that size.
TEST_F(GlTest, ReflectorMapOfEveryLayoutFallsBackUnderAnAllocationLimit) {
    AllocationLimit limit(4u << 20);
    struct Case {
        ReflectorMap map;
        ReflectorFill fill;
        int resolution; // tennis balls are n × 3n: 8192 is over llvmpipe's 16384 texels already
    };
    for (const Case& c : {Case{ReflectorMap::Cube, ReflectorFill::Resampled, 8192},
                          Case{ReflectorMap::DualParaboloid, ReflectorFill::Resampled, 8192},
                          Case{ReflectorMap::DualParaboloid, ReflectorFill::Direct, 8192},
                          Case{ReflectorMap::TennisBall, ReflectorFill::Direct, 4096},
                          Case{ReflectorMap::TennisBall, ReflectorFill::Resampled, 4096},
                          Case{ReflectorMap::Octahedral, ReflectorFill::Resampled, 8192}}) {
        SCOPED_TRACE(std::string(names::fileName(names::kReflectorMaps, c.map)) +
                     (c.fill == ReflectorFill::Direct ? " direct" : ""));
        FrameInput input = scene(256, true);
        input.reflectors[0].map = c.map;
        input.reflectors[0].fill = c.fill;
        input.reflectors[0].resolution = c.resolution;
        const Image image = renderImage(input, 64, 36);
        const FrameReport report = lastReport();
        ASSERT_EQ(report.warnings.size(), 1u) << ::testing::PrintToString(report.warnings);
        const std::string& w = report.warnings[0];
        EXPECT_EQ(w.rfind("reflector 'Ball': the " + std::to_string(c.resolution) + " " +
                              std::string(names::fileName(names::kReflectorMaps, c.map)) +
                              " environment map did not fit in GPU memory",
                          0),
                  0u)
            << w;
        const int used = usedSize(w);
        EXPECT_GE(used, 8) << w;
        EXPECT_LT(used, c.resolution) << w;
        EXPECT_EQ(c.resolution % used, 0) << "not found by halving: " << w;
        EXPECT_LE(report.memory.envmap, 3u * (4u << 20))
            << "a map, its depth and a cube, each within the limit";
        const PlannedPass* envmap = findPass(report, PassKind::Envmap);
        ASSERT_NE(envmap, nullptr) << "the reflector was dropped";
        EXPECT_EQ(envmap->details.resolution, used) << envmap->reason();
        EXPECT_GT(report.memory.envmap, 0u);
        // The same as asking for the size used: the reflector is drawn with its map.
        input.reflectors[0].resolution = used;
        const Image direct = renderImage(input, 64, 36);
        EXPECT_TRUE(lastReport().warnings.empty()) << ::testing::PrintToString(lastReport().warnings);
        EXPECT_TRUE(std::equal(image.rgba.begin(), image.rgba.end(), direct.rgba.begin()));
    }
}

// One frame on a float target of its own, its report.
FrameReport drawFrame(Renderer& renderer, const FrameInput& input, int width, int height) {
    gl::FramebufferBinding keep;
    gl::Texture color = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, color.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    gl::Framebuffer framebuffer = gl::makeFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
    return renderer.render(input, {framebuffer.id(), width, height, false});
}

// Any GPU: each frame is planned once. A planned size that fails now (one never tried) is not planned
// again within the frame: the frame goes without that map, says so (a warning, a skip, drawAgain) and keeps
// the plan it was drawn with; the next frame is planned with the size found to work, the warning among the
// plan's own. A still draws such a frame again (renderImage, above), so it is never without the map.
TEST_F(GlTest, AMapThatFailsAtItsPlannedSizeIsLeftOutOfThatFrameAndPlannedSmallerInTheNext) {
    AllocationLimit limit(16u << 20);
    const FrameInput input = scene(8192);
    const std::vector<std::string> fellBack{
        "light 'Lamp': the 8192² cube shadow map did not fit in GPU memory "
        "(over the test limit of 16777216 bytes); using 512²"};
    const FrameReport first = drawFrame(renderer(), input, 64, 36);
    ASSERT_EQ(first.plan.shadows.size(), 1u);
    EXPECT_EQ(first.plan.shadows[0].mapSize, 8192) << "the plan the frame was drawn with, made once";
    EXPECT_TRUE(first.plan.warnings.empty()) << "nothing had failed when it was planned";
    EXPECT_EQ(first.warnings, fellBack);
    EXPECT_TRUE(first.drawAgain);
    EXPECT_EQ(findPass(first, PassKind::Shadow), nullptr);
    EXPECT_TRUE(std::any_of(first.skipped.begin(), first.skipped.end(), [](const SkippedEffect& e) {
        return e.target == "Lamp" && e.code == PlanReason::ShadowMapNotAllocated;
    })) << "the frame says it went without the map";
    EXPECT_EQ(first.memory.shadows, 0u);

    const FrameReport second = drawFrame(renderer(), input, 64, 36);
    EXPECT_FALSE(second.drawAgain);
    ASSERT_EQ(second.plan.shadows.size(), 1u);
    EXPECT_EQ(second.plan.shadows[0].mapSize, 512);
    EXPECT_EQ(second.plan.warnings, fellBack) << "planned with what the first frame learnt";
    EXPECT_EQ(second.warnings, fellBack);
    ASSERT_NE(findPass(second, PassKind::Shadow), nullptr);
    EXPECT_EQ(second.memory.shadows, 6u * 512 * 512 * 4);
}

// Any GPU: the frame's own colour buffer does not fit. Nothing can be drawn: the report says so instead of
// returning an empty image as if all was well.
TEST_F(GlTest, FrameWhoseColourBufferDoesNotFitReportsAnError) {
    FrameInput input = scene(256);
    renderImage(input, 64, 36); // meshes and maps are uploaded under no limit
    AllocationLimit limit(64 * 36 * 8 - 1);
    // The frame says so, and runs no pass (it returns before touching the target).
    const FrameReport report = renderer().render(input, RenderTarget{0, 64, 36 * 2, false});
    EXPECT_NE(report.error.find("colour buffer did not fit in GPU memory"), std::string::npos)
        << report.error;
    EXPECT_TRUE(mentions(report.warnings, "the frame could not be drawn"))
        << ::testing::PrintToString(report.warnings);
    EXPECT_TRUE(report.ran.empty());
    // A still of it fails with that error rather than being an empty image.
    auto still = renderStill(renderer(), input, {64, 36 * 2, 1});
    ASSERT_FALSE(still.ok());
    EXPECT_NE(still.error().find("the frame could not be drawn"), std::string::npos) << still.error();
}

// Any GPU: a texture-technique mirror whose reflection texture does not fit is skipped with a warning and
// a reason among the frame's skips, instead of showing whatever an incomplete texture samples as.
TEST_F(GlTest, MirrorWhoseReflectionTextureDoesNotFitIsSkippedWithAWarning) {
    FrameInput input = scene(256);
    Mirror mirror;
    mirror.name = "Glass";
    mirror.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 1.0, -1.5)) *
                   glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1.0, 0.0, 0.0));
    mirror.size = {2.0, 1.5};
    mirror.technique = MirrorTechnique::Texture;
    FrameInput stencil = input;
    mirror.technique = MirrorTechnique::Stencil;
    stencil.mirrors.push_back(mirror);
    renderImage(stencil, 64, 36); // the colour buffer and maps, under no limit
    ASSERT_TRUE(lastReport().warnings.empty()) << ::testing::PrintToString(lastReport().warnings);
    mirror.technique = MirrorTechnique::Texture;
    input.mirrors.push_back(mirror);
    AllocationLimit limit(64 * 36 * 8 + 1); // the mirror's mip chain is a third more
    renderImage(input, 64, 36);
    EXPECT_TRUE(lastReport().error.empty()) << lastReport().error;
    EXPECT_TRUE(mentions(lastReport().warnings, "mirror 'Glass': no reflection, its reflection texture: the "
                                                "64×36 colour buffer did not fit in GPU memory"))
        << ::testing::PrintToString(lastReport().warnings);
    EXPECT_TRUE(
        std::any_of(lastReport().skipped.begin(), lastReport().skipped.end(), [](const SkippedEffect& e) {
            return e.target == "Glass" && e.code == PlanReason::MirrorNoTexture;
        }));
    EXPECT_EQ(findPass(lastReport(), PassKind::Mirror), nullptr);
    EXPECT_TRUE(std::any_of(lastReport().plan.passes.begin(), lastReport().plan.passes.end(),
                            [](const PlannedPass& p) { return p.kind == PassKind::Mirror; }))
        << "the plan keeps the pass execution could not run";
}

} // namespace
} // namespace speculum::test

namespace speculum::test {
namespace {

// The fallback itself, without GL: halving from the size asked for, and sizes that failed are not asked
// for again (a huge allocation that failed once is not retried every frame).
TEST(SizeFallback, HalvesToTheLargestSizeThatWorksAndRemembersFailures) {
    render::gl::SizeFallback fallback;
    std::vector<int> tried;
    auto upTo = [&](int largest) {
        return [&tried, largest](int size) -> base::Status {
            tried.push_back(size);
            if (size > largest)
                return base::Error{"did not fit in GPU memory"};
            return base::Done{};
        };
    };
    auto fitted = fallback.fit(8192, 16, upTo(3000));
    EXPECT_EQ(fitted.size, 2048);
    EXPECT_EQ(fitted.reason, "did not fit in GPU memory");
    EXPECT_EQ(tried, (std::vector<int>{8192, 4096, 2048}));
    EXPECT_EQ(fallback.failedAt(), 4096);
    // The next frame asks for 8192 again: straight to 2048, the failed sizes untried.
    tried.clear();
    fitted = fallback.fit(8192, 16, upTo(3000));
    EXPECT_EQ(fitted.size, 2048);
    EXPECT_EQ(fitted.reason, "did not fit in GPU memory");
    EXPECT_EQ(tried, (std::vector<int>{2048}));
    // A size below every failure is asked for as it is, with no reason.
    tried.clear();
    fitted = fallback.fit(1000, 16, upTo(3000));
    EXPECT_EQ(fitted.size, 1000);
    EXPECT_TRUE(fitted.reason.empty());
    // Nothing fits: 0, down to the minimum and no further.
    render::gl::SizeFallback none;
    tried.clear();
    fitted = none.fit(64, 16, upTo(8));
    EXPECT_EQ(fitted.size, 0);
    EXPECT_EQ(tried, (std::vector<int>{64, 32, 16}));
    tried.clear();
    EXPECT_EQ(none.fit(64, 16, upTo(8)).size, 0);
    EXPECT_TRUE(tried.empty()) << "the minimum failed before: not tried again";
}

} // namespace
} // namespace speculum::test
