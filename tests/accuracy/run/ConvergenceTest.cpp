// Is the reference good enough? Its noise halves as its paths quadruple, and so does the interval it
// leaves on an error figure; the study picks the paths a run needs.
#include "accuracy/run/Convergence.hpp"

#include "accuracy/run/Furnace.hpp"
#include "accuracy/run/Measure.hpp"
#include "render/metrics/ReferenceNoise.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace speculum::test {
namespace {

// A rough floor mirror seen at a slant under a white sky: every pixel is rough, so every pixel is noisy.
accuracy::SweepInput roughFloor() {
    accuracy::SweepInput input;
    input.sceneName = "rough floor";
    input.scene = accuracy::planarFurnace(0.6, 40.0);
    input.quick = true;
    return input;
}

TEST(ReferenceConvergence, NoiseHalvesAsPathsQuadrupleAndTheNeededCountIsPicked) {
    auto study = accuracy::studyConvergence(roughFloor(), 16, 16, 0.25);
    ASSERT_TRUE(study.ok()) << study.error();
    EXPECT_FALSE(study->exact);
    ASSERT_EQ(study->points.size(), accuracy::convergenceSamples(true).size());
    for (std::size_t i = 1; i < study->points.size(); ++i) {
        const double ratio = study->points[i].noise / study->points[i - 1].noise;
        std::printf("[ measured ] %4d paths: noise %.5f (×%.3f), RMSE against the most %.5f\n",
                    study->points[i].samples, study->points[i].noise, ratio, study->points[i].rmse);
        EXPECT_NEAR(ratio, 0.5, 0.1) << study->points[i].samples;
    }
    EXPECT_NEAR(study->slope, -0.5, 0.05);
    // The pick: the fewest paths whose noise is below a tenth of the smallest error (0.025).
    ASSERT_TRUE(study->enough.has_value()) << "256 paths should get below 0.025";
    for (const accuracy::ConvergencePoint& p : study->points) {
        if (p.samples < *study->enough) {
            EXPECT_GT(p.noise, 0.025) << p.samples;
        }
        if (p.samples == *study->enough) {
            EXPECT_LE(p.noise, 0.025);
        }
    }
    // A smaller error asks for more paths than were traced: extrapolated along the slope (noise ∝ n^−½:
    // ten times less noise than 256 paths have needs about 100 × 256).
    auto strict = accuracy::studyConvergence(roughFloor(), 16, 16, study->points.back().noise);
    ASSERT_TRUE(strict.ok());
    EXPECT_FALSE(strict->enough.has_value());
    EXPECT_NEAR(std::log10(double(strict->extrapolated)), std::log10(25600.0), 0.15);
}

TEST(ReferenceConvergence, TheIntervalOnAnErrorHalvesAsPathsQuadruple) {
    const render::FrameInput scene = accuracy::planarFurnace(0.6, 40.0);
    auto coarse = accuracy::traceReference(scene, accuracy::ReferenceKind::Scene, 16, 16, {}, 64);
    auto fine = accuracy::traceReference(scene, accuracy::ReferenceKind::Scene, 16, 16, {}, 256);
    ASSERT_TRUE(coarse.ok() && fine.ok());
    // A raster-like image 8 % too dark: its error dominates the noise.
    render::Image test = fine->traced.image;
    for (std::size_t i = 0; i < test.rgba.size(); ++i)
        if (i % 4 != 3)
            test.rgba[i] *= 0.92f;
    auto wide = render::metrics::noiseInterval(test, coarse->traced.image, coarse->traced.noise);
    auto narrow = render::metrics::noiseInterval(test, fine->traced.image, fine->traced.noise);
    ASSERT_TRUE(wide.ok() && narrow.ok());
    const double ratio = (narrow->rmseHigh - narrow->rmseLow) / (wide->rmseHigh - wide->rmseLow);
    std::printf("[ measured ] RMSE interval at 64 paths %.5f–%.5f, at 256 %.5f–%.5f: ×%.3f\n", wide->rmseLow,
                wide->rmseHigh, narrow->rmseLow, narrow->rmseHigh, ratio);
    EXPECT_NEAR(ratio, 0.5, 0.1);
}

// Two raster-like images against one traced reference: where they differ by less than the reference's noise
// can tell apart they are tied, where by more they are ranked; against an exact reference nothing is tied.
// (The noise is shared, so a small difference repeated over many pixels is still told apart: the test
// changes one 4x4 patch.)
TEST(ReferenceConvergence, RasterImagesThatDifferWithinTheReferencesNoiseAreTied) {
    auto patched = [](const render::Image& image, float factor) {
        render::Image out = image;
        for (int y = 6; y < 10; ++y)
            for (int x = 6; x < 10; ++x)
                for (int c = 0; c < 3; ++c)
                    out.rgba[(std::size_t(y) * 16 + std::size_t(x)) * 4 + std::size_t(c)] *= factor;
        return out;
    };
    auto tiedAgainst = [&](const accuracy::Reference& reference, float factor) {
        const render::Image& image = reference.traced.image;
        auto tie =
            accuracy::comparedWithinNoise(image, patched(image, factor), reference, accuracy::Metric::Psnr);
        EXPECT_TRUE(tie.ok());
        return tie.ok() && *tie;
    };
    auto noisy = accuracy::traceReference(accuracy::planarFurnace(0.6, 40.0), accuracy::ReferenceKind::Scene,
                                          16, 16, {}, 16);
    ASSERT_TRUE(noisy.ok());
    EXPECT_TRUE(tiedAgainst(*noisy, 0.99f)) << "1 % on 16 pixels, against ±4 % noise";
    EXPECT_FALSE(tiedAgainst(*noisy, 0.7f)) << "30 % on the same pixels";
    auto exact = accuracy::traceReference(accuracy::planarFurnace(0.0, 40.0), accuracy::ReferenceKind::Scene,
                                          16, 16, {}, 16);
    ASSERT_TRUE(exact.ok());
    EXPECT_FALSE(tiedAgainst(*exact, 0.99f)) << "an exact reference tells even 1 % apart";
}

TEST(ReferenceConvergence, ASceneWithoutRoughSurfacesIsExact) {
    accuracy::SweepInput input = roughFloor();
    input.scene = accuracy::planarFurnace(0.0, 40.0);
    auto study = accuracy::studyConvergence(input, 8, 8, 0.01);
    ASSERT_TRUE(study.ok());
    EXPECT_TRUE(study->exact);
    EXPECT_TRUE(study->points.empty());
}

} // namespace
} // namespace speculum::test
