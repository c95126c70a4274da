#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/gl/Program.hpp"
#include "render/passes/EnvironmentCapture.hpp"
#include "render/passes/MainPass.hpp"
#include "render/passes/WarpMeshes.hpp"
#include "render/plan/FramePlan.hpp"

#include <glm/mat4x4.hpp>
#include <unordered_map>

namespace speculum::render::passes {

// The programs planar mirrors need inside one kind of environment target: for cube faces shadow.vert +
// flat.frag (masks) and mesh.vert + mirror.frag (surfaces); for the direct fill their ENVMAP_WARP variants.
struct EnvironmentMirrorPrograms {
    const gl::Program* flat = nullptr;   // the mirror masks
    const gl::Program* mirror = nullptr; // the mirror surfaces
};

// What the environment pass remembers of each mesh while the mesh lives: its bounds and whether it is
// closed (isClosed). Items of closed meshes seen from outside are drawn with their back faces culled:
// with small, many-sided objects an environment map's cost is mostly triangles, not texels.
class MeshFacts {
public:
    struct Facts {
        Bounds bounds;
        bool closed = false;
    };
    const Facts& get(const MeshHandle& mesh);
    // Forgets meshes nobody holds any more.
    void purge();

private:
    struct Entry {
        std::weak_ptr<const MeshData> owner;
        Facts facts;
    };
    std::unordered_map<const MeshData*, Entry> m_entries;
};

// One target of the reflector's environment (pass 1): a cube face, or a component of the direct fill.
struct EnvironmentTarget {
    // A cube face (warp is null): its view (envmap::cubeFaceView), near and far, its size in texels.
    glm::dmat4 faceView{1.0};
    double near = 0.01;
    double far = 100.0;
    int size = 1;
    // The direct fill: the component's warp, and the cache that splits the meshes for each (virtual)
    // capture point they are seen from (edges up to warpAngle; shorter than `near` never split).
    const envmap::WarpPass* warp = nullptr;
    WarpMeshes* warpMeshes = nullptr;
    double warpAngle = 0.3;
    MeshFacts* meshFacts = nullptr; // null: every face of every item is drawn
    // The mirror views the planner planned in this face or component (planEnvmapMirrors): `face` indexes
    // plan->faces. No plan: no mirror reflects (every mirror shows its own material).
    const EnvmapPlan* plan = nullptr;
    int face = -1;
};

// Draws the environment `env` (the scene without the reflector, camera at the capture point) into the
// bound target, with the mirror views the planner planned for it (target.plan, target.face) reflecting
// the scene (mirrors in mirrors included; mirrors without a view show their own material). Decides
// nothing: which mirrors reflect, how deep, their reflections, oblique projections and clip planes are
// the plan's, and after the face's own view it runs the plan's passes for this face (EnvmapPlan::passes
// whose view lies in target.face) in plan order, each through the stencil level and with the winding its
// PassWrites declare. The one thing it adds is what the capture alone knows: a direct-fill warp that
// mirrors the image flips every winding. context.program draws the scene: mesh.vert + mesh.frag, or its
// ENVMAP_WARP variant.
//
// The stencil technique of the main pass, nested the same way: a mirror's visible pixels (those of its
// parent's stencil level whose depth test passes) are marked one level deeper and reset to the background
// at the far plane, the scene reflected in it is drawn there, then its own mirrors, then its surface is
// blended over its reflection, restoring its depth and stepping its pixels back to the parent's level.
// A cube face cuts a reflection at its mirror with Lengyel's oblique near plane; the warp, which has no
// projection matrix, with clip distance 0. Reflected points lie up to (2·depth + 1)·far away, so each level
// gets a far distance that deep.
void drawEnvironmentTarget(const FrameInput& env, const EnvironmentTarget& target,
                           const EnvironmentMirrorPrograms& programs, MainPassContext& context);

} // namespace speculum::render::passes
