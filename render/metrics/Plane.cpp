#include "render/metrics/Plane.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::render::metrics {

namespace {

// One pass along rows (horizontal) or columns, clamping the index at the edges.
Plane convolveAlong(const Plane& plane, const Kernel& kernel, bool horizontal) {
    Plane out(plane.width, plane.height);
    const int radius = static_cast<int>(kernel.size() / 2);
    const int length = horizontal ? plane.width : plane.height;
    const int lines = horizontal ? plane.height : plane.width;
    std::vector<float> line(static_cast<std::size_t>(length + 2 * radius));
    for (int l = 0; l < lines; ++l) {
        for (int i = -radius; i < length + radius; ++i) {
            const int c = std::clamp(i, 0, length - 1);
            line[static_cast<std::size_t>(i + radius)] = horizontal ? plane.at(c, l) : plane.at(l, c);
        }
        for (int i = 0; i < length; ++i) {
            double sum = 0.0;
            for (std::size_t k = 0; k < kernel.size(); ++k)
                sum += double(kernel[k]) * line[static_cast<std::size_t>(i) + k];
            (horizontal ? out.at(i, l) : out.at(l, i)) = static_cast<float>(sum);
        }
    }
    return out;
}

} // namespace

Plane convolveSeparable(const Plane& plane, const Kernel& horizontal, const Kernel& vertical) {
    if (plane.width == 0 || plane.height == 0)
        return plane;
    return convolveAlong(convolveAlong(plane, horizontal, true), vertical, false);
}

Kernel gaussianKernel(double sigma, int radius) {
    Kernel kernel(static_cast<std::size_t>(2 * radius + 1));
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const double w = std::exp(-double(i * i) / (2.0 * sigma * sigma));
        kernel[static_cast<std::size_t>(i + radius)] = static_cast<float>(w);
        sum += w;
    }
    for (float& w : kernel)
        w = static_cast<float>(w / sum);
    return kernel;
}

} // namespace speculum::render::metrics
