#pragma once

#include <cstddef>
#include <vector>

namespace speculum::render::metrics {

// One channel of an image as floats, row 0 at the top: what the perceptual metrics filter.
struct Plane {
    int width = 0;
    int height = 0;
    std::vector<float> values; // width * height

    Plane() = default;
    Plane(int w, int h, float fill = 0.0f)
        : width(w)
        , height(h)
        , values(static_cast<std::size_t>(w) * h, fill) {}
    float& at(int x, int y) { return values[static_cast<std::size_t>(y) * width + x]; }
    float at(int x, int y) const { return values[static_cast<std::size_t>(y) * width + x]; }
};

// A 1-D kernel centred on its middle tap (an odd number of taps).
using Kernel = std::vector<float>;

// The plane convolved with `horizontal` along rows and then `vertical` along columns, the image's edge
// pixels repeated beyond it (so a uniform image stays uniform under a normalised kernel). The kernels are
// used as given: normalising them is the caller's.
Plane convolveSeparable(const Plane& plane, const Kernel& horizontal, const Kernel& vertical);

// A Gaussian kernel of standard deviation `sigma` taps with `radius` taps each side, summing to 1.
Kernel gaussianKernel(double sigma, int radius);

} // namespace speculum::render::metrics
