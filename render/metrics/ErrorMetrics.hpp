#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace speculum::render::metrics {

// Which values errors are measured on. Srgb (the default): what a viewer sees, the sRGB encoding of the
// linear value clamped to 0..1, so an error in the shadows counts as much as one in the highlights, as
// it does on screen and in the PNG. Linear: the raw linear values (unclamped), for HDR comparisons.
enum class Encoding { Srgb, Linear };

// PSNR of identical images (rmse 0) and of empty masks: a finite stand-in for infinity, so reports and
// JSON stay numbers.
inline constexpr double kMaxPsnr = 100.0;

struct ErrorStats {
    double rmse = 0.0;      // root mean square over the R, G, B values of the pixels compared
    double psnr = kMaxPsnr; // 20·log10(1 / rmse) in dB (peak 1), at most kMaxPsnr
    double maxError = 0.0;  // largest per-pixel error (RMS over the pixel's three channels)
    double mae = 0.0;       // mean absolute error over the R, G, B values (in the chosen encoding)
    // Relative MSE, as pbrt's imgtool reports it: the mean over the R, G, B values of
    // (test − reference)² / (reference² + kRelativeMseEpsilon), always on the linear values (unclamped),
    // so an error in a dark pixel counts as much as a proportional one in a bright pixel.
    double relativeMse = 0.0;
    std::size_t pixels = 0; // pixels compared (those in the mask)
};

// Keeps the relative MSE finite where the reference is black.
inline constexpr double kRelativeMseEpsilon = 0.01;

// Whether two images can be compared: the same size, and data that matches it (the error names both
// sizes), and a mask, if given, with one byte per pixel.
base::Status checkComparable(const Image& test, const Image& reference,
                             const std::vector<std::uint8_t>* mask = nullptr);

// RMSE and PSNR of `test` against `reference` over all pixels, or over those whose mask byte is non-zero
// (mask: one byte per pixel, row 0 at the top, e.g. reference::mirrorMask). Errors: sizes differ, or the
// mask has the wrong length. Non-finite values count as 0.
base::Result<ErrorStats> compare(const Image& test, const Image& reference,
                                 const std::vector<std::uint8_t>* mask = nullptr,
                                 Encoding encoding = Encoding::Srgb);

// Per-pixel absolute difference |test − reference| per channel (in `encoding`), alpha 1.
base::Result<Image> absoluteDifference(const Image& test, const Image& reference,
                                       Encoding encoding = Encoding::Srgb);

// Full scale of the error map: a per-pixel error of 0.25 (a quarter of the sRGB range, 64 of 255 levels)
// or more gets the ramp's top colour.
inline constexpr double kErrorMapFullScale = 0.25;

// The ramp colour (linear RGB) for x in 0..1 (clamped): black → indigo → magenta-red → orange → pale
// yellow. Brightness rises steadily along it, so the map reads as "brighter = worse" in grey too.
glm::dvec3 errorRamp(double x);

// Colours each pixel of a difference image (absoluteDifference) by its error, the RMS over its three
// channels, on the fixed scale 0 .. fullScale (no legend needed: the scale is always the same, so maps
// of different settings compare by eye). Returns a linear image ready for ImageWriter.
Image errorColorMap(const Image& difference, double fullScale = kErrorMapFullScale);

// Writes errorColorMap(difference) through ImageWriter (format by extension; atomic).
base::Status writeErrorMap(const std::string& path, const Image& difference,
                           double fullScale = kErrorMapFullScale);

// The angle between two directions in radians (0..π), stable for nearly equal and nearly opposite
// directions; 0 if either is zero or not finite (there is no angle to measure).
double angleBetween(const glm::dvec3& a, const glm::dvec3& b);

struct AngularStats {
    double meanDegrees = 0.0;
    double rmsDegrees = 0.0;
    double maxDegrees = 0.0;
    std::size_t count = 0;
};

// The angular error of environment-map lookups: angle between each direction the map gives (`looked up`)
// and the exact direction, pairwise. Errors: the two sets differ in length.
base::Result<AngularStats> angularError(const std::vector<glm::dvec3>& lookedUp,
                                        const std::vector<glm::dvec3>& exact);

} // namespace speculum::render::metrics
