#include "render/passes/MipConvolve.hpp"

#include <algorithm>

namespace speculum::render::passes {

namespace {

// `drawn` on level `level`, grown by the texels the kernels of the levels so far can have carried its
// content out by: each level's kernel reaches 1.5 texels of the level below, 1.5 / 2^(k−j) of level k's
// from level j, which sums to under 1.5; 2 with the rounding.
math::PixelRect levelRect(const math::PixelRect& drawn, int level, int width, int height) {
    const int scale = 1 << level;
    return {std::max(drawn.x0 / scale - 2, 0), std::max(drawn.y0 / scale - 2, 0),
            std::min((drawn.x1 + scale - 1) / scale + 2, width),
            std::min((drawn.y1 + scale - 1) / scale + 2, height)};
}

} // namespace

void convolveMipChain(gl::RenderTexture& texture, const gl::Program& program, GLuint framebuffer, GLuint vao,
                      const math::PixelRect& drawn, const glm::vec4& outside) {
    if (texture.levels() <= 1)
        return;
    gl::FramebufferBinding keep;
    const gl::PlainDrawState plain;
    program.use();
    program.set("uSource", 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture.color());
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glBindVertexArray(vao);
    for (int level = 1; level < texture.levels(); ++level) {
        // Only the level below is visible to the lookups: no loop through the level being written.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, level - 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, level - 1);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.color(), level);
        const int width = std::max(texture.width() >> level, 1);
        const int height = std::max(texture.height() >> level, 1);
        glViewport(0, 0, width, height);
        const math::PixelRect rect = levelRect(drawn, level, width, height);
        if (rect.width() < width || rect.height() < height) {
            glClearColor(outside.r, outside.g, outside.b, outside.a);
            glClear(GL_COLOR_BUFFER_BIT);
            glEnable(GL_SCISSOR_TEST);
            glScissor(rect.x0, rect.y0, std::max(rect.width(), 0), std::max(rect.height(), 0));
        }
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisable(GL_SCISSOR_TEST);
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, texture.levels() - 1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
}

} // namespace speculum::render::passes
