#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace speculum::render {

// The exact piecewise sRGB transfer functions (IEC 61966-2-1). The linear segment near black matters:
// a pure power curve would crush dark tones and make round trips through 8 bits lossy there.
inline float linearToSrgb(float linear) {
    if (!(linear > 0.0f)) { // also maps NaN to 0
        return 0.0f;
    }
    if (linear <= 0.0031308f) {
        return 12.92f * linear;
    }
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

inline float srgbToLinear(float encoded) {
    if (!(encoded > 0.0f)) {
        return 0.0f;
    }
    if (encoded <= 0.04045f) {
        return encoded / 12.92f;
    }
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

// Quantises a 0..1 value (already encoded) to 8 bits: clamp, then round to nearest.
inline std::uint8_t toUnorm8(float value) {
    if (!(value > 0.0f)) {
        return 0;
    }
    return static_cast<std::uint8_t>(std::lround(std::min(value, 1.0f) * 255.0f));
}

// Linear value to an 8-bit sRGB code.
inline std::uint8_t linearToSrgb8(float linear) {
    return toUnorm8(linearToSrgb(std::min(linear, 1.0f)));
}

// 8-bit sRGB code to a linear value.
inline float srgb8ToLinear(std::uint8_t code) {
    return srgbToLinear(static_cast<float>(code) / 255.0f);
}

} // namespace speculum::render
