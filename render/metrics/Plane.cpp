#include "render/metrics/Plane.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::render::metrics {

namespace {

// dst[i] += w · src[i] for n values. Written in blocks of eight so that the compiler's block vectoriser
// turns each block into vector instructions at -O2 (the loop vectoriser's cheap model would not).
void addScaled(float* __restrict dst, const float* __restrict src, float w, int n) {
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        float block[8];
        for (int j = 0; j < 8; ++j)
            block[j] = dst[i + j] + w * src[i + j];
        for (int j = 0; j < 8; ++j)
            dst[i + j] = block[j];
    }
    for (; i < n; ++i)
        dst[i] += w * src[i];
}

// Along rows, clamping the index at the edges; tap by tap over the whole row, so that the work runs along
// contiguous memory with no reduction.
Plane convolveRows(const Plane& plane, const Kernel& kernel) {
    Plane out(plane.width, plane.height);
    const int radius = static_cast<int>(kernel.size() / 2);
    std::vector<float> line(static_cast<std::size_t>(plane.width + 2 * radius));
    for (int y = 0; y < plane.height; ++y) {
        for (int i = -radius; i < plane.width + radius; ++i)
            line[static_cast<std::size_t>(i + radius)] = plane.at(std::clamp(i, 0, plane.width - 1), y);
        float* row = &out.at(0, y);
        for (std::size_t k = 0; k < kernel.size(); ++k)
            addScaled(row, line.data() + k, kernel[k], plane.width);
    }
    return out;
}

// Along columns: each output row is the weighted sum of whole input rows (clamped at the top and
// bottom), so memory is read a row at a time.
Plane convolveColumns(const Plane& plane, const Kernel& kernel) {
    Plane out(plane.width, plane.height);
    const int radius = static_cast<int>(kernel.size() / 2);
    for (int y = 0; y < plane.height; ++y) {
        float* row = &out.at(0, y);
        for (std::size_t k = 0; k < kernel.size(); ++k) {
            const int from = std::clamp(y + static_cast<int>(k) - radius, 0, plane.height - 1);
            addScaled(row, plane.values.data() + static_cast<std::size_t>(from) * plane.width, kernel[k],
                      plane.width);
        }
    }
    return out;
}

} // namespace

Plane convolveSeparable(const Plane& plane, const Kernel& horizontal, const Kernel& vertical) {
    if (plane.width == 0 || plane.height == 0)
        return plane;
    return convolveColumns(convolveRows(plane, horizontal), vertical);
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
