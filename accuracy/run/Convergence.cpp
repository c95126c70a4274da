#include "accuracy/run/Convergence.hpp"

#include "accuracy/run/Measure.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/ReferenceNoise.hpp"

#include <cmath>
#include <cstdio>

namespace speculum::accuracy {

namespace {

// The least-squares slope of log noise against log samples over the points with noise.
double fittedSlope(const std::vector<ConvergencePoint>& points) {
    double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (const ConvergencePoint& p : points) {
        if (!(p.noise > 0.0))
            continue;
        const double x = std::log(double(p.samples)), y = std::log(p.noise);
        n += 1.0;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double d = n * sxx - sx * sx;
    return n >= 2.0 && d > 0.0 ? (n * sxy - sx * sy) / d : 0.0;
}

void pick(ConvergenceStudy& study) {
    const double target = 0.1 * study.smallestError;
    if (!(target > 0.0))
        return; // no error to judge: nothing is needed
    for (const ConvergencePoint& p : study.points)
        if (p.noise <= target) {
            study.enough = p.samples;
            return;
        }
    const ConvergencePoint& last = study.points.back();
    if (!(last.noise > 0.0))
        return;
    // The fitted slope where it is plausible for Monte Carlo noise; a shallow fit (a few points, bad luck)
    // would ask for absurd counts, so −½ stands in for it.
    const double slope = study.slope <= -0.25 && study.slope >= -1.0 ? study.slope : -0.5;
    const double needed = std::ceil(double(last.samples) * std::pow(target / last.noise, 1.0 / slope));
    study.extrapolated = static_cast<int>(std::min(needed, double(kMaxExtrapolated))); // an int holds it
}

} // namespace

void judgeConvergence(ConvergenceStudy& study, double smallestError) {
    study.smallestError = smallestError;
    study.enough.reset();
    study.extrapolated = 0;
    if (!study.exact && !study.points.empty())
        pick(study);
}

std::vector<int> convergenceSamples(bool quick) {
    return quick ? std::vector<int>{4, 16, 64, 256} : std::vector<int>{4, 16, 64, 256, 1024};
}

base::Result<ConvergenceStudy> studyConvergence(const SweepInput& sweep, int width, int height,
                                                double smallestError,
                                                const std::function<void(const std::string&)>& progress,
                                                const std::function<bool()>& stop) {
    ConvergenceStudy study;
    study.smallestError = smallestError;
    const render::FrameInput input = referenceInput(sweep.scene, ReferenceKind::Scene, sweep.tessellate);
    std::vector<Reference> traced;
    for (int samples : convergenceSamples(sweep.quick)) {
        if (progress)
            progress("convergence: tracing the reference with " + std::to_string(samples) +
                     " paths per rough pixel");
        auto reference = traceReference(
            input, ReferenceKind::Scene, width, height, [&](double) { return !stop || !stop(); }, samples);
        if (stop && stop())
            return base::Error{"stopped"};
        if (!reference)
            return base::Error{reference.error()};
        if (reference->traced.glossyPixels == 0) {
            study.exact = true; // every pixel exact with one path: nothing converges
            return study;
        }
        const render::Image& image = reference->traced.image;
        auto noise = render::metrics::noiseInterval(image, image, reference->traced.noise);
        if (!noise)
            return base::Error{noise.error()};
        study.points.push_back({samples, reference->traced.totalMs, noise->noiseRms, 0.0});
        traced.push_back(std::move(*reference));
    }
    for (std::size_t i = 0; i < traced.size(); ++i) {
        auto error = render::metrics::compare(traced[i].traced.image, traced.back().traced.image);
        if (!error)
            return base::Error{error.error()};
        study.points[i].rmse = error->rmse;
    }
    study.slope = fittedSlope(study.points);
    pick(study);
    return study;
}

} // namespace speculum::accuracy
