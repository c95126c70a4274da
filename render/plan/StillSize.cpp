#include "render/plan/StillSize.hpp"

#include <cstdio>
#include <string>

namespace speculum::render {

namespace {

std::string sizeText(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

} // namespace

base::Status checkStillSize(int width, int height) {
    if (width <= 0 || height <= 0)
        return base::Error{"image size must be positive, got " + sizeText(width, height)};
    const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * 4 * sizeof(float);
    if (bytes > kMaxStillBytes) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "image size %s is too large: its pixels would take %.0f GiB (at most %llu GiB)",
                      sizeText(width, height).c_str(), double(bytes) / double(1ull << 30),
                      static_cast<unsigned long long>(kMaxStillBytes >> 30));
        return base::Error{text};
    }
    return base::Done{};
}

} // namespace speculum::render
