// The one GL call behind GpuLimits: the struct and the fitting of map sizes belong to the GL-free core, so
// that the planner's tests fit sizes without a context.
#include "render/gl/Objects.hpp"
#include "render/plan/GpuLimits.hpp"

#include <algorithm>
#include <string>

namespace speculum::render {

GpuLimits queryGpuLimits() {
    GpuLimits limits;
    GLint viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &limits.maxTextureSize);
    glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &limits.maxCubeMapSize);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &limits.maxRenderbufferSize);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    limits.maxViewportSize = std::min(viewport[0], viewport[1]);
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = renderer ? renderer : "";
    limits.software = name.find("llvmpipe") != std::string::npos ||
                      name.find("softpipe") != std::string::npos ||
                      name.find("Software Rasterizer") != std::string::npos;
    return limits;
}

} // namespace speculum::render
