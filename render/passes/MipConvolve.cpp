#include "render/passes/MipConvolve.hpp"

#include <algorithm>

namespace speculum::render::passes {

void convolveMipChain(gl::RenderTexture& texture, const gl::Program& program, GLuint framebuffer,
                      GLuint vao) {
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
        glViewport(0, 0, std::max(texture.width() >> level, 1), std::max(texture.height() >> level, 1));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, texture.levels() - 1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
}

} // namespace speculum::render::passes
