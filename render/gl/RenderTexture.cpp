#include "render/gl/RenderTexture.hpp"

#include "render/gl/Allocation.hpp"
#include "render/gl/Memory.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::render::gl {

base::Status RenderTexture::ensure(int width, int height, GLenum colorFormat, bool mipmapped) {
    const int levels = mipmapped ? 1 + static_cast<int>(std::floor(std::log2(std::max(width, height)))) : 1;
    const bool same = width == m_width && height == m_height && colorFormat == m_format && levels == m_levels;
    if (same && m_framebuffer)
        return base::Done{};
    if (same && !m_failure.empty())
        return base::Error{m_failure};
    m_width = width;
    m_height = height;
    m_format = colorFormat;
    m_levels = levels;
    m_failure.clear();
    // The old target's memory first: it may be what the new one needs.
    m_framebuffer.reset();
    m_color.reset();
    m_depthStencil.reset();
    const std::string size = std::to_string(width) + "×" + std::to_string(height);
    auto fail = [&](const std::string& what, const std::string& why) -> base::Status {
        m_framebuffer.reset();
        m_color.reset();
        m_depthStencil.reset();
        m_failure = "the " + size + " " + what + " " + why;
        return base::Error{m_failure};
    };
    const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (base::Status fits =
            beginAllocation(mipChainTexels(width, height, levels) * bytesPerTexel(colorFormat));
        !fits)
        return fail("colour buffer", fits.error());
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
    if (base::Status done = finishAllocation(); !done)
        return fail("colour buffer", done.error());
    if (base::Status fits = beginAllocation(pixels * bytesPerTexel(GL_DEPTH24_STENCIL8)); !fits)
        return fail("depth-stencil buffer", fits.error());
    m_depthStencil = makeRenderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, m_depthStencil.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    if (base::Status done = finishAllocation(); !done)
        return fail("depth-stencil buffer", done.error());
    m_framebuffer = makeFramebuffer();
    FramebufferBinding keep;
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_color.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              m_depthStencil.id());
    if (base::Status complete = checkFramebuffer(); !complete)
        return fail("render target", complete.error());
    return base::Done{};
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
