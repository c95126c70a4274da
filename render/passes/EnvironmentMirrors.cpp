#include "render/passes/EnvironmentMirrors.hpp"

#include "render/envmap/CaptureMath.hpp"
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
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

// One view of the environment: the capture point's own (mirror −1), or the scene reflected in a chain of
// mirrors ending with `mirror`.
struct Level {
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

// The side of mirror m that is reflected, a constant world distance off its plane (as the main pass keeps).
std::optional<glm::dvec4> keptPlane(const Mirror& mirror) {
    const auto plane = math::mirrorPlane(mirror.world);
    if (!plane)
        return std::nullopt;
    return glm::dvec4(plane->normal, plane->d - kMirrorClipOffset);
}

class TargetDrawer {
public:
    TargetDrawer(const FrameInput& env, const EnvironmentTarget& target, int mirrorDepth,
                 const EnvironmentMirrorPrograms& programs, MainPassContext& ctx)
        : m_env(env)
        , m_target(target)
        , m_mirrorDepth(programs.flat && programs.mirror ? std::clamp(mirrorDepth, 0, kStencilLevels) : 0)
        , m_programs(programs)
        , m_ctx(ctx)
        , m_toRelative(math::cameraRelative(env.camera)) {}

    void draw() {
        Level root;
        root.eye = m_env.camera.position;
        if (!m_target.warp)
            root.viewProjection = projection(0) * m_target.faceView;
        drawLevel(root, 0);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_CLIP_DISTANCE0);
        m_ctx.mirrorMeshes.clear();
        m_ctx.cullBackFaces.clear();
    }

private:
    glm::dmat4 projection(int depth) const {
        return envmap::cubeFaceProjection(m_target.near, (2.0 * depth + 1.0) * m_target.far);
    }

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

    LevelScene sceneFor(const Level& level) const {
        LevelScene scene;
        scene.env = &m_env;
        if (!m_target.warp)
            return scene;
        // Seen from a virtual capture point the reflected scene spans the angles the real scene spans from
        // there: split for that point.
        const WarpTolerance tolerance{level.eye, m_target.warpAngle, m_target.near};
        scene.split = m_env;
        for (DrawItem& item : scene.split->items)
            item.mesh = m_target.warpMeshes->get(item.mesh, item.world, tolerance);
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

    ViewSetup setupFor(const Level& level) const {
        ViewSetup setup;
        setup.viewProjection = level.viewProjection;
        setup.reflection = level.reflection;
        setup.eye = level.eye;
        setup.skipMirror.assign(m_env.mirrors.size(), false);
        setup.flipWinding = m_target.warp && m_target.warp->warp.mirrored;
        return setup;
    }

    // Mirror m seen in `parent`, or nothing when it cannot be seen there: the parent's capture point is
    // behind or on it, it lies wholly behind the parent's mirror or outside the target, or no oblique
    // projection exists.
    std::optional<Level> child(const Level& parent, int m) const {
        if (m == parent.mirror)
            return std::nullopt; // a planar mirror never sees itself
        const Mirror& mirror = m_env.mirrors[static_cast<std::size_t>(m)];
        const auto plane = math::mirrorPlane(mirror.world);
        const auto kept = keptPlane(mirror);
        if (!plane || !kept || plane->distance(parent.eye) <= 1e-9)
            return std::nullopt;
        const auto reflection = math::reflectionMatrix(*plane);
        if (!reflection)
            return std::nullopt;
        const auto corners = math::mirrorCorners(mirror);
        // The parent mirror's kept side (unreflected world), all zero at the top level.
        glm::dvec4 parentKept(0.0);
        if (parent.mirror >= 0) {
            parentKept =
                keptPlane(m_env.mirrors[static_cast<std::size_t>(parent.mirror)]).value_or(parentKept);
            const bool behind = std::all_of(corners.begin(), corners.end(), [&](const glm::dvec3& c) {
                return glm::dot(parentKept, glm::dvec4(c, 1.0)) <= 0.0;
            });
            if (behind)
                return std::nullopt;
        }
        std::vector<glm::dvec3> drawn; // camera-relative, as the parent draws them
        for (const glm::dvec3& c : corners)
            drawn.push_back(glm::dvec3(parent.reflection * glm::dvec4(c, 1.0)) - m_env.camera.position);

        Level level;
        level.mirror = m;
        level.depth = parent.depth + 1;
        level.reflection = parent.reflection * *reflection;
        level.eye = glm::dvec3(glm::inverse(level.reflection) * glm::dvec4(m_env.camera.position, 1.0));
        // The kept side in camera-relative drawn coordinates: the plane carried through the whole reflection.
        const glm::dvec4 keptDrawn =
            math::transformPlane(math::transformPlane(*kept, level.reflection), m_toRelative);
        if (m_target.warp) {
            if (!inWarp(drawn))
                return std::nullopt;
            level.clipPlane = keptDrawn;
            return level;
        }
        const glm::dvec4 parentKeptDrawn =
            math::transformPlane(math::transformPlane(parentKept, parent.reflection), m_toRelative);
        const math::PixelRect whole{0, 0, m_target.size, m_target.size};
        const math::ScreenCoverage coverage =
            math::screenCoverage(drawn, parent.viewProjection, m_target.size, m_target.size, whole,
                                 parent.mirror >= 0 ? &parentKeptDrawn : nullptr);
        if (coverage.rect.empty() || coverage.pixelArea < 1.0)
            return std::nullopt;
        const auto oblique = math::obliqueProjection(projection(level.depth),
                                                     math::transformPlane(keptDrawn, m_target.faceView));
        if (!oblique)
            return std::nullopt;
        level.viewProjection = *oblique * m_target.faceView;
        return level;
    }

    // False when a paraboloid component cannot show the rectangle: every corner lies in the cone behind it
    // that its near plane clips (a convex cone, so the whole rectangle does). The tennis ball's components
    // wrap all round: any rectangle may show.
    bool inWarp(const std::vector<glm::dvec3>& drawn) const {
        const envmap::WarpParameters& w = m_target.warp->warp;
        if (w.type != envmap::MapType::DualParaboloid)
            return true;
        return std::any_of(drawn.begin(), drawn.end(), [&](const glm::dvec3& c) {
            const glm::dvec3 d = glm::dmat3(m_target.warp->view) * c;
            const double s = (w.component == 0 ? -d.z : d.z) / std::max(glm::length(d), 1e-300);
            return s >= -w.rimSine;
        });
    }

    void drawLevel(const Level& level, int stencil) {
        std::vector<Level> children;
        if (level.depth < m_mirrorDepth)
            for (int m = 0; m < static_cast<int>(m_env.mirrors.size()) && m_views < kMaxMirrorViews; ++m)
                if (auto c = child(level, m)) {
                    children.push_back(std::move(*c));
                    ++m_views;
                }
        const LevelScene scene = sceneFor(level);
        ViewSetup setup = setupFor(level);
        for (const Level& c : children)
            setup.skipMirror[static_cast<std::size_t>(c.mirror)] = true;

        // The level's scene, on its own pixels (the whole target at the top, where the test is not needed).
        if (stencil > 0) {
            glEnable(GL_STENCIL_TEST);
            glStencilMask(0xFF);
            glStencilFunc(GL_EQUAL, stencil, 0xFF);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        }
        m_ctx.mirrorMeshes = scene.mirrorMeshes;
        m_ctx.cullBackFaces = cullFor(level);
        prepareWarp(m_ctx.program, level);
        drawMainPass(scene.input(), setup, m_ctx);
        m_ctx.cullBackFaces.clear();

        for (const Level& c : children) {
            drawMask(level, scene, c, stencil);
            drawLevel(c, stencil + 1);
            drawSurface(level, scene, setup, c, stencil + 1);
        }
    }

    // In the parent's view: marks the mirror's visible pixels of the parent's level one level deeper, then
    // resets their colour to the background and their depth to the far plane.
    void drawMask(const Level& parent, const LevelScene& scene, const Level& mirrorLevel, int stencil) {
        const Mirror& mirror = m_env.mirrors[static_cast<std::size_t>(mirrorLevel.mirror)];
        const gl::Program& p = *m_programs.flat;
        p.use();
        prepareWarp(p, parent);
        const glm::dmat4 drawn = m_toRelative * parent.reflection * mirrorRectangle(mirror);
        p.set("uModelLightClip", glm::mat4(m_target.warp ? drawn : parent.viewProjection * drawn));
        const gl::GpuMesh& mesh =
            m_ctx.meshes.get(m_target.warp ? scene.mirrorMeshes[static_cast<std::size_t>(mirrorLevel.mirror)]
                                           : m_ctx.unitPlane);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
        glStencilFunc(GL_EQUAL, stencil, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
        mesh.draw();
        glStencilFunc(GL_EQUAL, stencil + 1, 0xFF);
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
    // shaders/mirror.frag does for the stencil technique); restores its depth and steps its pixels back.
    void drawSurface(const Level& parent, const LevelScene& scene, const ViewSetup& setup,
                     const Level& mirrorLevel, int stencil) {
        const std::size_t index = static_cast<std::size_t>(mirrorLevel.mirror);
        const Mirror& mirror = m_env.mirrors[index];
        const gl::Program& p = *m_programs.mirror;
        m_ctx.mirrorMeshes = scene.mirrorMeshes;
        beginLitView(scene.input(), setup, p, m_ctx);
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
        glStencilFunc(GL_EQUAL, stencil, 0xFF);
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
    int m_mirrorDepth;
    EnvironmentMirrorPrograms m_programs;
    MainPassContext& m_ctx;
    glm::dmat4 m_toRelative;
    int m_views = 0;
};

} // namespace

void drawEnvironmentTarget(const FrameInput& env, const EnvironmentTarget& target, int mirrorDepth,
                           const EnvironmentMirrorPrograms& programs, MainPassContext& context) {
    TargetDrawer(env, target, mirrorDepth, programs, context).draw();
}

} // namespace speculum::render::passes
