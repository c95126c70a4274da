#include "render/metrics/Flip.hpp"

#include "render/image/ColorSpace.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/FlipColour.hpp"
#include "render/metrics/Plane.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/common.hpp>

namespace speculum::render::metrics {

namespace {

namespace colour = flipcolour;

// The exponents and the redistribution of the colour error (HPG 2020, section 4).
constexpr double kColourExponent = 0.7;  // q_c
constexpr double kFeatureExponent = 0.5; // q_f
constexpr double kRedistributeAt = 0.4;  // p_c: errors below p_c · c_max ...
constexpr double kRedistributeTo = 0.95; // p_t: ... take this share of the 0..1 range
// Peak-to-trough width of the eye's edge detector, degrees (twice its standard deviation).
constexpr double kEdgeWidthDegrees = 0.082;

// A contrast sensitivity function as a sum of two Gaussians in visual angle:
// a1 √(π/b1) exp(−π² x²/b1) + a2 √(π/b2) exp(−π² x²/b2).
struct Csf {
    double a1, b1, a2, b2;
};
constexpr Csf kAchromatic{1.0, 0.0047, 0.0, 1e-5};
constexpr Csf kRedGreen{1.0, 0.0053, 0.0, 1e-5};
constexpr Csf kBlueYellow{34.1, 0.04, 13.5, 0.025};
constexpr double kWidestCsfScale = 0.04; // the largest b: it sets the filters' common radius

using Displayed = std::function<float(float)>; // a linear value as the display shows it, 0..1

struct Opponent {
    Plane y, cx, cz;
};

Opponent toOpponent(const Image& image, const Displayed& display) {
    Opponent o{Plane(image.width, image.height), Plane(image.width, image.height),
               Plane(image.width, image.height)};
    for (std::size_t p = 0; p < o.y.values.size(); ++p) {
        const glm::dvec3 rgb(display(image.rgba[p * 4]), display(image.rgba[p * 4 + 1]),
                             display(image.rgba[p * 4 + 2]));
        const glm::dvec3 v = colour::xyzToYcxcz(colour::linearRgbToXyz(rgb));
        o.y.values[p] = float(v.x);
        o.cx.values[p] = float(v.y);
        o.cz.values[p] = float(v.z);
    }
    return o;
}

int csfRadius(double ppd) {
    return static_cast<int>(std::ceil(3.0 * std::sqrt(kWidestCsfScale / (2.0 * M_PI * M_PI)) * ppd));
}

// The CSF is a sum of two separable Gaussians: each is applied separably and the sum normalised so the
// 2-D filter's weights add up to 1.
Plane csfFilter(const Plane& plane, const Csf& csf, double ppd) {
    const int radius = csfRadius(ppd);
    Plane sum(plane.width, plane.height);
    double total = 0.0;
    for (const auto& [a, b] : {std::pair{csf.a1, csf.b1}, std::pair{csf.a2, csf.b2}}) {
        if (a <= 0.0)
            continue;
        Kernel kernel(static_cast<std::size_t>(2 * radius + 1));
        double taps = 0.0;
        for (int i = -radius; i <= radius; ++i) {
            const double x = i / ppd;
            kernel[static_cast<std::size_t>(i + radius)] = float(std::exp(-M_PI * M_PI * x * x / b));
            taps += kernel[static_cast<std::size_t>(i + radius)];
        }
        const double weight = a * std::sqrt(M_PI / b);
        const Plane filtered = convolveSeparable(plane, kernel, kernel);
        for (std::size_t p = 0; p < sum.values.size(); ++p)
            sum.values[p] += float(weight * filtered.values[p]);
        total += weight * taps * taps;
    }
    for (float& v : sum.values)
        v = float(v / total);
    return sum;
}

// Per pixel: the filtered colour, back in linear RGB clamped to the displayable cube, in Hunt-adjusted Lab.
std::vector<glm::dvec3> filteredLab(const Opponent& o, double ppd) {
    const Plane y = csfFilter(o.y, kAchromatic, ppd), cx = csfFilter(o.cx, kRedGreen, ppd),
                cz = csfFilter(o.cz, kBlueYellow, ppd);
    std::vector<glm::dvec3> lab(y.values.size());
    for (std::size_t p = 0; p < lab.size(); ++p) {
        const glm::dvec3 rgb =
            colour::xyzToLinearRgb(colour::ycxczToXyz({y.values[p], cx.values[p], cz.values[p]}));
        lab[p] = colour::huntLab(glm::clamp(rgb, 0.0, 1.0));
    }
    return lab;
}

double maxColourError() {
    static const double cmax = std::pow(
        colour::hyab(colour::huntLab({0.0, 1.0, 0.0}), colour::huntLab({0.0, 0.0, 1.0})), kColourExponent);
    return cmax;
}

double redistribute(double error) {
    const double cmax = maxColourError(), knee = kRedistributeAt * cmax;
    if (error < knee)
        return kRedistributeTo / knee * error;
    return kRedistributeTo + (error - knee) / (cmax - knee) * (1.0 - kRedistributeTo);
}

// The edge (first derivative) or point (second derivative) detector along x, the Gaussian along y; the
// detector's positive taps normalised to sum 1 and its negative ones to −1.
struct FeatureKernels {
    Kernel edge, point, smooth;
};

Kernel normalisedSigned(std::vector<double> raw) {
    double positive = 0.0, negative = 0.0;
    for (double w : raw)
        (w > 0.0 ? positive : negative) += std::abs(w);
    Kernel kernel(raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i)
        kernel[i] = float(raw[i] > 0.0 ? raw[i] / positive : (negative > 0.0 ? raw[i] / negative : 0.0));
    return kernel;
}

FeatureKernels featureKernels(double ppd) {
    const double sd = 0.5 * kEdgeWidthDegrees * ppd;
    const int radius = static_cast<int>(std::ceil(3.0 * sd));
    std::vector<double> edge, point;
    for (int x = -radius; x <= radius; ++x) {
        const double g = std::exp(-double(x * x) / (2.0 * sd * sd));
        edge.push_back(-x * g);
        point.push_back((double(x * x) / (sd * sd) - 1.0) * g);
    }
    return {normalisedSigned(edge), normalisedSigned(point), gaussianKernel(sd, radius)};
}

struct Features {
    Plane edge, point; // the magnitudes of the x and y responses
};

Features features(const Plane& opponentY, const FeatureKernels& k) {
    Plane y = opponentY;
    for (float& v : y.values)
        v = (v + 16.0f) / 116.0f; // Y/Yn: luminance 0..1
    const Plane ex = convolveSeparable(y, k.edge, k.smooth), ey = convolveSeparable(y, k.smooth, k.edge);
    const Plane px = convolveSeparable(y, k.point, k.smooth), py = convolveSeparable(y, k.smooth, k.point);
    Features f{Plane(y.width, y.height), Plane(y.width, y.height)};
    for (std::size_t p = 0; p < y.values.size(); ++p) {
        f.edge.values[p] = std::hypot(ex.values[p], ey.values[p]);
        f.point.values[p] = std::hypot(px.values[p], py.values[p]);
    }
    return f;
}

std::vector<float> flipOfDisplayed(const Image& test, const Image& reference, double ppd,
                                   const Displayed& display) {
    const Opponent t = toOpponent(test, display), r = toOpponent(reference, display);
    const std::vector<glm::dvec3> labT = filteredLab(t, ppd), labR = filteredLab(r, ppd);
    const FeatureKernels kernels = featureKernels(ppd);
    const Features ft = features(t.y, kernels), fr = features(r.y, kernels);
    std::vector<float> errors(labT.size());
    for (std::size_t p = 0; p < errors.size(); ++p) {
        const double colourError = redistribute(std::pow(colour::hyab(labR[p], labT[p]), kColourExponent));
        const double featureDifference = std::max(std::abs(fr.edge.values[p] - ft.edge.values[p]),
                                                  std::abs(fr.point.values[p] - ft.point.values[p]));
        const double featureError = std::pow(featureDifference / std::sqrt(2.0), kFeatureExponent);
        errors[p] = float(std::pow(colourError, 1.0 - featureError));
    }
    return errors;
}

double meanOf(const std::vector<float>& values) {
    double sum = 0.0;
    for (float v : values)
        sum += v;
    return values.empty() ? 0.0 : sum / double(values.size());
}

float displayClamped(float v) {
    return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
}

} // namespace

double flipOfColourDifference(double hyab) {
    return redistribute(std::pow(std::max(hyab, 0.0), kColourExponent));
}

double flipJnd() {
    return flipOfColourDifference(kJndColourDifference);
}

std::optional<double> FlipResult::meanOver(const std::vector<std::uint8_t>& mask) const {
    if (mask.size() != errors.size())
        return std::nullopt;
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t p = 0; p < errors.size(); ++p) {
        if (mask[p] == 0)
            continue;
        sum += errors[p];
        ++count;
    }
    return count == 0 ? std::nullopt : std::optional<double>(sum / double(count));
}

base::Result<FlipResult> ldrFlip(const Image& test, const Image& reference, double pixelsPerDegree) {
    if (base::Status sizes = checkComparable(test, reference); !sizes)
        return base::Error{sizes.error()};
    FlipResult result;
    result.width = test.width;
    result.height = test.height;
    result.errors = flipOfDisplayed(test, reference, pixelsPerDegree, displayClamped);
    result.mean = meanOf(result.errors);
    return result;
}

} // namespace speculum::render::metrics
