#pragma once

#include "accuracy/Sweep.hpp"
#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/image/Image.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/reference/Tracer.hpp"
#include "render/renderer/Renderer.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace speculum::accuracy {

// Paths per pixel through rough surfaces in the bench's references: enough that the reference's own noise
// (TraceResult::noiseRms) stays below the errors the glossy approximations make.
inline constexpr int kReferenceGlossySamples = 256;
inline constexpr int kQuickReferenceGlossySamples = 64;

// One exact image, with the pixel masks the per-surface errors are measured on.
struct Reference {
    ReferenceKind kind = ReferenceKind::Scene;
    render::reference::TraceResult traced;
    std::vector<std::uint8_t> mirrorMask;    // primary ray hit a planar mirror's reflective side
    std::vector<std::uint8_t> reflectorMask; // primary ray hit the curved reflector
};

// Traces `input` at width × height, one sample per pixel (like the frames it is compared with), with
// exact hard shadows for ReferenceKind::HardShadows and each light's PCF footprint otherwise; pixels that
// see a rough surface average `glossySamples` paths through its lobe. `progress` gets the finished fraction
// and returns false to cancel; errors: the tracer cannot start, or cancelled.
base::Result<Reference> traceReference(const render::FrameInput& input, ReferenceKind kind, int width,
                                       int height, const std::function<bool(double)>& progress = {},
                                       int glossySamples = kReferenceGlossySamples);

// What one configuration costs: medians over the timed frames.
struct FrameCost {
    double gpuMs = -1.0; // -1: no GPU timer on this context
    double cpuMs = 0.0;
    render::TargetMemory memory;
    render::Image image; // the last timed frame, linear
    std::vector<std::string> warnings;
};

// Plays `frames` in order, as the editor plays an animation: the first draws every map, the others keep
// what their update policies keep (RenderOptions::reuseMaps on). The image is the last frame's; the times
// are the medians over the frames after the first, what a played frame costs.
base::Result<FrameCost> measurePlayed(render::Renderer& renderer,
                                      const std::vector<render::FrameInput>& frames, int width, int height,
                                      const std::function<bool()>& stop);

// Renders `warmUp` frames, then times `frames` more. Every frame renders all its shadow and environment
// maps again (RenderOptions::reuseMaps off), so the time is what the settings cost an animated scene.
// `stop`, asked before each frame, ends the measurement early with an error ("stopped").
base::Result<FrameCost> measureFrames(render::Renderer& renderer, const render::FrameInput& input, int width,
                                      int height, int warmUp, int frames,
                                      const std::function<bool()>& stop = {});

struct ErrorFigures {
    render::metrics::ErrorStats overall;
    std::optional<render::metrics::ErrorStats> mirrors;   // none when no pixel shows a mirror
    std::optional<render::metrics::ErrorStats> reflector; // none when no pixel shows the reflector
    render::Image difference;                             // for the error map
};

// Errors of `image` against the reference, in sRGB as a viewer sees them (render::metrics).
base::Result<ErrorFigures> compareWithReference(const render::Image& image, const Reference& reference);

double median(std::vector<double> values);

} // namespace speculum::accuracy
