#pragma once

#include "render/envmap/CaptureMath.hpp"
#include "render/math/Mirror.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <optional>
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
    // Shadow passes: the signature of what the map holds (shadowSignature), which the renderer records
    // once the map is drawn, so the next frame's planner can reuse it.
    std::uint64_t signature = 0;
};

// An effect the scene has that got no pass this frame, and why.
struct SkippedEffect {
    std::string target;
    std::string reason;
    int face = -1; // skips inside the environment map: index into EnvmapPlan::faces (-1: every face)
};

// The scene seen in one mirror, possibly through other mirrors: everything the renderer needs to draw
// it, derived in double precision by the planner. The camera's views live in FramePlan::views, the
// environment map's in EnvmapPlan::views; both are planned by planMirrors' one planner.
struct MirrorView {
    int mirror = -1; // index into FrameInput::mirrors
    int parent = -1; // index into the same list of the view the mirror is seen in; -1: the space's own
    int depth = 1;   // 1: seen directly by the camera (or the capture point)
    int face = -1;   // map views: index into EnvmapPlan::faces; -1: the camera's
    glm::dmat4 reflection{1.0}; // world → reflected world: the parent's reflection × this mirror's
    // The projection with the oblique near plane on the mirror: the camera's (used with its rotation), or
    // the cube face's (used with EnvmapFace::view). Unused in a direct-fill component, which clips with:
    glm::dmat4 projection{1.0};
    glm::dvec4 clipPlane{0.0}; // the mirror's kept side in relative (camera- or capture-relative) drawn space
    glm::dvec3 eye{0.0};       // the virtual eye in (unreflected) world space: reflection⁻¹ · camera
    math::PixelRect rect;      // the pixels (texels) the mirror covers, within its parent's
    double pixelArea = 0.0;
    bool ownTarget = false;     // texture technique: rendered into a texture of its own
    int stencilLevel = 0;       // the stencil value of its pixels in the target it is drawn into
    int parentStencilLevel = 0; // the stencil value of the parent view's pixels, where the mirror appears
    int textureSlot = -1;       // own-target views: which render texture (one per nesting of texture views)
};

// Where the reflector's environment map is captured from: the centre of the reflector's world bounds
// (a teapot's node origin is its base), with a near distance that clips nothing outside the reflector
// and a far distance that reaches every corner of the scene.
struct EnvmapCapture {
    glm::dvec3 centre{0.0};
    double near = 0.01;
    double far = 100.0;
};

// One face of the map's cube (cube maps and the resampled fill) or one component of the direct fill, as
// pass 1 draws it: mirrors are planned in each, seen from the capture point.
struct EnvmapFace {
    std::string label;   // "+X face", "−Z half", "part 1"
    int index = 0;       // the cube face (GL order +X −X +Y −Y +Z −Z) or the component
    bool warped = false; // a direct-fill component, drawn through `warp`; else a cube face
    glm::dmat4 view{1.0}; // capture-relative world → the face's view (envmap::cubeFaceView), or the map frame
    envmap::WarpParameters warp;
    int width = 1; // texels
    int height = 1;
};

// What the environment pass draws, planned with the frame: the capture point, the faces, and the mirror
// views in each face with their passes (in execution order, face by face) and skips, with reasons.
struct EnvmapPlan {
    std::string target; // the reflector's name
    EnvmapCapture capture;
    // What the renderer records once the map is drawn (envmapSignature, envmapSettingsKey).
    std::uint64_t signature = 0;
    std::uint64_t settingsKey = 0;
    std::vector<EnvmapFace> faces;
    std::vector<MirrorView> views;
    std::vector<PlannedPass> passes; // view: index into `views`
    std::vector<SkippedEffect> skipped;
};

struct FramePlan {
    std::vector<PlannedPass> passes;
    std::vector<SkippedEffect> skipped;
    // Lights (indices into FrameInput::lights) whose shadow map the main pass samples, rendered this
    // frame or reused; at most kMaxShadowedLights.
    std::vector<int> shadowedLights;
    std::vector<MirrorView> views;
    // Set when the environment pass runs this frame.
    std::optional<EnvmapPlan> envmap;
};

} // namespace speculum::render
