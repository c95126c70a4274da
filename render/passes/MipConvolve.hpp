#pragma once

#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"
#include "render/gl/RenderTexture.hpp"

namespace speculum::render::passes {

// Fills levels 1… of `texture`'s mip chain from level 0, each from the one before it with the binomial
// kernel of shaders/mip_convolve.frag (`program`: fullscreen.vert + mip_convolve.frag), instead of
// glGenerateMipmap's box filter: a chain of Gaussian blurs a rough mirror reads at the level its lobe's
// footprint asks for (GlossyFilter::Chain). `framebuffer` is a spare framebuffer object; `vao` an empty
// vertex array. Leaves the texture's base and max levels as they were and unbinds what it bound.
void convolveMipChain(gl::RenderTexture& texture, const gl::Program& program, GLuint framebuffer, GLuint vao);

} // namespace speculum::render::passes
