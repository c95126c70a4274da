#pragma once

#include "render/Result.hpp"
#include "render/image/Image.hpp"

#include <string>

namespace speculum::render {

// The largest width or height loadTexture() accepts; bigger files are refused rather than allocated.
inline constexpr int kMaxTextureSide = 16384;

// Loads any image OpenImageIO reads as 8-bit sRGB-encoded RGBA, row 0 at the top: grey is spread to
// RGB, a missing alpha becomes 255, 16-bit values are rounded to 8 bits, float (linear) files are
// sRGB-encoded. Alpha stays straight. Truncated or corrupt files are errors, never partial images.
Result<TextureImage> loadTexture(const std::string& path);

// A magenta/black checker: the deliberately loud stand-in for a texture that failed to load.
TextureImage checkerTexture(int size = 64);

} // namespace speculum::render
