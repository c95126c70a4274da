#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"

#include <cstdint>
#include <vector>

namespace speculum::render::metrics {

// SSIM (Wang, Bovik, Sheikh and Simoncelli, "Image Quality Assessment: From Error Visibility to
// Structural Similarity", 2004): per pixel, how alike the two images' local means, contrasts and
// structure are, 1 for identical neighbourhoods. As the paper computes it: an 11×11 Gaussian window of
// standard deviation 1.5 pixels, K1 = 0.01, K2 = 0.03, dynamic range 1; here on each of R, G and B of the
// sRGB encoding (the linear values clamped to 0..1), averaged. The window repeats the image's edge pixels
// beyond it, so every pixel has a value (the paper drops a 5-pixel border instead) and masks apply.
struct SsimResult {
    std::vector<float> map; // per pixel, the mean over R, G, B; row 0 at the top
    double mean = 1.0;      // over all pixels, or over the mask's
};

// Errors: sizes differ, or the mask's length is not the image's. An empty mask selection gives mean 1.
base::Result<SsimResult> ssim(const Image& test, const Image& reference,
                              const std::vector<std::uint8_t>* mask = nullptr);

} // namespace speculum::render::metrics
