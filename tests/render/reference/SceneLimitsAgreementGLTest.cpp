// Values at the edges of what a project may hold (render/frame/SceneLimits.hpp) render finite and right in
// both renderers, and values beyond them (NaN, 1e39: only reachable by bypassing the reader) still give only
// finite pixels. "Right" is the tracer's image, compared as the accuracy tests compare: flat colours that
// say which object each pixel shows, or the lit colour within a relative tolerance.
#include "render/frame/SceneLimits.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"
#include "render/reference/Tracer.hpp"
#include "support/GlTest.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

MeshHandle boxMesh() {
    static const auto box = std::make_shared<const MeshData>(makeBox());
    return box;
}

Material flat(glm::dvec3 colour) {
    Material m;
    m.color = glm::dvec3(0.0);
    m.ambient = 0.0;
    m.diffuse = 0.0;
    m.specular = 0.0;
    m.emission = colour;
    return m;
}

Material lit(glm::dvec3 colour) {
    Material m;
    m.color = colour;
    m.ambient = 1.0;
    m.diffuse = 1.0;
    m.specular = 0.5;
    m.shininess = 16.0;
    return m;
}

DrawItem box(const std::string& name, const glm::dmat4& world, const Material& material) {
    return {name, world, boxMesh(), material, true};
}

glm::dmat4 placed(glm::dvec3 centre, glm::dvec3 halfSize) {
    return glm::scale(glm::translate(glm::dmat4(1.0), centre), halfSize);
}

// A mirror in the plane through `centre` facing +Z (its local +Y turned onto +Z).
Mirror mirrorFacingZ(glm::dvec3 centre, glm::dvec2 size, const Material& surface) {
    Mirror mirror;
    mirror.name = "Mirror";
    mirror.world =
        glm::rotate(glm::translate(glm::dmat4(1.0), centre), glm::radians(90.0), glm::dvec3(1, 0, 0));
    mirror.size = size;
    mirror.reflectivity = 1.0;
    mirror.material = surface;
    mirror.hasMaterial = true;
    return mirror;
}

reference::TraceResult trace(const FrameInput& input) {
    auto tracer = reference::Tracer::create(input);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error());
    if (!tracer.ok())
        return {};
    reference::TraceSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.threads = 2;
    auto result = tracer->render(settings);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error());
    return result.ok() ? std::move(*result) : reference::TraceResult{};
}

std::size_t nonFinite(const Image& image) {
    std::size_t count = 0;
    for (float v : image.rgba)
        count += !std::isfinite(v);
    return count;
}

void dump(const std::string& name, const Image& raster, const Image& traced) {
    const char* folder = std::getenv("SPECULUM_TEST_DUMP");
    if (!folder)
        return;
    EXPECT_TRUE(writeImage(std::string(folder) + "/" + name + "_raster.png", raster).ok());
    EXPECT_TRUE(writeImage(std::string(folder) + "/" + name + "_reference.png", traced).ok());
}

// Distinct flat colours, far apart in linear RGB (as in reference/test_reference_agreement.cpp).
const std::array<glm::dvec3, 6> kPalette = {glm::dvec3(0, 0, 0), {1, 0, 0}, {0, 1, 0},
                                            {0, 0, 1},           {1, 1, 0}, {0, 1, 1}};

int classOf(const glm::vec4& c) {
    int best = 0;
    double bestDistance = 1e300;
    for (std::size_t i = 0; i < kPalette.size(); ++i) {
        const double d = glm::length(glm::dvec3(glm::vec3(c)) - kPalette[i]);
        if (d < bestDistance) {
            bestDistance = d;
            best = static_cast<int>(i);
        }
    }
    return best;
}

struct Agreement {
    double fraction = 0.0;        // pixels that show the same object in both
    std::vector<int> rasterCount; // pixels per class in the rasterized image
    std::vector<int> tracedCount; // and in the traced one
};

Agreement classAgreement(const Image& raster, const Image& traced) {
    Agreement a;
    a.rasterCount.assign(kPalette.size(), 0);
    a.tracedCount.assign(kPalette.size(), 0);
    if (raster.width != traced.width || raster.height != traced.height || raster.width == 0)
        return a;
    std::size_t same = 0;
    for (int y = 0; y < raster.height; ++y)
        for (int x = 0; x < raster.width; ++x) {
            const int c = classOf(raster.at(x, y));
            const int t = classOf(traced.at(x, y));
            ++a.rasterCount[static_cast<std::size_t>(c)];
            ++a.tracedCount[static_cast<std::size_t>(t)];
            same += c == t;
        }
    a.fraction = double(same) / double(raster.width * raster.height);
    return a;
}

// Lit colours: the fraction of pixels whose channels agree within 2% (relative) or 0.01 (absolute).
double colourAgreement(const Image& raster, const Image& traced) {
    if (raster.width != traced.width || raster.height != traced.height || raster.width == 0)
        return 0.0;
    std::size_t same = 0;
    for (int y = 0; y < raster.height; ++y)
        for (int x = 0; x < raster.width; ++x) {
            const glm::vec4 a = raster.at(x, y), b = traced.at(x, y);
            bool ok = true;
            for (int c = 0; c < 3; ++c)
                ok = ok && std::abs(a[c] - b[c]) <= 0.02f * std::max(std::abs(a[c]), std::abs(b[c])) + 0.01f;
            same += ok;
        }
    return double(same) / double(raster.width * raster.height);
}

class ExtremeValues : public GlTest {
protected:
    // Renders with both, checks every pixel is finite in each, and returns them.
    std::pair<Image, Image> renderBoth(const FrameInput& input, const std::string& name) {
        Image raster = renderImage(input, kWidth, kHeight);
        reference::TraceResult traced = trace(input);
        EXPECT_EQ(raster.width, kWidth) << name;
        EXPECT_EQ(nonFinite(raster), 0u) << name << ": rasterizer";
        EXPECT_EQ(nonFinite(traced.image), 0u) << name << ": tracer";
        dump(name, raster, traced.image);
        return {std::move(raster), std::move(traced.image)};
    }

    void expectSameObjects(const FrameInput& input, const std::string& name, double minimum = 0.97) {
        const auto [raster, traced] = renderBoth(input, name);
        const Agreement a = classAgreement(raster, traced);
        std::printf(
            "[ measured ] %s: %.1f%% of pixels show the same object; pixels per object (raster/traced):",
            name.c_str(), a.fraction * 100.0);
        for (std::size_t i = 0; i < a.rasterCount.size(); ++i)
            std::printf(" %d/%d", a.rasterCount[i], a.tracedCount[i]);
        std::printf("\n");
        EXPECT_GE(a.fraction, minimum) << name;
        if (std::getenv("SPECULUM_TEST_DUMP")) {
            const FramePlan plan = planFrame(input, PlannerState{}, PlanViewport{kWidth, kHeight});
            for (const SkippedEffect& s : plan.skipped)
                std::printf("  skipped %s: %s\n", s.target.c_str(), s.reason().c_str());
            for (const MirrorView& v : plan.views)
                std::printf("  view of mirror %d: %g px\n", v.mirror, v.pixelArea);
        }
    }
};

// A red box in front of a green one on a black background, seen from `eye` looking down −Z, everything
// scaled by `unit` and moved by `offset`.
FrameInput boxes(double unit, glm::dvec3 offset) {
    FrameInput input;
    input.settings.background = kPalette[0];
    input.settings.ambient = 0.0;
    input.camera.position = offset + glm::dvec3(0.0, 0.0, 6.0) * unit;
    input.camera.target = offset;
    input.camera.near = 0.1 * unit;
    input.camera.far = 100.0 * unit;
    input.items.push_back(box("Near", placed(offset + glm::dvec3(-0.8, 0, 1) * unit, glm::dvec3(0.5 * unit)),
                              flat(kPalette[1])));
    input.items.push_back(box("Far", placed(offset + glm::dvec3(0.8, 0, -1) * unit, glm::dvec3(1.0 * unit)),
                              flat(kPalette[2])));
    return input;
}

TEST_F(ExtremeValues, TinyAndHugeScalesRenderTheSameObjects) {
    // Scale 1e-9 on a mesh 1e9 wide, and scale 1e9 on a unit mesh seen from 1e9 away.
    FrameInput tiny = boxes(1.0, glm::dvec3(0.0));
    static const auto bigBox = [] {
        MeshData m = makeBox();
        for (glm::vec3& p : m.positions)
            p *= 1e9f;
        return std::make_shared<const MeshData>(std::move(m));
    }();
    for (DrawItem& item : tiny.items) {
        item.mesh = bigBox;
        item.world = item.world * glm::scale(glm::dmat4(1.0), glm::dvec3(kMinScale));
        item.material = lit(glm::dvec3(item.material.emission));
    }
    tiny.lights.push_back({});
    tiny.lights.back().position = {2.0, 3.0, 5.0};
    expectSameObjects(tiny, "scale_1e-9");
    FrameInput huge = boxes(kMaxScale, glm::dvec3(0.0));
    huge.camera.near = 1e3 * kMaxScale / 1e3; // far/near = 100
    expectSameObjects(huge, "scale_1e9");
    // A box squashed flat by 1e-9 along one axis, lit: its normal matrix scales by 1e9.
    FrameInput squashed = boxes(1.0, glm::dvec3(0.0));
    squashed.items[0].world = placed({-0.8, 0, 1}, {0.5, 0.5, kMinScale});
    squashed.items[1].world = placed({0.8, 0, -1}, {kMinScale, 1.0, 1.0});
    for (DrawItem& item : squashed.items)
        item.material = flat(glm::dvec3(item.material.emission));
    squashed.lights.push_back({});
    squashed.lights.back().position = {2.0, 3.0, 5.0};
    expectSameObjects(squashed, "squashed");
    // The same boxes lit: the shading normal of a face whose normal matrix scales by 1e9 is right.
    for (DrawItem& item : squashed.items)
        item.material = lit(glm::dvec3(item.material.emission) * 0.5 + 0.2);
    squashed.settings.ambient = 0.1;
    const auto [raster, traced] = renderBoth(squashed, "squashed_lit");
    const double agree = colourAgreement(raster, traced);
    std::printf("[ measured ] squashed, lit: %.1f%% of pixels agree in colour\n", agree * 100.0);
    EXPECT_GE(agree, 0.97);
}

// Known limit, measured and not asserted: a box stretched by 1e9 along one axis and seen from 6 m has
// vertices 1e8 times farther off screen than its distance; llvmpipe's rasterizer then draws only part of
// it (about half the pixels the tracer shows). Both images stay finite.
TEST_F(ExtremeValues, StretchedBoxStaysFinite) {
    FrameInput stretched = boxes(1.0, glm::dvec3(0.0));
    stretched.items[1].world = placed({0.8, 0, -1}, {1.0, kMaxScale, 1.0});
    const auto [raster, traced] = renderBoth(stretched, "stretched");
    const Agreement a = classAgreement(raster, traced);
    std::printf("[ measured ] stretched 1e9: %.1f%% of pixels show the same object (not asserted)\n",
                a.fraction * 100.0);
}

TEST_F(ExtremeValues, FarAndBrightLightsStayFiniteAndAgree) {
    for (double intensity : {1.0, kMaxIntensity}) {
        FrameInput input = boxes(1.0, glm::dvec3(0.0));
        for (DrawItem& item : input.items)
            item.material = lit(glm::dvec3(item.material.emission) * 0.5 + 0.1);
        input.settings.ambient = 0.1;
        Light point;
        point.position = glm::dvec3(0.3, 0.8, 0.5) * kMaxCoordinate;
        point.intensity = intensity;
        point.shadows = ShadowParams{};
        point.shadows->mapSize = 64;
        Light spot = point;
        spot.type = LightType::Spot;
        spot.position = glm::dvec3(-0.2, 0.5, 1.0) * kMaxCoordinate;
        spot.direction = -glm::normalize(spot.position);
        spot.spotAngle = 10.0;
        Light sun = point;
        sun.type = LightType::Directional;
        sun.direction = glm::normalize(glm::dvec3(-1, -2, -1));
        input.lights = {point, spot, sun};
        const std::string name = intensity > 1.0 ? "bright_far_lights" : "far_lights";
        const auto [raster, traced] = renderBoth(input, name);
        const double agree = colourAgreement(raster, traced);
        std::printf("[ measured ] %s: %.1f%% of pixels agree in colour\n", name.c_str(), agree * 100.0);
        EXPECT_GE(agree, 0.95) << name;
    }
}

TEST_F(ExtremeValues, NearAndFarAtTheirLimits) {
    // near 1e-6 with far 1 (the largest ratio), the scene within a metre.
    FrameInput close = boxes(0.1, glm::dvec3(0.0));
    close.camera.near = kMinNear;
    close.camera.far = close.camera.near * kMaxFarNearRatio;
    expectSameObjects(close, "near_1e-6");
    // far 1e12 with near 1e6, the scene 1e11 across.
    FrameInput distant = boxes(1e10, glm::dvec3(0.0));
    distant.camera.far = kMaxCoordinate;
    distant.camera.near = kMaxCoordinate / kMaxFarNearRatio;
    expectSameObjects(distant, "far_1e12");
}

// A yellow mirror surface (seen only where it does not reflect) at z = 0 facing the camera at z = 6, with
// a red box in front and a green box behind the camera, seen in it.
FrameInput mirrorScene(double unit, glm::dvec3 offset, double mirrorSize) {
    FrameInput input;
    input.settings.background = kPalette[0];
    input.settings.ambient = 0.0;
    input.camera.position = offset + glm::dvec3(0.5, 0.3, 6.0) * unit;
    input.camera.target = offset + glm::dvec3(0.0, 0.0, 0.0);
    input.camera.near = 0.1 * unit;
    input.camera.far = 100.0 * unit;
    input.items.push_back(box("Front",
                              placed(offset + glm::dvec3(-1.0, 0, 1.5) * unit, glm::dvec3(0.5 * unit)),
                              flat(kPalette[1])));
    input.items.push_back(box("Behind camera",
                              placed(offset + glm::dvec3(1.0, 0.5, 9) * unit, glm::dvec3(1.0 * unit)),
                              flat(kPalette[2])));
    input.mirrors.push_back(mirrorFacingZ(offset, glm::dvec2(mirrorSize), flat(kPalette[4])));
    return input;
}

TEST_F(ExtremeValues, MirrorsAtTheLimits) {
    expectSameObjects(mirrorScene(1.0, glm::dvec3(0.0), 4.0), "mirror_plain");
    // A mirror 1e12 across: the box in front of it stays whole.
    expectSameObjects(mirrorScene(1.0, glm::dvec3(0.0), kMaxCoordinate), "mirror_huge");
    // The whole scene, mirror included, 1e9 from the origin.
    expectSameObjects(mirrorScene(1.0, glm::dvec3(1e9, -4e8, 7e8), 4.0), "mirror_far_from_origin");
    // far 1e12 / near 1e6 seen in a mirror (the oblique near plane with a huge far).
    FrameInput deep = mirrorScene(1e10, glm::dvec3(0.0), 4e10);
    deep.camera.far = kMaxCoordinate;
    deep.camera.near = kMaxCoordinate / kMaxFarNearRatio;
    expectSameObjects(deep, "mirror_far_1e12");
    // near 1e-6, far 1 seen in a mirror.
    FrameInput shallow = mirrorScene(0.05, glm::dvec3(0.0), 0.2);
    shallow.camera.near = kMinNear;
    shallow.camera.far = 1.0;
    expectSameObjects(shallow, "mirror_near_1e-6");
}

// A mirror that cannot be drawn gets no pass and a reason that says why, not a misleading one.
TEST(ExtremeMirrorPlan, UndrawableMirrorsAreSkippedWithAPlainReason) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    FrameInput input = mirrorScene(1.0, glm::dvec3(0.0), 4.0);
    input.mirrors.push_back(input.mirrors[0]);
    input.mirrors.push_back(input.mirrors[0]);
    input.mirrors[0].name = "NaN size";
    input.mirrors[0].size = glm::dvec2(nan, 4.0);
    input.mirrors[1].name = "NaN transform";
    input.mirrors[1].world[3] = glm::dvec4(nan, 0.0, 0.0, 1.0);
    input.mirrors[2].name = "Good";
    const FramePlan plan = planFrame(input, PlannerState{}, PlanViewport{kWidth, kHeight});
    auto skipOf = [&](const std::string& name) -> const SkippedEffect* {
        for (const SkippedEffect& s : plan.skipped)
            if (s.target.find(name) != std::string::npos)
                return &s;
        return nullptr;
    };
    ASSERT_NE(skipOf("NaN size"), nullptr);
    EXPECT_EQ(skipOf("NaN size")->code, PlanReason::MirrorSizeInvalid) << skipOf("NaN size")->reason();
    ASSERT_NE(skipOf("NaN transform"), nullptr);
    EXPECT_EQ(skipOf("NaN transform")->code, PlanReason::MirrorNoPlane) << skipOf("NaN transform")->reason();
    EXPECT_NE(skipOf("NaN transform")->details.error.find("not a finite number"), std::string::npos)
        << skipOf("NaN transform")->reason();
    ASSERT_EQ(plan.views.size(), 1u);
    EXPECT_EQ(plan.views[0].mirror, 2);
}

// Values no reader lets through, fed straight into FrameInput: the image may be wrong, but every pixel
// must be a number.
TEST_F(ExtremeValues, HostileValuesStillGiveFinitePixels) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<std::pair<std::string, FrameInput>> cases;
    auto base = [] {
        FrameInput input = mirrorScene(1.0, glm::dvec3(0.0), 4.0);
        for (DrawItem& item : input.items)
            item.material = lit(glm::dvec3(item.material.emission) + 0.1);
        input.mirrors[0].reflectivity = 0.7;
        input.mirrors[0].material = lit({0.5, 0.5, 0.5});
        input.lights.push_back({});
        input.lights.back().position = {1.0, 4.0, 4.0};
        input.lights.back().shadows = ShadowParams{};
        input.lights.back().shadows->mapSize = 64;
        return input;
    };
    {
        FrameInput in = base();
        in.lights[0].intensity = 1e39;
        cases.emplace_back("intensity 1e39", in);
    }
    {
        FrameInput in = base();
        in.lights[0].position = glm::dvec3(1e39, 1e39, 1e39);
        cases.emplace_back("light at 1e39", in);
    }
    {
        FrameInput in = base();
        in.lights[0].position = glm::dvec3(nan);
        in.lights[0].intensity = nan;
        cases.emplace_back("NaN light", in);
    }
    {
        FrameInput in = base();
        in.lights[0].type = LightType::Spot;
        in.lights[0].direction = glm::dvec3(0.0);
        in.lights[0].color = glm::dvec3(inf);
        cases.emplace_back("spot with no direction, infinite colour", in);
    }
    {
        FrameInput in = base();
        in.items[0].world = placed({-1, 0, 1.5}, glm::dvec3(1e-39));
        in.items[1].world = placed({1, 0.5, 9}, glm::dvec3(1e20));
        cases.emplace_back("scales 1e-39 and 1e20", in);
    }
    {
        FrameInput in = base();
        in.items[0].world[3] = glm::dvec4(nan, nan, nan, 1.0);
        in.items[1].material.emission = glm::dvec3(nan);
        in.items[1].material.shininess = -5.0;
        cases.emplace_back("NaN position, NaN emission, negative shininess", in);
    }
    {
        FrameInput in = base();
        in.camera.near = 1e-30;
        in.camera.far = 1e30;
        cases.emplace_back("near 1e-30, far 1e30", in);
    }
    {
        FrameInput in = base();
        in.mirrors[0].size = glm::dvec2(1e39);
        in.mirrors[0].reflectivity = nan;
        cases.emplace_back("mirror 1e39 wide, NaN reflectivity", in);
    }
    {
        FrameInput in = base();
        in.settings.ambient = 1e39;
        in.settings.background = glm::dvec3(nan);
        cases.emplace_back("ambient 1e39, NaN background", in);
    }
    {
        FrameInput in = base();
        in.lights[0].intensity = 1e39;
        Reflector reflector;
        reflector.name = "Ball";
        reflector.mesh = std::make_shared<const MeshData>(makeSphere(16));
        reflector.world = placed({1.5, 0.0, 1.0}, glm::dvec3(0.7));
        reflector.resolution = 32;
        reflector.reflectivity = 0.6;
        in.reflectors = {reflector};
        cases.emplace_back("curved reflector lit by intensity 1e39", in);
    }
    for (const auto& [name, input] : cases) {
        SCOPED_TRACE(name);
        const Image raster = renderImage(input, kWidth, kHeight);
        EXPECT_EQ(nonFinite(raster), 0u) << name << ": rasterizer";
        const reference::TraceResult traced = trace(input);
        EXPECT_EQ(nonFinite(traced.image), 0u) << name << ": tracer";
    }
}

} // namespace
} // namespace speculum::test
