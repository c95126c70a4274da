#include "accuracy/run/Measure.hpp"

#include "render/metrics/Ssim.hpp"
#include "render/renderer/StillRenderer.hpp"

#include <algorithm>

namespace speculum::accuracy {

double median(std::vector<double> values) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

base::Result<Reference> traceReference(const render::FrameInput& input, ReferenceKind kind, int width,
                                       int height, const std::function<bool(double)>& progress,
                                       int glossySamples) {
    auto tracer = render::reference::Tracer::create(input);
    if (!tracer)
        return base::Error{"reference tracer: " + tracer.error()};
    render::reference::TraceSettings settings;
    settings.width = width;
    settings.height = height;
    settings.ssaa = 1;
    settings.samples = glossySamples;
    settings.shadows = kind == ReferenceKind::HardShadows ? render::reference::ShadowMode::Hard
                                                          : render::reference::ShadowMode::PcfFootprint;
    auto traced = tracer->render(settings, [&](double fraction) { return !progress || progress(fraction); });
    if (!traced)
        return base::Error{"reference tracer: " + traced.error()};
    Reference reference;
    reference.kind = kind;
    reference.traced = std::move(*traced);
    reference.mirrorMask = render::reference::mirrorMask(reference.traced.ids);
    reference.reflectorMask = render::reference::reflectorMask(reference.traced.ids);
    return reference;
}

base::Result<FrameCost> measureFrames(render::Renderer& renderer, const render::FrameInput& input, int width,
                                      int height, int warmUp, int frames, const std::function<bool()>& stop) {
    render::StillSettings settings{width, height, 1};
    settings.reuseMaps = false;
    std::vector<double> gpu, cpu;
    FrameCost cost;
    for (int i = 0; i < warmUp + frames; ++i) {
        if (stop && stop())
            return base::Error{"stopped"};
        auto still = render::renderStill(renderer, input, settings);
        if (!still)
            return base::Error{still.error()};
        if (i < warmUp) {
            if (i == 0)
                cost.warnings = still->firstSample.warnings;
            continue;
        }
        gpu.push_back(still->firstSample.gpuMs);
        cpu.push_back(still->firstSample.cpuMs);
        cost.memory = still->firstSample.memory;
        if (i + 1 == warmUp + frames)
            cost.image = std::move(still->image);
    }
    const bool timed = std::all_of(gpu.begin(), gpu.end(), [](double ms) { return ms >= 0.0; });
    cost.gpuMs = timed ? median(gpu) : -1.0;
    cost.cpuMs = median(cpu);
    return cost;
}

base::Result<FrameCost> measurePlayed(render::Renderer& renderer,
                                      const std::vector<render::FrameInput>& frames, int width, int height,
                                      const std::function<bool()>& stop) {
    render::StillSettings settings{width, height, 1};
    std::vector<double> gpu, cpu;
    FrameCost cost;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (stop && stop())
            return base::Error{"stopped"};
        settings.reuseMaps = i > 0;
        auto still = render::renderStill(renderer, frames[i], settings);
        if (!still)
            return base::Error{still.error()};
        if (i == 0) {
            cost.warnings = still->firstSample.warnings;
            continue;
        }
        gpu.push_back(still->firstSample.gpuMs);
        cpu.push_back(still->firstSample.cpuMs);
        cost.memory = still->firstSample.memory;
        if (i + 1 == frames.size())
            cost.image = std::move(still->image);
    }
    const bool timed = std::all_of(gpu.begin(), gpu.end(), [](double ms) { return ms >= 0.0; });
    cost.gpuMs = timed ? median(gpu) : -1.0;
    cost.cpuMs = median(cpu);
    return cost;
}

namespace {

base::Status addPerceptualFigures(ErrorFigures& figures, const render::Image& image,
                                  const Reference& reference) {
    const render::Image& exact = reference.traced.image;
    auto ssim = render::metrics::ssim(image, exact);
    auto flip = render::metrics::ldrFlip(image, exact);
    auto hdr = render::metrics::hdrFlip(image, exact);
    if (!ssim || !flip || !hdr)
        return base::Error{!ssim ? ssim.error() : !flip ? flip.error() : hdr.error()};
    figures.ssim = ssim->mean;
    figures.flip = std::move(*flip);
    figures.flipMirrors = figures.flip.meanOver(reference.mirrorMask);
    figures.flipReflector = figures.flip.meanOver(reference.reflectorMask);
    figures.hdrFlip = hdr->mean;
    // A reference traced without noise (no rough surface) has no noise image: an exact point.
    const render::Image& noise = reference.traced.noise;
    const bool noisy = noise.width == exact.width && noise.height == exact.height;
    auto interval = render::metrics::noiseInterval(image, exact, noisy ? noise : blankLike(exact));
    if (!interval)
        return base::Error{interval.error()};
    figures.interval = *interval;
    if (!noisy) { // exact: the interval is the PSNR itself (its sums differ from compare's by rounding only)
        figures.interval.psnrLow = figures.interval.psnrHigh = figures.overall.psnr;
        return base::Done{};
    }
    // The relative error on the pixels that see a rough surface (those with noise): what the white
    // furnace's energy error is compared with.
    std::vector<std::uint8_t> rough(noise.rgba.size() / 4, 0);
    for (std::size_t p = 0; p < rough.size(); ++p)
        rough[p] = noise.rgba[p * 4] > 0.0f || noise.rgba[p * 4 + 1] > 0.0f || noise.rgba[p * 4 + 2] > 0.0f;
    auto onRough = render::metrics::compare(image, exact, &rough);
    if (onRough && onRough->pixels > 0)
        figures.roughRelativeMse = onRough->relativeMse;
    return base::Done{};
}

} // namespace

render::Image blankLike(const render::Image& image) {
    render::Image blank;
    blank.width = image.width;
    blank.height = image.height;
    blank.rgba.assign(image.rgba.size(), 0.0f);
    return blank;
}

base::Result<ErrorFigures> compareWithReference(const render::Image& image, const Reference& reference) {
    const render::Image& exact = reference.traced.image;
    ErrorFigures figures;
    auto overall = render::metrics::compare(image, exact);
    if (!overall)
        return base::Error{overall.error()};
    figures.overall = *overall;
    auto masked = [&](const std::vector<std::uint8_t>& mask) -> std::optional<render::metrics::ErrorStats> {
        auto stats = render::metrics::compare(image, exact, &mask);
        if (!stats || stats->pixels == 0)
            return std::nullopt;
        return *stats;
    };
    figures.mirrors = masked(reference.mirrorMask);
    figures.reflector = masked(reference.reflectorMask);
    auto difference = render::metrics::absoluteDifference(image, exact);
    if (!difference)
        return base::Error{difference.error()};
    figures.difference = std::move(*difference);
    if (base::Status perceptual = addPerceptualFigures(figures, image, reference); !perceptual)
        return base::Error{perceptual.error()};
    return figures;
}

namespace {

// The pixels `metric` judges: the mirrors', the reflector's, or (none: no such pixel, as focusValue) the
// whole frame.
const std::vector<std::uint8_t>* judgedMask(const Reference& reference, Metric metric) {
    const std::vector<std::uint8_t>* mask = metric == Metric::PsnrMirrors     ? &reference.mirrorMask
                                            : metric == Metric::PsnrReflector ? &reference.reflectorMask
                                                                              : nullptr;
    if (mask && std::none_of(mask->begin(), mask->end(), [](std::uint8_t m) { return m != 0; }))
        return nullptr;
    return mask;
}

} // namespace

base::Result<double> flipBetween(const render::Image& image, const render::Image& best,
                                 const Reference& reference, Metric metric) {
    auto flip = render::metrics::ldrFlip(image, best);
    if (!flip)
        return base::Error{flip.error()};
    const std::vector<std::uint8_t>* mask = judgedMask(reference, metric);
    std::vector<float> values;
    for (std::size_t p = 0; p < flip->errors.size(); ++p)
        if (!mask || (*mask)[p] != 0)
            values.push_back(flip->errors[p]);
    if (values.empty())
        return 0.0;
    auto at = values.begin() + std::ptrdiff_t(std::min(values.size() - 1, values.size() * 99 / 100));
    std::nth_element(values.begin(), at, values.end());
    return double(*at);
}

base::Result<bool> comparedWithinNoise(const render::Image& a, const render::Image& b,
                                       const Reference& reference, Metric metric) {
    const render::Image& exact = reference.traced.image;
    const render::Image& noise = reference.traced.noise;
    if (noise.width != exact.width || noise.height != exact.height)
        return false; // an exact reference tells every difference apart
    const std::vector<std::uint8_t>* mask = judgedMask(reference, metric);
    auto comparison = render::metrics::compareWithinNoise(a, b, exact, noise, mask);
    if (!comparison)
        return base::Error{comparison.error()};
    return comparison->tie && comparison->mseDifference != 0.0;
}

} // namespace speculum::accuracy
