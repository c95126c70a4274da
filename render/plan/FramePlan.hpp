#pragma once

#include "render/math/Mirror.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace speculum::render {

enum class PassKind { Shadow, MirrorMask, Mirror, MirrorSurface, Envmap, Main, Composite };

std::string_view toString(PassKind kind);

// One pass the renderer will run, and why. Timings are filled in after the frame executed
// (gpuMs < 0 means no GPU timing was available).
struct PlannedPass {
    PassKind kind = PassKind::Main;
    std::string target; // node name, or empty for the whole frame
    std::string reason;
    int lightIndex = -1; // shadow passes: index into FrameInput::lights
    int view = -1;       // mirror passes: index into FramePlan::views
    double gpuMs = -1.0;
    double cpuMs = 0.0;
};

// An effect the scene has that got no pass this frame, and why.
struct SkippedEffect {
    std::string target;
    std::string reason;
};

// The scene seen in one mirror, possibly through other mirrors: everything the renderer needs to draw
// it, derived in double precision by the planner.
struct MirrorView {
    int mirror = -1; // index into FrameInput::mirrors
    int parent = -1; // index into FramePlan::views of the view the mirror is seen in; -1: the camera's
    int depth = 1;   // 1: seen directly by the camera
    glm::dmat4 reflection{1.0}; // world → reflected world: the parent's reflection × this mirror's
    glm::dmat4 projection{1.0}; // the camera's projection with the oblique near plane on the mirror
    glm::dvec3 eye{0.0};        // the virtual eye in (unreflected) world space: reflection⁻¹ · camera
    math::PixelRect rect;       // the pixels the mirror covers, within its parent's
    double pixelArea = 0.0;
    bool ownTarget = false;     // texture technique: rendered into a texture of its own
    int stencilLevel = 0;       // the stencil value of its pixels in the target it is drawn into
    int parentStencilLevel = 0; // the stencil value of the parent view's pixels, where the mirror appears
    int textureSlot = -1;       // own-target views: which render texture (one per nesting of texture views)
};

struct FramePlan {
    std::vector<PlannedPass> passes;
    std::vector<SkippedEffect> skipped;
    // Lights (indices into FrameInput::lights) whose shadow map the main pass samples, rendered this
    // frame or reused; at most kMaxShadowedLights.
    std::vector<int> shadowedLights;
    std::vector<MirrorView> views;
};

} // namespace speculum::render
