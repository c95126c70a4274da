#include "render/passes/EnvironmentMirrors.hpp"

#include "render/envmap/CaptureMath.hpp"
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cassert>
#include <glm/gtc/matrix_inverse.hpp>
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

// One view of the environment: the capture point's own (view −1), or the scene reflected in a chain of
// mirrors ending with `mirror`, as the planner planned it (EnvmapPlan::views[view]).
struct Level {
    int view = -1;
    int mirror = -1;
    int depth = 0;
    glm::dmat4 reflection{1.0};     // world → drawn (reflected) world
    glm::dvec3 eye{0.0};            // the virtual capture point, in unreflected world space
    glm::dmat4 viewProjection{1.0}; // cube face: camera-relative drawn world → clip, oblique at `mirror`
    glm::dvec4 clipPlane{0.0};      // warp: `mirror`'s kept side, in camera-relative drawn coordinates
};

// What one level draws: the scene (for a warp, with meshes split for the level's capture point) and, for
// a warp, each mirror's split rectangle.
struct LevelScene {
    const FrameInput* env = nullptr;
    std::optional<FrameInput> split;
    std::vector<MeshHandle> mirrorMeshes;

    const FrameInput& input() const { return split ? *split : *env; }
};

class TargetDrawer {
public:
    TargetDrawer(const FrameInput& env, const EnvironmentTarget& target,
                 const EnvironmentMirrorPrograms& programs, MainPassContext& ctx)
        : m_env(env)
        , m_target(target)
        , m_plan(programs.flat && programs.mirror ? target.plan : nullptr)
        , m_programs(programs)
        , m_ctx(ctx)
        , m_toRelative(math::cameraRelative(env.camera)) {
        assert((!m_plan ||
                (target.face >= 0 && target.face < static_cast<int>(m_plan->faces.size()) &&
                 m_plan->faces[static_cast<std::size_t>(target.face)].warped == (target.warp != nullptr) &&
                 m_plan->faces[static_cast<std::size_t>(target.face)].warp.mirrored == warpMirrored())) &&
               "drawEnvironmentTarget(): the target is not the planned face");
        m_scenes.resize(m_plan ? m_plan->views.size() + 1 : 1);
    }

    // The face's own view over the whole target, then the plan's passes for this face in plan order: for
    // each mirror view its mask, its reflection, the views inside it, its surface.
    void draw() {
        drawOwnView();
        if (m_plan)
            for (const PlannedPass& pass : m_plan->passes)
                if (viewOf(pass).face == m_target.face)
                    run(pass);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_CLIP_DISTANCE0);
        m_ctx.mirrorMeshes.clear();
        m_ctx.cullBackFaces.clear();
    }

private:
    const MirrorView& viewOf(const PlannedPass& pass) const {
        return m_plan->views[static_cast<std::size_t>(pass.view)];
    }

    void run(const PlannedPass& pass) {
        const MirrorView& view = viewOf(pass);
        switch (pass.kind) {
        case PassKind::MirrorMask:
            drawMask(levelOf(view.parent), sceneOf(view.parent), view.mirror, pass.writes);
            break;
        case PassKind::Mirror:
            drawView(levelOf(pass.view), sceneOf(pass.view), pass.writes);
            break;
        case PassKind::MirrorSurface:
            drawSurface(levelOf(view.parent), sceneOf(view.parent), view.mirror, pass.writes);
            // Every pass that draws in this view (its own, its children's masks and surfaces) has run.
            m_scenes[static_cast<std::size_t>(pass.view + 1)].reset();
            break;
        default:
            assert(false && "drawEnvironmentTarget(): only mirror passes draw inside a face");
            break;
        }
    }

    glm::dmat4 projection(int depth) const {
        return envmap::cubeFaceProjection(m_target.near, (2.0 * depth + 1.0) * m_target.far);
    }

    // A direct-fill component whose warp mirrors the image (paraboloid component 1) flips every triangle
    // of the target, the face's own view's as every mirror's. That is how the capture projects the face,
    // not a reflection: PassWrites::clockwise declares the views' reflections only (render/plan/
    // PassWrites.cpp), and the flip of the warp this target is drawn with is composed with it here, once.
    bool warpMirrored() const { return m_target.warp && m_target.warp->warp.mirrored; }
    bool clockwise(const PassWrites& writes) const { return writes.clockwise != warpMirrored(); }

    // The warp of a level: its far distance grows with its depth like the cube faces' projections.
    envmap::WarpPass warpFor(const Level& level) const {
        envmap::WarpPass pass = *m_target.warp;
        pass.warp.far = (2.0 * level.depth + 1.0) * m_target.warp->warp.far;
        return pass;
    }

    // Binds `program` and sets what a warp needs for this level: the warp and the clip plane.
    void prepareWarp(const gl::Program& program, const Level& level) const {
        if (!m_target.warp)
            return;
        program.use();
        envmap::setWarpUniforms(program, warpFor(level));
        program.set("uClipPlane", glm::vec4(level.clipPlane));
        (level.mirror >= 0 ? glEnable : glDisable)(GL_CLIP_DISTANCE0);
    }

    // What the level of view `index` (-1: the face's own) draws, made on first use and kept until the
    // view's surface pass, the last to draw in it.
    const LevelScene& sceneOf(int index) {
        std::optional<LevelScene>& scene = m_scenes[static_cast<std::size_t>(index + 1)];
        if (!scene)
            scene = sceneFor(levelOf(index));
        return *scene;
    }

    LevelScene sceneFor(const Level& level) const {
        LevelScene scene;
        scene.env = &m_env;
        if (!m_target.warp)
            return scene;
        // Seen from a virtual capture point the reflected scene spans the angles the real scene spans from
        // there: split for that point.
        const WarpTolerance tolerance{level.eye, m_target.warpAngle, m_target.near};
        scene.split = m_env;
        for (std::size_t i = 0; i < scene.split->items.size(); ++i) {
            DrawItem& item = scene.split->items[i];
            const bool coarse = i < m_ctx.coarseItems.size() && m_ctx.coarseItems[i];
            item.mesh = m_target.warpMeshes->get(item.mesh, item.world, tolerance,
                                                 coarse ? gl::Detail::Coarse : gl::Detail::Full);
        }
        for (const Mirror& mirror : m_env.mirrors)
            scene.mirrorMeshes.push_back(
                m_target.warpMeshes->get(m_ctx.unitPlane, mirrorRectangle(mirror), tolerance));
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

    // The level's view, drawn with `frontClockwise` as its winding (the winding of a view with no
    // reflection, for the face's own). The mirrors the plan gives views of their own in it are left to
    // their passes.
    ViewSetup setupFor(const Level& level, bool frontClockwise) const {
        ViewSetup setup;
        setup.viewProjection = level.viewProjection;
        setup.reflection = level.reflection;
        setup.eye = level.eye;
        setup.skipMirror.assign(m_env.mirrors.size(), false);
        if (m_plan)
            for (const MirrorView& view : m_plan->views)
                if (view.face == m_target.face && view.parent == level.view)
                    setup.skipMirror[static_cast<std::size_t>(view.mirror)] = true;
        setup.clockwise = frontClockwise;
        setup.coarseDetail = true;
        return setup;
    }

    // The planned view `index` as this target draws it; -1: the face's own view.
    Level levelOf(int index) const {
        Level level;
        if (index < 0) {
            level.eye = m_env.camera.position;
            if (!m_target.warp)
                level.viewProjection = projection(0) * m_target.faceView;
            return level;
        }
        const MirrorView& view = m_plan->views[static_cast<std::size_t>(index)];
        level.view = index;
        level.mirror = view.mirror;
        level.depth = view.depth;
        level.reflection = view.reflection;
        level.eye = view.eye;
        if (!m_target.warp)
            level.viewProjection = view.projection * m_target.faceView;
        level.clipPlane = view.clipPlane;
        return level;
    }

    // The face's own view: the whole target, where no stencil test is needed, with no reflection.
    void drawOwnView() {
        const Level root = levelOf(-1);
        drawScene(root, sceneOf(-1), setupFor(root, clockwise(PassWrites{})));
    }

    // The scene reflected in the level's mirror, on the pixels of the stencil level its mask marked.
    void drawView(const Level& level, const LevelScene& scene, const PassWrites& writes) {
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
        glStencilFunc(GL_EQUAL, writes.stencilEqual, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        drawScene(level, scene, setupFor(level, clockwise(writes)));
    }

    void drawScene(const Level& level, const LevelScene& scene, const ViewSetup& setup) {
        m_ctx.mirrorMeshes = scene.mirrorMeshes;
        m_ctx.cullBackFaces = cullFor(level);
        prepareWarp(m_ctx.program, level);
        drawMainPass(scene.input(), setup, m_ctx);
        m_ctx.cullBackFaces.clear();
    }

    // In the parent's view: marks the mirror's visible pixels of the parent's stencil level
    // (writes.stencilEqual) one level deeper, then resets their colour to the background and their depth
    // to the far plane.
    void drawMask(const Level& parent, const LevelScene& scene, int mirrorIndex, const PassWrites& writes) {
        const Mirror& mirror = m_env.mirrors[static_cast<std::size_t>(mirrorIndex)];
        const gl::Program& p = *m_programs.flat;
        p.use();
        prepareWarp(p, parent);
        const glm::dmat4 drawn = m_toRelative * parent.reflection * mirrorRectangle(mirror);
        p.set("uModelLightClip", glm::mat4(m_target.warp ? drawn : parent.viewProjection * drawn));
        const gl::GpuMesh& mesh = m_ctx.meshes.get(
            m_target.warp ? scene.mirrorMeshes[static_cast<std::size_t>(mirrorIndex)] : m_ctx.unitPlane);
        glFrontFace(clockwise(writes) ? GL_CW : GL_CCW);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
        glStencilFunc(GL_EQUAL, writes.stencilEqual, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
        mesh.draw();
        glStencilFunc(GL_EQUAL, writes.stencilEqual + 1, 0xFF); // the level GL_INCR just marked
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        p.set("uFlatColor", glm::vec4(glm::vec3(m_env.settings.background), 1.0f));
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_ALWAYS);
        glDepthRange(1.0, 1.0);
        mesh.draw();
        glDepthRange(0.0, 1.0);
        glDepthFunc(GL_LESS);
    }

    // In the parent's view: the mirror's surface blended over its reflection (dual-source, as
    // shaders/mirror.frag does for the stencil technique), on the mirror's stencil level
    // (writes.stencilEqual); restores its depth and steps its pixels back.
    void drawSurface(const Level& parent, const LevelScene& scene, int mirrorIndex,
                     const PassWrites& writes) {
        const std::size_t index = static_cast<std::size_t>(mirrorIndex);
        const Mirror& mirror = m_env.mirrors[index];
        const gl::Program& p = *m_programs.mirror;
        m_ctx.mirrorMeshes = scene.mirrorMeshes;
        beginLitView(scene.input(), setupFor(parent, clockwise(writes)), p, m_ctx);
        prepareWarp(p, parent);
        setMaterial(mirror.hasMaterial ? mirror.material : Material{}, p, m_ctx);
        p.set("uReflectivity", float(mirror.reflectivity));
        p.set("uTint", glm::vec3(mirror.tint));
        p.set("uFresnel", mirror.fresnel ? 1 : 0);
        p.set("uFromTexture", 0);
        p.set("uReflectionTexture", kReflectionTextureUnit);
        p.set("uTargetSize", glm::vec2(float(m_target.size)));
        p.set("uBlurLod", 0.0f);
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
        glStencilFunc(GL_EQUAL, writes.stencilEqual, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_ALWAYS);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_SRC1_COLOR);
        drawLitMesh(m_ctx.mirrorMesh(index), mirrorRectangle(mirror), scene.input(), p, m_ctx);
        glDisable(GL_BLEND);
        glDepthFunc(GL_LESS);
    }

    const FrameInput& m_env;
    const EnvironmentTarget& m_target;
    const EnvmapPlan* m_plan; // null: no mirror reflects
    EnvironmentMirrorPrograms m_programs;
    MainPassContext& m_ctx;
    glm::dmat4 m_toRelative;
    std::vector<std::optional<LevelScene>> m_scenes; // by view + 1: what each level draws, while needed
};

} // namespace

void drawEnvironmentTarget(const FrameInput& env, const EnvironmentTarget& target,
                           const EnvironmentMirrorPrograms& programs, MainPassContext& context) {
    TargetDrawer(env, target, programs, context).draw();
}

} // namespace speculum::render::passes
