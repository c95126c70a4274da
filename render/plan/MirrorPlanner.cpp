// Plans the views of planar mirrors: which mirrors are seen (directly or in other mirrors, to the depth
// the scene allows), the reflected eye of each, its oblique projection and its pixels, and the passes
// that draw them. One planner for every place mirrors are seen from: the camera's image, and each face or
// component of the reflector's environment map (seen from its capture point). Everything is derived in
// double precision; a mirror that cannot be drawn correctly is skipped with a reason, never given a NaN
// matrix.
#include "render/frame/Settings.hpp"
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/gtc/matrix_inverse.hpp>
#include <optional>

namespace speculum::render {

namespace {

// Up to this roughness the convolved chain's error stays within 1 dB of 16 footprint taps
// (GlossyAgreementGLTest), so the planner may trade the taps for it where they would buy little.
constexpr double kChainBoundedRoughness = 0.3;
// A reflection covering fewer pixels than this (64 × 64) is too small for 16 taps to show their worth.
constexpr double kFewPixels = 4096.0;

// How a mirror's rough reflection is filtered: as the settings say, but a Footprint mirror seen inside
// another mirror (where the reflection is small and dimmed by the mirrors it is seen through) or covering
// few pixels takes the convolved chain, four lookups a pixel instead of the taps, where its error is
// bounded. The mirrors demo's rough back mirror, seen four times through the side mirrors, cost over
// 200 ms of its frame on llvmpipe with 16 taps each time.
GlossyFilter glossyFilterFor(const Settings& settings, const Mirror& mirror, int depth, double pixelArea) {
    const bool trade = settings.glossyFilter == GlossyFilter::Footprint && mirror.roughness > 0.0 &&
                       mirror.roughness <= kChainBoundedRoughness && (depth > 1 || pixelArea < kFewPixels);
    return trade ? GlossyFilter::Chain : settings.glossyFilter;
}

std::string label(const FrameInput& input, int mirror) {
    std::string name = input.mirrors[static_cast<std::size_t>(mirror)].name;
    if (name.empty())
        name = "mirror " + std::to_string(mirror);
    return name;
}

// Where mirror views are planned: the camera's image, or one face or component of the environment map.
struct ViewSpace {
    glm::dvec3 eye{0.0};      // the camera or the capture point: the origin of relative coordinates
    glm::dmat4 rotation{1.0}; // relative world → view: the camera's rotation, or the face's view
    std::function<glm::dmat4(int depth)> projection; // of a view `depth` mirrors deep (0: the space's own)
    int width = 1;
    int height = 1;
    int maxDepth = 0;
    int face = -1;                                // index into EnvmapPlan::faces; -1: the camera
    const envmap::WarpParameters* warp = nullptr; // a direct-fill component: no projection, no pixels
    bool mirrorTextures = true;                   // texture-technique mirrors get a texture (the camera)
    std::string mapFace;                          // "Ball's map, +X face"; empty: the camera's image
};

struct Planner {
    const FrameInput& input;
    const ViewSpace& space;
    std::vector<MirrorView>& views;
    std::vector<PlannedPass>& passes;
    std::vector<SkippedEffect>& skipped;
    glm::dmat4 toRelative;
    int spaceViews = 0;                // views planned in this space
    std::vector<int> screenSpaceViews; // planned, their passes left for planScreenSpacePasses

    // `details` with where a mirror seen from `parentView` (-1: the space's own view) is seen, for its
    // reasons: the mirrors it is seen in, outermost first, and the map's face.
    ReasonDetails seenFrom(int parentView, ReasonDetails details = {}) const {
        for (int v = parentView; v >= 0; v = views[static_cast<std::size_t>(v)].parent)
            details.seenIn.insert(details.seenIn.begin(),
                                  mirrorAt(views[static_cast<std::size_t>(v)].mirror).name);
        details.mapFace = space.mapFace;
        return details;
    }

    // Skips the mirror where it is seen from `parentView`; `details`: what the code's sentence names.
    void skip(int parentView, int mirror, PlanReason code, ReasonDetails details = {}) {
        skipped.push_back({label(input, mirror), code, seenFrom(parentView, std::move(details)), space.face});
    }

    // False when a paraboloid component cannot show the polygon: every corner lies in the cone behind it
    // that its near plane clips (a convex cone, so the whole polygon does). The tennis ball's components
    // wrap all round: any polygon may show.
    bool inWarp(const std::vector<glm::dvec3>& relative) const {
        const envmap::WarpParameters& w = *space.warp;
        if (w.type != envmap::MapType::DualParaboloid)
            return true;
        return std::any_of(relative.begin(), relative.end(), [&](const glm::dvec3& c) {
            const glm::dvec3 d = glm::dmat3(space.rotation) * c;
            const double s = (w.component == 0 ? -d.z : d.z) / std::max(glm::length(d), 1e-300);
            return s >= -w.rimSine;
        });
    }

    const Mirror& mirrorAt(int m) const { return input.mirrors[static_cast<std::size_t>(m)]; }

    // What the mirrors seen from one view inherit from it.
    struct ParentView {
        int index = -1; // into views; -1: the space's own view
        // A copy, not a pointer: planning the children appends to views, which may reallocate it.
        std::optional<MirrorView> view;
        int depth = 1; // the children's
        glm::dmat4 reflection{1.0};
        glm::dvec3 eye{0.0};
        math::PixelRect bounds;
        glm::dmat4 projection{1.0};
        // The parent's kept side, in reflected (drawn) world coordinates: only what lies beyond its mirror.
        glm::dvec4 keepPlane{0.0};
    };

    ParentView parentOf(int parentView) const {
        ParentView p;
        p.index = parentView;
        if (parentView >= 0)
            p.view = views[static_cast<std::size_t>(parentView)];
        const MirrorView* parent = p.view ? &*p.view : nullptr;
        p.depth = parent ? parent->depth + 1 : 1;
        p.reflection = parent ? parent->reflection : glm::dmat4(1.0);
        p.eye = parent ? parent->eye : space.eye;
        p.bounds = parent ? parent->rect : math::PixelRect{0, 0, space.width, space.height};
        p.projection = parent ? parent->projection : space.projection(0);
        if (parent) {
            const auto plane = math::mirrorPlane(mirrorAt(parent->mirror).world);
            p.keepPlane = math::transformPlane(glm::dvec4(plane->normal, plane->d), p.reflection);
        }
        return p;
    }

    // The plane of mirror `m` when the parent's viewer sees its reflective side; otherwise the mirror is
    // skipped with the reason (a mirror that cannot be drawn at all is reported once, where seen directly).
    std::optional<math::Plane> facingPlane(const ParentView& parent, int m) {
        const Mirror& mirror = mirrorAt(m);
        // A size that is not a positive finite number has no rectangle to draw (NaN would pass every
        // later test as "outside the view", which is not why).
        if (!(mirror.size.x > 0.0 && mirror.size.y > 0.0 && std::isfinite(mirror.size.x) &&
              std::isfinite(mirror.size.y))) {
            if (!parent.view)
                skip(parent.index, m, PlanReason::MirrorSizeInvalid);
            return std::nullopt;
        }
        const auto plane = math::mirrorPlane(mirror.world);
        if (!plane) {
            if (!parent.view)
                skip(parent.index, m, PlanReason::MirrorNoPlane, {.error = plane.error()});
            return std::nullopt;
        }
        const double side = plane->distance(parent.eye);
        const double scale = std::max({1.0, glm::length(parent.eye), std::abs(plane->d)});
        if (std::abs(side) <= 1e-12 * scale) {
            skip(parent.index, m, PlanReason::MirrorEdgeOn);
            return std::nullopt;
        }
        if (side < 0.0) {
            skip(parent.index, m, PlanReason::MirrorBehind);
            return std::nullopt;
        }
        return *plane;
    }

    // Where mirror `m` lands in the target, as drawn in the parent's view (its reflection applied); nothing
    // (the mirror skipped with the reason) when it covers too little of it.
    std::optional<math::ScreenCoverage> coverageIn(const ParentView& parent, int m) {
        std::vector<glm::dvec3> corners;
        for (const glm::dvec3& c : math::mirrorCorners(mirrorAt(m)))
            corners.push_back(glm::dvec3(parent.reflection * glm::dvec4(c, 1.0)) - space.eye);
        glm::dvec4 keepRelative = parent.keepPlane;
        if (parent.view) // the keep plane in relative coordinates
            keepRelative = math::transformPlane(parent.keepPlane, toRelative);
        const PlanReason outside =
            parent.view ? PlanReason::MirrorOutsideParent : PlanReason::MirrorOutsideView;
        math::ScreenCoverage coverage;
        if (space.warp) {
            // No projection to measure pixels with: the mirror is kept if any of it lies beyond the
            // parent's mirror and in front of the component's rim.
            const bool beyondParent =
                !parent.view || std::any_of(corners.begin(), corners.end(), [&](const glm::dvec3& c) {
                    return glm::dot(keepRelative, glm::dvec4(c, 1.0)) > 0.0;
                });
            if (!beyondParent || !inWarp(corners)) {
                skip(parent.index, m, outside);
                return std::nullopt;
            }
            coverage.rect = parent.bounds;
            return coverage;
        }
        coverage = math::screenCoverage(corners, parent.projection * space.rotation, space.width,
                                        space.height, parent.bounds, parent.view ? &keepRelative : nullptr);
        if (coverage.rect.empty() || coverage.pixelArea <= 0.0) {
            skip(parent.index, m, outside);
            return std::nullopt;
        }
        if (coverage.pixelArea < 1.0) {
            skip(parent.index, m, PlanReason::MirrorBelowPixel, {.area = coverage.pixelArea});
            return std::nullopt;
        }
        return coverage;
    }

    // False (the mirror skipped with the reason) when the space has no room for another mirror view.
    bool withinLimits(const ParentView& parent, int m) {
        if (parent.depth > space.maxDepth) {
            skip(parent.index, m, PlanReason::MirrorDepthLimit, {.limit = space.maxDepth});
            return false;
        }
        if (spaceViews >= kMaxMirrorViews) {
            skip(parent.index, m, PlanReason::MirrorViewLimit, {.limit = kMaxMirrorViews});
            return false;
        }
        return true;
    }

    // The view of mirror `m` from the parent: its reflection, clip plane and projection, its pixels and
    // where it is drawn. Nothing (the mirror skipped with the reason) when it cannot be drawn correctly.
    std::optional<MirrorView> makeView(const ParentView& parent, int m, const math::Plane& plane,
                                       const math::ScreenCoverage& coverage) {
        const Mirror& mirror = mirrorAt(m);
        auto reflection = math::reflectionMatrix(plane);
        if (!reflection) {
            skip(parent.index, m, PlanReason::MirrorNoReflectionMatrix, {.error = reflection.error()});
            return std::nullopt;
        }
        MirrorView view;
        view.mirror = m;
        view.parent = parent.index;
        view.depth = parent.depth;
        view.face = space.face;
        view.reflection = parent.reflection * *reflection;
        view.eye = glm::dvec3(glm::inverse(view.reflection) * glm::dvec4(space.eye, 1.0));
        // Keep only what lies on the mirror's reflective side, a constant world distance off the plane;
        // in drawn coordinates that is the plane carried through the whole reflection.
        const glm::dvec4 kept(plane.normal, plane.d - kMirrorClipOffset);
        const glm::dvec4 drawn = math::transformPlane(kept, view.reflection);
        view.clipPlane = math::transformPlane(drawn, toRelative);
        if (!space.warp) {
            auto oblique = math::obliqueProjection(space.projection(parent.depth),
                                                   math::transformPlane(drawn, space.rotation * toRelative));
            if (!oblique) {
                skip(parent.index, m, PlanReason::MirrorNoObliqueProjection, {.error = oblique.error()});
                return std::nullopt;
            }
            view.projection = *oblique;
        }
        view.rect = coverage.rect;
        view.pixelArea = coverage.pixelArea;
        view.glossyFilter = glossyFilterFor(input.settings, mirror, view.depth, view.pixelArea);
        // A rough mirror needs its reflection as an image of its own to filter: the stencil technique
        // draws it straight into the parent's buffer, so a rough stencil mirror is drawn as a texture
        // one.
        // A screen-space mirror traces the camera's own image, so only where the camera sees it directly;
        // seen inside another mirror it is drawn as a texture one (the image holds nothing of that view).
        view.screenSpace = mirror.technique == MirrorTechnique::ScreenSpace && space.mirrorTextures &&
                           !parent.view && space.face < 0 && !space.warp;
        view.ownTarget =
            space.mirrorTextures && (mirror.technique != MirrorTechnique::Stencil || mirror.roughness > 0.0);
        // A texture view starts a fresh stencil space in a render texture of its own, one slot deeper
        // than the texture its parent draws into; a stencil view nests one level inside its parent's.
        const int parentLevel = parent.view ? parent.view->stencilLevel : 0;
        const int parentSlot = parent.view ? parent.view->textureSlot : -1;
        view.stencilLevel = view.ownTarget ? 0 : parentLevel + 1;
        view.parentStencilLevel = parentLevel;
        view.textureSlot = view.ownTarget ? parentSlot + 1 : parentSlot;
        if (!view.ownTarget && view.stencilLevel > kStencilLevels) {
            skip(parent.index, m, PlanReason::MirrorStencilTooDeep);
            return std::nullopt;
        }
        return view;
    }

    // A pass of the view `index`, and why it runs.
    void addPass(PassKind kind, const MirrorView& view, int index, PlanReason code,
                 const ReasonDetails& details) {
        PlannedPass pass;
        pass.kind = kind;
        pass.target = label(input, view.mirror);
        pass.code = code;
        pass.details = details;
        pass.view = index;
        passes.push_back(std::move(pass));
    }

    // The passes that draw a view's reflection before the views seen in it: its mask, then the scene
    // reflected in it.
    void planReflectionPasses(const MirrorView& view, int index) {
        const Mirror& mirror = mirrorAt(view.mirror);
        ReasonDetails details = seenFrom(view.parent);
        if (!space.warp)
            details.area = view.pixelArea;
        addPass(PassKind::MirrorMask, view, index,
                view.ownTarget ? PlanReason::MirrorMaskCount : PlanReason::MirrorMaskStencil, details);
        details.roughStencil = view.ownTarget && mirror.technique == MirrorTechnique::Stencil;
        details.screenSpaceAsTexture = mirror.technique == MirrorTechnique::ScreenSpace && view.ownTarget;
        addPass(PassKind::Mirror, view, index,
                view.ownTarget ? PlanReason::MirrorIntoTexture : PlanReason::MirrorInStencil, details);
    }

    // The pass that finishes a view, after the views seen in it: the mirror's own surface over it.
    void planSurfacePass(const MirrorView& view, int index) {
        const Mirror& mirror = mirrorAt(view.mirror);
        ReasonDetails details;
        details.mapFace = space.mapFace;
        details.reflectivity = mirror.reflectivity;
        details.roughness = std::clamp(mirror.roughness, 0.0, 1.0);
        if (input.settings.glossyFilter == GlossyFilter::Footprint)
            details.glossyTaps = glossyTapCount(input.settings);
        details.glossyChain = view.glossyFilter == GlossyFilter::Chain;
        if (details.glossyChain && input.settings.glossyFilter != GlossyFilter::Chain)
            details.chainInstead = view.depth > 1 ? "seen inside another mirror" : "it covers few pixels";
        addPass(PassKind::MirrorSurface, view, index, PlanReason::MirrorSurface, details);
    }

    // The screen-space mirrors' passes, after every other mirror's, so that the image they trace holds
    // those mirrors' reflections: once the depth pyramid, then each mirror's mask, trace and surface.
    void planScreenSpacePasses() {
        if (screenSpaceViews.empty())
            return;
        PlannedPass depth;
        depth.kind = PassKind::ScreenDepth;
        depth.code = PlanReason::ScreenDepthPyramid;
        for (int index : screenSpaceViews)
            depth.details.node += (depth.details.node.empty() ? "for " : ", ") +
                                  label(input, views[static_cast<std::size_t>(index)].mirror);
        passes.push_back(std::move(depth));
        for (int index : screenSpaceViews) {
            const MirrorView& view = views[static_cast<std::size_t>(index)];
            ReasonDetails details = seenFrom(view.parent);
            details.area = view.pixelArea;
            addPass(PassKind::MirrorMask, view, index, PlanReason::MirrorMaskCount, details);
            const int probe = probeReflector(input);
            details.screenFallsBackToMap = input.settings.screenFallback == ScreenFallback::Map && probe >= 0;
            if (details.screenFallsBackToMap)
                details.node = input.reflectors[static_cast<std::size_t>(probe)].name;
            addPass(PassKind::Mirror, view, index, PlanReason::MirrorScreenTrace, details);
            planSurfacePass(view, index);
        }
    }

    // Plans every mirror seen from `parentView` (-1: the space's own view) and recurses. Each test that
    // fails skips the mirror with its reason, in this order.
    void planChildren(int parentView) {
        const ParentView parent = parentOf(parentView);
        for (int m = 0; m < static_cast<int>(input.mirrors.size()); ++m) {
            if (parent.view && parent.view->mirror == m)
                continue; // a planar mirror never sees itself
            const std::optional<math::Plane> plane = facingPlane(parent, m);
            if (!plane)
                continue;
            const std::optional<math::ScreenCoverage> coverage = coverageIn(parent, m);
            if (!coverage || !withinLimits(parent, m))
                continue;
            const std::optional<MirrorView> view = makeView(parent, m, *plane, *coverage);
            if (!view)
                continue;
            const int index = static_cast<int>(views.size());
            views.push_back(*view);
            ++spaceViews;
            if (view->screenSpace) {
                screenSpaceViews.push_back(index);
                continue;
            }
            planReflectionPasses(*view, index);
            planChildren(index);
            planSurfacePass(*view, index);
        }
    }
};

} // namespace

void planMirrors(const FrameInput& input, const PlanViewport& viewport, FramePlan& plan) {
    if (input.mirrors.empty())
        return;
    ViewSpace space;
    space.eye = input.camera.position;
    space.rotation = math::viewRotation(input.camera);
    const glm::dmat4 projection = cameraProjection(input, viewport);
    space.projection = [projection](int) { return projection; };
    space.width = viewport.width;
    space.height = viewport.height;
    space.maxDepth = std::clamp(input.settings.mirrorDepth, 0, kStencilLevels);
    Planner planner{input, space, plan.views, plan.passes, plan.skipped, math::cameraRelative(input.camera)};
    if (space.maxDepth == 0) {
        for (int m = 0; m < static_cast<int>(input.mirrors.size()); ++m)
            planner.skip(-1, m, PlanReason::MirrorDepthZero);
        return;
    }
    planner.planChildren(-1);
    planner.planScreenSpacePasses();
}

void planEnvmapMirrors(const FrameInput& input, EnvmapPlan& map) {
    if (input.mirrors.empty() || map.reflector < 0 ||
        static_cast<std::size_t>(map.reflector) >= input.reflectors.size())
        return;
    const Reflector& reflector = input.reflectors[static_cast<std::size_t>(map.reflector)];
    const std::string name = reflector.name.empty() ? std::string("the reflector") : reflector.name;
    const int maxDepth = std::clamp(reflector.mirrorDepth, 0, kStencilLevels);
    if (maxDepth == 0) {
        for (int m = 0; m < static_cast<int>(input.mirrors.size()); ++m)
            map.skipped.push_back({label(input, m), PlanReason::MapMirrorDepthZero, {.node = name}});
        return;
    }
    Camera capturePoint; // the map's views are drawn relative to the capture point
    capturePoint.position = map.capture.centre;
    const glm::dmat4 toRelative = math::cameraRelative(capturePoint);
    for (int f = 0; f < static_cast<int>(map.faces.size()); ++f) {
        const EnvmapFace& face = map.faces[static_cast<std::size_t>(f)];
        ViewSpace space;
        space.eye = map.capture.centre;
        space.rotation = face.view;
        const double near = map.capture.near, far = map.capture.far;
        // Reflected points lie up to (2·depth + 1)·far away: each level sees that deep.
        space.projection = [near, far](int depth) {
            return envmap::cubeFaceProjection(near, (2.0 * depth + 1.0) * far);
        };
        space.width = face.width;
        space.height = face.height;
        space.maxDepth = maxDepth;
        space.face = f;
        space.warp = face.warped ? &face.warp : nullptr;
        space.mirrorTextures = false; // the map nests every mirror with the stencil technique
        space.mapFace = name + "'s map, " + face.label;
        Planner planner{input, space, map.views, map.passes, map.skipped, toRelative};
        planner.planChildren(-1);
    }
}

} // namespace speculum::render
