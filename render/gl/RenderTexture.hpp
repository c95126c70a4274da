#pragma once

#include "base/Result.hpp"
#include "render/gl/Objects.hpp"

#include <cstddef>
#include <string>

namespace speculum::render::gl {

// A colour texture with a depth-stencil buffer, as one framebuffer: the linear frame buffer every frame is
// drawn into, and the reflection textures of texture-technique mirrors.
class RenderTexture {
public:
    // (Re)allocates when the size or format changes; `mipmapped` allows blurred lookups. Checked: an
    // error ("the 1280×720 colour buffer did not fit in GPU memory") leaves no target (framebuffer() is 0),
    // and the same request fails again at once, without asking the driver every frame.
    base::Status ensure(int width, int height, GLenum colorFormat, bool mipmapped);
    void generateMipmaps();

    GLuint framebuffer() const { return m_framebuffer.id(); }
    GLuint color() const { return m_color.id(); }
    int width() const { return m_width; }
    int height() const { return m_height; }
    int levels() const { return m_levels; }
    GLenum format() const { return m_format; } // the colour buffer's internal format
    // GPU memory of the colour mip chain and the depth-stencil buffer (0 before ensure()).
    std::size_t bytes() const;

private:
    int m_width = 0;
    int m_height = 0;
    int m_levels = 1;
    GLenum m_format = 0;
    std::string m_failure; // why the allocation of the size and format above failed; empty: it did not
    Texture m_color;
    Renderbuffer m_depthStencil;
    Framebuffer m_framebuffer;
};

} // namespace speculum::render::gl
