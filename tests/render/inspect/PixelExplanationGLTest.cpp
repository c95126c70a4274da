// One pixel explained: the exact path the tracer records, the passes the rasterizer ran on the pixel with
// what each left there, the map lookup, and the causes; on a mirror corridor that reaches its depth limit,
// the same corridor 1e5 from the origin, and reflector lookups on every layout's seams.
#include "render/envmap/Mapping.hpp"
#include "render/inspect/PixelExplanation.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"
#include "render/reference/Tracer.hpp"
#include "support/GlTest.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;
using reference::PathEventKind;
using reference::PathVertex;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// Two facing perfect mirrors 4 apart, a lit box between them, a lamp with a shadow map, the camera
// between them looking at the back one; `offset` moves everything, camera and lamp included.
FrameInput corridor(int mirrorDepth, glm::dvec3 offset = glm::dvec3(0.0)) {
    FrameInput input;
    input.settings.background = {0.1, 0.1, 0.2};
    input.settings.ambient = 0.3;
    input.settings.mirrorDepth = mirrorDepth;
    input.camera.position = offset + glm::dvec3(0.5, 0.3, 1.2);
    input.camera.target = offset + glm::dvec3(0.0, 0.0, -2.0);
    input.camera.fovY = 50.0;
    input.camera.far = 200.0;
    Light lamp;
    lamp.name = "Lamp";
    lamp.position = offset + glm::dvec3(0.0, 1.5, 0.0);
    lamp.shadows = ShadowParams{};
    input.lights.push_back(lamp);
    Material red;
    red.color = {0.9, 0.1, 0.1};
    static const auto box = std::make_shared<const MeshData>(makeBox());
    input.items.push_back(
        {"Red",
         glm::scale(glm::translate(glm::dmat4(1.0), offset + glm::dvec3(-0.4, -0.3, -0.5)), glm::dvec3(0.25)),
         box, red, true});
    static const auto plane = std::make_shared<const MeshData>(makePlane(1));
    input.items.push_back(
        {"Floor",
         glm::scale(glm::translate(glm::dmat4(1.0), offset + glm::dvec3(0.0, -1.0, 0.0)), glm::dvec3(3.0)),
         plane, Material{}, true});
    for (double side : {-1.0, 1.0}) {
        Mirror mirror;
        mirror.name = side < 0 ? "Back" : "Front";
        mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), offset + glm::dvec3(0.0, 0.0, 2.0 * side)),
                                   glm::radians(-90.0 * side), glm::dvec3(1, 0, 0));
        mirror.size = {6.0, 6.0};
        input.mirrors.push_back(mirror);
    }
    return input;
}

class PixelExplanationTest : public GlTest {
protected:
    inspect::PixelExplanation explain(const FrameInput& input, glm::ivec2 pixel) {
        StillSettings settings{kWidth, kHeight, 1};
        settings.probePixel = pixel;
        auto still = renderStill(renderer(), input, settings);
        EXPECT_TRUE(still.ok()) << (still.ok() ? "" : still.error());
        auto tracer = reference::Tracer::create(input);
        EXPECT_TRUE(tracer.ok());
        reference::TraceSettings trace;
        trace.width = kWidth;
        trace.height = kHeight;
        auto paths = tracer->explainPixel(trace, pixel.x, pixel.y);
        EXPECT_TRUE(paths.ok()) << (paths.ok() ? "" : paths.error());
        m_still = std::move(*still);
        auto e = inspect::explainPixel(input, m_still.firstSample, m_still.image, *paths, *tracer);
        EXPECT_TRUE(e.ok()) << (e.ok() ? "" : e.error());
        return e.ok() ? *e : inspect::PixelExplanation{};
    }
    StillResult m_still;
};

std::vector<PathEventKind> kinds(const reference::TracedPath& path) {
    std::vector<PathEventKind> out;
    for (const PathVertex& v : path.vertices)
        out.push_back(v.kind);
    return out;
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

const glm::ivec2 kOnTheBackMirror(48, 20);

TEST_F(PixelExplanationTest, AtTheDepthLimitThePathEndsThereAndTheRecipeHasEveryLevelsStencil) {
    const inspect::PixelExplanation e = explain(corridor(2), kOnTheBackMirror);
    const std::vector<PathEventKind> path = kinds(e.exact.centre);
    ASSERT_EQ(path.size(), 3u);
    EXPECT_EQ(path[0], PathEventKind::Mirror);
    EXPECT_EQ(path[1], PathEventKind::Mirror);
    EXPECT_EQ(path[2], PathEventKind::DepthLimit);
    EXPECT_EQ(e.exact.centre.vertices[2].mirrorLevel, 2);
    // The limit follows nothing: no lobe, no direction, and nothing sampled again.
    const PathVertex& limit = e.exact.centre.vertices[2];
    EXPECT_EQ(limit.roughness, 0.0);
    EXPECT_TRUE(finite(limit.outgoing) && finite(limit.mirrored));
    EXPECT_TRUE(e.exact.samples.empty());
    EXPECT_EQ(limit.weight, glm::dvec3(1.0)) << "two perfect mirrors before it";
    EXPECT_TRUE(std::any_of(e.causes.begin(), e.causes.end(),
                            [](const inspect::Cause& c) { return c.code == "depth-limit"; }));
    // The raster marked the two levels with stencil values 1 and 2; only level 2's scene covers the pixel
    // (level 1's pass draws where the stencil still holds 1), and both surfaces blend on the way back.
    std::vector<std::pair<int, int>> masks; // level, stencil after it
    std::vector<int> drawn, blended;
    for (const inspect::RecipeStep& s : e.recipe) {
        if (s.pass == "mirror-mask")
            masks.emplace_back(s.mirrorLevel, s.stencil);
        if (s.pass == "mirror")
            drawn.push_back(s.mirrorLevel);
        if (s.pass == "mirror-surface")
            blended.push_back(s.mirrorLevel);
    }
    EXPECT_EQ(masks, (std::vector<std::pair<int, int>>{{1, 1}, {2, 2}}));
    EXPECT_EQ(drawn, (std::vector<int>{2}));
    EXPECT_EQ(blended, (std::vector<int>{2, 1}));
    // The last step's colour is the still's pixel.
    const std::size_t p = (std::size_t(kOnTheBackMirror.y) * kWidth + kOnTheBackMirror.x) * 4;
    EXPECT_FLOAT_EQ(float(e.recipe.back().colour.r), m_still.image.rgba[p]);
    EXPECT_FLOAT_EQ(float(e.rasterColour.g), m_still.image.rgba[p + 1]);
}

TEST_F(PixelExplanationTest, TheExactColourIsTheTracedStillsPixelAndTheTermsAddUp) {
    const FrameInput input = corridor(2);
    const inspect::PixelExplanation e = explain(input, {20, 50});
    auto tracer = reference::Tracer::create(input);
    ASSERT_TRUE(tracer.ok());
    reference::TraceSettings trace;
    trace.width = kWidth;
    trace.height = kHeight;
    auto image = tracer->render(trace);
    ASSERT_TRUE(image.ok());
    const std::size_t p = (std::size_t(50) * kWidth + 20) * 4;
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(float(e.exactColour[c]), image->image.rgba[p + std::size_t(c)]) << "channel " << c;
    // At the surface that ends the path, material.glsl's terms add up to its colour.
    const PathVertex& last = e.exact.centre.vertices.back();
    ASSERT_TRUE(last.shaded);
    glm::dvec3 sum = last.shading.emitted + last.shading.ambient;
    for (const reference::LightTerm& t : last.shading.lights)
        sum += t.diffuse + t.specular;
    EXPECT_NEAR(sum.r, last.shading.total.r, 1e-9);
    EXPECT_NEAR(sum.g, last.shading.total.g, 1e-9);
    EXPECT_NEAR(sum.b, last.shading.total.b, 1e-9);
}

TEST_F(PixelExplanationTest, FarFromTheOriginTheExplanationIsTheSame) {
    const inspect::PixelExplanation near = explain(corridor(2), kOnTheBackMirror);
    const inspect::PixelExplanation far = explain(corridor(2, glm::dvec3(1e5, -1e5, 1e5)), kOnTheBackMirror);
    EXPECT_EQ(kinds(far.exact.centre), kinds(near.exact.centre));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(far.exactColour[c], near.exactColour[c], 1e-4);
        EXPECT_NEAR(far.rasterColour[c], near.rasterColour[c], 2e-3);
    }
    for (const PathVertex& v : far.exact.centre.vertices) {
        EXPECT_TRUE(finite(v.position) && finite(v.normal) && finite(v.colour));
        EXPECT_GT(v.position.x, 9e4) << "positions are world positions";
    }
    EXPECT_EQ(far.recipe.size(), near.recipe.size());
}

// A reflector whose map type and lookup the test chooses, and a path that meets it with a given reflected
// direction (a mirror-like reflection about the normal halfway between the view and that direction).
struct LookupCase {
    FrameInput input;
    FramePlan plan;
    reference::TracedPath path;
};

LookupCase lookupTowards(ReflectorMap map, const glm::dvec3& reflected) {
    LookupCase c;
    Reflector r;
    r.name = "Ball";
    r.map = map;
    r.resolution = 64;
    r.mesh = std::make_shared<const MeshData>(makeSphere(16));
    c.input.reflectors.push_back(r);
    c.plan.reflectorResolutions = {64};
    PathVertex v;
    v.kind = PathEventKind::Reflector;
    v.hit = {reference::HitKind::Reflector, 0};
    const glm::dvec3 toEye = glm::normalize(glm::dvec3(0.3, 0.2, 1.0));
    v.normal = glm::normalize(toEye + glm::normalize(reflected));
    v.incoming = -toEye;
    v.position = v.normal; // on the unit sphere around the capture point
    c.path.vertices.push_back(v);
    return c;
}

TEST(MapLookup, TheTexelReadHoldsTheReflectedDirectionOnEveryLayout) {
    for (ReflectorMap map : {ReflectorMap::Cube, ReflectorMap::DualParaboloid, ReflectorMap::TennisBall,
                             ReflectorMap::Octahedral}) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(0.2, 0.35, -0.9));
        const LookupCase c = lookupTowards(map, d);
        const auto lookup = inspect::mapLookup(c.input, c.plan, c.path);
        ASSERT_TRUE(lookup.has_value());
        EXPECT_LT(glm::length(lookup->reflected - d), 1e-9);
        const double angle = std::acos(std::clamp(glm::dot(lookup->texelCentre, d), -1.0, 1.0));
        EXPECT_LT(angle, std::sqrt(lookup->texelSolidAngle)) << lookup->layout;
        EXPECT_GT(lookup->seamTexels, 2.0) << lookup->layout << ": well inside its component";
    }
}

TEST(MapLookup, ASeamOfEachLayoutIsFound) {
    struct Seam {
        ReflectorMap map;
        glm::dvec3 direction;
    };
    // A cube's face edge (x = y), a paraboloid's rim (z = 0), the tennis ball's and the octahedron's sides.
    const Seam seams[] = {{ReflectorMap::Cube, {1.0, 1.0, 0.3}},
                          {ReflectorMap::DualParaboloid, {0.6, 0.8, 0.0}},
                          {ReflectorMap::TennisBall, {0.0, 0.7071, 0.7071}},
                          {ReflectorMap::Octahedral, {0.5, 0.0, -0.5}}};
    for (const Seam& seam : seams) {
        const LookupCase c = lookupTowards(seam.map, glm::normalize(seam.direction));
        const auto lookup = inspect::mapLookup(c.input, c.plan, c.path);
        ASSERT_TRUE(lookup.has_value());
        EXPECT_LT(lookup->seamTexels, 2.0) << lookup->layout;
    }
}

} // namespace
} // namespace speculum::test
