// Rough (GGX) reflections in the reference tracer: roughness 0 is the sharp image bit for bit, a rough
// perfect mirror under a uniform sky shows the lobe's albedo, the noise estimate is honest and falls as
// 1/samples, and nothing non-finite comes out at the extremes.
#include "render/reference/Tracer.hpp"
#include "support/GgxReference.hpp"
#include "support/SceneBuilder.hpp"

#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <vector>

namespace speculum::test {
namespace {

using render::FrameInput;
using render::reference::Tracer;
using render::reference::TraceResult;
using render::reference::TraceSettings;

TraceResult trace(const FrameInput& input, int width, int height, int samples, int ssaa = 1,
                  int threads = 0) {
    auto tracer = Tracer::create(input);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error());
    TraceSettings settings;
    settings.width = width;
    settings.height = height;
    settings.samples = samples;
    settings.ssaa = ssaa;
    settings.threads = threads;
    auto result = tracer->render(settings);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error());
    return std::move(*result);
}

// The camera one unit from the origin at `viewDegrees` from the +Y normal of a huge mirror through the
// origin, looking at the origin with a narrow field: the centre pixel sees the mirror at exactly that
// angle. Nothing else but a white sky.
FrameInput mirrorUnderWhiteSky(double viewDegrees, double roughness) {
    FrameInput input;
    const double t = glm::radians(viewDegrees);
    input.camera.position = {std::sin(t), std::cos(t), 0.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.up = {0.0, 0.0, -1.0};
    input.camera.fovY = 1.0;
    input.camera.near = 0.01;
    input.camera.far = 100.0;
    input.settings.background = {1.0, 1.0, 1.0};
    render::Mirror m = mirror({0, 0, 0}, {0, 1, 0}, {1000.0, 1000.0});
    m.reflectivity = 1.0;
    m.fresnel = false;
    m.tint = {1.0, 1.0, 1.0};
    m.roughness = roughness;
    input.mirrors.push_back(m);
    return input;
}

// A rough floor mirror reflecting a black-and-white checkered wall, lit by nothing (emission only).
FrameInput roughMirrorBeforeChecker(double roughness) {
    FrameInput input;
    input.camera.position = {0.0, 1.0, 2.0};
    input.camera.target = {0.0, 0.0, -1.0};
    input.camera.fovY = 50.0;
    input.settings.background = {0.0, 0.0, 0.0};
    render::Mirror m = mirror({0, 0, 0}, {0, 1, 0}, {8.0, 8.0});
    m.roughness = roughness;
    input.mirrors.push_back(m);
    auto checker = std::make_shared<render::TextureImage>();
    checker->width = checker->height = 64;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const std::uint8_t v = ((x / 8 + y / 8) % 2) ? 255 : 0;
            checker->rgba8.insert(checker->rgba8.end(), {v, v, v, 255});
        }
    render::Material wall = emissive({1.0, 1.0, 1.0});
    wall.emissionTexture.path = "checker#0";
    wall.emissionTexture.image = checker;
    // The plane ([−1, 1]² in XZ, facing +Y) stood up to face the camera: 4 × 4 at z = −3.
    const glm::dmat4 standing = glm::scale(
        glm::rotate(glm::translate(glm::dmat4(1.0), {0, 2, -3}), glm::radians(90.0), glm::dvec3(1, 0, 0)),
        glm::dvec3(2, 1, 2));
    input.items.push_back(item("Wall", planeMesh(), standing, wall));
    return input;
}

// The same kinds of surfaces as today's mirror tests, every one sharp: a lit box, a Fresnel mirror with
// a material, and a flat reflector.
FrameInput sharpScene() {
    FrameInput input = roughMirrorBeforeChecker(0.0);
    input.mirrors[0].fresnel = true;
    input.mirrors[0].reflectivity = 0.6;
    input.mirrors[0].hasMaterial = true;
    input.mirrors[0].material.color = {0.3, 0.2, 0.1};
    render::Material box;
    box.specular = 0.5;
    input.items.push_back(item("Box", boxMesh(), placed({0.5, 0.5, -1.0}, {0.5, 0.5, 0.5}), box));
    render::Light light;
    light.position = {1.0, 3.0, 1.0};
    input.lights.push_back(light);
    render::Reflector reflector;
    reflector.mesh = planeMesh();
    // Facing +X, towards the middle.
    reflector.world = glm::scale(glm::rotate(glm::translate(glm::dmat4(1.0), {-2.0, 1.0, -1.0}),
                                             glm::radians(-90.0), glm::dvec3(0, 0, 1)),
                                 glm::dvec3(1, 1, 1));
    reflector.reflectivity = 0.8;
    reflector.fresnel = true;
    input.reflectors = {reflector};
    return input;
}

double meanSquaredDifference(const render::Image& a, const render::Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        if (i % 4 != 3)
            sum += (double(a.rgba[i]) - b.rgba[i]) * (double(a.rgba[i]) - b.rgba[i]);
    return sum / (a.rgba.size() / 4 * 3);
}

void expectAllFinite(const TraceResult& r, const std::string& what) {
    for (std::size_t i = 0; i < r.image.rgba.size(); ++i) {
        ASSERT_TRUE(std::isfinite(r.image.rgba[i])) << what << ", value " << i;
        ASSERT_TRUE(std::isfinite(r.noise.rgba[i])) << what << ", noise " << i;
    }
    EXPECT_TRUE(std::isfinite(r.noiseRms)) << what;
}

TEST(GlossyTracer, RoughnessZeroSamplesNothing) {
    const FrameInput input = sharpScene();
    const TraceResult one = trace(input, 96, 54, 1);
    const TraceResult many = trace(input, 96, 54, 64);
    EXPECT_EQ(one.image.rgba, many.image.rgba); // bit for bit
    EXPECT_EQ(many.glossyPixels, 0);
    EXPECT_EQ(many.noiseRms, 0.0);
    for (float e : many.noise.rgba)
        EXPECT_TRUE(e == 0.0f || e == 1.0f); // squared errors 0, alpha 1
    // With SSAA too.
    EXPECT_EQ(trace(input, 32, 18, 1, 3).image.rgba, trace(input, 32, 18, 64, 3).image.rgba);
}

// A perfect mirror (reflectivity 1, no Fresnel, white tint) under a sky of radiance 1 shows exactly the
// lobe's directional albedo E(μ_v, α) with F = 1, here by quadrature written from the paper's formulas.
// GGX's long tail sends a share of the samples below the mirror (α²/(1 + α²) of them seen along the normal),
// so even 65536 paths leave a standard error near 1e-3 at the higher roughnesses.
TEST(GlossyTracer, RoughMirrorUnderWhiteSkyShowsTheLobeAlbedo) {
    for (double roughness : {0.2, 0.5, 1.0})
        for (double view : {0.0, 60.0, 85.0}) {
            const double alpha = roughness * roughness;
            const double expected = ggx::albedo(glm::radians(view), alpha);
            const TraceResult r = trace(mirrorUnderWhiteSky(view, roughness), 1, 1, 65536);
            const double standardError = std::sqrt(double(r.noise.at(0, 0).g));
            EXPECT_LT(standardError, 2e-3) << "roughness " << roughness << ", view " << view;
            EXPECT_EQ(r.glossyPixels, 1);
            // 4 standard errors, and the pixel's float storage (its last bit is 6e-8 near 1).
            EXPECT_NEAR(r.image.at(0, 0).g, expected, 4.0 * standardError + 2e-7)
                << "roughness " << roughness << ", view " << view << ", standard error " << standardError;
        }
}

TEST(GlossyTracer, RoughFlatReflectorUnderWhiteSkyShowsTheLobeAlbedo) {
    for (double view : {0.0, 60.0}) {
        FrameInput input = mirrorUnderWhiteSky(view, 0.0);
        input.mirrors.clear();
        render::Reflector reflector;
        reflector.mesh = planeMesh();
        reflector.world = placed({0, 0, 0}, {1000, 1, 1000});
        reflector.reflectivity = 1.0;
        reflector.roughness = 0.7;
        input.reflectors = {reflector};
        const TraceResult r = trace(input, 1, 1, 65536);
        const double standardError = std::sqrt(double(r.noise.at(0, 0).r));
        EXPECT_NEAR(r.image.at(0, 0).r, ggx::albedo(glm::radians(view), 0.49), 4.0 * standardError + 2e-7)
            << "view " << view;
    }
}

// Independent samples: the squared standard error halves when the paths double, the estimate agrees with
// the actual error against a 1024-path render (which shares the first N paths, so the expected mean
// squared difference is σ²(1/N − 1/1024)), and that error falls accordingly.
TEST(GlossyTracer, NoiseFallsAsOneOverSamples) {
    const FrameInput input = roughMirrorBeforeChecker(0.4);
    const int w = 64, h = 36;
    const TraceResult best = trace(input, w, h, 1024);
    std::vector<TraceResult> runs;
    for (int n : {16, 32, 64, 128})
        runs.push_back(trace(input, w, h, n));
    EXPECT_GT(best.glossyPixels, w * h / 4);
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const int n = 16 << i;
        EXPECT_EQ(runs[i].glossyPixels, best.glossyPixels);
        EXPECT_GT(runs[i].noiseRms, 0.0);
        const double difference = meanSquaredDifference(runs[i].image, best.image);
        const double predicted = runs[i].noiseRms * runs[i].noiseRms * (1.0 - n / 1024.0);
        EXPECT_NEAR(difference / predicted, 1.0, 0.25) << n << " paths";
        if (i == 0)
            continue;
        const double ratio = std::pow(runs[i].noiseRms / runs[i - 1].noiseRms, 2.0);
        EXPECT_NEAR(ratio, 0.5, 0.1) << n << " paths against " << n / 2;
        const double expected = (1.0 / n - 1.0 / 1024) / (2.0 / n - 1.0 / 1024);
        EXPECT_NEAR(difference / meanSquaredDifference(runs[i - 1].image, best.image), expected, 0.1)
            << n << " paths against " << n / 2;
    }
}

TEST(GlossyTracer, ImagesDoNotDependOnThreads) {
    const FrameInput input = roughMirrorBeforeChecker(0.5);
    const TraceResult a = trace(input, 40, 24, 8, 1, 1);
    const TraceResult b = trace(input, 40, 24, 8, 1, 3);
    EXPECT_EQ(a.image.rgba, b.image.rgba);
    EXPECT_EQ(a.noiseRms, b.noiseRms);
}

TEST(GlossyTracer, OnePathHasNoNoiseEstimate) {
    const TraceResult r = trace(roughMirrorBeforeChecker(0.5), 16, 9, 1);
    EXPECT_GT(r.glossyPixels, 0);
    EXPECT_TRUE(std::isnan(r.noiseRms));
    for (std::size_t i = 0; i < r.image.rgba.size(); ++i)
        ASSERT_TRUE(std::isfinite(r.image.rgba[i]));
}

TEST(GlossyTracer, NothingNonFiniteAtFullRoughnessAndGrazingViews) {
    for (double roughness : {1.0, 0.05}) {
        // The camera a hair above a huge mirror, looking along it.
        FrameInput grazing = roughMirrorBeforeChecker(roughness);
        grazing.mirrors[0].size = {1e4, 1e4};
        grazing.mirrors[0].fresnel = true;
        grazing.camera.position = {0.0, 1e-6, 2.0};
        grazing.camera.target = {0.0, 1e-6, -1.0};
        expectAllFinite(trace(grazing, 48, 27, 8), "mirror, roughness " + std::to_string(roughness));

        // A rough reflector sphere: its silhouette is seen at grazing angles, where the interpolated
        // normal may even face away from the viewer.
        FrameInput sphere = roughMirrorBeforeChecker(roughness);
        render::Reflector reflector;
        reflector.mesh = std::make_shared<const render::MeshData>(render::makeSphere(12));
        reflector.world = placed({0.0, 0.5, -0.5}, {0.6, 0.6, 0.6});
        reflector.roughness = roughness;
        reflector.fresnel = true;
        sphere.reflectors = {reflector};
        const TraceResult r = trace(sphere, 48, 27, 8, 2);
        expectAllFinite(r, "reflector, roughness " + std::to_string(roughness));
        EXPECT_GT(r.glossyPixels, 0);
    }
}

} // namespace
} // namespace speculum::test
