#pragma once

#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"
#include "render/gl/RenderTexture.hpp"
#include "render/math/Mirror.hpp"

#include <glm/vec4.hpp>

namespace speculum::render::passes {

// Fills levels 1… of `texture`'s mip chain from level 0, each from the one before it with the binomial
// kernel of shaders/mip_convolve.frag (`program`: fullscreen.vert + mip_convolve.frag), instead of
// glGenerateMipmap's box filter: a chain of Gaussian blurs a rough mirror reads at the level its lobe's
// footprint asks for (GlossyFilter::Chain). `framebuffer` is a spare framebuffer object; `vao` an empty
// vertex array. Leaves the texture's base and max levels as they were and unbinds what it bound.
//
// A mirror's reflection fills only its own pixels (`drawn`); level 0 holds `outside` everywhere else. A
// constant stays that constant under the kernel, so each level is cleared to it (a whole-level clear is a
// plain fill) and convolved only over `drawn` scaled to the level, with a margin of the kernel's reach:
// the same chain, at the cost of the mirror's pixels instead of the whole frame's.
void convolveMipChain(gl::RenderTexture& texture, const gl::Program& program, GLuint framebuffer, GLuint vao,
                      const math::PixelRect& drawn, const glm::vec4& outside);

} // namespace speculum::render::passes
