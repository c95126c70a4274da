#include "accuracy/run/Measure.hpp"

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
    return figures;
}

} // namespace speculum::accuracy
