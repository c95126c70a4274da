#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace speculum::render {

enum class PassKind { Shadow, MirrorMask, Mirror, Envmap, Main, Composite };

std::string_view toString(PassKind kind);

// One pass the renderer will run, and why. Timings are filled in after the frame executed
// (gpuMs < 0 means no GPU timing was available).
struct PlannedPass {
    PassKind kind = PassKind::Main;
    std::string target; // node name, or empty for the whole frame
    std::string reason;
    int lightIndex = -1; // shadow passes: index into FrameInput::lights
    double gpuMs = -1.0;
    double cpuMs = 0.0;
};

// An effect the scene has that got no pass this frame, and why.
struct SkippedEffect {
    std::string target;
    std::string reason;
};

struct FramePlan {
    std::vector<PlannedPass> passes;
    std::vector<SkippedEffect> skipped;
    // Lights (indices into FrameInput::lights) whose shadow map the main pass samples, rendered this
    // frame or reused; at most kMaxShadowedLights.
    std::vector<int> shadowedLights;
};

} // namespace speculum::render
