#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace speculum::render::metrics {

// FLIP (Andersson et al., "FLIP: A Difference Evaluator for Alternating Images", HPG 2020) and HDR-FLIP
// (Andersson et al., "Visualizing Errors in Rendered High Dynamic Range Images", Eurographics 2021): the
// difference a person flipping between two images perceives, per pixel, 0 (none) to 1 (as far apart as
// pure green from pure blue). It weighs colour after filtering by the eye's contrast sensitivity, and
// edges and points that appear or vanish.
//
// The observer the papers assume by default: a 0.7 m wide monitor 3840 pixels across, seen from 0.7 m,
// i.e. about 67 pixels per degree of visual angle.
inline constexpr double kFlipPixelsPerDegree = 3840.0 / 0.7 * 0.7 * M_PI / 180.0;

// The classic just-noticeable colour difference, ΔE*ab ≈ 2.3, and the FLIP value a uniform difference
// of that size scores (colour alone, no edges: about 0.103). Used as "one JND" when settings are
// compared by their mean FLIP.
inline constexpr double kJndColourDifference = 2.3;
double flipOfColourDifference(double hyab);
double flipJnd(); // flipOfColourDifference(kJndColourDifference)

struct FlipResult {
    int width = 0;
    int height = 0;
    std::vector<float> errors; // per pixel, 0..1, row 0 at the top
    double mean = 0.0;         // mean over all pixels
    // HDR-FLIP only: the exposure range (stops) and the number of exposures compared; LDR: 0, 0, 1.
    double startExposure = 0.0;
    double stopExposure = 0.0;
    int exposures = 1;

    // The mean over the pixels whose mask byte is non-zero; none if no such pixel or the mask's length
    // is not the image's.
    std::optional<double> meanOver(const std::vector<std::uint8_t>& mask) const;
};

// LDR-FLIP of two linear images as a display shows them: each value clamped to 0..1 (what the sRGB PNG
// holds). Errors: sizes differ.
base::Result<FlipResult> ldrFlip(const Image& test, const Image& reference,
                                 double pixelsPerDegree = kFlipPixelsPerDegree);

// HDR-FLIP of two linear (unclamped) images: LDR-FLIP at each of a range of exposures through the ACES
// filmic curve, the range chosen from the reference (from the exposure that brings its brightest pixel to
// 0.85 to the one that brings its median there; as many exposures as the range has stops, rounded up, at
// least two, spread evenly over it), and the largest per pixel. Errors: sizes differ.
base::Result<FlipResult> hdrFlip(const Image& test, const Image& reference,
                                 double pixelsPerDegree = kFlipPixelsPerDegree);

// The FLIP error map in the papers' colour map (magma: black, purple, red, orange, pale yellow for 1),
// linear RGB, ready for ImageWriter.
Image flipColorMap(const FlipResult& flip);

// Writes flipColorMap(flip) through ImageWriter (format by extension; atomic).
base::Status writeFlipMap(const std::string& path, const FlipResult& flip);

} // namespace speculum::render::metrics
