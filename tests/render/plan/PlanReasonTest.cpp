// The reason codes and their sentences: every code has a name of its own for explain's JSON and a
// sentence for people, worded from the details the planner gives it.
#include "render/plan/PlanReason.hpp"

#include <gtest/gtest.h>
#include <set>
#include <string_view>
#include <vector>

namespace speculum::render {
namespace {

std::vector<PlanReason> everyCode() {
    std::vector<PlanReason> codes;
    for (std::size_t i = 0; i < kPlanReasonCount; ++i)
        codes.push_back(static_cast<PlanReason>(i));
    return codes;
}

TEST(PlanReason, EveryCodeHasADistinctKebabCaseName) {
    std::set<std::string_view> names;
    for (PlanReason code : everyCode()) {
        const std::string_view name = toString(code);
        ASSERT_FALSE(name.empty()) << static_cast<int>(code);
        EXPECT_TRUE(names.insert(name).second) << "two codes are named " << name;
        for (char c : name)
            EXPECT_TRUE((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-') << name;
        EXPECT_NE(name.front(), '-') << name;
        EXPECT_NE(name.back(), '-') << name;
    }
    EXPECT_EQ(names.size(), kPlanReasonCount);
    EXPECT_EQ(toString(PlanReason::MirrorOutsideView), "mirror-outside-view");
}

TEST(PlanReason, EveryCodeHasASentence) {
    ReasonDetails details;
    details.node = "Ball";
    details.error = "the mirror's transform is not a finite number";
    details.limit = 8;
    details.mapSize = 1024;
    details.casters = 3;
    details.objects = 4;
    details.lights = 1;
    details.resolution = 256;
    details.levels = 6;
    details.samples = 64;
    details.roughness = 0.5;
    details.area = 120.0;
    for (PlanReason code : everyCode()) {
        EXPECT_FALSE(formatReason(code, {}).empty()) << toString(code);
        EXPECT_FALSE(formatReason(code, details).empty()) << toString(code);
    }
}

// A few sentences word for word: what explain and the Render Passes panel show for them.
TEST(PlanReason, SentencesNameTheirDetails) {
    ReasonDetails cube;
    cube.mapSize = 2048;
    cube.pcf = 3;
    cube.casters = 1;
    cube.cubeFacesWithCasters = 4;
    ReasonDetails flat = cube;
    flat.cubeFacesWithCasters.reset();
    flat.casters = 5;
    ReasonDetails inMap;
    inMap.seenIn = {"Left", "Right"};
    inMap.mapFace = "Ball's map, +X face";
    inMap.area = 1234.4;
    ReasonDetails inCamera = inMap;
    inCamera.mapFace.clear();
    const struct {
        PlanReason code;
        ReasonDetails details;
        const char* sentence;
    } cases[] = {
        {PlanReason::ShadowFirstMap, cube,
         "light casts shadows (2048² map, PCF 3×3) from 1 caster; 4 of 6 cube faces hold casters; no map "
         "yet"},
        {PlanReason::ShadowChanged, flat,
         "light casts shadows (2048² map, PCF 3×3) from 5 casters; light or casters changed"},
        {PlanReason::MirrorMaskStencil, inMap,
         "marks the mirror's visible texels in the stencil buffer (seen in Left → Right (depth 3), in Ball's "
         "map, +X face, 1234 texels)"},
        {PlanReason::MirrorOutsideParent, inCamera,
         "no reflection: outside the parent mirror's reflected view (seen in Left → Right (depth 3))"},
        {PlanReason::ShadowMapNotAllocated, flat,
         "no shadow this frame: its 2048² map could not be allocated (see the warnings)"},
        {PlanReason::PreviewMirrorDepth, ReasonDetails{.limit = 2, .asked = 4},
         "preview: mirrors nest 2 levels deep, not 4 (settings.mirrorDepth)"},
        {PlanReason::PreviewEnvmapHeld, ReasonDetails{.update = ReflectorUpdate::Always},
         "preview: environment map held while the view moves (update \"always\" applies again at rest)"},
        {PlanReason::MirrorOccluded, inCamera,
         "no reflection: fully occluded: no pixel of it passed the depth test"},
    };
    for (const auto& c : cases)
        EXPECT_EQ(formatReason(c.code, c.details), c.sentence) << c.code;
}

// A preview's skips are told apart by their code, whose name says so.
// What the commands warn of: a skip that drops what the scene asks for. The scene's own settings working
// as meant (a sharp reflector needs no pre-filter, the Mip filter none either, a map of mirror depth 0
// shows no mirror) are not, nor are reuse, occlusion and previews.
TEST(PlanReason, OnlySkipsThatDropWhatTheSceneAsksAreDrops) {
    for (const PlanReason ordinary :
         {PlanReason::PrefilterSharp, PlanReason::PrefilterMipFilter, PlanReason::PrefilterReused,
          PlanReason::MapMirrorDepthZero, PlanReason::CompositeNotNeeded, PlanReason::EnvmapUnchanged,
          PlanReason::MirrorOccluded, PlanReason::ShadowsOff, PlanReason::PreviewScaled,
          PlanReason::MainSrgb})
        EXPECT_FALSE(dropsWhatTheSceneAsks(ordinary)) << ordinary;
    for (const PlanReason drop :
         {PlanReason::ShadowMapDoesNotFit, PlanReason::EnvmapDoesNotFit, PlanReason::MirrorViewLimit,
          PlanReason::MirrorNoPlane, PlanReason::PrefilterNoMap, PlanReason::MirrorNoTexture})
        EXPECT_TRUE(dropsWhatTheSceneAsks(drop)) << drop;
}

TEST(PlanReason, PreviewCodesAreNamedSo) {
    for (PlanReason code : everyCode())
        EXPECT_EQ(isPreview(code), toString(code).starts_with("preview-")) << code;
}

} // namespace
} // namespace speculum::render
