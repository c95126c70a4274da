// Plans the views of planar mirrors: which mirrors are seen (directly or in other mirrors, to the depth
// the scene allows), the reflected camera of each, its oblique projection and its pixels, and the passes
// that draw them. Everything is derived in double precision; a mirror that cannot be drawn correctly is
// skipped with a reason, never given a NaN matrix.
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_inverse.hpp>
#include <optional>

namespace speculum::render {

namespace {

std::string label(const FrameInput& input, int mirror) {
    std::string name = input.mirrors[static_cast<std::size_t>(mirror)].name;
    if (name.empty())
        name = "mirror " + std::to_string(mirror);
    return name;
}

// "seen directly" or "seen in Left → Right (depth 3)"
std::string where(const FrameInput& input, const FramePlan& plan, int parentView) {
    if (parentView < 0)
        return "seen directly";
    std::string chain;
    for (int v = parentView; v >= 0; v = plan.views[static_cast<std::size_t>(v)].parent) {
        const std::string& name =
            input.mirrors[static_cast<std::size_t>(plan.views[static_cast<std::size_t>(v)].mirror)].name;
        chain = chain.empty() ? name : name + " → " + chain;
    }
    return "seen in " + chain + " (depth " +
           std::to_string(plan.views[static_cast<std::size_t>(parentView)].depth + 1) + ")";
}

std::string pixels(double area) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f", area);
    return text;
}

struct Planner {
    const FrameInput& input;
    const PlanViewport& viewport;
    FramePlan& plan;
    glm::dmat4 projection;
    glm::dmat4 viewProjection; // camera-relative world → clip
    glm::dmat4 toCameraRelative;
    int maxDepth;

    void skip(int parentView, int mirror, const std::string& reason) {
        plan.skipped.push_back({label(input, mirror), reason + " (" + where(input, plan, parentView) + ")"});
    }

    // Plans every mirror seen from `parentView` (-1: the camera) and recurses.
    void planChildren(int parentView) {
        // A copy, not a pointer: planning the children appends to plan.views, which may reallocate it.
        const std::optional<MirrorView> parentCopy =
            parentView >= 0 ? std::optional<MirrorView>(plan.views[static_cast<std::size_t>(parentView)])
                            : std::nullopt;
        const MirrorView* parent = parentCopy ? &*parentCopy : nullptr;
        const int depth = parent ? parent->depth + 1 : 1;
        const glm::dmat4 parentReflection = parent ? parent->reflection : glm::dmat4(1.0);
        const glm::dvec3 parentEye = parent ? parent->eye : input.camera.position;
        const math::PixelRect bounds =
            parent ? parent->rect : math::PixelRect{0, 0, viewport.width, viewport.height};
        const glm::dmat4 parentProjection = parent ? parent->projection : projection;
        // The parent's kept side, in reflected (drawn) world coordinates: only what lies beyond its mirror.
        glm::dvec4 keepPlane(0.0);
        if (parent) {
            const auto plane =
                math::mirrorPlane(input.mirrors[static_cast<std::size_t>(parent->mirror)].world);
            keepPlane = math::transformPlane(glm::dvec4(plane->normal, plane->d), parentReflection);
        }

        for (int m = 0; m < static_cast<int>(input.mirrors.size()); ++m) {
            if (parent && parent->mirror == m)
                continue; // a planar mirror never sees itself
            const Mirror& mirror = input.mirrors[static_cast<std::size_t>(m)];
            // A size that is not a positive finite number has no rectangle to draw (NaN would pass every
            // later test as "outside the view", which is not why).
            if (!(mirror.size.x > 0.0 && mirror.size.y > 0.0 && std::isfinite(mirror.size.x) &&
                  std::isfinite(mirror.size.y))) {
                if (!parent)
                    skip(parentView, m, "no reflection: the mirror's size is not a positive finite number");
                continue;
            }
            const auto plane = math::mirrorPlane(mirror.world);
            if (!plane) {
                if (!parent)
                    skip(parentView, m, "no reflection: " + plane.error());
                continue;
            }
            const double side = plane->distance(parentEye);
            const double scale = std::max({1.0, glm::length(parentEye), std::abs(plane->d)});
            if (std::abs(side) <= 1e-12 * scale) {
                skip(parentView, m,
                     "no reflection: the camera is on the mirror's plane, which it sees edge-on");
                continue;
            }
            if (side < 0.0) {
                skip(parentView, m, "no reflection: the camera is behind the mirror (it sees its back)");
                continue;
            }
            // Where the mirror lands on screen, as drawn in the parent's view (its reflection applied).
            std::vector<glm::dvec3> corners;
            for (const glm::dvec3& c : math::mirrorCorners(mirror))
                corners.push_back(glm::dvec3(parentReflection * glm::dvec4(c, 1.0)) - input.camera.position);
            glm::dvec4 keepRelative = keepPlane;
            if (parent) // the keep plane in camera-relative coordinates
                keepRelative = math::transformPlane(keepPlane, toCameraRelative);
            const glm::dmat4 parentViewProjection = parentProjection * math::viewRotation(input.camera);
            const math::ScreenCoverage coverage =
                math::screenCoverage(corners, parentViewProjection, viewport.width, viewport.height, bounds,
                                     parent ? &keepRelative : nullptr);
            if (coverage.rect.empty() || coverage.pixelArea <= 0.0) {
                skip(parentView, m,
                     parent ? "no reflection: outside the parent mirror's reflected view"
                            : "no reflection: outside the view");
                continue;
            }
            if (coverage.pixelArea < 1.0) {
                skip(parentView, m,
                     "no reflection: covers less than one pixel (" + pixels(coverage.pixelArea * 100) +
                         "% of one)");
                continue;
            }
            if (depth > maxDepth) {
                skip(parentView, m,
                     "no reflection: the mirror depth limit (" + std::to_string(maxDepth) +
                         ") is reached; drawn with its own material");
                continue;
            }
            if (static_cast<int>(plan.views.size()) >= kMaxMirrorViews) {
                skip(parentView, m,
                     "no reflection: the frame already has " + std::to_string(kMaxMirrorViews) +
                         " mirror views; drawn with its own material");
                continue;
            }
            auto reflection = math::reflectionMatrix(*plane);
            if (!reflection) {
                skip(parentView, m, "no reflection: " + reflection.error());
                continue;
            }
            MirrorView view;
            view.mirror = m;
            view.parent = parentView;
            view.depth = depth;
            view.reflection = parentReflection * *reflection;
            view.eye = glm::dvec3(glm::inverse(view.reflection) * glm::dvec4(input.camera.position, 1.0));
            // Keep only what lies on the mirror's reflective side, a constant world distance off the plane;
            // in drawn coordinates that is the plane carried through the whole reflection.
            const glm::dvec4 kept(plane->normal, plane->d - kMirrorClipOffset);
            const glm::dvec4 drawn = math::transformPlane(kept, view.reflection);
            const glm::dvec4 inView =
                math::transformPlane(drawn, math::viewRotation(input.camera) * toCameraRelative);
            auto oblique = math::obliqueProjection(projection, inView);
            if (!oblique) {
                skip(parentView, m, "no reflection: " + oblique.error());
                continue;
            }
            view.projection = *oblique;
            view.rect = coverage.rect;
            view.pixelArea = coverage.pixelArea;
            view.ownTarget = mirror.technique == MirrorTechnique::Texture;
            // A texture view starts a fresh stencil space in a render texture of its own, one slot deeper
            // than the texture its parent draws into; a stencil view nests one level inside its parent's.
            const int parentLevel = parent ? parent->stencilLevel : 0;
            const int parentSlot = parent ? parent->textureSlot : -1;
            view.stencilLevel = view.ownTarget ? 0 : parentLevel + 1;
            view.parentStencilLevel = parentLevel;
            view.textureSlot = view.ownTarget ? parentSlot + 1 : parentSlot;
            if (!view.ownTarget && view.stencilLevel > kStencilLevels) {
                skip(parentView, m, "no reflection: the stencil buffer cannot nest deeper");
                continue;
            }
            const int index = static_cast<int>(plan.views.size());
            plan.views.push_back(view);

            const std::string name = label(input, m);
            const std::string context = where(input, plan, parentView);
            const std::string area = pixels(view.pixelArea) + " px";
            if (!view.ownTarget)
                plan.passes.push_back({PassKind::MirrorMask, name,
                                       "marks the mirror's visible pixels in the stencil buffer (" + context +
                                           ", " + area + ")",
                                       -1, index});
            else
                plan.passes.push_back(
                    {PassKind::MirrorMask, name,
                     "counts the mirror's visible pixels, so a hidden mirror costs nothing (" + context + ")",
                     -1, index});
            plan.passes.push_back(
                {PassKind::Mirror, name,
                 std::string("draws the scene reflected in the mirror ") +
                     (view.ownTarget ? "into its reflection texture" : "inside its stencil mask") +
                     " with an oblique near plane on the mirror (" + context + ", " + area + ")",
                 -1, index});
            planChildren(index);
            plan.passes.push_back(
                {PassKind::MirrorSurface, name,
                 std::string("blends the mirror's own surface over the reflection (reflectivity ") +
                     pixels(mirror.reflectivity * 100) + "%)",
                 -1, index});
        }
    }
};

} // namespace

void planMirrors(const FrameInput& input, const PlanViewport& viewport, FramePlan& plan) {
    if (input.mirrors.empty())
        return;
    Planner planner{input,
                    viewport,
                    plan,
                    cameraProjection(input, viewport),
                    {},
                    math::cameraRelative(input.camera),
                    std::clamp(input.settings.mirrorDepth, 0, kStencilLevels)};
    planner.viewProjection = planner.projection * math::viewRotation(input.camera);
    if (planner.maxDepth == 0) {
        for (int m = 0; m < static_cast<int>(input.mirrors.size()); ++m)
            planner.skip(-1, m, "no reflection: mirrorDepth is 0; drawn with its own material");
        return;
    }
    planner.planChildren(-1);
}

} // namespace speculum::render
