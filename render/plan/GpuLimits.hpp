#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/frame/SceneLimits.hpp"

#include <optional>
#include <string>
#include <vector>

namespace speculum::render {

// The sizes an OpenGL context can allocate and draw into, in pixels per side.
struct GpuLimits {
    int maxTextureSize = 16384;      // GL_MAX_TEXTURE_SIZE
    int maxCubeMapSize = 16384;      // GL_MAX_CUBE_MAP_TEXTURE_SIZE
    int maxRenderbufferSize = 16384; // GL_MAX_RENDERBUFFER_SIZE
    int maxViewportSize = 16384;     // the smaller of GL_MAX_VIEWPORT_DIMS
};

// Asks the current context. Defined by the GL library (render/gl/GpuLimitsQuery.cpp); the rest of this
// header is GL-free.
GpuLimits queryGpuLimits();

// Smallest sizes the passes work with (render/frame/SceneLimits.hpp): a shadow map below 16 texels is no map,
// and the environment maps' guard bands need a few texels each side.
inline constexpr int kMinEnvmapResolution = kMinEnvironmentMapSize;

// The frame's shadow map sizes and reflector resolution brought within `limits` (and above the minimums
// above): a size the GPU cannot hold would fail to allocate and make every later draw into it a GL
// error. Returns the adjusted copy, or nothing when every size fits; each change adds a warning naming
// the light or reflector, the size asked for and the size used. Needs no GL.
std::optional<FrameInput> fitToGpuLimits(const FrameInput& input, const GpuLimits& limits,
                                         std::vector<std::string>& warnings);

} // namespace speculum::render
