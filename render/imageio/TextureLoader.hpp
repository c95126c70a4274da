#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"

#include <cstddef>
#include <string>

namespace speculum::render {

// The largest width or height a texture file may declare; bigger files are refused before any pixel is
// read.
inline constexpr int kMaxTextureSide = 16384;

// The most memory one decoded texture may take by default: 256 MiB, which holds a 4096×4096 texture of
// 16-bit or float texels (16 bytes each) or an 8192×8192 one of 8-bit texels (4 bytes each).
inline constexpr std::size_t kTextureBudgetBytes = std::size_t{256} << 20;

// How large a decoded texture may be. A file that declares more is read smaller, by the smallest whole
// factor that fits: from a MIP level the file holds when it has one, else with each block of factor×factor
// texels averaged as its rows are read, so that the full-size image is never held in memory
// (docs/rendering.md, "Texture limits").
struct TextureLimits {
    int maxSide = kMaxTextureSide;              // the GPU's GL_MAX_TEXTURE_SIZE where one is known
    std::size_t maxBytes = kTextureBudgetBytes; // of the decoded texels as TextureImage holds them
};

// Loads any image OpenImageIO reads as RGBA with row 0 the BOTTOM row of the stored image (TextureImage):
// grey is spread to RGB, a missing alpha becomes opaque, alpha stays straight. 8-bit files fill `rgba8`
// (sRGB-encoded as stored); 16-bit, half and float files fill `linear` (integer files decoded from sRGB,
// float files taken as linear). Only regular files are read. Truncated or corrupt files are errors, never
// partial images, and so is a decode that runs out of memory. The declared size is checked against
// `limits` before any pixel is read. A file read smaller than it is sets `reduced`, when given, to the
// warning to give ("texture 'NAME' is 16384×16384; loaded at 4096×4096"); otherwise it is left empty.
base::Result<TextureImage> loadTexture(const std::string& path, const TextureLimits& limits = {},
                                       std::string* reduced = nullptr);

// The same for an image held in memory (a texture embedded in a model file: PNG, JPEG, ... bytes);
// `name` only labels messages.
base::Result<TextureImage> decodeTexture(const void* bytes, std::size_t size, const std::string& name,
                                         const TextureLimits& limits = {}, std::string* reduced = nullptr);

// A magenta/black checker: the deliberately loud stand-in for a texture that failed to load.
TextureImage checkerTexture(int size = 64);

} // namespace speculum::render
