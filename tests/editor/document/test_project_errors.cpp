#include "editor/document/ProjectFile.hpp"

#include <QJsonArray>
#include <QJsonObject>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace speculum::document {
namespace {

// Every validation error names where it is, so a user can find it in the file.

struct BadCase {
    const char* label;
    std::string json;
    std::vector<std::string> expected; // substrings of the message
};

std::string document(const std::string& body) {
    return R"({ "format": "speculum-scene", "version": 1, )" + body + "}";
}

// Two valid nodes first, so the bad one is nodes[2].
std::string thirdNode(const std::string& node) {
    return document(R"("nodes": [ { "name": "a" }, { "name": "b", "mesh": { "builtin": "box" } }, )" + node +
                    "]");
}

std::string message(const std::string& json) {
    std::vector<std::string> warnings = {"earlier warning"};
    auto result = parseProject(QByteArray::fromStdString(json), QDir("/tmp"), warnings);
    EXPECT_EQ(warnings.size(), 1u) << "a failed load adds no warnings";
    return result.ok() ? std::string("<loaded>") : result.error();
}

std::vector<BadCase> badCases() {
    return {
        {"format missing", R"({ "version": 1 })", {"format: missing"}},
        {"format wrong",
         R"({ "format": "blender", "version": 1 })",
         {"format: expected \"speculum-scene\"", "blender"}},
        {"version missing", R"({ "format": "speculum-scene" })", {"version: missing"}},
        {"version newer",
         R"({ "format": "speculum-scene", "version": 3 })",
         {"version: version 3 is newer than this speculum (reads up to 1)"}},
        {"version zero", R"({ "format": "speculum-scene", "version": 0 })", {"version: must be at least 1"}},
        {"version fraction",
         R"({ "format": "speculum-scene", "version": 1.5 })",
         {"version: expected an integer", "1.5"}},
        {"version next",
         R"({ "format": "speculum-scene", "version": 2 })",
         {"version: version 2 is newer", "reads up to 1"}},
        {"version far future",
         R"({ "format": "speculum-scene", "version": 1e12 })",
         {"version: version 1e+12 is newer", "reads up to 1"}},
        {"version negative",
         R"({ "format": "speculum-scene", "version": -2 })",
         {"version: must be at least 1", "-2"}},
        {"version text",
         R"({ "format": "speculum-scene", "version": "1" })",
         {"version: expected an integer", "\"1\""}},
        {"version null",
         R"({ "format": "speculum-scene", "version": null })",
         {"version: expected an integer", "null"}},
        {"version array",
         R"({ "format": "speculum-scene", "version": [1] })",
         {"version: expected an integer", "an array"}},
        {"top level array", R"([1, 2])", {"expected a JSON object"}},
        {"settings not object", document(R"("settings": 3)"), {"settings: expected an object"}},
        {"background short",
         document(R"("settings": { "background": [0, 1] })"),
         {"settings.background: expected 3 numbers"}},
        {"background range",
         document(R"("settings": { "background": [0, 1, 2] })"),
         {"settings.background:", "0..1"}},
        {"mirrorDepth range",
         document(R"("settings": { "mirrorDepth": 17 })"),
         {"settings.mirrorDepth: must be in 0..16, got 17"}},
        {"mirrorDepth fraction",
         document(R"("settings": { "mirrorDepth": 2.5 })"),
         {"settings.mirrorDepth: expected an integer"}},
        {"ambient type",
         document(R"("settings": { "ambient": "bright" })"),
         {"settings.ambient: expected a number"}},
        {"ambient range",
         document(R"("settings": { "ambient": -0.1 })"),
         {"settings.ambient: must be in 0..1"}},
        {"fovY zero", document(R"("camera": { "fovY": 0 })"), {"camera.fovY: must be between 0 and 180"}},
        {"fovY 180", document(R"("camera": { "fovY": 180 })"), {"camera.fovY:"}},
        {"near zero", document(R"("camera": { "near": 0 })"), {"camera.near: must be greater than 0"}},
        {"far below near",
         document(R"("camera": { "near": 1, "far": 0.5 })"),
         {"camera.far: must be greater than near"}},
        {"position vector",
         document(R"("camera": { "position": [0, "a", 0] })"),
         {"camera.position: expected 3 numbers"}},
        {"target equals position",
         document(R"("camera": { "position": [1, 2, 3], "target": [1, 2, 3] })"),
         {"camera.target: must differ"}},
        {"up parallel", document(R"("camera": { "up": [0, 0, 1] })"), {"camera.up:", "parallel"}},
        {"nodes not array", document(R"("nodes": {})"), {"nodes: expected an array"}},
        {"node not object", thirdNode("7"), {"nodes[2]: expected an object"}},
        {"name type", thirdNode(R"({ "name": 5 })"), {"nodes[2].name: expected a string"}},
        {"transform type", thirdNode(R"({ "transform": [] })"), {"nodes[2].transform: expected an object"}},
        {"scale zero",
         thirdNode(R"({ "transform": { "scale": [1, 0, 1] } })"),
         {"nodes[2].transform.scale:", "non-zero"}},
        {"rotate short",
         thirdNode(R"({ "transform": { "rotate": [90] } })"),
         {"nodes[2].transform.rotate: expected 3 numbers"}},
        {"mesh empty", thirdNode(R"({ "mesh": {} })"), {"nodes[2].mesh: expected \"builtin\" or \"file\""}},
        {"mesh both",
         thirdNode(R"({ "mesh": { "builtin": "box", "file": "a.obj" } })"),
         {"nodes[2].mesh: has both"}},
        {"mesh builtin unknown",
         thirdNode(R"({ "mesh": { "builtin": "cone" } })"),
         {"nodes[2].mesh.builtin: unknown builtin mesh \"cone\" (expected teapot, sphere, box or plane)"}},
        {"tessellation range",
         thirdNode(R"({ "mesh": { "builtin": "teapot", "tessellation": 65 } })"),
         {"nodes[2].mesh.tessellation: must be in 1..64, got 65"}},
        {"tessellation zero",
         thirdNode(R"({ "mesh": { "builtin": "teapot", "tessellation": 0 } })"),
         {"nodes[2].mesh.tessellation:"}},
        {"file tessellation",
         thirdNode(R"({ "mesh": { "file": "a.obj", "tessellation": 3 } })"),
         {"nodes[2].mesh.tessellation: only built-in"}},
        {"file empty", thirdNode(R"({ "mesh": { "file": "" } })"), {"nodes[2].mesh.file:", "empty"}},
        {"material color",
         thirdNode(R"({ "material": { "color": [1, 1, 1, 1] } })"),
         {"nodes[2].material.color: expected 3 numbers"}},
        {"material diffuse",
         thirdNode(R"({ "material": { "diffuse": -1 } })"),
         {"nodes[2].material.diffuse: must not be negative"}},
        {"material specular",
         thirdNode(R"({ "material": { "specular": true } })"),
         {"nodes[2].material.specular: expected a number"}},
        {"material shininess",
         thirdNode(R"({ "material": { "shininess": -2 } })"),
         {"nodes[2].material.shininess:"}},
        {"material emission",
         thirdNode(R"({ "material": { "emission": [2, 0, 0] } })"),
         {"nodes[2].material.emission:"}},
        {"material texture",
         thirdNode(R"({ "material": { "texture": 3 } })"),
         {"nodes[2].material.texture: expected a string"}},
        {"light type",
         thirdNode(R"({ "light": { "type": "lamp" } })"),
         {"nodes[2].light.type: unknown light type \"lamp\" (expected point, directional or spot)"}},
        {"light intensity", thirdNode(R"({ "light": { "intensity": -1 } })"), {"nodes[2].light.intensity:"}},
        {"spot angle",
         thirdNode(R"({ "light": { "type": "spot", "spotAngle": 95 } })"),
         {"nodes[2].light.spotAngle:"}},
        {"spot blend",
         thirdNode(R"({ "light": { "type": "spot", "spotBlend": 1.5 } })"),
         {"nodes[2].light.spotBlend:"}},
        {"mapSize power",
         thirdNode(R"({ "light": { "shadows": { "mapSize": 1000 } } })"),
         {"nodes[2].light.shadows.mapSize: must be a power of two in 16..16384, got 1000"}},
        {"mapSize big",
         thirdNode(R"({ "light": { "shadows": { "mapSize": 32768 } } })"),
         {"nodes[2].light.shadows.mapSize:"}},
        {"mapSize small",
         thirdNode(R"({ "light": { "shadows": { "mapSize": 8 } } })"),
         {"nodes[2].light.shadows.mapSize:"}},
        {"pcf even",
         thirdNode(R"({ "light": { "shadows": { "pcf": 4 } } })"),
         {"nodes[2].light.shadows.pcf: must be an odd kernel width in 1..15, got 4"}},
        {"pcf big",
         thirdNode(R"({ "light": { "shadows": { "pcf": 17 } } })"),
         {"nodes[2].light.shadows.pcf:"}},
        {"shadows type",
         thirdNode(R"({ "light": { "shadows": true } })"),
         {"nodes[2].light.shadows: expected an object"}},
        {"mirror size",
         thirdNode(R"({ "mirror": { "size": [4] } })"),
         {"nodes[2].mirror.size: expected 2 numbers"}},
        {"mirror size zero",
         thirdNode(R"({ "mirror": { "size": [4, 0] } })"),
         {"nodes[2].mirror.size:", "greater than 0"}},
        {"mirror reflectivity",
         thirdNode(R"({ "mirror": { "reflectivity": 1.5 } })"),
         {"nodes[2].mirror.reflectivity: must be in 0..1, got 1.5"}},
        {"mirror technique",
         thirdNode(R"({ "mirror": { "technique": "raytrace" } })"),
         {"nodes[2].mirror.technique: unknown mirror technique \"raytrace\" (expected stencil or texture)"}},
        {"reflector map",
         thirdNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "map": "sphere" } })"),
         {"nodes[2].reflector.map: unknown reflector map \"sphere\" (expected cube, dual-paraboloid or "
          "tennis-ball)"}},
        {"reflector resolution",
         thirdNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "resolution": 4 } })"),
         {"nodes[2].reflector.resolution: must be in 8..8192, got 4"}},
        {"reflector reflectivity",
         thirdNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "reflectivity": -1 } })"),
         {"nodes[2].reflector.reflectivity:"}},
        {"reflector fresnel",
         thirdNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "fresnel": 1 } })"),
         {"nodes[2].reflector.fresnel: expected true or false"}},
        {"reflector fill",
         thirdNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "fill": "warp" } })"),
         {"nodes[2].reflector.fill: unknown reflector fill \"warp\" (expected direct or resampled)"}},
        {"reflector update",
         thirdNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "update": "never" } })"),
         {"nodes[2].reflector.update: unknown reflector update \"never\" (expected always, on-change or "
          "once)"}},
        {"reflector mirror depth",
         thirdNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "mirrorDepth": 17 } })"),
         {"nodes[2].reflector.mirrorDepth: must be in 0..16, got 17"}},
        {"parallax without shape",
         thirdNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "parallax": { "radius": 2 } } })"),
         {"nodes[2].reflector.parallax: expected a \"shape\""}},
        {"parallax shape",
         thirdNode(
             R"({ "mesh": { "builtin": "sphere" }, "reflector": { "parallax": { "shape": "cone" } } })"),
         {"nodes[2].reflector.parallax.shape: unknown parallax shape \"cone\" (expected sphere or box)"}},
        {"parallax radius",
         thirdNode(
             R"({ "mesh": { "builtin": "sphere" }, "reflector": { "parallax": { "shape": "sphere", "radius": 0 } } })"),
         {"nodes[2].reflector.parallax.radius: must be greater than 0"}},
        {"parallax box",
         thirdNode(R"({ "mesh": { "builtin": "sphere" },
                        "reflector": { "parallax": { "shape": "box", "min": [1, -1, -1], "max": [2, 1, 1] } } })"),
         {"nodes[2].reflector.parallax.min:", "contain the capture point"}},
        {"parallax box size",
         thirdNode(R"({ "mesh": { "builtin": "sphere" },
                        "reflector": { "parallax": { "shape": "box", "min": [-1, -1] } } })"),
         {"nodes[2].reflector.parallax.min: expected 3 numbers"}},
        {"reflector without mesh", thirdNode(R"({ "reflector": {} })"), {"nodes[2].reflector: needs a mesh"}},
        {"second reflector",
         document(R"("nodes": [ { "mesh": { "builtin": "sphere" }, "reflector": {} },
                                { "children": [ { "mesh": { "builtin": "box" }, "reflector": {} } ] } ])"),
         {"nodes[1].children[0].reflector: a scene has at most one reflector (the first is nodes[0])"}},
        {"bounce period",
         thirdNode(R"({ "animation": { "bounce": { "period": 0 } } })"),
         {"nodes[2].animation.bounce.period: must be greater than 0"}},
        {"bounce height",
         thirdNode(R"({ "animation": { "bounce": { "height": "high" } } })"),
         {"nodes[2].animation.bounce.height: expected a number"}},
        {"orbit center",
         thirdNode(R"({ "animation": { "orbit": { "center": [0, 0] } } })"),
         {"nodes[2].animation.orbit.center: expected 3 numbers"}},
        {"orbit radius",
         thirdNode(R"({ "animation": { "orbit": { "radius": -1 } } })"),
         {"nodes[2].animation.orbit.radius:"}},
        {"orbit period",
         thirdNode(R"({ "animation": { "orbit": { "period": -6 } } })"),
         {"nodes[2].animation.orbit.period:"}},
        {"children type", thirdNode(R"({ "children": {} })"), {"nodes[2].children: expected an array"}},
        {"nested light type",
         document(
             R"("nodes": [ { "name": "p", "children": [ { "name": "c0" }, { "light": { "type": "lamp" } } ] } ])"),
         {"nodes[0].children[1].light.type: unknown light type \"lamp\" (expected point, directional or "
          "spot)"}},
    };
}

TEST(ProjectErrors, EveryValidationErrorNamesItsJsonPath) {
    for (const BadCase& c : badCases()) {
        const std::string m = message(c.json);
        for (const std::string& part : c.expected) {
            EXPECT_NE(m.find(part), std::string::npos)
                << c.label << ": \"" << m << "\" lacks \"" << part << "\"";
        }
    }
}

TEST(ProjectErrors, SyntaxErrorsGiveLineAndColumn) {
    const std::string json = "{\n  \"format\": \"speculum-scene\",\n  \"version\": 1\n  \"nodes\": []\n}\n";
    const std::string m = message(json);
    EXPECT_NE(m.find("line 4, column"), std::string::npos) << m;
    EXPECT_NE(m.find("JSON syntax error"), std::string::npos) << m;

    const std::string unicode =
        "{ \"format\": \"speculum-scene\",\n\"nodes\": [ { \"name\": \"\u00e9\u00e9\" ,, } ] }";
    const std::string m2 = message(unicode);
    EXPECT_NE(m2.find("line 2, column"), std::string::npos) << m2;
}

TEST(ProjectErrors, EmptyFileIsReported) {
    EXPECT_NE(message("  \n").find("empty"), std::string::npos);
}

TEST(ProjectErrors, MinimalDocumentLoadsWithDefaults) {
    std::vector<std::string> warnings;
    auto scene = parseProject(R"({ "format": "speculum-scene", "version": 1 })", QDir("/tmp"), warnings);
    ASSERT_TRUE(scene.ok()) << scene.error();
    EXPECT_EQ(*scene, SceneData{});
    auto sphere = parseProject(QByteArray::fromStdString(thirdNode(R"({ "mesh": { "builtin": "sphere" } })")),
                               QDir("/tmp"), warnings);
    ASSERT_TRUE(sphere.ok()) << sphere.error();
    EXPECT_EQ(sphere->nodes[2].data.mesh->tessellation, defaultTessellation(BuiltinMesh::Sphere));
    EXPECT_TRUE(warnings.empty());
}

} // namespace
} // namespace speculum::document

namespace speculum::document {
namespace {

// Version 1 is the first format: the upgrade step has nothing to convert, and the header check is what
// every file passes before the readers see it.
TEST(ProjectVersion, CurrentVersionFilesPassTheHeaderAndUpgradeUnchanged) {
    const QJsonObject root{
        {"format", "speculum-scene"}, {"version", kProjectFormatVersion}, {"nodes", QJsonArray{}}};
    const auto version = readProjectHeader(root);
    ASSERT_TRUE(version.ok()) << version.error();
    EXPECT_EQ(*version, kProjectFormatVersion);
    QJsonObject upgraded = root;
    upgradeToCurrentVersion(upgraded, *version);
    EXPECT_EQ(upgraded, root);
}

} // namespace
} // namespace speculum::document
