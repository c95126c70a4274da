#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"

#include <cstdint>
#include <vector>

namespace speculum::render::metrics {

// What a path-traced reference's own Monte Carlo noise does to an error figure measured against it. The
// noise is the tracer's per-pixel estimate (reference::TraceResult::noise: each value's squared standard
// error, linear RGB). Errors are measured on the sRGB encoding, so the noise is carried into it by the
// encoding's slope at the reference's value (0 where the reference is above 1 and clamped).
//
// The figures are first-order (the delta method). Against a noisy reference r̂ = r + ε the measured MSE m
// is on average the true one plus the mean of s² (s the noise's standard deviation in sRGB), with variance
// Σ (4 d² s² + 2 s⁴) / M² over the M values, d the true difference. The interval is for the error against
// the noiseless image: m less the mean s², ± 1.96 standard errors (d² estimated by the measured d² − s²),
// so it can lie below the measured error. Quadrupling the reference's samples halves s and so halves the
// interval while the error dominates.

// The z of a two-sided 95 % interval.
inline constexpr double kConfidenceZ = 1.96;

struct NoiseInterval {
    double rmse = 0.0;    // the measured RMSE (sRGB)
    double rmseLow = 0.0; // the 95 % interval of the RMSE against the noiseless image
    double rmseHigh = 0.0;
    double psnrLow = 0.0; // the PSNR interval (dB, from rmseHigh and rmseLow)
    double psnrHigh = 0.0;
    double noiseRms = 0.0;     // the reference's noise in sRGB, RMS over the values compared
    double maeHalfWidth = 0.0; // ± on the MAE: 1.96 √(Σ s²) / M
};

// Errors: sizes differ, or the mask's length is wrong. No pixel selected: all zero.
base::Result<NoiseInterval> noiseInterval(const Image& test, const Image& reference, const Image& noise,
                                          const std::vector<std::uint8_t>* mask = nullptr);

// Two images measured against the same noisy reference: the difference of their MSEs (a − b; negative:
// a is closer) and its standard error from the reference's noise alone, Σ 4 (a − b)² s² / M² (the
// noise moves both errors together, so only where a and b differ does it count). A difference within
// 1.96 standard errors is a tie: the reference cannot tell them apart.
struct PairedComparison {
    double mseDifference = 0.0;
    double standardError = 0.0;
    bool tie = true;
};

base::Result<PairedComparison> compareWithinNoise(const Image& a, const Image& b, const Image& reference,
                                                  const Image& noise,
                                                  const std::vector<std::uint8_t>* mask = nullptr);

} // namespace speculum::render::metrics
