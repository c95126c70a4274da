#pragma once

#include "render/image/Image.hpp"

#include <cstdint>

namespace speculum::render {

// A procedural white marble with grey veins (Perlin's sin(x + turbulence) marble), size x size,
// sRGB-encoded RGBA8, opaque. It tiles seamlessly, and the same (size, seed) gives the same bytes on
// every platform: the noise uses an integer hash and only +, *, / and floor (no libm, no std::
// distributions), so no library or instruction-set difference can change a pixel.
TextureImage generateMarble(int size, std::uint32_t seed);

} // namespace speculum::render
