// FLIP, SSIM, MAE, relative MSE and the reference-noise figures on inputs whose answers are known by
// construction or computed by hand from the papers' formulas.
#include "render/image/ColorSpace.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/Flip.hpp"
#include "render/metrics/ReferenceNoise.hpp"
#include "render/metrics/Ssim.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace speculum::test {
namespace {

using namespace render::metrics;

render::Image filled(int w, int h, float r, float g, float b) {
    render::Image image;
    image.width = w;
    image.height = h;
    for (int i = 0; i < w * h; ++i)
        image.rgba.insert(image.rgba.end(), {r, g, b, 1.0f});
    return image;
}

// A linear image with structure: a diagonal gradient with a bright square and a thin dark line.
render::Image patterned(int w, int h) {
    render::Image image = filled(w, h, 0.0f, 0.0f, 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &image.rgba[(std::size_t(y) * w + x) * 4];
            const float t = float(x + y) / float(w + h);
            p[0] = t;
            p[1] = 0.5f * t + 0.2f;
            p[2] = 1.0f - t;
            if (x > w / 4 && x < w / 2 && y > h / 4 && y < h / 2)
                p[0] = p[1] = p[2] = 0.9f;
            if (x == 3 * w / 4)
                p[0] = p[1] = p[2] = 0.02f;
        }
    return image;
}

TEST(Flip, OfAnImageWithItselfIsZero) {
    const render::Image image = patterned(48, 32);
    auto ldr = ldrFlip(image, image);
    ASSERT_TRUE(ldr.ok());
    EXPECT_EQ(ldr->mean, 0.0);
    auto hdr = hdrFlip(image, image);
    ASSERT_TRUE(hdr.ok());
    EXPECT_EQ(hdr->mean, 0.0);
    EXPECT_EQ(ldr->errors.size(), 48u * 32u);
}

TEST(Flip, PureGreenAgainstPureBlueIsTheLargestError) {
    // The papers normalise the colour error by the distance between green and blue: on uniform images
    // (no features) that pair scores exactly 1.
    auto flip = ldrFlip(filled(24, 24, 0, 1, 0), filled(24, 24, 0, 0, 1));
    ASSERT_TRUE(flip.ok());
    EXPECT_NEAR(flip->mean, 1.0, 1e-4);
}

TEST(Flip, BlackAgainstWhiteByHand) {
    // By hand from the HPG 2020 formulas with the CIELAB values of the sRGB primaries (L, a, b):
    // green (87.737, −86.185, 83.181), blue (32.303, 79.197, −107.864). Hunt-adjusted (a, b × L/100)
    // their HyAB distance is 55.434 + 147.88 = 203.31, so c_max = 203.31^0.7 = 41.27. Black against white
    // is HyAB 100, 100^0.7 = 25.12: above p_c · c_max = 16.51, so 0.95 + (25.12 − 16.51)/(41.27 − 16.51)
    // · 0.05 = 0.9674.
    auto flip = ldrFlip(filled(24, 24, 0, 0, 0), filled(24, 24, 1, 1, 1));
    ASSERT_TRUE(flip.ok());
    EXPECT_NEAR(flip->mean, 0.9674, 1e-3);
}

TEST(Flip, GrowsWithTheDifferenceAndEdgesCountMore) {
    const render::Image grey = filled(32, 32, 0.2f, 0.2f, 0.2f);
    double previous = 0.0;
    for (float offset : {0.01f, 0.03f, 0.1f, 0.3f}) {
        const render::Image brighter = filled(32, 32, 0.2f + offset, 0.2f + offset, 0.2f + offset);
        auto flip = ldrFlip(brighter, grey);
        ASSERT_TRUE(flip.ok());
        EXPECT_GT(flip->mean, previous);
        previous = flip->mean;
    }
    // A thin line that only one image has: the feature term raises its error above the colour term's.
    render::Image line = grey;
    for (int y = 0; y < 32; ++y)
        for (int c = 0; c < 3; ++c)
            line.rgba[(std::size_t(y) * 32 + 16) * 4 + c] = 0.5f;
    auto withLine = ldrFlip(line, grey);
    ASSERT_TRUE(withLine.ok());
    const float onLine = withLine->errors[16 * 32 + 16], beside = withLine->errors[16 * 32 + 20];
    EXPECT_GT(onLine, 0.3f);
    EXPECT_GT(beside, 0.0f) << "the eye's filters spread the line";
    EXPECT_LT(beside, onLine);
}

TEST(Flip, HdrSeesWhatClampingHides) {
    // Both images are brighter than the display's white everywhere: LDR-FLIP sees no difference, HDR-FLIP
    // looks at them through darker exposures and does.
    const render::Image reference = filled(16, 16, 4.0f, 4.0f, 4.0f);
    const render::Image test = filled(16, 16, 6.0f, 6.0f, 6.0f);
    auto ldr = ldrFlip(test, reference);
    auto hdr = hdrFlip(test, reference);
    ASSERT_TRUE(ldr.ok() && hdr.ok());
    EXPECT_EQ(ldr->mean, 0.0);
    EXPECT_GT(hdr->mean, 0.05);
}

TEST(Flip, HdrExposureRangeSpansTheBrightestToTheMedian) {
    // A third of the pixels at 16, the rest at 1/16: from the brightest to the median is 8 stops, so eight
    // exposures spread evenly over them.
    render::Image reference = filled(3, 30, 1.0f / 16.0f, 1.0f / 16.0f, 1.0f / 16.0f);
    for (int y = 0; y < 30; ++y)
        for (int c = 0; c < 3; ++c)
            reference.rgba[std::size_t(y) * 3 * 4 + std::size_t(c)] = 16.0f;
    auto hdr = hdrFlip(reference, reference);
    ASSERT_TRUE(hdr.ok());
    EXPECT_NEAR(hdr->stopExposure - hdr->startExposure, 8.0, 1e-6);
    EXPECT_EQ(hdr->exposures, 8);
    // A black reference still gives a figure (one exposure, twice), not a NaN.
    auto black = hdrFlip(filled(4, 4, 0.5f, 0.5f, 0.5f), filled(4, 4, 0, 0, 0));
    ASSERT_TRUE(black.ok());
    EXPECT_TRUE(std::isfinite(black->mean));
    EXPECT_EQ(black->exposures, 2);
}

TEST(Flip, HdrIsTheSameEveryTimeWhateverTheThreadsDo) {
    // Two exposures shared by the cores: whichever thread takes which, every exposure counts.
    const render::Image reference = filled(16, 16, 0.0f, 0.0f, 0.0f), test = filled(16, 16, 0.5f, 0.5f, 0.5f);
    auto first = hdrFlip(test, reference);
    ASSERT_TRUE(first.ok());
    EXPECT_EQ(first->exposures, 2);
    EXPECT_GT(first->mean, 0.1);
    for (int i = 0; i < 50; ++i) {
        auto again = hdrFlip(test, reference);
        ASSERT_TRUE(again.ok());
        ASSERT_EQ(again->mean, first->mean) << "run " << i;
    }
}

TEST(Flip, MasksAndSizes) {
    auto flip = ldrFlip(filled(4, 1, 0, 1, 0), filled(4, 1, 0, 0, 1));
    ASSERT_TRUE(flip.ok());
    EXPECT_NEAR(*flip->meanOver({0, 1, 0, 0}), 1.0, 1e-4);
    EXPECT_FALSE(flip->meanOver({0, 0, 0, 0}).has_value());
    EXPECT_FALSE(flip->meanOver({1, 1}).has_value());
    EXPECT_FALSE(ldrFlip(filled(4, 1, 0, 0, 0), filled(2, 2, 0, 0, 0)).ok());
    const render::Image map = flipColorMap(*flip);
    EXPECT_EQ(map.width, 4);
    EXPECT_GT(map.at(0, 0).r, 0.9f) << "an error of 1 is magma's pale yellow";
    auto none = ldrFlip(filled(2, 1, 0.3f, 0.3f, 0.3f), filled(2, 1, 0.3f, 0.3f, 0.3f));
    EXPECT_LT(flipColorMap(*none).at(0, 0).r, 0.01f) << "no error is black";
}

TEST(Ssim, IdenticalImagesScoreOne) {
    const render::Image image = patterned(40, 30);
    auto s = ssim(image, image);
    ASSERT_TRUE(s.ok());
    EXPECT_NEAR(s->mean, 1.0, 1e-6);
}

TEST(Ssim, UniformImagesByHand) {
    // No contrast in either image: only the luminance term is left, (2 μx μy + C1) / (μx² + μy² + C1),
    // on the sRGB values 0.5 and 0.25.
    const float a = render::srgbToLinear(0.5f), b = render::srgbToLinear(0.25f);
    auto s = ssim(filled(16, 16, a, a, a), filled(16, 16, b, b, b));
    ASSERT_TRUE(s.ok());
    const double c1 = 1e-4;
    EXPECT_NEAR(s->mean, (2 * 0.5 * 0.25 + c1) / (0.25 + 0.0625 + c1), 1e-4);
}

TEST(Ssim, InvertedStructureScoresBelowZero) {
    // A checkerboard against its inverse: the same means and contrasts, opposite structure.
    render::Image x = filled(16, 16, 0, 0, 0), y = x;
    const float dark = render::srgbToLinear(0.25f), light = render::srgbToLinear(0.75f);
    for (int i = 0; i < 16 * 16; ++i) {
        const bool odd = ((i % 16) + (i / 16)) % 2 == 1;
        for (int c = 0; c < 3; ++c) {
            x.rgba[std::size_t(i) * 4 + c] = odd ? light : dark;
            y.rgba[std::size_t(i) * 4 + c] = odd ? dark : light;
        }
    }
    auto s = ssim(x, y);
    ASSERT_TRUE(s.ok());
    EXPECT_LT(s->mean, -0.9);
    const std::vector<std::uint8_t> none(16 * 16, 0);
    EXPECT_EQ(ssim(x, y, &none)->mean, 1.0);
}

TEST(ErrorMetrics, MaeAndRelativeMseByHand) {
    auto linear =
        compare(filled(3, 2, 0.5f, 0.5f, 0.5f), filled(3, 2, 0.6f, 0.6f, 0.6f), nullptr, Encoding::Linear);
    ASSERT_TRUE(linear.ok());
    EXPECT_NEAR(linear->mae, 0.1, 1e-6);
    EXPECT_NEAR(linear->relativeMse, 0.01 / (0.36 + kRelativeMseEpsilon), 1e-6);
    auto srgb = compare(filled(3, 2, 0.5f, 0.5f, 0.5f), filled(3, 2, 0.6f, 0.6f, 0.6f));
    EXPECT_NEAR(srgb->mae, render::linearToSrgb(0.6f) - render::linearToSrgb(0.5f), 1e-6);
    EXPECT_NEAR(srgb->relativeMse, linear->relativeMse, 1e-9) << "relative MSE is on linear values";
    // One red value off by 0.3 against black, in 1 of 2 pixels: MAE 0.3/6, relative MSE 0.09/0.01/6.
    render::Image test = filled(2, 1, 0, 0, 0);
    test.rgba[0] = 0.3f;
    auto one = compare(test, filled(2, 1, 0, 0, 0), nullptr, Encoding::Linear);
    EXPECT_NEAR(one->mae, 0.05, 1e-6);
    EXPECT_NEAR(one->relativeMse, 1.5, 1e-5);
}

TEST(ReferenceNoise, TheIntervalHalvesWhenTheNoiseDoes) {
    // Quadrupling the reference's samples quarters its variance: the interval on the RMSE halves.
    const render::Image reference = patterned(32, 32);
    render::Image test = reference;
    for (std::size_t i = 0; i < test.rgba.size(); ++i)
        if (i % 4 != 3)
            test.rgba[i] = std::min(1.0f, test.rgba[i] * 1.15f + 0.01f);
    const float variance = 1e-5f;
    auto wide = noiseInterval(test, reference, filled(32, 32, variance, variance, variance));
    auto narrow = noiseInterval(test, reference, filled(32, 32, variance / 4, variance / 4, variance / 4));
    ASSERT_TRUE(wide.ok() && narrow.ok());
    const double wideWidth = wide->rmseHigh - wide->rmseLow, narrowWidth = narrow->rmseHigh - narrow->rmseLow;
    EXPECT_GT(wideWidth, 0.0);
    EXPECT_NEAR(narrowWidth / wideWidth, 0.5, 0.02);
    EXPECT_NEAR(narrow->noiseRms / wide->noiseRms, 0.5, 1e-6);
    EXPECT_LE(wide->rmseLow, wide->rmse);
    EXPECT_GE(wide->rmseHigh, wide->rmse);
    EXPECT_LE(wide->psnrLow, wide->psnrHigh);
    auto exact = noiseInterval(test, reference, filled(32, 32, 0, 0, 0));
    EXPECT_EQ(exact->rmseHigh - exact->rmseLow, 0.0) << "a noiseless reference gives a point";
}

TEST(ReferenceNoise, TheIntervalIsForTheErrorAgainstTheNoiselessImage) {
    // A noisy reference: the truth plus ±σ, alternating, with the tracer's estimate of σ² beside it.
    const render::Image truth = filled(32, 32, 0.2f, 0.2f, 0.2f);
    render::Image noisy = truth;
    const float sigma = 0.01f;
    for (std::size_t i = 0; i < noisy.rgba.size(); ++i)
        if (i % 4 != 3)
            noisy.rgba[i] += (i / 4 + i % 4) % 2 == 0 ? sigma : -sigma;
    const render::Image variance = filled(32, 32, sigma * sigma, sigma * sigma, sigma * sigma);
    // A perfect raster image: measured against the noisy reference it seems off by σ, the interval says 0.
    auto perfect = noiseInterval(truth, noisy, variance);
    ASSERT_TRUE(perfect.ok());
    EXPECT_GT(perfect->rmse, 0.0) << "the measured error is the noise's";
    EXPECT_EQ(perfect->rmseLow, 0.0);
    EXPECT_LT(perfect->rmseHigh, 0.5 * perfect->rmse);
    EXPECT_EQ(perfect->psnrHigh, kMaxPsnr);
    // An image 0.03 too bright (linear): its true error lies inside the interval, the measured one above.
    const render::Image brighter = filled(32, 32, 0.23f, 0.23f, 0.23f);
    auto offset = noiseInterval(brighter, noisy, variance);
    auto trueError = compare(brighter, truth);
    ASSERT_TRUE(offset.ok() && trueError.ok());
    EXPECT_LE(offset->rmseLow, trueError->rmse);
    EXPECT_GE(offset->rmseHigh, trueError->rmse);
    EXPECT_GT(offset->rmse, trueError->rmse) << "the noise makes the measured error pessimistic";
}

TEST(ReferenceNoise, DifferencesWithinTheNoiseAreTies) {
    const render::Image reference = patterned(32, 32);
    render::Image a = reference, b = reference;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        a.rgba[i] = std::min(1.0f, a.rgba[i] + 0.004f);
        b.rgba[i] = std::max(0.0f, b.rgba[i] - 0.003f);
    }
    const float noisy = 1e-3f; // a standard error of ~0.03 linear
    auto tie = compareWithinNoise(a, b, reference, filled(32, 32, noisy, noisy, noisy));
    ASSERT_TRUE(tie.ok());
    EXPECT_TRUE(tie->tie) << tie->mseDifference << " ± " << tie->standardError;
    // Without the noise, the same small difference is measurable.
    auto exact = compareWithinNoise(a, b, reference, filled(32, 32, 0, 0, 0));
    EXPECT_FALSE(exact->tie);
    // A large difference stands out of the same noise.
    render::Image far = reference;
    for (std::size_t i = 0; i < far.rgba.size(); i += 4)
        far.rgba[i] = std::min(1.0f, far.rgba[i] + 0.3f);
    auto clear = compareWithinNoise(far, a, reference, filled(32, 32, noisy, noisy, noisy));
    EXPECT_FALSE(clear->tie);
    EXPECT_GT(clear->mseDifference, 0.0) << "far is the worse of the two";
}

} // namespace
} // namespace speculum::test
