#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/gl/Program.hpp"
#include "render/passes/EnvironmentCapture.hpp"
#include "render/passes/MainPass.hpp"
#include "render/passes/MirrorPasses.hpp"
#include "render/passes/WarpMeshes.hpp"
#include "render/plan/FramePlan.hpp"

#include <functional>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <unordered_map>

namespace speculum::render::passes {

// The programs planar mirrors need inside one kind of environment target: for cube faces shadow.vert +
// flat.frag (masks, perfect mirrors' tints) and mesh.vert + mirror.frag (surfaces); for the direct fill
// their ENVMAP_WARP variants.
struct EnvironmentMirrorPrograms {
    const gl::Program& flat;
    const gl::Program& mirror;
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
    // A cube face (warp is null): its view (envmap::cubeFaceView), near and far.
    glm::dmat4 faceView{1.0};
    double near = 0.01;
    double far = 100.0;
    // The framebuffer the capture bound for the target, and the target's size in texels
    // (EnvironmentCapture::framebuffer, targetSize).
    GLuint framebuffer = 0;
    glm::ivec2 size{1, 1};
    // The direct fill: the component's warp, and the cache that splits the meshes for each (virtual)
    // capture point they are seen from (edges up to warpAngle; shorter than `near` never split).
    const envmap::WarpPass* warp = nullptr;
    WarpMeshes* warpMeshes = nullptr;
    double warpAngle = 0.3;
    MeshFacts* meshFacts = nullptr; // null: every face of every item is drawn
    // The mirror views the planner planned in this face or component (planEnvmapMirrors): `face` indexes
    // plan->faces.
    const EnvmapPlan* plan = nullptr;
    int face = -1;
};

// Runs the plan's mirror passes of one face (EnvmapPlan::passes whose views lie in it), in plan order, in
// the face's space.
using RunFacePasses = std::function<void(const ViewSpace& face)>;

// Draws the environment `env` (the scene without the reflector, camera at the capture point) into the
// bound target: the face's own view over the whole target, then, through runFacePasses, the mirror passes
// the planner planned in it (target.plan, target.face), which reflect the scene (mirrors in mirrors
// included; mirrors without a view show only their surface's share). They run in the face as a ViewSpace,
// with the executors and the stencil recipe of the camera's mirrors (MirrorPasses); the face decides nothing
// about them, and adds what the capture alone knows: the face's view and projection (a cube face's; the
// warp has none and cuts each reflection at its mirror with clip distance 0), a far distance that grows
// to (2·depth + 1)·far with each level since reflected points lie that far, a direct-fill warp that
// mirrors the image flipping every winding, and what each view draws: meshes split for its virtual
// capture point, and the back faces that point cannot see culled. context.program draws the scene:
// mesh.vert + mesh.frag, or its ENVMAP_WARP variant.
void drawEnvironmentTarget(const FrameInput& env, const EnvironmentTarget& target,
                           const EnvironmentMirrorPrograms& programs, MainPassContext& context,
                           const RunFacePasses& runFacePasses);

} // namespace speculum::render::passes
