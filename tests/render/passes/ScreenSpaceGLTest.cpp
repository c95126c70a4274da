// Screen-space mirrors (MirrorTechnique::ScreenSpace): a floor mirror whose reflected scene is all in the
// image agrees with the texture technique; what the image does not hold shows the fallback (the
// reflector's map, or the background) and the still counts it; half resolution comes close to full; the
// debug view colours each pixel by its source; a scene without one runs none of their passes; and the
// hard views stay finite.
#include "render/imageio/ImageWriter.hpp"
#include "render/mesh/Primitives.hpp"
#include "support/GlTest.hpp"
#include "support/SceneBuilder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 160;
constexpr int kHeight = 96;
const glm::dvec3 kSky{0.2, 0.3, 0.5};

// A floor mirror with two emissive boxes standing on it and an emissive back wall: flat colours, so that
// the reflected eye sees what the camera sees of their sides, and the camera looking down at them so that
// everything the mirror reflects is in the image (or is the sky above the camera, which both show).
FrameInput floorScene(MirrorTechnique technique) {
    FrameInput input;
    input.settings.background = kSky;
    input.settings.ambient = 0.0;
    input.camera.position = {0.0, 2.2, 4.0};
    input.camera.target = {0.0, 0.2, -1.0};
    input.camera.fovY = 60.0;
    input.camera.far = 100.0;
    input.items.push_back(
        item("Red", boxMesh(), placed({-1.0, 0.5, -1.0}, glm::dvec3(0.5)), emissive({0.9, 0.15, 0.1})));
    input.items.push_back(
        item("Green", boxMesh(), placed({1.2, 0.35, -0.4}, glm::dvec3(0.35)), emissive({0.1, 0.8, 0.2})));
    input.items.push_back(
        item("Wall", boxMesh(), placed({0.0, 1.0, -3.2}, {4.0, 1.0, 0.2}), emissive({0.8, 0.8, 0.75})));
    Mirror floor = mirror({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {8.0, 8.0});
    floor.name = "Floor";
    floor.technique = technique;
    input.mirrors.push_back(floor);
    return input;
}

// The floor scene with a yellow box above the camera's view (the texture technique reflects it, the
// image never shows it) and a chrome ball on the floor whose map, through a box proxy whose top is the
// yellow box's underside, sees it where the floor's rays would meet it.
FrameInput sceneWithMapAbove(MirrorTechnique technique, ScreenFallback fallback) {
    FrameInput input = floorScene(technique);
    input.settings.screenFallback = fallback;
    input.items.push_back(
        item("Above", boxMesh(), placed({0.0, 4.0, -2.0}, {1.0, 0.3, 0.8}), emissive({0.9, 0.9, 0.1})));
    const glm::dvec3 centre{0.4, 0.3, 0.8};
    Reflector ball;
    ball.name = "Ball";
    ball.mesh = std::make_shared<const MeshData>(makeSphere(48));
    ball.world = glm::scale(glm::translate(glm::dmat4(1.0), centre), glm::dvec3(0.3));
    ball.material = emissive({0.0, 0.0, 0.0});
    ball.reflectivity = 1.0;
    ball.resolution = 256;
    ParallaxParams proxy;
    proxy.shape = ParallaxShape::Box;
    proxy.min = glm::dvec3(-4.3, 0.0, -3.0) - centre;
    proxy.max = glm::dvec3(4.3, 3.7, 4.0) - centre;
    ball.parallax = proxy;
    input.reflectors = {ball};
    return input;
}

bool yellow(const glm::vec4& c) {
    return c.b < 0.3f && c.r > 0.5f && c.g > 0.5f;
}

void dump(const Image& image, const std::string& name) {
    if (const char* folder = std::getenv("SPECULUM_TEST_DUMP"))
        (void)writeImage(std::string(folder) + "/" + name + ".png", image);
}

float difference(const glm::vec4& a, const glm::vec4& b) {
    const glm::vec3 d = glm::abs(glm::vec3(a) - glm::vec3(b));
    return std::max({d.x, d.y, d.z});
}

bool allFinite(const Image& image) {
    return std::all_of(image.rgba.begin(), image.rgba.end(), [](float v) { return std::isfinite(v); });
}

class ScreenSpaceMirror : public GlTest {
protected:
    Image render(const FrameInput& input) { return renderImage(input, kWidth, kHeight); }

    // The mirror's pixels: those a black mirror (tint 0) turns black, every other surface being bright.
    std::vector<bool> mirrorPixels(FrameInput input) {
        input.mirrors[0].tint = glm::dvec3(0.0);
        const Image black = render(input);
        std::vector<bool> mask(static_cast<std::size_t>(kWidth * kHeight), false);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                mask[static_cast<std::size_t>(y * kWidth + x)] = glm::vec3(black.at(x, y)) == glm::vec3(0.0f);
        return mask;
    }
};

TEST_F(ScreenSpaceMirror, AFloorMirrorWhoseSceneIsInTheImageAgreesWithTheTextureTechnique) {
    const Image planar = render(floorScene(MirrorTechnique::Texture));
    const Image screen = render(floorScene(MirrorTechnique::ScreenSpace));
    dump(planar, "screen-space-planar");
    dump(screen, "screen-space-traced");
    const std::vector<bool> mirror = mirrorPixels(floorScene(MirrorTechnique::Texture));
    // Interior pixels: the mirror all around, and no edge of the reflection through them (where one pixel's
    // rounding decides which side of an edge the ray meets).
    int interior = 0, agree = 0, reflecting = 0, reflectingAgree = 0;
    for (int y = 1; y < kHeight - 1; ++y)
        for (int x = 1; x < kWidth - 1; ++x) {
            bool inside = true;
            float spread = 0.0f;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    inside = inside && mirror[static_cast<std::size_t>((y + dy) * kWidth + x + dx)];
                    spread = std::max(spread, difference(planar.at(x + dx, y + dy), planar.at(x, y)));
                }
            if (!inside || spread > 0.05f)
                continue;
            const bool same = difference(planar.at(x, y), screen.at(x, y)) <= 0.02f;
            ++interior;
            agree += same ? 1 : 0;
            // Those that show the boxes or the wall, not the sky both techniques agree on trivially.
            if (difference(planar.at(x, y), glm::vec4(glm::vec3(kSky), 1.0f)) > 0.1f) {
                ++reflecting;
                reflectingAgree += same ? 1 : 0;
            }
        }
    ASSERT_GT(interior, kWidth * kHeight / 5);
    ASSERT_GT(reflecting, 500) << "the reflection shows the boxes and the wall";
    EXPECT_GE(double(agree), 0.99 * interior)
        << agree << " of " << interior << " interior mirror pixels agree";
    EXPECT_GE(double(reflectingAgree), 0.99 * reflecting)
        << reflectingAgree << " of " << reflecting << " interior pixels reflecting an object agree";
    EXPECT_TRUE(allFinite(screen));
}

TEST_F(ScreenSpaceMirror, WhatTheImageDoesNotHoldShowsTheBackground) {
    // A box above the camera's view: the texture technique reflects it, the image never shows it.
    FrameInput planarInput = floorScene(MirrorTechnique::Texture);
    FrameInput screenInput = floorScene(MirrorTechnique::ScreenSpace);
    for (FrameInput* input : {&planarInput, &screenInput})
        input->items.push_back(
            item("Above", boxMesh(), placed({0.0, 4.0, -2.0}, {1.0, 0.3, 0.8}), emissive({0.9, 0.9, 0.1})));
    const Image planar = render(planarInput);
    const Image screen = render(screenInput);
    dump(planar, "screen-space-above-planar");
    dump(screen, "screen-space-above-traced");
    int yellowInPlanar = 0, skyInScreen = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec4 p = planar.at(x, y);
            if (p.b < 0.3f && p.r > 0.5f && p.g > 0.5f) { // the yellow box, reflected
                ++yellowInPlanar;
                if (difference(screen.at(x, y), glm::vec4(glm::vec3(kSky), 1.0f)) < 0.02f)
                    ++skyInScreen;
            }
        }
    ASSERT_GT(yellowInPlanar, 50) << "the texture technique reflects the box above the view";
    EXPECT_GE(double(skyInScreen), 0.95 * yellowInPlanar);
}

TEST_F(ScreenSpaceMirror, PassesRunOnlyForAScreenSpaceMirrorAndSayWhy) {
    render(floorScene(MirrorTechnique::Texture));
    EXPECT_EQ(lastReport().countRan(PassKind::ScreenDepth), 0u);
    render(floorScene(MirrorTechnique::ScreenSpace));
    const FrameReport& report = lastReport();
    ASSERT_EQ(report.countRan(PassKind::ScreenDepth), 1u);
    bool traced = false;
    for (const PassRun& run : report.ran)
        if (report.planned(run).code == PlanReason::MirrorScreenTrace) {
            traced = true;
            // A still counts where each pixel's reflection came from.
            EXPECT_NE(report.reason(run).find("pixels meet what the image shows"), std::string::npos)
                << report.reason(run);
            EXPECT_NE(report.reason(run).find("show the background"), std::string::npos)
                << report.reason(run);
            EXPECT_EQ(run.outcome.find(" 0 pixels"), std::string::npos) << run.outcome;
        }
    EXPECT_TRUE(traced);
    // The trace runs after the depth pyramid, which runs after the main pass.
    std::vector<PassKind> order;
    for (const PassRun& run : report.ran)
        order.push_back(report.planned(run).kind);
    const auto main = std::find(order.begin(), order.end(), PassKind::Main);
    const auto depth = std::find(order.begin(), order.end(), PassKind::ScreenDepth);
    EXPECT_LT(main - order.begin(), depth - order.begin());
}

TEST_F(ScreenSpaceMirror, HardViewsStayFinite) {
    struct View {
        const char* name;
        glm::dvec3 position;
        glm::dvec3 target;
        glm::dvec3 up{0.0, 1.0, 0.0};
        double near = 0.1;
        double far = 100.0;
    };
    const View views[] = {
        {"straight-down", {0.0, 3.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}},
        {"grazing", {0.0, 0.02, 3.9}, {0.0, 0.0, -4.0}},
        {"far-plane-1e6", {0.0, 2.2, 4.0}, {0.0, 0.2, -1.0}, {0.0, 1.0, 0.0}, 0.1, 1e6},
        {"half-off-screen", {3.0, 1.0, 2.0}, {5.0, 0.3, -1.0}},
    };
    for (const View& v : views) {
        FrameInput input = floorScene(MirrorTechnique::ScreenSpace);
        input.camera.position = v.position;
        input.camera.target = v.target;
        input.camera.up = v.up;
        input.camera.near = v.near;
        input.camera.far = v.far;
        input.mirrors[0].roughness = 0.3;
        const Image image = render(input);
        dump(image, std::string("screen-space-") + v.name);
        EXPECT_TRUE(allFinite(image)) << v.name;
        EXPECT_EQ(image.width, kWidth) << v.name;
    }
    // 1e5 from the origin: the scene moved, the camera with it.
    FrameInput far = floorScene(MirrorTechnique::ScreenSpace);
    const glm::dvec3 offset{1e5, 0.0, -1e5};
    for (DrawItem& i : far.items)
        i.world = glm::translate(glm::dmat4(1.0), offset) * i.world;
    far.mirrors[0].world = glm::translate(glm::dmat4(1.0), offset) * far.mirrors[0].world;
    far.camera.position += offset;
    far.camera.target += offset;
    const Image moved = render(far);
    const Image home = render(floorScene(MirrorTechnique::ScreenSpace));
    ASSERT_TRUE(allFinite(moved));
    int close = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            close += difference(moved.at(x, y), home.at(x, y)) <= 0.02f ? 1 : 0;
    EXPECT_GE(double(close), 0.98 * kWidth * kHeight) << "the same image 1e5 from the origin";
}

// A tile holds only its own pixels, so a still with a screen-space mirror is drawn in one piece where a
// plain one would be tiled, and one that must be tiled says what that costs.
TEST_F(ScreenSpaceMirror, AWideStillIsTracedInOnePieceAndATiledOneSaysSo) {
    const FrameInput input = floorScene(MirrorTechnique::ScreenSpace);
    StillSettings wide;
    wide.width = 2200;
    wide.height = 100;
    const auto whole = renderStill(renderer(), input, wide);
    ASSERT_TRUE(whole.ok()) << whole.error();
    EXPECT_EQ(whole->tiles, 1);
    const auto plain = renderStill(renderer(), floorScene(MirrorTechnique::Texture), wide);
    ASSERT_TRUE(plain.ok()) << plain.error();
    EXPECT_GT(plain->tiles, 1) << "a still without one is tiled as before";
    auto said = [](const StillResult& still) {
        return std::any_of(still.firstSample.warnings.begin(), still.firstSample.warnings.end(),
                           [](const std::string& w) { return w.find("tile by tile") != std::string::npos; });
    };
    EXPECT_FALSE(said(*whole));
    StillSettings tiled = wide;
    tiled.tileSize = 1024;
    const auto inTiles = renderStill(renderer(), input, tiled);
    ASSERT_TRUE(inTiles.ok()) << inTiles.error();
    EXPECT_GT(inTiles->tiles, 1);
    EXPECT_TRUE(said(*inTiles));
}

TEST_F(ScreenSpaceMirror, WhatTheImageDoesNotHoldShowsTheReflectorsMapAndTheStillCountsIt) {
    const Image planar = render(sceneWithMapAbove(MirrorTechnique::Texture, ScreenFallback::Map));
    const Image map = render(sceneWithMapAbove(MirrorTechnique::ScreenSpace, ScreenFallback::Map));
    std::string outcome;
    for (const PassRun& run : lastReport().ran)
        if (lastReport().planned(run).code == PlanReason::MirrorScreenTrace)
            outcome = run.outcome;
    const Image background =
        render(sceneWithMapAbove(MirrorTechnique::ScreenSpace, ScreenFallback::Background));
    dump(map, "screen-space-fallback-map");
    dump(background, "screen-space-fallback-background");
    int yellowInPlanar = 0, yellowInMap = 0, skyInBackground = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (yellow(planar.at(x, y))) {
                ++yellowInPlanar;
                yellowInMap += yellow(map.at(x, y)) ? 1 : 0;
                skyInBackground +=
                    difference(background.at(x, y), glm::vec4(glm::vec3(kSky), 1.0f)) < 0.02f ? 1 : 0;
            }
    ASSERT_GT(yellowInPlanar, 50);
    // Through the proxy the map finds the box where the floor's rays meet it.
    EXPECT_GE(double(yellowInMap), 0.85 * yellowInPlanar) << yellowInMap << " of " << yellowInPlanar;
    EXPECT_GE(double(skyInBackground), 0.95 * yellowInPlanar) << skyInBackground << " of " << yellowInPlanar;
    EXPECT_NE(outcome.find("fall back to the reflector's map"), std::string::npos) << outcome;
    EXPECT_NE(outcome.find("pixels meet what the image shows"), std::string::npos) << outcome;
    EXPECT_TRUE(allFinite(map));
}

TEST_F(ScreenSpaceMirror, TheMapRunsForTheFallbackWhenTheReflectorIsOutOfSight) {
    FrameInput input = sceneWithMapAbove(MirrorTechnique::ScreenSpace, ScreenFallback::Map);
    // Behind the camera, and below the floor, so no view sees the ball.
    input.reflectors[0].world =
        glm::scale(glm::translate(glm::dmat4(1.0), {0.0, -3.0, 8.0}), glm::dvec3(0.3));
    const Image image = render(input);
    ASSERT_EQ(lastReport().countRan(PassKind::Envmap), 1u);
    for (const PassRun& run : lastReport().ran) {
        if (lastReport().planned(run).kind == PassKind::Envmap) {
            EXPECT_NE(lastReport().reason(run).find("screen-space mirrors Floor fall back to its map"),
                      std::string::npos)
                << lastReport().reason(run);
        }
    }
    input.settings.screenFallback = ScreenFallback::Background;
    render(input);
    EXPECT_EQ(lastReport().countRan(PassKind::Envmap), 0u) << "nothing reads it";
    EXPECT_TRUE(allFinite(image));
}

TEST_F(ScreenSpaceMirror, HalfResolutionComesCloseToFullAndSaysSo) {
    FrameInput input = floorScene(MirrorTechnique::ScreenSpace);
    const Image full = render(input);
    input.settings.screenResolution = ScreenResolution::Half;
    const Image half = render(input);
    dump(half, "screen-space-half");
    std::string outcome;
    for (const PassRun& run : lastReport().ran)
        if (lastReport().planned(run).code == PlanReason::MirrorScreenTrace)
            outcome = run.outcome;
    EXPECT_NE(outcome.find("at half resolution"), std::string::npos) << outcome;
    const std::vector<bool> mirror = mirrorPixels(floorScene(MirrorTechnique::ScreenSpace));
    int pixels = 0, close = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (mirror[static_cast<std::size_t>(y * kWidth + x)]) {
                ++pixels;
                close += difference(full.at(x, y), half.at(x, y)) <= 0.05f ? 1 : 0;
            }
    ASSERT_GT(pixels, kWidth * kHeight / 4);
    // Edges of what it reflects move by up to a pixel and blur over two; flat regions agree.
    EXPECT_GE(double(close), 0.85 * pixels) << close << " of " << pixels;
    EXPECT_TRUE(allFinite(half));
}

TEST_F(ScreenSpaceMirror, TheDebugViewColoursEachPixelByItsSource) {
    const Image planar = render(sceneWithMapAbove(MirrorTechnique::Texture, ScreenFallback::Map));
    StillSettings debug{kWidth, kHeight, 1};
    debug.showScreenSpaceSources = true;
    const Image map =
        renderImage(sceneWithMapAbove(MirrorTechnique::ScreenSpace, ScreenFallback::Map), debug);
    const Image background =
        renderImage(sceneWithMapAbove(MirrorTechnique::ScreenSpace, ScreenFallback::Background), debug);
    dump(map, "screen-space-sources-map");
    dump(background, "screen-space-sources-background");
    const std::vector<bool> mirror = mirrorPixels(floorScene(MirrorTechnique::ScreenSpace));
    const glm::vec4 wall(0.8f, 0.8f, 0.75f, 1.0f);
    int yellowPixels = 0, blue = 0, red = 0, wallPixels = 0, green = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!mirror[static_cast<std::size_t>(y * kWidth + x)])
                continue;
            const glm::vec4 p = planar.at(x, y);
            if (yellow(p)) {
                ++yellowPixels;
                blue += map.at(x, y).b > 0.8f && map.at(x, y).g < 0.2f ? 1 : 0;
                red += background.at(x, y).r > 0.8f && background.at(x, y).g < 0.2f ? 1 : 0;
            } else if (difference(p, wall) < 0.05f) {
                ++wallPixels;
                green += map.at(x, y).g > 0.8f && map.at(x, y).r < 0.2f ? 1 : 0;
            }
        }
    ASSERT_GT(yellowPixels, 50);
    ASSERT_GT(wallPixels, 200);
    EXPECT_GE(double(blue), 0.95 * yellowPixels) << "off screen, the map: " << blue << " of " << yellowPixels;
    EXPECT_GE(double(red), 0.95 * yellowPixels) << "or the background: " << red << " of " << yellowPixels;
    EXPECT_GE(double(green), 0.9 * wallPixels) << "on screen, the image: " << green << " of " << wallPixels;
}

// A ray that meets the image only by passing behind what it crosses, by more than half the thickness, is
// not sure it met it: its confidence fades towards the fallback (the background here) as it passes
// deeper. A box floating over the floor: the rays from the floor seen under it and behind it pass behind
// it; the thicker surfaces are taken to be, the more of them "meet" it, blended. With no fade there would
// be no blend there at any thickness.
TEST_F(ScreenSpaceMirror, AHitFarBehindWhatItCrossesFadesIntoTheFallback) {
    auto blended = [&](double thickness) {
        FrameInput input = floorScene(MirrorTechnique::ScreenSpace);
        input.items.push_back(item("Floating", boxMesh(), placed({0.0, 1.0, -1.8}, {0.6, 0.3, 0.3}),
                                   emissive({0.2, 0.4, 0.9})));
        input.settings.screenThickness = thickness;
        StillSettings debug{kWidth, kHeight, 1};
        debug.showScreenSpaceSources = true;
        const Image sources = renderImage(input, debug);
        dump(sources, "screen-space-thickness-" + std::to_string(int(thickness * 100)));
        const std::vector<bool> mirror = mirrorPixels(input);
        int count = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const glm::vec4 p = sources.at(x, y);
                if (mirror[static_cast<std::size_t>(y * kWidth + x)] && p.g > 0.1f && p.g < 0.9f)
                    ++count;
                EXPECT_TRUE(std::isfinite(p.r) && std::isfinite(p.g));
            }
        return count;
    };
    const int thin = blended(0.01), thick = blended(0.3);
    std::printf("[ measured ] blended sources: %d pixels at thickness 0.01, %d at 0.3\n", thin, thick);
    EXPECT_GE(thick, thin + 20);
}

// The reflector traced in screen space: planned only for a reflector the camera sees, with the depth
// pyramid it shares with the screen-space mirrors; a rough one with the image's blurred pyramid just before
// its trace; a still counts where its pixels' reflections came from; its sources show in the debug view.
TEST_F(ScreenSpaceMirror, TheReflectorIsTracedWhereItIsSeenAndBlursTheImageWhenRough) {
    FrameInput input = sceneWithMapAbove(MirrorTechnique::Texture, ScreenFallback::Map);
    input.reflectors[0].technique = ReflectorTechnique::ScreenSpace;
    const Image image = render(input);
    EXPECT_TRUE(allFinite(image));
    const FrameReport& report = lastReport();
    ASSERT_EQ(report.countRan(PassKind::ScreenDepth), 1u);
    ASSERT_EQ(report.countRan(PassKind::ReflectorTrace), 1u);
    for (const PassRun& run : report.ran) {
        if (report.planned(run).kind == PassKind::ReflectorTrace) {
            EXPECT_NE(run.outcome.find("pixels meet what the image shows"), std::string::npos) << run.outcome;
        }
    }
    // The ball on a screen-space floor: a second pyramid, after the floor's trace, which holds the floor.
    input.mirrors[0].technique = MirrorTechnique::ScreenSpace;
    render(input);
    EXPECT_EQ(lastReport().countRan(PassKind::ScreenDepth), 2u);
    EXPECT_EQ(lastReport().countRan(PassKind::ReflectorTrace), 1u);
    // Rough: the image's blurred pyramid runs too, after everything else that draws into it, just before
    // the trace that reads it; a sharp reflector runs none.
    EXPECT_EQ(lastReport().countRan(PassKind::ScreenColour), 0u);
    input.reflectors[0].roughness = 0.3;
    render(input);
    EXPECT_EQ(lastReport().countRan(PassKind::ReflectorTrace), 1u);
    ASSERT_EQ(lastReport().countRan(PassKind::ScreenColour), 1u);
    std::vector<PassKind> order;
    for (const PassRun& run : lastReport().ran)
        order.push_back(lastReport().planned(run).kind);
    const auto colour = std::find(order.begin(), order.end(), PassKind::ScreenColour);
    const auto mirrorPasses = std::find(order.begin(), order.end(), PassKind::MirrorSurface);
    ASSERT_NE(colour, order.end());
    EXPECT_EQ(*std::next(colour), PassKind::ReflectorTrace);
    EXPECT_LT(mirrorPasses - order.begin(), colour - order.begin());
    input.reflectors[0].roughness = 0.0;
    input.reflectors[0].technique = ReflectorTechnique::Map;
    input.mirrors[0].technique = MirrorTechnique::Texture;
    render(input);
    EXPECT_EQ(lastReport().countRan(PassKind::ScreenDepth), 0u) << "nothing traces: no pyramid";
}

TEST_F(ScreenSpaceMirror, TheReflectorsTraceReplacesTheMapWhereTheImageShowsWhatItReflects) {
    // The ball, close to the wall and the boxes, reflects them with the map's parallax error; traced, the
    // reflection of what the image shows comes from the image. Where the trace meets nothing (the sky
    // above, the yellow box off-screen) the map stays, bit for bit.
    FrameInput input = sceneWithMapAbove(MirrorTechnique::Texture, ScreenFallback::Map);
    // A bigger ball, nearer the camera, and no proxy: what it reflects of the image shows from the map
    // at the directions seen from its centre.
    input.reflectors[0].world = glm::scale(glm::translate(glm::dmat4(1.0), {0.0, 0.7, 0.8}), glm::dvec3(0.7));
    input.reflectors[0].parallax.reset();
    const Image map = render(input);
    input.reflectors[0].technique = ReflectorTechnique::ScreenSpace;
    const Image traced = render(input);
    StillSettings debug{kWidth, kHeight, 1};
    debug.showScreenSpaceSources = true;
    const Image sources = renderImage(input, debug);
    dump(traced, "screen-space-reflector-traced");
    dump(map, "screen-space-reflector-map");
    dump(sources, "screen-space-reflector-sources");
    int green = 0, blue = 0, changed = 0, keptWhereBlue = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec4 s = sources.at(x, y);
            const bool isGreen = s.g > 0.9f && s.r < 0.1f && s.b < 0.1f;
            const bool isBlue = s.b > 0.99f && s.r < 0.01f && s.g < 0.01f; // confidence below 0.01
            green += isGreen ? 1 : 0;
            blue += isBlue ? 1 : 0;
            if (isGreen)
                changed += difference(map.at(x, y), traced.at(x, y)) > 0.0f ? 1 : 0;
            if (isBlue)
                keptWhereBlue += difference(map.at(x, y), traced.at(x, y)) <= 0.01f ? 1 : 0;
        }
    EXPECT_GT(green, 100) << "the ball's pixels that reflect what the image shows";
    EXPECT_GT(blue, 100) << "the ball's pixels that reflect the sky and the box above";
    EXPECT_GE(double(keptWhereBlue), 0.99 * blue) << "where the trace meets nothing, the map stays";
    EXPECT_GT(changed, green / 4) << "the image's reflection is not the map's";
}

// The rest of the hard cases: a thin pole on the floor, a mirror a pixel wide, the camera inside the
// reflector's proxy with the floor and the ball both traced, and the image resized between frames.
TEST_F(ScreenSpaceMirror, ThinTinyInsideRoughAndResizedStayFinite) {
    FrameInput thin = floorScene(MirrorTechnique::ScreenSpace);
    thin.items.push_back(
        item("Pole", boxMesh(), placed({0.3, 1.0, 0.5}, {0.01, 1.0, 0.01}), emissive({0.9, 0.9, 0.9})));
    EXPECT_TRUE(allFinite(render(thin))) << "thin pole";

    FrameInput tiny = floorScene(MirrorTechnique::ScreenSpace);
    tiny.mirrors[0].world = glm::scale(glm::translate(glm::dmat4(1.0), {0.0, 0.0, -2.0}), glm::dvec3(0.004));
    EXPECT_TRUE(allFinite(render(tiny))) << "a mirror about a pixel wide";

    FrameInput inside = sceneWithMapAbove(MirrorTechnique::ScreenSpace, ScreenFallback::Map);
    inside.reflectors[0].technique = ReflectorTechnique::ScreenSpace;
    inside.camera.position = {0.0, 1.5, 2.0}; // within the proxy box
    const Image within = render(inside);
    EXPECT_TRUE(allFinite(within)) << "camera inside the proxy";
    EXPECT_EQ(lastReport().countRan(PassKind::ReflectorTrace), 1u);

    // Rough, the cone read from the blurred image, with the far plane at 1e6 (cones that reach far, levels
    // clamped), and the pyramid remade at each size below.
    inside.reflectors[0].roughness = 0.4;
    inside.camera.far = 1e6;
    EXPECT_TRUE(allFinite(render(inside))) << "rough, far plane at 1e6";
    EXPECT_EQ(lastReport().countRan(PassKind::ScreenColour), 1u);
    for (const auto& [width, height] :
         {std::pair{kWidth, kHeight}, std::pair{97, 61}, std::pair{kWidth, kHeight}}) {
        const Image image = renderImage(inside, width, height);
        EXPECT_EQ(image.width, width);
        EXPECT_TRUE(allFinite(image)) << width << "x" << height;
    }
}

} // namespace
} // namespace speculum::test
