#include "render/gl/RenderTexture.hpp"

#include "render/gl/Memory.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::render::gl {

void RenderTexture::ensure(int width, int height, GLenum colorFormat, bool mipmapped) {
    const int levels = mipmapped ? 1 + static_cast<int>(std::floor(std::log2(std::max(width, height)))) : 1;
    if (m_framebuffer && width == m_width && height == m_height && colorFormat == m_format &&
        levels == m_levels)
        return;
    m_width = width;
    m_height = height;
    m_format = colorFormat;
    m_levels = levels;
    m_color = makeTexture();
    glBindTexture(GL_TEXTURE_2D, m_color.id());
    for (int level = 0, w = width, h = height; level < levels;
         ++level, w = std::max(1, w / 2), h = std::max(1, h / 2))
        glTexImage2D(GL_TEXTURE_2D, level, static_cast<GLint>(colorFormat), w, h, 0, GL_RGBA, GL_FLOAT,
                     nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mipmapped ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mipmapped ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    m_depthStencil = makeRenderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, m_depthStencil.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    m_framebuffer = makeFramebuffer();
    FramebufferBinding keep;
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_color.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              m_depthStencil.id());
}

std::size_t RenderTexture::bytes() const {
    if (!m_framebuffer)
        return 0;
    const auto pixels = static_cast<std::size_t>(m_width) * static_cast<std::size_t>(m_height);
    return mipChainTexels(m_width, m_height, m_levels) * bytesPerTexel(m_format) +
           pixels * bytesPerTexel(GL_DEPTH24_STENCIL8);
}

void RenderTexture::generateMipmaps() {
    if (m_levels <= 1)
        return;
    glBindTexture(GL_TEXTURE_2D, m_color.id());
    glGenerateMipmap(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
}

} // namespace speculum::render::gl
