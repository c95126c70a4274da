#include "render/passes/EnvironmentFaces.hpp"

#include "render/envmap/CaptureMath.hpp"
#include "render/math/Mirror.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cassert>
#include <optional>

namespace speculum::render::passes {

const MeshFacts::Facts& MeshFacts::get(const MeshHandle& mesh) {
    auto it = m_entries.find(mesh.get());
    // A new mesh may reuse the address of a freed one: only a live weak pointer to this very mesh counts.
    if (it != m_entries.end() && it->second.owner.lock() == mesh)
        return it->second.facts;
    Entry entry{mesh, {computeBounds(*mesh), isClosed(*mesh)}};
    return m_entries.insert_or_assign(mesh.get(), std::move(entry)).first->second.facts;
}

void MeshFacts::purge() {
    std::erase_if(m_entries, [](const auto& kv) { return kv.second.owner.expired(); });
}

namespace {

// Where one view of the face looks from: the capture point's own view (depth 0), or the scene reflected
// in a chain of mirrors ending with `mirror`, as the planner planned it (EnvmapPlan::views).
struct Level {
    int mirror = -1;
    int depth = 0;
    glm::dvec3 eye{0.0};       // the virtual capture point, in unreflected world space
    glm::dvec4 clipPlane{0.0}; // warp: `mirror`'s kept side, in camera-relative drawn coordinates
};

// What one view draws: the scene (for a warp, with meshes split for the view's capture point), for a
// warp each mirror's split rectangle, and the items whose back faces the capture point cannot see.
struct LevelScene {
    Level level;
    const FrameInput* env = nullptr;
    std::optional<FrameInput> split;
    std::vector<MeshHandle> mirrorMeshes;
    std::vector<bool> cullBackFaces;

    const FrameInput& input() const { return split ? *split : *env; }
};

// The face's views as its mirror passes draw them.
class FaceScenes final : public SpaceScenes {
public:
    FaceScenes(const FrameInput& env, const EnvironmentTarget& target, const MainPassContext& context)
        : m_env(env)
        , m_target(target)
        , m_context(context)
        , m_scenes(target.plan->views.size() + 1) {}

    const FrameInput& enter(int view, const gl::Program& program, MainPassContext& context) override {
        const LevelScene& scene = sceneOf(view);
        context.mirrorMeshes = scene.mirrorMeshes;
        context.cullBackFaces = scene.cullBackFaces;
        prepareWarp(program, scene.level);
        if (m_target.warp)
            context.prepareProgram = [this, level = scene.level](const gl::Program& p) {
                prepareWarp(p, level);
            };
        return scene.input();
    }

    void leave(int view) override { m_scenes[static_cast<std::size_t>(view + 1)].reset(); }

private:
    // What view `index` (-1: the face's own) draws, made on first use and kept until the view is left.
    const LevelScene& sceneOf(int index) {
        std::optional<LevelScene>& scene = m_scenes[static_cast<std::size_t>(index + 1)];
        if (!scene)
            scene = sceneFor(levelOf(index));
        return *scene;
    }

    Level levelOf(int index) const {
        Level level;
        if (index < 0) {
            level.eye = m_env.camera.position;
            return level;
        }
        const MirrorView& view = m_target.plan->views[static_cast<std::size_t>(index)];
        level.mirror = view.mirror;
        level.depth = view.depth;
        level.eye = view.eye;
        level.clipPlane = view.clipPlane;
        return level;
    }

    LevelScene sceneFor(const Level& level) const {
        LevelScene scene;
        scene.level = level;
        scene.env = &m_env;
        scene.cullBackFaces = cullFor(level);
        if (!m_target.warp)
            return scene;
        // Seen from a virtual capture point the reflected scene spans the angles the real scene spans from
        // there: split for that point.
        const WarpTolerance tolerance{level.eye, m_target.warpAngle, m_target.near};
        scene.split = m_env;
        for (std::size_t i = 0; i < scene.split->items.size(); ++i) {
            DrawItem& item = scene.split->items[i];
            const bool coarse = i < m_context.coarseItems.size() && m_context.coarseItems[i];
            item.mesh = m_target.warpMeshes->get(item.mesh, item.world, tolerance,
                                                 coarse ? gl::Detail::Coarse : gl::Detail::Full);
        }
        for (Reflector& reflector : scene.split->reflectors) // the other reflectors, drawn plain
            if (reflector.mesh)
                reflector.mesh =
                    m_target.warpMeshes->get(reflector.mesh, reflector.world, tolerance, gl::Detail::Full);
        for (const Mirror& mirror : m_env.mirrors)
            scene.mirrorMeshes.push_back(
                m_target.warpMeshes->get(m_context.unitPlane, mirrorRectangle(mirror), tolerance));
        return scene;
    }

    // Items whose back faces the level's (virtual) capture point cannot see: closed meshes it is outside of.
    std::vector<bool> cullFor(const Level& level) const {
        std::vector<bool> cull;
        if (!m_target.meshFacts)
            return cull;
        cull.reserve(m_env.items.size());
        for (const DrawItem& item : m_env.items) {
            if (!item.mesh) {
                cull.push_back(false);
                continue;
            }
            const MeshFacts::Facts& facts = m_target.meshFacts->get(item.mesh);
            const math::Box box = math::worldBounds(facts.bounds, item.world);
            const bool inside = glm::all(glm::greaterThanEqual(level.eye, box.min)) &&
                                glm::all(glm::lessThanEqual(level.eye, box.max));
            cull.push_back(facts.closed && !inside);
        }
        return cull;
    }

    // Binds `program` and sets what a warp needs for the level: the warp, whose far distance grows with
    // the level's depth like the cube faces' projections, and the clip plane at the level's mirror.
    void prepareWarp(const gl::Program& program, const Level& level) const {
        if (!m_target.warp)
            return;
        envmap::WarpPass pass = *m_target.warp;
        pass.warp.far = (2.0 * level.depth + 1.0) * m_target.warp->warp.far;
        program.use();
        envmap::setWarpUniforms(program, pass);
        program.set("uClipPlane", glm::vec4(level.clipPlane));
        (level.mirror >= 0 ? glEnable : glDisable)(GL_CLIP_DISTANCE0);
    }

    const FrameInput& m_env;
    const EnvironmentTarget& m_target;
    const MainPassContext& m_context;
    std::vector<std::optional<LevelScene>> m_scenes; // by view + 1: what each view draws, while needed
};

} // namespace

void drawEnvironmentTarget(const FrameInput& env, const EnvironmentTarget& target,
                           const EnvironmentMirrorPrograms& programs, MainPassContext& context,
                           const RunFacePasses& runFacePasses) {
    // A direct-fill component whose warp mirrors the image (paraboloid component 1) flips every triangle
    // of the target, the face's own view's as every mirror's. That is how the capture projects the face,
    // not a reflection: PassWrites::clockwise declares the views' reflections only (render/plan/
    // PassWrites.cpp), and the space composes the flip with it.
    const bool warpMirrored = target.warp && target.warp->warp.mirrored;
    assert(target.plan && target.face >= 0 && target.face < static_cast<int>(target.plan->faces.size()) &&
           target.plan->faces[static_cast<std::size_t>(target.face)].warped == (target.warp != nullptr) &&
           target.plan->faces[static_cast<std::size_t>(target.face)].warp.mirrored == warpMirrored &&
           "drawEnvironmentTarget(): the target is not the planned face");
    FaceScenes scenes(env, target, context);
    const ViewSpace face{.input = env,
                         .views = target.plan->views,
                         .face = target.face,
                         .rotation = target.warp ? glm::dmat4(1.0) : target.faceView,
                         .projection = target.warp ? glm::dmat4(1.0)
                                                   : envmap::cubeFaceProjection(target.near, target.far),
                         .size = target.size,
                         .mapFramebuffer = target.framebuffer,
                         .frustum = !target.warp,
                         .flipsWinding = warpMirrored,
                         .ownViewCoarse = true,
                         .context = context,
                         .flatProgram = programs.flat,
                         .mirrorProgram = programs.mirror,
                         .scenes = &scenes};
    // The face's own view covers the whole target, where no stencil test is needed, and reflects nothing.
    drawSpaceView(face, -1, false);
    runFacePasses(face);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CLIP_DISTANCE0);
    context.mirrorMeshes.clear();
    context.cullBackFaces.clear();
    context.prepareProgram = nullptr; // it holds the face's scenes, which end here
}

} // namespace speculum::render::passes
