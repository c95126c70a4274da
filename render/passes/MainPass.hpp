#pragma once

#include "render/FrameInput.hpp"
#include "render/gl/GpuMesh.hpp"
#include "render/gl/Program.hpp"
#include "render/gl/TextureCache.hpp"
#include "render/passes/ShadowMaps.hpp"

#include <glm/mat4x4.hpp>
#include <vector>

namespace speculum::render::passes {

// Texture units the main pass uses: 0 for the material texture, then the shadow slots.
inline constexpr int kMaterialTextureUnit = 0;
inline constexpr int kShadow2DUnit = 1;   // 1..4
inline constexpr int kShadowCubeUnit = 5; // 5..8

// Everything the main pass needs besides the scene: resources owned by the renderer.
struct MainPassContext {
    const gl::Program& program;
    gl::MeshCache& meshes;
    gl::TextureCache& textures;
    const ShadowMaps& shadows;
    const std::vector<int>& shadowedLights; // light index per shadow slot
    GLuint dummyShadow2D;
    GLuint dummyShadowCube;
    MeshHandle unitPlane; // the mirror rectangle: [-1,1]² in XZ
};

// Draws every object with Blinn-Phong lighting and filtered shadows into the bound framebuffer.
// `viewProjection` maps camera-relative world space to clip space.
void drawMainPass(const FrameInput& input, const glm::dmat4& viewProjection, const MainPassContext& context);

} // namespace speculum::render::passes
