// Rough (glossy) planar mirrors in the rasterizer against the exact tracer. mirror.frag approximates the
// GGX lobe's integral by blurring the mirror's reflection texture (render::GlossyFilter): these tests
// check that roughness 0 runs no blur at all, that the Footprint filter's error falls towards the tracer as
// its taps rise and beats the cheap Mip filter, that the convolved Chain comes within 1 dB of 16 taps,
// that nothing non-finite comes out at the extremes (rough, grazing, close), and that the blur grows with
// the distance beyond the mirror, which is what the Footprint and Chain filters exist for.
#include "render/imageio/ImageWriter.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/reference/Tracer.hpp"
#include "support/GlTest.hpp"
#include "support/SceneBuilder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace speculum::test {
namespace {

using render::FrameInput;
using render::GlossyFilter;
namespace reference = render::reference;
namespace metrics = render::metrics;

// An emissive black-and-white checker, 8 squares a side.
render::Material checkerEmission(glm::dvec3 colour) {
    auto checker = std::make_shared<render::TextureImage>();
    checker->width = checker->height = 64;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const std::uint8_t v = ((x / 8 + y / 8) % 2) ? 255 : 0;
            checker->rgba8.insert(checker->rgba8.end(), {v, v, v, 255});
        }
    render::Material m = emissive(colour);
    m.emissionTexture.path = "checker#0";
    m.emissionTexture.image = checker;
    return m;
}

// A floor mirror (y = 0, facing +Y, perfect: reflectivity 1, no tint or Fresnel) with the given roughness,
// reflecting an emissive checkered wall behind it and coloured boxes at different heights above it: one
// standing on the mirror, one floating low, one high. Emission only, so shading is not what differs.
FrameInput floorMirrorScene(double roughness) {
    FrameInput input;
    input.camera.position = {0.0, 1.1, 3.2};
    input.camera.target = {0.0, 0.1, -1.0};
    input.camera.fovY = 55.0;
    input.camera.near = 0.05;
    input.camera.far = 30.0;
    input.settings.background = {0.02, 0.02, 0.03};
    render::Mirror floor = mirror({0, 0, 0}, {0, 1, 0}, {8.0, 8.0});
    floor.roughness = roughness;
    input.mirrors.push_back(floor);
    // The plane ([−1, 1]² in XZ, facing +Y) stood up to face the camera: 5 wide, 3 high at z = −3.
    const glm::dmat4 standing = glm::scale(
        glm::rotate(glm::translate(glm::dmat4(1.0), {0, 1.5, -3}), glm::radians(90.0), glm::dvec3(1, 0, 0)),
        glm::dvec3(2.5, 1, 1.5));
    input.items.push_back(item("Wall", planeMesh(), standing, checkerEmission({0.9, 0.9, 0.9})));
    input.items.push_back(
        item("Red box", boxMesh(), placed({-1.0, 0.3, -0.8}, {0.3, 0.3, 0.3}), emissive({1.0, 0.15, 0.1})));
    input.items.push_back(
        item("Green box", boxMesh(), placed({0.15, 0.55, -1.6}, {0.2, 0.2, 0.2}), emissive({0.1, 1.0, 0.2})));
    input.items.push_back(
        item("Blue box", boxMesh(), placed({1.1, 1.2, -0.9}, {0.2, 0.2, 0.2}), emissive({0.15, 0.3, 1.0})));
    return input;
}

reference::TraceResult traceFrame(const FrameInput& input, int width, int height, int samples) {
    auto tracer = reference::Tracer::create(input);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error());
    reference::TraceSettings settings;
    settings.width = width;
    settings.height = height;
    settings.samples = samples;
    settings.shadows = reference::ShadowMode::PcfFootprint;
    auto result = tracer->render(settings);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error());
    return std::move(*result);
}

// √(mean over the masked pixels' RGB of the tracer's squared standard error): its noise there.
double maskedNoise(const reference::TraceResult& traced, const std::vector<std::uint8_t>& mask) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i])
            continue;
        for (int c = 0; c < 3; ++c)
            sum += traced.noise.rgba[i * 4 + static_cast<std::size_t>(c)];
        n += 3;
    }
    return n ? std::sqrt(sum / double(n)) : 0.0;
}

void dumpImage(const std::string& name, const render::Image& image) {
    if (const char* folder = std::getenv("SPECULUM_TEST_DUMP")) {
        EXPECT_TRUE(render::writeImage(std::string(folder) + "/" + name + ".png", image).ok());
    }
}

class GlossyAgreement : public GlTest {
protected:
    struct Still {
        render::Image image;
        double ms = 0.0; // the whole still, second of two renders (shaders compiled, maps reused)
    };

    Still renderWith(FrameInput input, GlossyFilter filter, int taps, int width, int height) {
        input.settings.glossyFilter = filter;
        input.settings.glossyTaps = taps;
        Still out;
        for (int run = 0; run < 2; ++run) {
            auto still = render::renderStill(renderer(), input, {width, height, 1});
            EXPECT_TRUE(still.ok()) << (still.ok() ? "" : still.error());
            if (!still.ok())
                return out;
            for (const std::string& warning : still->firstSample.warnings)
                ADD_FAILURE() << warning;
            out.image = std::move(still->image);
            out.ms = still->totalMs;
        }
        return out;
    }
};

// Roughness 0: the planner keeps the stencil mirror a stencil mirror and mirror.frag reads the texture
// mirror's reflection sharp, whatever the glossy settings say, so the image is the same bit for bit.
TEST_F(GlossyAgreement, RoughnessZeroIsTheSharpImageWhateverTheFilter) {
    FrameInput input = floorMirrorScene(0.0);
    input.mirrors[0].size = {3.0, 6.0};
    input.mirrors[0].world = placed({-1.5, 0.0, 0.0});
    render::Mirror wall = mirror({1.2, 1.0, -2.0}, {0, 0, 1}, {2.0, 1.6});
    wall.technique = render::MirrorTechnique::Texture;
    wall.reflectivity = 0.8;
    wall.tint = {1.0, 0.9, 0.8};
    input.mirrors.push_back(wall);
    const int width = 160, height = 90;
    const render::Image sharp = renderWith(input, GlossyFilter::Footprint, 16, width, height).image;
    ASSERT_EQ(sharp.width, width);
    EXPECT_EQ(lastReport().warnings.size(), 0u);
    dumpImage("glossy_roughness0", sharp);
    for (GlossyFilter filter : {GlossyFilter::Mip, GlossyFilter::Footprint, GlossyFilter::Chain})
        for (int taps : {1, 4, 16, 64}) {
            const render::Image other = renderWith(input, filter, taps, width, height).image;
            EXPECT_TRUE(other.rgba == sharp.rgba) << "filter " << int(filter) << ", " << taps << " taps";
        }
}

// The floor mirror at roughness 0.3 and 0.6 against the tracer (2048 paths per pixel, for a noise well below
// the errors measured): the RMSE over the mirror's pixels (linear radiance) of the Mip filter and of the
// Footprint filter at 1, 4, 16 and 64 taps.
TEST_F(GlossyAgreement, FootprintErrorFallsWithTapsAndBeatsMip) {
    const int width = 160, height = 96, samples = 2048;
    for (double roughness : {0.3, 0.6}) {
        SCOPED_TRACE("roughness " + std::to_string(roughness));
        const FrameInput input = floorMirrorScene(roughness);
        const reference::TraceResult traced = traceFrame(input, width, height, samples);
        for (float v : traced.image.rgba)
            ASSERT_TRUE(std::isfinite(v));
        const std::vector<std::uint8_t> mask = reference::mirrorMask(traced.ids);
        const double noise = maskedNoise(traced, mask);
        const std::string tag = "r" + std::to_string(int(std::lround(roughness * 10)));
        dumpImage("glossy_" + tag + "_reference", traced.image);

        auto measure = [&](GlossyFilter filter, int taps, const std::string& name) {
            const Still still = renderWith(input, filter, taps, width, height);
            auto stats = metrics::compare(still.image, traced.image, &mask, metrics::Encoding::Linear);
            EXPECT_TRUE(stats.ok()) << (stats.ok() ? "" : stats.error());
            const double rmse = stats.ok() ? stats->rmse : 1e9;
            // What is left of the error once the reference's own noise is taken out (errors add in squares).
            const double bias = std::sqrt(std::max(rmse * rmse - noise * noise, 0.0));
            std::printf(
                "[ measured ] roughness %.1f %-11s RMSE %.5f (without the tracer's noise %.5f; linear, "
                "%zu mirror px), still %.1f ms\n",
                roughness, name.c_str(), rmse, bias, stats.ok() ? stats->pixels : 0, still.ms);
            RecordProperty(tag + "_" + name + "_rmse", std::to_string(rmse));
            RecordProperty(tag + "_" + name + "_ms", std::to_string(still.ms));
            dumpImage("glossy_" + tag + "_" + name, still.image);
            return rmse;
        };
        const double mip = measure(GlossyFilter::Mip, 16, "mip");
        const double taps1 = measure(GlossyFilter::Footprint, 1, "footprint1");
        const double taps4 = measure(GlossyFilter::Footprint, 4, "footprint4");
        const double taps16 = measure(GlossyFilter::Footprint, 16, "footprint16");
        const double taps64 = measure(GlossyFilter::Footprint, 64, "footprint64");
        std::printf(
            "[ measured ] roughness %.1f tracer %d paths: noise %.5f on the mirror (%.5f whole image), "
            "%d glossy px, %.0f ms\n",
            roughness, samples, noise, traced.noiseRms, traced.glossyPixels, traced.totalMs);
        RecordProperty(tag + "_tracer_noise", std::to_string(noise));

        EXPECT_GT(std::count(mask.begin(), mask.end(), std::uint8_t(1)), width * height / 4)
            << "the mirror must fill a good part of the frame";
        // The reference must be much better than the differences it is to measure.
        EXPECT_LT(3.0 * noise, taps64);
        EXPECT_LT(taps16, mip);
        EXPECT_LT(taps64, mip);
        // More taps, less error: each step, down to the tracer's noise (measured strictly falling on
        // llvmpipe).
        EXPECT_LE(taps64, taps4 + noise);
        EXPECT_LE(taps64, taps16 + noise);
        EXPECT_LE(taps16, taps4 + noise);
        EXPECT_LE(taps4, taps1 + noise);
    }
}

// The convolved chain (four lookups a pixel up to roughness 0.4, 12 taps of its levels from 0.5) against
// the 16-tap footprint, both against the tracer on the mirror's pixels: within 1 dB of its PSNR at
// roughness 0.1, 0.3 and 0.6, and better than one mip level everywhere. Measured on llvmpipe: 30.8 / 29.7,
// 28.3 / 29.0 and 27.3 / 27.3 dB (chain / footprint).
TEST_F(GlossyAgreement, ChainComesWithinOneDecibelOfSixteenTaps) {
    const int width = 160, height = 96, samples = 1024;
    for (double roughness : {0.1, 0.3, 0.6}) {
        SCOPED_TRACE("roughness " + std::to_string(roughness));
        const FrameInput input = floorMirrorScene(roughness);
        const reference::TraceResult traced = traceFrame(input, width, height, samples);
        const std::vector<std::uint8_t> mask = reference::mirrorMask(traced.ids);
        const std::string tag = "r" + std::to_string(int(std::lround(roughness * 10)));
        auto psnr = [&](GlossyFilter filter, const std::string& name) {
            const Still still = renderWith(input, filter, 16, width, height);
            dumpImage("glossy_" + tag + "_" + name, still.image);
            auto stats = metrics::compare(still.image, traced.image, &mask);
            EXPECT_TRUE(stats.ok()) << (stats.ok() ? "" : stats.error());
            std::printf("[ measured ] roughness %.1f %-11s PSNR %.2f dB on the mirror, still %.1f ms\n",
                        roughness, name.c_str(), stats.ok() ? stats->psnr : 0.0, still.ms);
            return stats.ok() ? stats->psnr : 0.0;
        };
        dumpImage("glossy_" + tag + "_reference", traced.image);
        const double taps16 = psnr(GlossyFilter::Footprint, "footprint16");
        const double chain = psnr(GlossyFilter::Chain, "chain");
        const double mip = psnr(GlossyFilter::Mip, "mip");
        EXPECT_GE(chain, taps16 - 1.0);
        EXPECT_GT(chain, mip);
    }
}

bool allFinite(const render::Image& image) {
    for (float v : image.rgba)
        if (!std::isfinite(v))
            return false;
    return true;
}

// Roughness 1 (the widest lobe, the 1.5 cap on the tap's tangent), a camera almost in the mirror's plane
// (cos θ at its clamp, the footprint's axis degenerate) and one almost touching it (the eye distance
// nearly 0): every pixel finite for both filters; the harness fails the test on any GL error.
TEST_F(GlossyAgreement, NothingNonFiniteAtTheExtremes) {
    const int width = 96, height = 64;
    struct Case {
        const char* name;
        glm::dvec3 position, target, up;
        double near;
    };
    const Case cases[] = {
        {"ordinary view", {0.0, 1.1, 3.2}, {0.0, 0.1, -1.0}, {0, 1, 0}, 0.05},
        {"grazing", {0.0, 0.002, 3.5}, {0.0, 0.0, -3.0}, {0, 1, 0}, 0.001},
        {"close", {0.3, 0.003, 0.2}, {0.3, 0.0, 0.2}, {0, 0, -1}, 0.001},
    };
    for (const Case& c : cases) {
        FrameInput input = floorMirrorScene(1.0);
        input.camera.position = c.position;
        input.camera.target = c.target;
        input.camera.up = c.up;
        input.camera.near = c.near;
        for (GlossyFilter filter : {GlossyFilter::Mip, GlossyFilter::Footprint, GlossyFilter::Chain})
            for (int taps : {1, 64}) {
                const render::Image image = renderWith(input, filter, taps, width, height).image;
                ASSERT_EQ(image.width, width);
                EXPECT_TRUE(allFinite(image))
                    << c.name << ", filter " << int(filter) << ", " << taps << " taps";
                if (filter == GlossyFilter::Footprint && taps == 64)
                    dumpImage(std::string("glossy_extreme_") + (c.name[0] == 'g' ? "grazing" : c.name),
                              image);
            }
    }
}

// The brightness-weighted RMS spread in x of the masked pixels in columns [x0, x1) and rows [y0, y1), row
// by row (so that a slanted line does not count as wide): the width of a vertical bar's image.
double spreadX(const render::Image& image, const std::vector<std::uint8_t>& mask, int x0, int x1, int y0,
               int y1) {
    double weight = 0.0, squares = 0.0;
    for (int y = y0; y < y1; ++y) {
        double w = 0.0, sx = 0.0, sxx = 0.0;
        for (int x = x0; x < x1; ++x) {
            if (!mask[static_cast<std::size_t>(y) * image.width + x])
                continue;
            const glm::vec4 p = image.at(x, y);
            const double v = double(p.r + p.g + p.b);
            w += v;
            sx += v * x;
            sxx += v * x * x;
        }
        if (w <= 0.0)
            continue;
        weight += w;
        squares += sxx - sx * sx / w;
    }
    return weight > 0.0 ? std::sqrt(squares / weight) : 0.0;
}

// Two identical thin bright posts over a black floor mirror, one standing on it and one far above it. The
// Footprint filter blurs by the distance beyond the mirror, so the far post's reflection is the wider.
TEST_F(GlossyAgreement, BlurGrowsWithDistanceBeyondTheMirror) {
    FrameInput input;
    input.camera.position = {0.0, 1.6, 3.0};
    input.camera.target = {0.0, 0.0, -0.8};
    input.camera.fovY = 50.0;
    input.camera.near = 0.05;
    input.camera.far = 30.0;
    input.settings.background = {0.0, 0.0, 0.0};
    render::Mirror floor = mirror({0, 0, 0}, {0, 1, 0}, {8.0, 8.0});
    floor.roughness = 0.3;
    input.mirrors.push_back(floor);
    const glm::dvec3 post(0.02, 0.15, 0.02);
    input.items.push_back(
        item("Near post", boxMesh(), placed({-0.7, 0.15, -0.6}, post), emissive({1, 1, 1})));
    input.items.push_back(item("Far post", boxMesh(), placed({0.7, 1.65, -0.6}, post), emissive({1, 1, 1})));
    const int width = 320, height = 200;
    // Which pixels show the mirror (the tracer's ids of the first hit), and in which rows its sharp image
    // shows each post's reflection: the near one in the left half, the far one in the right.
    FrameInput sharpInput = input;
    sharpInput.mirrors[0].roughness = 0.0;
    const reference::TraceResult ids = traceFrame(sharpInput, width, height, 1);
    const std::vector<std::uint8_t> mask = reference::mirrorMask(ids.ids);
    const render::Image blurred = renderWith(input, GlossyFilter::Footprint, 64, width, height).image;
    const render::Image sharp = renderWith(sharpInput, GlossyFilter::Footprint, 64, width, height).image;
    ASSERT_EQ(blurred.width, width);
    dumpImage("glossy_posts_blurred", blurred);
    dumpImage("glossy_posts_sharp", sharp);
    // The middle half of the rows where the post's sharp reflection is, away from its ends (which blur along
    // the post as well).
    auto rows = [&](int x0, int x1, int& y0, int& y1) {
        int first = height, last = -1;
        for (int y = 0; y < height; ++y)
            for (int x = x0; x < x1; ++x)
                if (mask[static_cast<std::size_t>(y) * width + x] && ids.image.at(x, y).r > 0.5f) {
                    first = std::min(first, y);
                    last = std::max(last, y);
                }
        y0 = first + (last - first) / 4;
        y1 = last - (last - first) / 4;
    };
    int ny0, ny1, fy0, fy1;
    rows(0, width / 2, ny0, ny1);
    rows(width / 2, width, fy0, fy1);
    ASSERT_LT(ny0, ny1) << "the near post's reflection must be in the picture";
    ASSERT_LT(fy0, fy1) << "the far post's reflection must be in the picture";
    const double nearSharp = spreadX(sharp, mask, 0, width / 2, ny0, ny1);
    const double farSharp = spreadX(sharp, mask, width / 2, width, fy0, fy1);
    const double nearBlurred = spreadX(blurred, mask, 0, width / 2, ny0, ny1);
    const double farBlurred = spreadX(blurred, mask, width / 2, width, fy0, fy1);
    std::printf(
        "[ measured ] post reflections' RMS width in px, sharp -> roughness 0.3 (Footprint, 64 taps): "
        "near %.2f -> %.2f (rows %d..%d), far %.2f -> %.2f (rows %d..%d)\n",
        nearSharp, nearBlurred, ny0, ny1, farSharp, farBlurred, fy0, fy1);
    // The tracer's widths for comparison (not asserted: the raster's one distance per pixel, that of the
    // sharp reflection, gives the mirror around the near post the far background's wide blur).
    const reference::TraceResult traced = traceFrame(input, width, height, 256);
    dumpImage("glossy_posts_reference", traced.image);
    std::printf("[ measured ] the tracer's (256 paths): near %.2f, far %.2f\n",
                spreadX(traced.image, mask, 0, width / 2, ny0, ny1),
                spreadX(traced.image, mask, width / 2, width, fy0, fy1));
    RecordProperty("nearPostWidthPx", std::to_string(nearBlurred));
    RecordProperty("farPostWidthPx", std::to_string(farBlurred));
    EXPECT_GT(farBlurred, 2.0 * nearBlurred);
    // What the blur adds to the sharp width (in quadrature) grows too: the far post's image is the smaller.
    EXPECT_GT(farBlurred * farBlurred - farSharp * farSharp,
              4.0 * (nearBlurred * nearBlurred - nearSharp * nearSharp));
}

} // namespace
} // namespace speculum::test
