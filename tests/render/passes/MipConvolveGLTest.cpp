// The convolved chain of a rough mirror's reflection (GlossyFilter::Chain): a reflection fills only its
// mirror's pixels and the background everywhere else, so convolving only those pixels (and the kernel's
// reach around them) must give the very chain the whole texture's convolution gives.
#include "render/gl/Program.hpp"
#include "render/gl/RenderTexture.hpp"
#include "render/passes/MipConvolve.hpp"
#include "support/GlTest.hpp"

#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>
#include <vector>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 200;
constexpr int kHeight = 120;
const glm::vec4 kBackground(0.1f, 0.2f, 0.3f, 65504.0f);

// Level 0: the background, and inside `drawn` a pattern with sharp edges and path lengths.
std::vector<glm::vec4> reflection(const math::PixelRect& drawn) {
    std::vector<glm::vec4> texels(static_cast<std::size_t>(kWidth) * kHeight, kBackground);
    for (int y = drawn.y0; y < drawn.y1; ++y)
        for (int x = drawn.x0; x < drawn.x1; ++x)
            texels[static_cast<std::size_t>(y) * kWidth + x] = glm::vec4(
                float((x / 7 + y / 5) % 3) * 2.0f, float(x % 11) / 11.0f, 0.5f, 1.0f + float(y % 13));
    return texels;
}

std::vector<std::vector<glm::vec4>> convolvedLevels(const math::PixelRect& drawn,
                                                    const math::PixelRect& told) {
    gl::RenderTexture texture;
    EXPECT_TRUE(texture.ensure(kWidth, kHeight, GL_RGBA16F, true).ok());
    const std::vector<glm::vec4> level0 = reflection(drawn);
    glBindTexture(GL_TEXTURE_2D, texture.color());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, level0.data());
    // Stale levels from an earlier frame: the restricted convolution must not leave any of them.
    for (int level = 1; level < texture.levels(); ++level) {
        const int w = std::max(kWidth >> level, 1), h = std::max(kHeight >> level, 1);
        const std::vector<glm::vec4> stale(static_cast<std::size_t>(w) * h, glm::vec4(7.0f));
        glTexSubImage2D(GL_TEXTURE_2D, level, 0, 0, w, h, GL_RGBA, GL_FLOAT, stale.data());
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    auto program = gl::Program::build("fullscreen.vert", "mip_convolve.frag");
    EXPECT_TRUE(program.ok()) << (program.ok() ? "" : program.error());
    const gl::Framebuffer framebuffer = gl::makeFramebuffer();
    const gl::VertexArray vao = gl::makeVertexArray();
    passes::convolveMipChain(texture, *program, framebuffer.id(), vao.id(), told, kBackground);
    std::vector<std::vector<glm::vec4>> levels;
    glBindTexture(GL_TEXTURE_2D, texture.color());
    for (int level = 1; level < texture.levels(); ++level) {
        const int w = std::max(kWidth >> level, 1), h = std::max(kHeight >> level, 1);
        levels.emplace_back(static_cast<std::size_t>(w) * h);
        glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_FLOAT, levels.back().data());
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    return levels;
}

class MipConvolve : public GlTest {};

TEST_F(MipConvolve, ConvolvingTheMirrorsPixelsGivesTheWholeChain) {
    for (const math::PixelRect drawn : {math::PixelRect{37, 21, 93, 70}, math::PixelRect{0, 50, 31, 120},
                                        math::PixelRect{150, 3, 200, 9}}) {
        const auto whole = convolvedLevels(drawn, {0, 0, kWidth, kHeight});
        const auto restricted = convolvedLevels(drawn, drawn);
        ASSERT_EQ(whole.size(), restricted.size());
        ASSERT_GE(whole.size(), 6u);
        for (std::size_t level = 0; level < whole.size(); ++level) {
            float worst = 0.0f;
            for (std::size_t i = 0; i < whole[level].size(); ++i)
                for (int c = 0; c < 4; ++c)
                    worst = std::max(worst, std::abs(whole[level][i][c] - restricted[level][i][c]) /
                                                std::max(1.0f, std::abs(whole[level][i][c])));
            // Half floats: a relative 2^-10 is their step.
            EXPECT_LE(worst, 2e-3f) << "level " << level + 1 << " of the rect at " << drawn.x0 << ", "
                                    << drawn.y0;
        }
    }
}

} // namespace
} // namespace speculum::test
