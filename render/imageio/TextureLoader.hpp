#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"

#include <cstddef>
#include <string>

namespace speculum::render {

// The largest width or height loadTexture() accepts; bigger files are refused rather than allocated.
inline constexpr int kMaxTextureSide = 16384;

// Loads any image OpenImageIO reads as RGBA with row 0 the BOTTOM row of the stored image (TextureImage):
// grey is spread to RGB, a missing alpha becomes opaque, alpha stays straight. 8-bit files fill `rgba8`
// (sRGB-encoded as stored); 16-bit, half and float files fill `linear` (integer files decoded from sRGB,
// float files taken as linear). Only regular files are read. Truncated or corrupt files are errors, never
// partial images.
base::Result<TextureImage> loadTexture(const std::string& path);

// The same for an image held in memory (a texture embedded in a model file: PNG, JPEG, ... bytes);
// `name` only labels messages.
base::Result<TextureImage> decodeTexture(const void* bytes, std::size_t size, const std::string& name);

// A magenta/black checker: the deliberately loud stand-in for a texture that failed to load.
TextureImage checkerTexture(int size = 64);

} // namespace speculum::render
