// Every kind of number a project holds is refused outside render/frame/SceneLimits.hpp, with its JSON path
// and the real cause, and accepted right at the limit; the inspector applies the same limits.
#include "editor/document/Properties.hpp"
#include "render/frame/SceneLimits.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QDir>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace speculum::document {
namespace {

std::string document(const std::string& body) {
    return R"({ "format": "speculum-scene", "version": 1, )" + body + "}";
}

std::string oneNode(const std::string& node) {
    return document(R"("nodes": [ )" + node + " ]");
}

base::Result<scene::SceneData> parse(const std::string& json) {
    std::vector<std::string> warnings;
    return scene::parseProject(QByteArray::fromStdString(json), QDir("/tmp"), warnings);
}

struct LimitCase {
    const char* label;
    std::string inside;               // loads
    std::string outside;              // refused
    std::vector<std::string> message; // substrings of the refusal
};

std::string sphereReflector(const std::string& parallax) {
    return oneNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "parallax": )" + parallax + " } }");
}

std::vector<LimitCase> limitCases() {
    return {
        {"camera position",
         document(R"("camera": { "position": [1e12, 0, 0], "target": [0, 0, 0] })"),
         document(R"("camera": { "position": [1.000001e12, 0, 0], "target": [0, 0, 0] })"),
         {"camera.position:", "1e+12", "1.000001e+12"}},
        {"camera target",
         document(R"("camera": { "target": [0, -1e12, 1], "up": [1, 0, 0] })"),
         document(R"("camera": { "target": [0, -2e12, 1], "up": [1, 0, 0] })"),
         {"camera.target:", "1e+12", "-2e+12"}},
        {"camera up",
         document(R"("camera": { "up": [0, 1e-9, 0] })"),
         document(R"("camera": { "up": [0, 1e-10, 0] })"),
         {"camera.up:", "1e-09"}},
        {"camera near",
         document(R"("camera": { "near": 1e-6, "far": 0.5 })"),
         document(R"("camera": { "near": 1e-9, "far": 0.5 })"),
         {"camera.near:", "1e-06", "1e-09"}},
        {"camera far/near",
         document(R"("camera": { "near": 0.0625, "far": 62500 })"),
         document(R"("camera": { "near": 1, "far": 1e9 })"),
         {"camera.far:", "1e+06 times near", "1e+09"}},
        {"camera far/near just over",
         document(R"("camera": { "near": 0.5, "far": 5e5 })"),
         document(R"("camera": { "near": 0.5, "far": 500001 })"),
         {"camera.far:", "depth"}},
        {"translate",
         oneNode(R"({ "transform": { "translate": [0, 1e12, 0] } })"),
         oneNode(R"({ "transform": { "translate": [0, 1.1e12, 0] } })"),
         {"nodes[0].transform.translate:", "1e+12", "1.1e+12"}},
        {"scale large",
         oneNode(R"({ "transform": { "scale": [1e9, -1e9, 1] } })"),
         oneNode(R"({ "transform": { "scale": [1, 1.5e9, 1] } })"),
         {"nodes[0].transform.scale:", "1e-09..1e+09", "1.5e+09"}},
        {"scale small",
         oneNode(R"({ "transform": { "scale": [1e-9, 1, -1e-9] } })"),
         oneNode(R"({ "transform": { "scale": [1, 1, 1e-38] } })"),
         {"nodes[0].transform.scale:", "1e-38"}},
        {"scale huge",
         oneNode(R"({ "transform": { "scale": [2, 2, 2] } })"),
         oneNode(R"({ "transform": { "scale": [1e19, 1, 1] } })"),
         {"nodes[0].transform.scale:", "1e+19"}},
        {"light intensity",
         oneNode(R"({ "light": { "intensity": 1e9 } })"),
         oneNode(R"({ "light": { "intensity": 1e39 } })"),
         {"nodes[0].light.intensity:", "at most 1e+09", "1e+39"}},
        {"light intensity beyond double",
         oneNode(R"({ "light": { "intensity": 1e9 } })"),
         oneNode(R"({ "light": { "intensity": 1e400 } })"),
         {"line 1, column", "illegal number"}}, // Qt's parser refuses what a double cannot hold
        {"material diffuse",
         oneNode(R"({ "material": { "diffuse": 1e9 } })"),
         oneNode(R"({ "material": { "diffuse": 1.01e9 } })"),
         {"nodes[0].material.diffuse:", "1e+09"}},
        {"material ambient",
         oneNode(R"({ "material": { "ambient": 1e9 } })"),
         oneNode(R"({ "material": { "ambient": 1e39 } })"),
         {"nodes[0].material.ambient:", "1e+39"}},
        {"material specular",
         oneNode(R"({ "material": { "specular": 1e9 } })"),
         oneNode(R"({ "material": { "specular": 1e30 } })"),
         {"nodes[0].material.specular:", "1e+30"}},
        {"mirror size large",
         oneNode(R"({ "mirror": { "size": [1e12, 1] } })"),
         oneNode(R"({ "mirror": { "size": [1, 2e12] } })"),
         {"nodes[0].mirror.size:", "2e+12"}},
        {"mirror size small",
         oneNode(R"({ "mirror": { "size": [1e-9, 1] } })"),
         oneNode(R"({ "mirror": { "size": [1e-300, 1] } })"),
         {"nodes[0].mirror.size:", "1e-300"}},
        {"bounce height",
         oneNode(R"({ "animation": { "bounce": { "height": -1e12 } } })"),
         oneNode(R"({ "animation": { "bounce": { "height": 1e308 } } })"),
         {"nodes[0].animation.bounce.height:", "1e+308"}},
        {"bounce period short",
         oneNode(R"({ "animation": { "bounce": { "period": 1e-3 } } })"),
         oneNode(R"({ "animation": { "bounce": { "period": 9e-4 } } })"),
         {"nodes[0].animation.bounce.period:", "0.001..1e+09 seconds", "9e-04"}},
        {"bounce period long",
         oneNode(R"({ "animation": { "bounce": { "period": 1e9 } } })"),
         oneNode(R"({ "animation": { "bounce": { "period": 1e300 } } })"),
         {"nodes[0].animation.bounce.period:", "1e+300"}},
        {"orbit period",
         oneNode(R"({ "animation": { "orbit": { "period": 1e-3 } } })"),
         oneNode(R"({ "animation": { "orbit": { "period": 5e-324 } } })"),
         {"nodes[0].animation.orbit.period:", "0.001", "5e-324"}},
        {"orbit radius",
         oneNode(R"({ "animation": { "orbit": { "radius": 1e12 } } })"),
         oneNode(R"({ "animation": { "orbit": { "radius": 1e13 } } })"),
         {"nodes[0].animation.orbit.radius:", "1e+13"}},
        {"orbit center",
         oneNode(R"({ "animation": { "orbit": { "center": [0, 0, -1e12], "radius": 0 } } })"),
         oneNode(R"({ "animation": { "orbit": { "center": [0, 0, 1e39] } } })"),
         {"nodes[0].animation.orbit.center:", "1e+39"}},
        {"parallax radius",
         sphereReflector(R"({ "shape": "sphere", "radius": 1e12 })"),
         sphereReflector(R"({ "shape": "sphere", "radius": 1e20 })"),
         {"nodes[0].reflector.parallax.radius:", "1e+20"}},
        {"parallax box",
         sphereReflector(R"({ "shape": "box", "min": [-1e-9, -1, -1], "max": [1e12, 1, 1] })"),
         sphereReflector(R"({ "shape": "box", "min": [-1e-20, -1, -1], "max": [1, 1, 1] })"),
         {"nodes[0].reflector.parallax.min:", "1e-20"}},
        {"world scale, nested",
         document(R"("nodes": [ { "name": "outer", "transform": { "scale": [1e5, 1e5, 1e5] },
                      "children": [ { "name": "inner", "transform": { "scale": [1e4, 1e4, 1e4] } } ] } ])"),
         document(R"("nodes": [ { "name": "outer", "transform": { "scale": [1e5, 1e5, 1e5] },
                      "children": [ { "name": "inner", "transform": { "scale": [1e5, 1, 1] } } ] } ])"),
         {"nodes[0].children[0]:", "node 'inner'", "world scale", "1e+10", "more than 1e+09"}},
        {"world scale, nested small",
         document(R"("nodes": [ { "transform": { "scale": [1e-5, 1, 1] },
                      "children": [ { "transform": { "scale": [1e-3, 1, 1] } } ] } ])"),
         document(R"("nodes": [ { "transform": { "scale": [1e-5, 1, 1] },
                      "children": [ { "transform": { "scale": [1e-5, 1, 1] } } ] } ])"),
         {"nodes[0].children[0]:", "the unnamed node", "world scale", "less than 1e-09"}},
        {"world position",
         document(R"("nodes": [ { "name": "big", "transform": { "scale": [10, 10, 10] },
                      "children": [ { "name": "far", "transform": { "translate": [1e11, 0, 0] } } ] } ])"),
         document(R"("nodes": [ { "name": "big", "transform": { "scale": [10, 10, 10] },
                      "children": [ { "name": "far", "transform": { "translate": [2e11, 0, 0] } } ] } ])"),
         {"nodes[0].children[0]:", "node 'far'", "world position", "2e+12"}},
        {"world position, animated",
         oneNode(
             R"({ "transform": { "translate": [0, 5e11, 0] }, "animation": { "bounce": { "height": 5e11 } } })"),
         oneNode(
             R"({ "transform": { "translate": [0, 5e11, 0] }, "animation": { "bounce": { "height": 6e11 } } })"),
         {"nodes[0]:", "world position", "1.1e+12"}},
    };
}

TEST(ProjectLimits, EachKindOfNumberLoadsAtItsLimitAndIsRefusedBeyondIt) {
    for (const LimitCase& c : limitCases()) {
        const auto inside = parse(c.inside);
        EXPECT_TRUE(inside.ok()) << c.label << " (inside): " << inside.error();
        const auto outside = parse(c.outside);
        ASSERT_FALSE(outside.ok()) << c.label << " (outside) loaded";
        for (const std::string& part : c.message) {
            EXPECT_NE(outside.error().find(part), std::string::npos)
                << c.label << ": \"" << outside.error() << "\" lacks \"" << part << "\"";
        }
        EXPECT_EQ(outside.error().find('\n'), std::string::npos) << c.label;
    }
}

TEST(ProjectLimits, FiveNestedLevelsOfLargeScalesAreRefusedNamingTheNode) {
    // Each 1e9 is allowed alone; composed they would reach 1e45, beyond float.
    std::string nodes = R"({ "name": "level 5", "transform": { "scale": [1e9, 1e9, 1e9] } })";
    for (int level = 4; level >= 1; --level) {
        nodes = R"({ "name": "level )" + std::to_string(level) +
                R"(", "transform": { "scale": [1e9, 1e9, 1e9] }, "children": [ )" + nodes + " ] }";
    }
    const auto result = parse(document(R"("nodes": [ )" + nodes + " ]"));
    ASSERT_FALSE(result.ok());
    // The first node whose composed scale overflows the limit is the second level.
    EXPECT_NE(result.error().find("nodes[0].children[0]: node 'level 2'"), std::string::npos)
        << result.error();
    EXPECT_NE(result.error().find("1e+18"), std::string::npos) << result.error();
}

TEST(ProjectLimits, LargeButCancellingNestedScalesLoad) {
    const auto result = parse(document(R"("nodes": [ { "transform": { "scale": [1e9, 1e9, 1e9] },
        "children": [ { "transform": { "scale": [0.5, 0.5, 0.5], "translate": [1e3, 0, 0] },
          "children": [ { "transform": { "scale": [2, 2, 2] } } ] } ] } ])"));
    EXPECT_TRUE(result.ok()) << result.error();
}

TEST(ProjectLimits, AValueAtEveryLimitSavesAndLoadsBack) {
    const std::string json = document(R"("camera": { "position": [1e12, 0, 0], "target": [-1e12, 0, 0],
        "near": 1e-6, "far": 0.5 },
      "nodes": [ { "transform": { "translate": [0, 0, -1e12], "scale": [1e9, 1e-9, -1] },
                   "light": { "intensity": 1e9 }, "material": { "diffuse": 1e9 },
                   "animation": { "orbit": { "center": [0, 0, 0], "radius": 0, "period": 1e9 } } } ])");
    const auto first = parse(json);
    ASSERT_TRUE(first.ok()) << first.error();
    const QByteArray saved = scene::serializeProject(*first, QDir("/tmp"));
    std::vector<std::string> warnings;
    const auto second = scene::parseProject(saved, QDir("/tmp"), warnings);
    ASSERT_TRUE(second.ok()) << second.error();
    EXPECT_EQ(*second, *first);
}

// ---- the inspector: the same limits, refused with a message, never clamped ----

scene::NodeData fullNode() {
    scene::NodeData d;
    d.name = "n";
    d.material = scene::MaterialComponent{};
    d.light = scene::LightComponent{};
    d.mirror = scene::MirrorComponent{};
    d.animation = scene::AnimationComponent{scene::BounceAnimation{}, scene::OrbitAnimation{}};
    return d;
}

TEST(ProjectLimits, TheInspectorRefusesWhatTheReaderRefuses) {
    struct Case {
        const char* key;
        QVariant inside;
        QVariant outside;
        const char* mentions;
    };
    const double c = render::kMaxCoordinate;
    const Case cases[] = {
        {"transform.translate", QVariantList{c, 0.0, 0.0}, QVariantList{c * 1.1, 0.0, 0.0}, "Translate"},
        {"transform.scale", QVariantList{1e9, 1e-9, -1.0}, QVariantList{1e19, 1.0, 1.0}, "1e+19"},
        {"transform.scale", QVariantList{1.0, 1.0, 1.0}, QVariantList{1.0, 1e-38, 1.0}, "1e-38"},
        {"light.intensity", 1e9, 1e39, "Intensity"},
        {"material.diffuse", 1e9, 2e9, "Diffuse"},
        {"material.ambient", 1e9, 1e39, "Ambient"},
        {"material.specular", 1e9, 1e39, "Specular"},
        {"mirror.size", QVariantList{c, 1e-9}, QVariantList{1.0, 1e-12}, "extents"},
        {"animation.bounce.height", -(c - 10), 1e308, "Bounce height"},
        {"animation.bounce.period", 1e-3, 5e-324, "Bounce period"},
        {"animation.orbit.period", 1e9, 1e10, "Orbit period"},
        {"animation.orbit.radius", c - 10, -1.0, "Orbit radius"},
        {"animation.orbit.center", QVariantList{0.0, c - 10, 0.0}, QVariantList{0.0, 1e39, 0.0},
         "Orbit centre"},
    };
    for (const Case& k : cases) {
        const auto* p = findNodeProperty(QString::fromLatin1(k.key));
        ASSERT_TRUE(p) << k.key;
        scene::NodeData d = fullNode();
        const auto in = p->set(d, k.inside);
        EXPECT_TRUE(in.ok()) << k.key << ": " << in.error();
        const scene::NodeData before = d;
        const auto out = p->set(d, k.outside);
        ASSERT_FALSE(out.ok()) << k.key << " accepted " << k.outside.toString().toStdString();
        EXPECT_NE(out.error().find(k.mentions), std::string::npos) << k.key << ": " << out.error();
        EXPECT_TRUE(d == before) << k.key << ": refused but changed";
        // What the inspector accepted, the reader loads.
        scene::SceneData scene;
        scene.nodes.push_back(scene::NodeTree{before, {}});
        std::vector<std::string> warnings;
        const auto loaded =
            scene::parseProject(scene::serializeProject(scene, QDir("/tmp")), QDir("/tmp"), warnings);
        EXPECT_TRUE(loaded.ok()) << k.key << ": " << loaded.error();
    }
}

TEST(ProjectLimits, TheInspectorAppliesTheReadersCameraRules) {
    scene::CameraData camera;
    const auto* near = findCameraProperty(QStringLiteral("camera.near"));
    const auto* far = findCameraProperty(QStringLiteral("camera.far"));
    const auto* position = findCameraProperty(QStringLiteral("camera.position"));
    ASSERT_TRUE(near && far && position);
    const auto tiny = near->set(camera, 1e-9);
    ASSERT_FALSE(tiny.ok());
    EXPECT_NE(tiny.error().find("Near"), std::string::npos) << tiny.error();
    const auto deep = far->set(camera, camera.near * 1e7);
    ASSERT_FALSE(deep.ok());
    EXPECT_NE(deep.error().find("Far"), std::string::npos) << deep.error();
    EXPECT_NE(deep.error().find("times near"), std::string::npos) << deep.error();
    const auto huge = position->set(camera, QVariantList{1e300, 0.0, 0.0});
    ASSERT_FALSE(huge.ok());
    EXPECT_NE(huge.error().find("Position"), std::string::npos) << huge.error();
    EXPECT_TRUE(camera == scene::CameraData{}) << "refused edits changed the camera";
    ASSERT_TRUE(near->set(camera, 0.5).ok());
    EXPECT_TRUE(far->set(camera, 5e5).ok()) << "far = 1e6 × near is the limit itself";
}

} // namespace
} // namespace speculum::document
