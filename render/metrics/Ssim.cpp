#include "render/metrics/Ssim.hpp"

#include "render/image/ColorSpace.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/Plane.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::render::metrics {

namespace {

constexpr double kWindowSigma = 1.5;
constexpr int kWindowRadius = 5; // 11 taps
constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;

Plane channel(const Image& image, int c) {
    Plane plane(image.width, image.height);
    for (std::size_t p = 0; p < plane.values.size(); ++p) {
        const float v = image.rgba[p * 4 + std::size_t(c)];
        plane.values[p] = std::isfinite(v) ? linearToSrgb(std::clamp(v, 0.0f, 1.0f)) : 0.0f;
    }
    return plane;
}

Plane product(const Plane& a, const Plane& b) {
    Plane out(a.width, a.height);
    for (std::size_t p = 0; p < out.values.size(); ++p)
        out.values[p] = a.values[p] * b.values[p];
    return out;
}

// Adds channel c's SSIM map to `sum`.
void addChannel(const Image& test, const Image& reference, int c, std::vector<float>& sum) {
    const Kernel window = gaussianKernel(kWindowSigma, kWindowRadius);
    const Plane x = channel(test, c), y = channel(reference, c);
    auto blur = [&](const Plane& p) { return convolveSeparable(p, window, window); };
    const Plane mx = blur(x), my = blur(y), xx = blur(product(x, x)), yy = blur(product(y, y)),
                xy = blur(product(x, y));
    for (std::size_t p = 0; p < sum.size(); ++p) {
        const double mux = mx.values[p], muy = my.values[p];
        const double vx = xx.values[p] - mux * mux, vy = yy.values[p] - muy * muy,
                     cov = xy.values[p] - mux * muy;
        const double s =
            (2.0 * mux * muy + kC1) * (2.0 * cov + kC2) / ((mux * mux + muy * muy + kC1) * (vx + vy + kC2));
        sum[p] += float(s);
    }
}

} // namespace

base::Result<SsimResult> ssim(const Image& test, const Image& reference,
                              const std::vector<std::uint8_t>* mask) {
    if (base::Status sizes = checkComparable(test, reference, mask); !sizes)
        return base::Error{sizes.error()};
    const std::size_t pixels = static_cast<std::size_t>(test.width) * test.height;
    SsimResult result;
    result.map.assign(pixels, 0.0f);
    for (int c = 0; c < 3; ++c)
        addChannel(test, reference, c, result.map);
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        result.map[p] /= 3.0f;
        if (mask && (*mask)[p] == 0)
            continue;
        sum += result.map[p];
        ++count;
    }
    result.mean = count > 0 ? sum / double(count) : 1.0;
    return result;
}

} // namespace speculum::render::metrics
