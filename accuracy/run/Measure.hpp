#pragma once

#include "accuracy/Analysis.hpp"
#include "accuracy/Sweep.hpp"
#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/image/Image.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/Flip.hpp"
#include "render/metrics/ReferenceNoise.hpp"
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
    double ssim = 1.0;
    render::metrics::FlipResult flip; // LDR-FLIP, with its per-pixel map
    std::optional<double> flipMirrors;
    std::optional<double> flipReflector;
    double hdrFlip = 0.0;
    render::metrics::NoiseInterval interval; // what the reference's noise leaves uncertain
    std::optional<double> roughRelativeMse;  // on the pixels that see a rough surface; none without
};

// Errors of `image` against the reference, in sRGB as a viewer sees them (render::metrics): RMSE, PSNR,
// MAE, relative MSE (linear), SSIM, LDR- and HDR-FLIP, and the interval the reference's noise leaves.
base::Result<ErrorFigures> compareWithReference(const render::Image& image, const Reference& reference);

// Whether two images' errors against `reference` differ by less than its noise can tell apart, on the
// pixels `metric` judges (the mirrors', the reflector's, or the whole frame where there are none):
// render::metrics::compareWithinNoise.
base::Result<bool> comparedWithinNoise(const render::Image& a, const render::Image& b,
                                       const Reference& reference, Metric metric);

// How far a viewer could tell `image` from `best`: the 99th percentile, over the pixels `metric` judges
// (the whole frame where there are none), of the LDR-FLIP between the two (0: identical).
base::Result<double> flipBetween(const render::Image& image, const render::Image& best,
                                 const Reference& reference, Metric metric);

double median(std::vector<double> values);

// An image of the same size, all zero (a noiseless reference's noise).
render::Image blankLike(const render::Image& image);

} // namespace speculum::accuracy
