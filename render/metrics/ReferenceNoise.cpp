#include "render/metrics/ReferenceNoise.hpp"

#include "render/image/ColorSpace.hpp"
#include "render/metrics/ErrorMetrics.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::render::metrics {

namespace {

double srgbOf(float linear) {
    return std::isfinite(linear) ? linearToSrgb(std::clamp(linear, 0.0f, 1.0f)) : 0.0;
}

// The sRGB encoding's slope at a linear value: how far a small linear error moves the encoded value.
double srgbSlope(float linear) {
    if (!std::isfinite(linear) || linear > 1.0f)
        return 0.0;
    if (linear <= 0.0031308f)
        return 12.92;
    return 1.055 / 2.4 * std::pow(double(linear), 1.0 / 2.4 - 1.0);
}

// The noise's variance in sRGB at value i (pixel · 4 + channel).
double srgbVariance(const Image& reference, const Image& noise, std::size_t i) {
    const double variance = std::isfinite(noise.rgba[i]) ? std::max(0.0f, noise.rgba[i]) : 0.0;
    const double slope = srgbSlope(reference.rgba[i]);
    return slope * slope * variance;
}

base::Status checkInputs(const Image& a, const Image& reference, const Image& noise,
                         const std::vector<std::uint8_t>* mask) {
    for (const Image* image : {&a, &noise})
        if (image->width != reference.width || image->height != reference.height ||
            image->rgba.size() != reference.rgba.size())
            return base::Error{"the images, the reference and its noise must be the same size"};
    if (mask && mask->size() != reference.rgba.size() / 4)
        return base::Error{"the mask's length is not the image's"};
    return base::Done{};
}

double psnrOf(double rmse) {
    return rmse > 0.0 ? std::min(kMaxPsnr, -20.0 * std::log10(rmse)) : kMaxPsnr;
}

} // namespace

base::Result<NoiseInterval> noiseInterval(const Image& test, const Image& reference, const Image& noise,
                                          const std::vector<std::uint8_t>* mask) {
    if (base::Status ok = checkInputs(test, reference, noise, mask); !ok)
        return base::Error{ok.error()};
    double squares = 0.0, varianceSum = 0.0, mseVariance = 0.0;
    std::size_t values = 0;
    for (std::size_t p = 0; p < reference.rgba.size() / 4; ++p) {
        if (mask && (*mask)[p] == 0)
            continue;
        for (std::size_t i = p * 4; i < p * 4 + 3; ++i) {
            const double d = srgbOf(test.rgba[i]) - srgbOf(reference.rgba[i]);
            const double s2 = srgbVariance(reference, noise, i);
            squares += d * d;
            varianceSum += s2;
            // The measured d² overstates the true one by s² on average: 4 d² s² − 2 s⁴ is the plug-in
            // estimate of 4 d_true² s² + 2 s⁴.
            mseVariance += 4.0 * d * d * s2 - 2.0 * s2 * s2;
            ++values;
        }
    }
    NoiseInterval interval;
    if (values == 0)
        return interval;
    const double m = double(values), mse = squares / m;
    // The noise adds its own variance to the measured MSE on average: the error against the noiseless
    // image is estimated by taking it off.
    const double trueMse = std::max(0.0, mse - varianceSum / m);
    const double mseError = std::sqrt(std::max(0.0, mseVariance)) / m;
    interval.rmse = std::sqrt(mse);
    interval.rmseLow = std::sqrt(std::max(0.0, trueMse - kConfidenceZ * mseError));
    interval.rmseHigh = std::sqrt(trueMse + kConfidenceZ * mseError);
    interval.psnrLow = psnrOf(interval.rmseHigh);
    interval.psnrHigh = psnrOf(interval.rmseLow);
    interval.noiseRms = std::sqrt(varianceSum / m);
    interval.maeHalfWidth = kConfidenceZ * std::sqrt(varianceSum) / m;
    return interval;
}

base::Result<PairedComparison> compareWithinNoise(const Image& a, const Image& b, const Image& reference,
                                                  const Image& noise, const std::vector<std::uint8_t>* mask) {
    if (base::Status ok = checkInputs(a, reference, noise, mask); !ok)
        return base::Error{ok.error()};
    if (base::Status ok = checkInputs(b, reference, noise, mask); !ok)
        return base::Error{ok.error()};
    double difference = 0.0, variance = 0.0;
    std::size_t values = 0;
    for (std::size_t p = 0; p < reference.rgba.size() / 4; ++p) {
        if (mask && (*mask)[p] == 0)
            continue;
        for (std::size_t i = p * 4; i < p * 4 + 3; ++i) {
            const double r = srgbOf(reference.rgba[i]), sa = srgbOf(a.rgba[i]), sb = srgbOf(b.rgba[i]);
            difference += (sa - r) * (sa - r) - (sb - r) * (sb - r);
            variance += 4.0 * (sa - sb) * (sa - sb) * srgbVariance(reference, noise, i);
            ++values;
        }
    }
    PairedComparison comparison;
    if (values == 0)
        return comparison;
    const double m = double(values);
    comparison.mseDifference = difference / m;
    comparison.standardError = std::sqrt(variance) / m;
    comparison.tie = std::abs(comparison.mseDifference) <= kConfidenceZ * comparison.standardError;
    return comparison;
}

} // namespace speculum::render::metrics
