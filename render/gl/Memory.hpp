#pragma once

#include <algorithm>
#include <cstddef>
#include <epoxy/gl.h>

namespace speculum::render::gl {

// Bytes one texel of a sized internal format takes. 24-bit depth counts as 4 bytes: drivers pad it to
// 32 bits (alone, or packed with 8 bits of stencil). 0 for a format this project does not allocate.
constexpr std::size_t bytesPerTexel(GLenum internalFormat) {
    switch (internalFormat) {
    case GL_RGBA8:
    case GL_SRGB8_ALPHA8:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH_COMPONENT32F:
    case GL_R32F:
        return 4;
    case GL_RGBA16F:
        return 8;
    case GL_RGBA32F:
        return 16;
    default:
        return 0;
    }
}

// Texels of a width × height image with `levels` mip levels (each half the size of the one before,
// at least 1×1), as glTexImage2D allocates them level by level.
constexpr std::size_t mipChainTexels(int width, int height, int levels) {
    std::size_t texels = 0;
    for (int level = 0; level < levels; ++level) {
        texels += static_cast<std::size_t>(std::max(1, width >> level)) *
                  static_cast<std::size_t>(std::max(1, height >> level));
    }
    return texels;
}

} // namespace speculum::render::gl
