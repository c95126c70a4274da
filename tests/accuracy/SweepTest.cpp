// The bench's plan and analysis without GL: which configurations a scene gets, that each family varies
// only its own settings around the scene's, and the Pareto front, "within 1 dB" and equal-error costs.
#include "accuracy/Sweep.hpp"

#include "accuracy/Analysis.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Simplify.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <set>

namespace speculum::accuracy {
namespace {

using render::FrameInput;
using render::MirrorTechnique;

render::MeshHandle sphere() {
    static const auto mesh = std::make_shared<const render::MeshData>(render::makeSphere(16));
    return mesh;
}

// A floor and a box around the origin, a light without shadows: nothing to sweep yet.
FrameInput plainScene() {
    FrameInput input;
    const auto plane = std::make_shared<const render::MeshData>(render::makePlane(1));
    const auto box = std::make_shared<const render::MeshData>(render::makeBox());
    input.items.push_back({"Floor", glm::dmat4(glm::dmat3(4.0)), plane, {}, true});
    glm::dmat4 boxWorld(1.0);
    boxWorld[3] = glm::dvec4(0.0, 2.0, 0.0, 1.0);
    input.items.push_back({"Box", boxWorld, box, {}, true});
    input.lights.push_back(render::Light{});
    return input;
}

FrameInput withReflector(FrameInput input) {
    render::Reflector r;
    r.name = "Ball";
    r.mesh = sphere();
    r.world = glm::dmat4(glm::dmat3(0.5));
    r.world[3] = glm::dvec4(0.0, 0.5, 0.0, 1.0);
    r.map = render::ReflectorMap::DualParaboloid;
    r.resolution = 96; // not among the swept values: the sweep must add it
    input.reflectors = {r};
    return input;
}

FrameInput withMirrorsAndShadows(FrameInput input) {
    render::Mirror m;
    m.name = "Mirror";
    input.mirrors.push_back(m);
    input.settings.mirrorDepth = 2;
    input.lights.front().shadows = render::ShadowParams{};
    input.lights.front().shadows->pcf = 9;
    return input;
}

// A mesh big enough to get a simplified level (MeshData::coarse).
FrameInput withBigMesh(FrameInput input) {
    static const render::MeshHandle big = render::freezeMesh(render::makeSphere(256));
    EXPECT_FALSE(render::coarseLevel(*big).indices.empty());
    glm::dmat4 world(1.0);
    world[3] = glm::dvec4(2.0, 1.0, 0.0, 1.0);
    input.items.push_back({"Statue", world, big, {}, true});
    return input;
}

std::set<Family> familiesOf(const std::vector<Configuration>& configs) {
    std::set<Family> families;
    for (const Configuration& c : configs)
        families.insert(c.family);
    return families;
}

TEST(BenchSweep, OnlyTheFamiliesTheSceneCallsFor) {
    const FrameInput plain = plainScene();
    const auto none = planSweep(plain, sceneTraits(plain, std::nullopt), {true});
    EXPECT_EQ(familiesOf(none), std::set<Family>{Family::Scene});

    const FrameInput mirrors = withMirrorsAndShadows(plainScene());
    const auto noMaps = planSweep(mirrors, sceneTraits(mirrors, 8), {true});
    EXPECT_EQ(familiesOf(noMaps),
              (std::set<Family>{Family::Scene, Family::MirrorTechnique, Family::MirrorDepth, Family::Shadows,
                                Family::Tessellation, Family::ScreenSpace}));

    const FrameInput ball = withReflector(plainScene());
    const SceneTraits traits = sceneTraits(ball, std::nullopt);
    EXPECT_TRUE(traits.proxyMakesSense) << "the floor and the box enclose the ball";
    EXPECT_EQ(familiesOf(planSweep(ball, traits, {true})),
              (std::set<Family>{Family::Scene, Family::Envmap, Family::Parallax, Family::ScreenSpace}));
}

// Reflectors that see each other get the bounces family (reflectorBounces 0..3, against the scene's
// reference); a scene that moves gets the update family, played, against where the frames end.
TEST(BenchSweep, SeveralReflectorsAreSweptByBouncesAndAMovingSceneByUpdate) {
    FrameInput two = withReflector(plainScene());
    two.reflectors.push_back(two.reflectors[0]);
    two.reflectors[1].world[3] = glm::dvec4(1.5, 0.5, 0.0, 1.0);
    SceneTraits traits = sceneTraits(two, std::nullopt);
    EXPECT_EQ(traits.reflectors, 2u);
    std::vector<int> bounces;
    for (const Configuration& c : planSweep(two, traits, {false})) {
        EXPECT_NE(c.family, Family::Update) << "nothing moves";
        if (c.family != Family::Bounces)
            continue;
        EXPECT_EQ(c.reference, ReferenceKind::Scene);
        bounces.push_back(std::get<int>(*c.variation.find(Part::Settings, "reflectorBounces")));
    }
    EXPECT_EQ(bounces, (std::vector<int>{0, 1, 2, 3}));
    const FrameInput one = withReflector(plainScene());
    EXPECT_EQ(familiesOf(planSweep(one, sceneTraits(one, std::nullopt), {true})).count(Family::Bounces), 0u)
        << "one reflector has nothing to bounce off";

    traits.moves = true;
    std::vector<render::ReflectorUpdate> updates;
    for (const Configuration& c : planSweep(two, traits, {true}))
        if (c.family == Family::Update) {
            EXPECT_EQ(c.reference, ReferenceKind::Played);
            updates.push_back(static_cast<render::ReflectorUpdate>(
                std::get<int>(*c.variation.find(Part::Reflector, "update"))));
        }
    EXPECT_EQ(updates, (std::vector<render::ReflectorUpdate>{render::ReflectorUpdate::Always,
                                                             render::ReflectorUpdate::TimeSliced}));
}

TEST(BenchSweep, BigMeshesInReflectionsAreSweptWholeAndSimplified) {
    const FrameInput alone = withBigMesh(plainScene());
    EXPECT_EQ(sceneTraits(alone, std::nullopt).simplifiableMeshes, 0u) << "nothing reflects it";
    EXPECT_FALSE(familiesOf(planSweep(alone, sceneTraits(alone, std::nullopt), {true}))
                     .count(Family::ReflectedDetail));

    for (const FrameInput& scene :
         {withMirrorsAndShadows(withBigMesh(plainScene())), withReflector(withBigMesh(plainScene()))}) {
        const SceneTraits traits = sceneTraits(scene, std::nullopt);
        EXPECT_EQ(traits.simplifiableMeshes, 1u);
        std::vector<std::string> ids;
        for (const Configuration& c : planSweep(scene, traits, {true}))
            if (c.family == Family::ReflectedDetail) {
                ids.push_back(c.id);
                EXPECT_EQ(c.reference, ReferenceKind::Scene) << "the tracer always draws every triangle";
                const FrameInput applied = applyVariation(scene, c.variation, traits.proxy, {});
                EXPECT_EQ(applied.settings.simplifyReflections, c.id == "reflected-detail-simplified");
                const Settings s = effectiveSettings(applied, std::nullopt, traits.simplifiableMeshes > 0);
                EXPECT_NE(
                    std::find(s.begin(), s.end(), std::make_pair(std::string("reflectedDetail"), c.label)),
                    s.end());
            }
        EXPECT_EQ(ids, (std::vector<std::string>{"reflected-detail-full", "reflected-detail-simplified"}));
    }
}

// Rough surfaces call for the glossy family: at each of three roughnesses, the mip filter, the convolved
// chain and the footprint at rising quality, each against the reference traced at that roughness. Only
// surfaces that are rough in the scene change roughness; a sharp mirror stays sharp.
TEST(BenchSweep, RoughSurfacesAreSweptAtThreeRoughnessesAgainstTheirOwnReferences) {
    FrameInput scene = withMirrorsAndShadows(withReflector(plainScene()));
    EXPECT_FALSE(familiesOf(planSweep(scene, sceneTraits(scene, std::nullopt), {true})).count(Family::Glossy))
        << "nothing is rough";
    render::Mirror sharp;
    sharp.name = "Sharp";
    scene.mirrors.push_back(sharp);
    scene.mirrors.front().roughness = 0.2;
    scene.reflectors[0].roughness = 0.4;
    const SceneTraits traits = sceneTraits(scene, std::nullopt);
    EXPECT_EQ(traits.roughMirrors, 1u);
    EXPECT_TRUE(traits.roughReflector);
    for (bool quick : {true, false}) {
        std::map<ReferenceKind, std::vector<std::string>> labels;
        for (const Configuration& c : planSweep(scene, traits, {quick})) {
            if (c.family != Family::Glossy)
                continue;
            const std::optional<double> roughness = referenceRoughness(c.reference);
            ASSERT_TRUE(roughness) << c.id;
            labels[c.reference].push_back(c.label);
            const FrameInput applied = applyVariation(scene, c.variation, traits.proxy, {});
            EXPECT_EQ(applied.mirrors[0].roughness, *roughness) << c.id;
            EXPECT_EQ(applied.mirrors[1].roughness, 0.0) << c.id << ": the sharp mirror stays sharp";
            EXPECT_EQ(applied.reflectors[0].roughness, *roughness) << c.id;
            const bool chain = c.label.starts_with("chain");
            EXPECT_EQ(applied.settings.glossyFilter, c.label == "mip" ? render::GlossyFilter::Mip
                                                     : chain          ? render::GlossyFilter::Chain
                                                                      : render::GlossyFilter::Footprint);
            const FrameInput reference = referenceInput(scene, c.reference, {});
            EXPECT_EQ(reference.mirrors[0].roughness, *roughness);
            EXPECT_EQ(reference.mirrors[1].roughness, 0.0);
            const Settings s = effectiveSettings(applied, std::nullopt, traits.simplifiableMeshes > 0);
            const std::map<std::string, std::string> m(s.begin(), s.end());
            EXPECT_EQ(m.at("glossy"), c.label == "mip" || chain ? c.label : "footprint " + c.label) << c.id;
        }
        ASSERT_EQ(labels.size(), 3u);
        for (const auto& [kind, list] : labels) {
            EXPECT_EQ(list.front(), "mip") << referenceName(kind);
            EXPECT_EQ(list[1], "chain 64 samples") << referenceName(kind);
            EXPECT_EQ(list.size(), quick ? 4u : 5u) << referenceName(kind);
            EXPECT_EQ(referenceFromName(referenceName(kind)), kind);
        }
        EXPECT_EQ(labels.at(ReferenceKind::RoughMid).back(),
                  quick ? "16 taps / 64 samples" : "64 taps / 256 samples");
    }
    EXPECT_EQ(familyFromName("glossy"), Family::Glossy);
}

TEST(BenchSweep, NoProxyForAReflectorOutsideTheScene) {
    FrameInput ball = withReflector(plainScene());
    ball.reflectors[0].world[3] = glm::dvec4(0.0, 10.0, 0.0, 1.0);
    const SceneTraits traits = sceneTraits(ball, std::nullopt);
    EXPECT_FALSE(traits.proxyMakesSense);
    EXPECT_FALSE(familiesOf(planSweep(ball, traits, {false})).count(Family::Parallax));
}

TEST(BenchSweep, EachFamilyVariesOnlyItsOwnSettingsAndIncludesTheScenes) {
    const FrameInput scene = withMirrorsAndShadows(withReflector(withBigMesh(plainScene())));
    const SceneTraits traits = sceneTraits(scene, 8);
    const Settings own = effectiveSettings(scene, 8, traits.simplifiableMeshes > 0);
    const std::map<std::string, std::string> ownMap(own.begin(), own.end());
    const std::map<Family, std::set<std::string>> varies = {
        {Family::Envmap, {"map", "resolution", "fill"}},
        {Family::Parallax, {"parallax", "resolution"}},
        // Traced, a mirror's trace settings show as columns.
        {Family::MirrorTechnique,
         {"technique", "screenSteps", "screenThickness", "screenResolution", "screenFallback"}},
        {Family::MirrorDepth, {"mirrorDepth"}},
        {Family::Shadows, {"pcf"}},
        {Family::Tessellation, {"tessellation"}},
        {Family::ReflectedDetail, {"reflectedDetail"}},
        {Family::ScreenSpace,
         {"technique", "screenSteps", "screenThickness", "screenResolution", "screenFallback",
          "reflectorTechnique"}}};
    const TessellateTeapot keep = [](const render::MeshHandle& m, int) { return m; };
    std::map<Family, bool> sawOwn;
    std::set<std::string> ids;
    for (bool quick : {true, false}) {
        ids.clear();
        for (const Configuration& c : planSweep(scene, traits, {quick})) {
            EXPECT_TRUE(ids.insert(c.id).second) << "duplicate id " << c.id;
            EXPECT_EQ(c.id.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-"), std::string::npos)
                << c.id;
            const FrameInput applied = applyVariation(scene, c.variation, traits.proxy, keep);
            const Settings list = effectiveSettings(applied, c.variation.tessellation.value_or(8),
                                                    traits.simplifiableMeshes > 0);
            const std::map<std::string, std::string> s(list.begin(), list.end());
            const bool same = s == ownMap;
            std::set<std::string> names;
            for (const auto& [name, value] : s)
                names.insert(name);
            for (const auto& [name, value] : ownMap)
                names.insert(name);
            for (const std::string& name : names) {
                if (c.family != Family::Scene && !varies.at(c.family).count(name)) {
                    EXPECT_EQ(s.count(name) ? s.at(name) : "", ownMap.count(name) ? ownMap.at(name) : "")
                        << c.id << " changes " << name;
                }
            }
            sawOwn[c.family] = sawOwn[c.family] || same;
        }
    }
    for (const auto& [family, saw] : sawOwn)
        EXPECT_TRUE(saw) << familyName(family) << " lacks the scene's own setting";
}

// Mirrors call for the screen-space family: the two planar techniques beside the trace with each of its
// settings varied, so that one plot and one Pareto front hold them; the fallback is varied only where
// there is a map to fall back to. Without mirrors, the reflector's map alone beside it traced first. The
// trace's settings are columns of the results where a mirror is traced, and read back into the same
// variation.
TEST(BenchSweep, MirrorsAreTracedInScreenSpaceBesideThePlanarTechniques) {
    for (bool ball : {false, true}) {
        const FrameInput scene =
            ball ? withMirrorsAndShadows(withReflector(plainScene())) : withMirrorsAndShadows(plainScene());
        const SceneTraits traits = sceneTraits(scene, 8);
        std::set<std::string> series;
        int traced = 0;
        for (const Configuration& c : planSweep(scene, traits, {false})) {
            if (c.family != Family::ScreenSpace)
                continue;
            series.insert(c.series);
            const FrameInput applied = applyVariation(scene, c.variation, traits.proxy, {});
            const bool screenSpace = applied.mirrors.front().technique == MirrorTechnique::ScreenSpace;
            EXPECT_EQ(screenSpace, c.series != "planar") << c.id;
            if (!screenSpace)
                continue;
            ++traced;
            const Settings list = effectiveSettings(applied, std::nullopt, false);
            const std::map<std::string, std::string> s(list.begin(), list.end());
            EXPECT_EQ(s.at("technique"), "screen-space");
            EXPECT_EQ(s.at("screenSteps"), std::to_string(applied.settings.screenSteps)) << c.id;
            EXPECT_EQ(s.count("screenFallback"), ball ? 1u : 0u) << c.id;
            for (const auto& [column, value] : list) {
                const auto read = variationOf(column, value);
                EXPECT_TRUE(read.ok()) << column << " = " << value;
            }
            if (c.id == "screen-space-half-64") {
                EXPECT_EQ(s.at("screenResolution"), "half");
            }
        }
        EXPECT_GE(traced, 10);
        std::set<std::string> expected{"planar", "steps", "thickness", "half resolution"};
        if (ball)
            expected.insert("fallback");
        EXPECT_EQ(series, expected);
    }
    // A reflector without mirrors: its map alone, then traced first; a rough one as a cone, alike.
    FrameInput ball = withReflector(plainScene());
    std::vector<std::string> ids;
    for (const Configuration& c : planSweep(ball, sceneTraits(ball, std::nullopt), {false}))
        if (c.family == Family::ScreenSpace) {
            ids.push_back(c.id);
            const FrameInput applied = applyVariation(ball, c.variation, std::nullopt, {});
            EXPECT_EQ(applied.reflectors[0].technique, c.series == "reflector map"
                                                           ? render::ReflectorTechnique::Map
                                                           : render::ReflectorTechnique::ScreenSpace);
        }
    EXPECT_EQ(ids, (std::vector<std::string>{"screen-space-reflector-map", "screen-space-reflector-steps-16",
                                             "screen-space-reflector-steps-64",
                                             "screen-space-reflector-steps-256"}));
    ball.reflectors[0].roughness = 0.3;
    std::vector<std::string> roughIds;
    for (const Configuration& c : planSweep(ball, sceneTraits(ball, std::nullopt), {true}))
        if (c.family == Family::ScreenSpace)
            roughIds.push_back(c.id);
    EXPECT_EQ(roughIds,
              (std::vector<std::string>{"screen-space-reflector-map", "screen-space-reflector-steps-64"}));
}

TEST(BenchSweep, QuickSweepsFewerPoints) {
    const FrameInput scene = withMirrorsAndShadows(withReflector(plainScene()));
    const SceneTraits traits = sceneTraits(scene, 8);
    EXPECT_LT(planSweep(scene, traits, {true}).size(), planSweep(scene, traits, {false}).size());
}

TEST(BenchSweep, ReferencesChangeOnlyWhatTheTracerDependsOn) {
    const FrameInput scene = withMirrorsAndShadows(withReflector(plainScene()));
    int swapped = 0;
    const TessellateTeapot count = [&](const render::MeshHandle& m, int tessellation) {
        EXPECT_EQ(tessellation, 64);
        ++swapped;
        return m;
    };
    EXPECT_EQ(referenceInput(scene, ReferenceKind::DeepMirrors, count).settings.mirrorDepth, 16);
    EXPECT_EQ(referenceInput(scene, ReferenceKind::Scene, count).settings.mirrorDepth, 2);
    EXPECT_EQ(swapped, 0);
    referenceInput(scene, ReferenceKind::FineMesh, count);
    EXPECT_EQ(swapped, 3) << "every item and the reflector are offered for the teapot swap";
}

TEST(BenchAnalysis, ParetoFrontKeepsWhatNothingBeats) {
    const std::vector<Point> points = {{10, 30}, {5, 20}, {12, 29}, {20, 35}, {5, 25}, {30, 34}};
    const std::vector<std::size_t> front = paretoFront(points);
    EXPECT_EQ(front, (std::vector<std::size_t>{4, 0, 3}));
}

TEST(BenchAnalysis, CheapestWithinOneDecibelOfTheBest) {
    const std::vector<Point> points = {{2, 20}, {4, 29.2}, {8, 30}, {16, 30.1}};
    EXPECT_EQ(cheapestWithin(points, 1.0), std::optional<std::size_t>(1));
    EXPECT_EQ(cheapestWithin({}, 1.0), std::nullopt);
}

TEST(BenchAnalysis, CostAtEqualErrorInterpolates) {
    const std::vector<Point> series = {{1, 20}, {2, 24}, {4, 26}};
    const CostAtError at = costAtError(series, 22.0);
    ASSERT_TRUE(at.interpolatedCost && at.firstReaching);
    EXPECT_DOUBLE_EQ(*at.interpolatedCost, 1.5);
    EXPECT_EQ(*at.firstReaching, 1u);
    EXPECT_FALSE(costAtError(series, 27.0).firstReaching);
    EXPECT_DOUBLE_EQ(*costAtError(series, 10.0).interpolatedCost, 1.0);
    EXPECT_DOUBLE_EQ(commonTarget({series, {{1, 21}, {3, 25}}}), 25.0);
}

TEST(BenchAnalysis, FamiliesAreJudgedOnThePixelsTheyChange) {
    EXPECT_EQ(focusMetric(Family::Envmap), Metric::PsnrReflector);
    EXPECT_EQ(focusMetric(Family::MirrorDepth), Metric::PsnrMirrors);
    EXPECT_EQ(focusMetric(Family::Shadows), Metric::Psnr);
    Record noMirrorPixels;
    noMirrorPixels.psnr = 31.0;
    EXPECT_EQ(effectiveMetric({&noMirrorPixels}, Metric::PsnrMirrors), Metric::Psnr);
    EXPECT_DOUBLE_EQ(focusValue(noMirrorPixels, Metric::PsnrMirrors), 31.0);
}

} // namespace
} // namespace speculum::accuracy
