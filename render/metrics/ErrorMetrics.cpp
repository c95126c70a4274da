#include "render/metrics/ErrorMetrics.hpp"

#include "render/image/ColorSpace.hpp"
#include "render/imageio/ImageWriter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace speculum::render::metrics {

namespace {

std::string sizeText(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

double encode(float value, Encoding encoding) {
    if (!std::isfinite(value))
        return 0.0;
    if (encoding == Encoding::Linear)
        return value;
    return linearToSrgb(std::clamp(value, 0.0f, 1.0f));
}

double relativeSquaredError(float test, float reference) {
    const double t = std::isfinite(test) ? test : 0.0, r = std::isfinite(reference) ? reference : 0.0;
    return (t - r) * (t - r) / (r * r + kRelativeMseEpsilon);
}

} // namespace

base::Status checkComparable(const Image& test, const Image& reference,
                             const std::vector<std::uint8_t>* mask) {
    if (test.width != reference.width || test.height != reference.height)
        return base::Error{"cannot compare a " + sizeText(test) + " image with a " + sizeText(reference) +
                           " reference"};
    const std::size_t values = static_cast<std::size_t>(test.width) * test.height * 4;
    if (test.rgba.size() != values || reference.rgba.size() != values)
        return base::Error{"image data does not match its size"};
    const std::size_t pixels = static_cast<std::size_t>(test.width) * test.height;
    if (mask && mask->size() != pixels)
        return base::Error{"the mask has " + std::to_string(mask->size()) + " entries for " +
                           std::to_string(pixels) + " pixels"};
    return base::Done{};
}

base::Result<ErrorStats> compare(const Image& test, const Image& reference,
                                 const std::vector<std::uint8_t>* mask, Encoding encoding) {
    if (base::Status sizes = checkComparable(test, reference, mask); !sizes)
        return base::Error{sizes.error()};
    const std::size_t pixels = static_cast<std::size_t>(test.width) * test.height;
    ErrorStats stats;
    double sum = 0.0, absolute = 0.0, relative = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) {
        if (mask && (*mask)[p] == 0)
            continue;
        double pixel = 0.0;
        for (int c = 0; c < 3; ++c) {
            const float t = test.rgba[p * 4 + c], r = reference.rgba[p * 4 + c];
            const double d = encode(t, encoding) - encode(r, encoding);
            pixel += d * d;
            absolute += std::abs(d);
            relative += relativeSquaredError(t, r);
        }
        sum += pixel;
        stats.maxError = std::max(stats.maxError, std::sqrt(pixel / 3.0));
        ++stats.pixels;
    }
    if (stats.pixels == 0)
        return stats;
    const double values = 3.0 * double(stats.pixels);
    stats.rmse = std::sqrt(sum / values);
    stats.mae = absolute / values;
    stats.relativeMse = relative / values;
    stats.psnr = stats.rmse > 0.0 ? std::min(kMaxPsnr, -20.0 * std::log10(stats.rmse)) : kMaxPsnr;
    return stats;
}

base::Result<Image> absoluteDifference(const Image& test, const Image& reference, Encoding encoding) {
    if (base::Status sizes = checkComparable(test, reference); !sizes)
        return base::Error{sizes.error()};
    Image diff;
    diff.width = test.width;
    diff.height = test.height;
    diff.rgba.resize(test.rgba.size());
    for (std::size_t p = 0; p < test.rgba.size() / 4; ++p) {
        for (int c = 0; c < 3; ++c)
            diff.rgba[p * 4 + c] = static_cast<float>(std::abs(encode(test.rgba[p * 4 + c], encoding) -
                                                               encode(reference.rgba[p * 4 + c], encoding)));
        diff.rgba[p * 4 + 3] = 1.0f;
    }
    return diff;
}

glm::dvec3 errorRamp(double x) {
    // Control colours in sRGB (as they look), decoded to linear for the linear image pipeline.
    static const std::array<glm::dvec3, 5> stops = {glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(0.25, 0.06, 0.50),
                                                    glm::dvec3(0.78, 0.16, 0.38),
                                                    glm::dvec3(0.98, 0.56, 0.10), glm::dvec3(1.0, 1.0, 0.78)};
    if (!std::isfinite(x))
        x = 1.0; // an error that cannot be measured shows as the worst
    x = std::clamp(x, 0.0, 1.0) * double(stops.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), stops.size() - 2);
    const glm::dvec3 srgb = glm::mix(stops[i], stops[i + 1], x - double(i));
    return {srgbToLinear(float(srgb.r)), srgbToLinear(float(srgb.g)), srgbToLinear(float(srgb.b))};
}

Image errorColorMap(const Image& difference, double fullScale) {
    Image map;
    map.width = difference.width;
    map.height = difference.height;
    map.rgba.resize(difference.rgba.size());
    const double scale = fullScale > 0.0 && std::isfinite(fullScale) ? fullScale : kErrorMapFullScale;
    for (std::size_t p = 0; p < difference.rgba.size() / 4; ++p) {
        double sum = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double d = difference.rgba[p * 4 + c];
            sum += std::isfinite(d) ? d * d : 1.0;
        }
        const glm::dvec3 colour = errorRamp(std::sqrt(sum / 3.0) / scale);
        map.rgba[p * 4 + 0] = static_cast<float>(colour.r);
        map.rgba[p * 4 + 1] = static_cast<float>(colour.g);
        map.rgba[p * 4 + 2] = static_cast<float>(colour.b);
        map.rgba[p * 4 + 3] = 1.0f;
    }
    return map;
}

base::Status writeErrorMap(const std::string& path, const Image& difference, double fullScale) {
    ImageMetadata metadata;
    char scale[64];
    std::snprintf(scale, sizeof scale, "%g", fullScale);
    metadata.attributes = {{"ImageDescription", std::string("speculum error map, full scale ") + scale},
                           {"speculum:errorFullScale", scale}};
    return writeImage(path, errorColorMap(difference, fullScale), metadata);
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    const double la = glm::length(a), lb = glm::length(b);
    if (!(la > 0.0) || !(lb > 0.0) || !std::isfinite(la) || !std::isfinite(lb))
        return 0.0;
    // atan2(|a×b|, a·b) keeps its precision near 0 and π, where acos of the dot product does not.
    const glm::dvec3 ua = a / la, ub = b / lb;
    return std::atan2(glm::length(glm::cross(ua, ub)), glm::dot(ua, ub));
}

base::Result<AngularStats> angularError(const std::vector<glm::dvec3>& lookedUp,
                                        const std::vector<glm::dvec3>& exact) {
    if (lookedUp.size() != exact.size())
        return base::Error{"cannot compare " + std::to_string(lookedUp.size()) + " directions with " +
                           std::to_string(exact.size())};
    AngularStats stats;
    stats.count = lookedUp.size();
    if (stats.count == 0)
        return stats;
    double sum = 0.0, sumSquares = 0.0;
    for (std::size_t i = 0; i < lookedUp.size(); ++i) {
        const double degrees = angleBetween(lookedUp[i], exact[i]) * 180.0 / M_PI;
        sum += degrees;
        sumSquares += degrees * degrees;
        stats.maxDegrees = std::max(stats.maxDegrees, degrees);
    }
    stats.meanDegrees = sum / double(stats.count);
    stats.rmsDegrees = std::sqrt(sumSquares / double(stats.count));
    return stats;
}

} // namespace speculum::render::metrics
