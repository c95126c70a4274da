#pragma once

#include "render/FrameInput.hpp"
#include "render/gl/Program.hpp"
#include "render/passes/MainPass.hpp"

#include <glm/mat4x4.hpp>

namespace speculum::render::passes {

// The programs planar mirrors need inside an environment map's cube faces.
struct EnvironmentMirrorPrograms {
    const gl::Program* flat = nullptr;   // shadow.vert + flat.frag: the mirror masks
    const gl::Program* mirror = nullptr; // mesh.vert + mirror.frag: the mirror surfaces
};

// One cube face of the reflector's environment (pass 1), with the planar mirrors it sees reflecting the
// scene one level deep (`mirrorDepth` ≥ 1; deeper mirrors, and every mirror when it is 0, show their own
// material). `env` is the scene as the environment sees it (camera at the capture point); near, far and
// the face's `view` (cubeFaceView) make up its capture-relative view-projection; `size` is its texel count.
//
// The capture target has no stencil buffer, so each mirror is masked through depth: with depth cleared to
// 0, the mirror rectangle writes depth 1 on its own pixels, and the reflected scene (reflection matrix,
// oblique near plane on the mirror) can pass the depth test only there. Then depth is cleared to 1, the
// mirror surfaces are blended over their reflections first (dual-source, as in the stencil technique),
// and the rest of the scene is drawn with ordinary depth testing, hiding what lies behind a mirror.
void drawEnvironmentFace(const FrameInput& env, double near, double far, const glm::dmat4& view, int size,
                         int mirrorDepth, const EnvironmentMirrorPrograms& programs,
                         MainPassContext& context);

} // namespace speculum::render::passes
