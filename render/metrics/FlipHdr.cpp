// HDR-FLIP's exposure range and tone mapping, and the FLIP colour map.
#include "render/image/ColorSpace.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/Flip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <thread>

namespace speculum::render::metrics {

namespace {

// The ACES filmic curve as Narkowicz fitted it, y = x (a x + b) / (x (c x + d) + e), applied to 0.6 x as
// HDR-FLIP does (the fit's own pre-exposure), so y = (k0 x² + k1 x) / (k3 x² + k4 x + k5).
constexpr double kPre = 0.6;
constexpr double k0 = kPre * kPre * 2.51, k1 = kPre * 0.03, k3 = kPre * kPre * 2.43, k4 = kPre * 0.59,
                 k5 = 0.14;
// The tone-mapped value the range's ends bring the brightest and the median pixel to.
constexpr double kExposureTarget = 0.85;

float toneMapped(float value, double scale) {
    if (std::isnan(value) || !(value > 0.0f))
        return 0.0f;
    const double x = double(value) * scale;
    if (!std::isfinite(x))
        return 1.0f;
    return float(std::clamp((k0 * x * x + k1 * x) / (k3 * x * x + k4 * x + k5), 0.0, 1.0));
}

// The x the curve maps to `t`: the positive root of (k0 − k3 t) x² + (k1 − k4 t) x − k5 t = 0.
double toneMapInverse(double t) {
    const double a = k0 - k3 * t, b = k1 - k4 * t, c = -k5 * t;
    return (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

struct ExposureRange {
    double start = 0.0, stop = 0.0;
    int count = 2;
};

ExposureRange exposureRange(const Image& reference) {
    std::vector<double> luminance(reference.rgba.size() / 4);
    for (std::size_t p = 0; p < luminance.size(); ++p) {
        const glm::dvec3 rgb(reference.rgba[p * 4], reference.rgba[p * 4 + 1], reference.rgba[p * 4 + 2]);
        const double y = 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
        luminance[p] = std::isfinite(y) ? std::max(y, 0.0) : 0.0;
    }
    ExposureRange range;
    if (luminance.empty())
        return range;
    const double brightest = *std::max_element(luminance.begin(), luminance.end());
    if (!(brightest > 0.0))
        return range; // a black reference: one exposure, twice
    auto middle = luminance.begin() + std::ptrdiff_t(luminance.size() / 2);
    std::nth_element(luminance.begin(), middle, luminance.end());
    // A median of black (a mostly black image) would ask for infinite exposure: the range then ends where
    // it starts.
    const double median = *middle > 0.0 ? *middle : brightest;
    const double x = toneMapInverse(kExposureTarget);
    range.start = std::log2(x / brightest);
    range.stop = std::log2(x / median);
    range.count = std::max(2, static_cast<int>(std::ceil(range.stop - range.start)));
    return range;
}

Image toneMappedImage(const Image& image, double exposure) {
    Image out = image;
    const double scale = std::exp2(exposure);
    for (std::size_t i = 0; i < out.rgba.size(); ++i)
        out.rgba[i] = i % 4 == 3 ? 1.0f : toneMapped(image.rgba[i], scale);
    return out;
}

// The per-pixel largest LDR-FLIP over the exposures, the exposures shared out over the machine's cores
// (each is independent). Each worker keeps one running maximum, so memory does not grow with the number of
// exposures; the shares are fixed, so the result never depends on timing.
base::Result<std::vector<float>> largestOverExposures(const Image& test, const Image& reference,
                                                      const ExposureRange& range, double pixelsPerDegree) {
    const double step = (range.stop - range.start) / double(range.count - 1);
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const unsigned workers = std::min(cores, static_cast<unsigned>(range.count));
    std::vector<std::vector<float>> largest(workers);
    std::vector<std::string> failures(workers);
    // Worker w takes exposures w, w + workers, …: a fixed share, so which worker does what never depends
    // on timing.
    auto work = [&](unsigned w) {
        for (int i = static_cast<int>(w); i < range.count; i += static_cast<int>(workers)) {
            const double exposure = range.start + step * i;
            auto ldr = ldrFlip(toneMappedImage(test, exposure), toneMappedImage(reference, exposure),
                               pixelsPerDegree);
            if (!ldr) {
                failures[w] = ldr.error();
                return;
            }
            if (largest[w].empty()) {
                largest[w] = std::move(ldr->errors);
                continue;
            }
            for (std::size_t p = 0; p < largest[w].size(); ++p)
                largest[w][p] = std::max(largest[w][p], ldr->errors[p]);
        }
    };
    std::vector<std::thread> helpers;
    for (unsigned w = 1; w < workers; ++w)
        helpers.emplace_back(work, w);
    work(0);
    for (std::thread& helper : helpers)
        helper.join();
    for (const std::string& failure : failures)
        if (!failure.empty())
            return base::Error{failure};
    // From zero, which no FLIP value is below, so that the result does not rest on any one worker's.
    std::vector<float> errors(static_cast<std::size_t>(test.width) * test.height, 0.0f);
    for (const std::vector<float>& worker : largest)
        for (std::size_t p = 0; p < worker.size() && p < errors.size(); ++p)
            errors[p] = std::max(errors[p], worker[p]);
    return errors;
}

} // namespace

base::Result<FlipResult> hdrFlip(const Image& test, const Image& reference, double pixelsPerDegree) {
    if (base::Status sizes = checkComparable(test, reference); !sizes)
        return base::Error{sizes.error()};
    const ExposureRange range = exposureRange(reference);
    auto errors = largestOverExposures(test, reference, range, pixelsPerDegree);
    if (!errors)
        return base::Error{errors.error()};
    FlipResult result;
    result.width = test.width;
    result.height = test.height;
    result.errors = std::move(*errors);
    double sum = 0.0;
    for (float e : result.errors)
        sum += e;
    result.mean = result.errors.empty() ? 0.0 : sum / double(result.errors.size());
    result.startExposure = range.start;
    result.stopExposure = range.stop;
    result.exposures = range.count;
    return result;
}

Image flipColorMap(const FlipResult& flip) {
    // Magma (matplotlib's perceptually uniform map) at nine even steps, sRGB 0..255: the map the FLIP
    // papers show their errors in.
    static const std::array<glm::dvec3, 9> stops = {
        glm::dvec3(0, 0, 4),      glm::dvec3(29, 17, 71),    glm::dvec3(81, 18, 124),
        glm::dvec3(130, 38, 129), glm::dvec3(183, 55, 121),  glm::dvec3(231, 82, 99),
        glm::dvec3(252, 137, 97), glm::dvec3(254, 194, 135), glm::dvec3(252, 253, 191)};
    Image map;
    map.width = flip.width;
    map.height = flip.height;
    map.rgba.resize(flip.errors.size() * 4);
    for (std::size_t p = 0; p < flip.errors.size(); ++p) {
        const double e = std::isfinite(flip.errors[p]) ? std::clamp(double(flip.errors[p]), 0.0, 1.0) : 1.0;
        const double x = e * double(stops.size() - 1);
        const std::size_t i = std::min(static_cast<std::size_t>(x), stops.size() - 2);
        const glm::dvec3 srgb = glm::mix(stops[i], stops[i + 1], x - double(i)) / 255.0;
        for (int c = 0; c < 3; ++c)
            map.rgba[p * 4 + std::size_t(c)] = srgbToLinear(float(srgb[c]));
        map.rgba[p * 4 + 3] = 1.0f;
    }
    return map;
}

base::Status writeFlipMap(const std::string& path, const FlipResult& flip) {
    ImageMetadata metadata;
    char mean[64];
    std::snprintf(mean, sizeof mean, "%.6f", flip.mean);
    metadata.attributes = {{"ImageDescription", std::string("speculum FLIP error map, mean ") + mean},
                           {"speculum:flipMean", mean}};
    return writeImage(path, flipColorMap(flip), metadata);
}

} // namespace speculum::render::metrics
