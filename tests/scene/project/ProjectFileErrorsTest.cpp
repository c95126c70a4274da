#include "scene/project/ProjectFile.hpp"

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
    auto result = scene::parseProject(QByteArray::fromStdString(json), QDir("/tmp"), warnings);
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
        {"simplifyReflections type",
         document(R"("settings": { "simplifyReflections": "yes" })"),
         {"settings.simplifyReflections: expected true or false"}},
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
        {"editorView not object", document(R"("editorView": [0, 0, 1])"), {"editorView: expected an object"}},
        {"editorView position missing",
         document(R"("editorView": { "target": [0, 0, 0] })"),
         {"editorView.position: missing"}},
        {"editorView target missing",
         document(R"("editorView": { "position": [0, 0, 1] })"),
         {"editorView.target: missing"}},
        {"editorView position type",
         document(R"("editorView": { "position": [0, "a", 0], "target": [0, 0, 0] })"),
         {"editorView.position: expected 3 numbers"}},
        {"editorView position short",
         document(R"("editorView": { "position": [0, 1], "target": [0, 0, 0] })"),
         {"editorView.position: expected 3 numbers"}},
        {"editorView position null",
         document(R"("editorView": { "position": null, "target": [0, 0, 0] })"),
         {"editorView.position: expected 3 numbers"}},
        {"editorView position range",
         document(R"("editorView": { "position": [1e300, 0, 0], "target": [0, 0, 0] })"),
         {"editorView.position: coordinates must be within"}},
        {"editorView target type",
         document(R"("editorView": { "position": [0, 0, 1], "target": "origin" })"),
         {"editorView.target: expected 3 numbers"}},
        {"editorView target range",
         document(R"("editorView": { "position": [0, 0, 1], "target": [0, -1e200, 0] })"),
         {"editorView.target: coordinates must be within"}},
        {"editorView target equals position",
         document(R"("editorView": { "position": [1, 2, 3], "target": [1, 2, 3] })"),
         {"editorView.target: must differ from the view position"}},
        {"editorView target too close",
         document(R"("editorView": { "position": [1e11, 0, 0], "target": [100000000000.00002, 0, 1e-6] })"),
         {"editorView.target: must differ from the view position by at least"}},
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
         {"nodes[2].mirror.technique: unknown mirror technique \"raytrace\" (expected stencil, texture or "
          "screen-space)"}},
        {"reflector map",
         thirdNode(R"({ "mesh": { "builtin": "sphere" }, "reflector": { "map": "sphere" } })"),
         {"nodes[2].reflector.map: unknown reflector map \"sphere\" (expected cube, dual-paraboloid, "
          "tennis-ball or octahedral)"}},
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
         {"nodes[2].reflector.update: unknown reflector update \"never\" (expected always, on-change, "
          "once or time-sliced)"}},
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
        {"reflector bounces",
         document(R"("settings": { "reflectorBounces": 9 })"),
         {"settings.reflectorBounces: must be in 0..4, got 9"}},
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

// The editor's view has no up vector of its own: a view straight down the camera's up loads (a top view),
// and an error in it never names the scene camera.
TEST(ProjectErrors, TheEditorViewIsCheckedOnItsOwn) {
    std::vector<std::string> warnings;
    auto top = scene::parseProject(QByteArray::fromStdString(document(
                                       R"("editorView": { "position": [0, 10, 0], "target": [0, 0, 0] })")),
                                   QDir("/tmp"), warnings);
    ASSERT_TRUE(top.ok()) << top.error();
    ASSERT_TRUE(top->editorView.has_value());
    EXPECT_EQ(top->editorView->position, glm::dvec3(0, 10, 0));
    EXPECT_EQ(top->camera, scene::CameraData{});
    EXPECT_TRUE(warnings.empty());

    const std::string m = message(document(R"("camera": { "position": [0, 0, 5] },
        "editorView": { "position": [0, 0, 5], "target": [0, 0, 5] })"));
    EXPECT_EQ(m.rfind("editorView.target:", 0), 0u) << m;
    EXPECT_EQ(m.find("camera"), std::string::npos) << m;
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
    auto scene =
        scene::parseProject(R"({ "format": "speculum-scene", "version": 1 })", QDir("/tmp"), warnings);
    ASSERT_TRUE(scene.ok()) << scene.error();
    EXPECT_EQ(*scene, scene::SceneData{});
    auto sphere =
        scene::parseProject(QByteArray::fromStdString(thirdNode(R"({ "mesh": { "builtin": "sphere" } })")),
                            QDir("/tmp"), warnings);
    ASSERT_TRUE(sphere.ok()) << sphere.error();
    EXPECT_EQ(sphere->nodes[2].data.mesh->tessellation,
              scene::defaultTessellation(scene::BuiltinMesh::Sphere));
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
        {"format", "speculum-scene"}, {"version", scene::kProjectFormatVersion}, {"nodes", QJsonArray{}}};
    const auto version = scene::readProjectHeader(root);
    ASSERT_TRUE(version.ok()) << version.error();
    EXPECT_EQ(*version, scene::kProjectFormatVersion);
    QJsonObject upgraded = root;
    scene::upgradeToCurrentVersion(upgraded, *version);
    EXPECT_EQ(upgraded, root);
}

} // namespace
} // namespace speculum::document

// ---- hostile text, repeated keys and paths that are not regular files ----

#include "editor/document/SweepResults.hpp"
#include "support/DocumentTestSupport.hpp"

#include <atomic>
#include <chrono>
#include <fcntl.h>
#include <memory>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace speculum::document {
namespace {

bool hasRawControl(const std::string& s) {
    for (const char c : s) {
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
            return true;
        }
    }
    return false;
}

std::string bad(const std::string& json) {
    std::vector<std::string> warnings;
    auto result = scene::parseProject(QByteArray::fromStdString(json), QDir("/tmp"), warnings);
    return result.ok() ? std::string("<loaded>") : result.error();
}

std::string sceneWith(const std::string& body) {
    return R"({ "format": "speculum-scene", "version": 1, )" + body + "}";
}

TEST(ProjectMessages, ControlCharactersInANodeNameAreEscapedOnOneLine) {
    // A name that would end the message line and forge one of its own, in a node the reader refuses.
    const std::string m = bad(sceneWith(R"("nodes": [ { "name": "evil\n\u001b[2Kspeculum: error: forged\r",
        "transform": { "scale": [1e9, 1, 1] },
        "children": [ { "transform": { "scale": [1e9, 1, 1] } } ] } ])"));
    // The child is refused; its own name is empty, so the parent's name is what a nested message names.
    const std::string parentNamed = bad(sceneWith(R"("nodes": [ { "transform": { "scale": [1e9, 1, 1] },
        "children": [ { "name": "evil\n\u001b[2Kspeculum: error: forged\r", "transform": { "scale": [2, 1, 1] } } ] } ])"));
    for (const std::string& message : {m, parentNamed}) {
        EXPECT_FALSE(hasRawControl(message)) << message;
    }
    EXPECT_NE(parentNamed.find("node 'evil\\n\\x1b[2Kspeculum: error: forged\\r'"), std::string::npos)
        << parentNamed;
    EXPECT_NE(parentNamed.find("nodes[0].children[0]:"), std::string::npos) << parentNamed;
}

TEST(ProjectMessages, ControlCharactersInStringValuesAreEscapedOnOneLine) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {sceneWith(R"("nodes": [ { "light": { "type": "lamp\nspeculum: error: x\u001b[0m" } } ])"),
         "\"lamp\\nspeculum: error: x\\x1b[0m\""},
        {sceneWith(R"("nodes": [ { "mesh": { "builtin": "\u0007bell\u2028" } } ])"), "\\x07bell\\u2028"},
        {sceneWith(R"("nodes": [ { "material": { "alphaMode": "\u001b]0;title\u0007" } } ])"),
         "\\x1b]0;title\\x07"},
        {R"({ "format": "speculum\n\u001bscene", "version": 1 })", "speculum\\n\\x1bscene"},
    };
    for (const auto& [json, shown] : cases) {
        const std::string m = bad(json);
        EXPECT_FALSE(hasRawControl(m)) << m;
        EXPECT_NE(m.find(shown), std::string::npos) << m << " lacks " << shown;
    }
    // A very long value is shortened, not echoed whole.
    const std::string longType =
        bad(sceneWith(R"("nodes": [ { "light": { "type": ")" + std::string(5000, 'x') + R"(" } } ])"));
    EXPECT_LT(longType.size(), 300u) << longType.size();
    EXPECT_NE(longType.find("..."), std::string::npos);
}

TEST(ProjectMessages, UnknownKeysInWarningsAreEscaped) {
    std::vector<std::string> warnings;
    auto scene = scene::parseProject(QByteArray(R"({ "format": "speculum-scene", "version": 1,
                                              "x\nspeculum: error: y\u001b": 1 })"),
                                     QDir("/tmp"), warnings);
    ASSERT_TRUE(scene.ok()) << scene.error();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_FALSE(hasRawControl(warnings[0])) << warnings[0];
    EXPECT_NE(warnings[0].find("x\\nspeculum: error: y\\x1b: unknown field"), std::string::npos)
        << warnings[0];
}

TEST(ProjectMessages, AnOverflowingCameraNamesTheFieldThatIsWrong) {
    // The view direction of these overflows if computed naively: the cause is the position, not `up`.
    const std::string m =
        bad(sceneWith(R"("camera": { "position": [1e300, 0, 0], "target": [-1e300, 0, 0] })"));
    EXPECT_NE(m.find("camera.position:"), std::string::npos) << m;
    EXPECT_EQ(m.find("camera.up"), std::string::npos) << m;
    const std::string t = bad(sceneWith(R"("camera": { "target": [0, 1e200, -1e200] })"));
    EXPECT_NE(t.find("camera.target:"), std::string::npos) << t;
    // In range but so close that float maths cannot tell them apart: named as the target, not `up`.
    const std::string close =
        bad(sceneWith(R"("camera": { "position": [1e11, 0, 0], "target": [100000000000.00002, 0, 1e-6] })"));
    EXPECT_NE(close.find("camera.target: must differ from the camera position"), std::string::npos) << close;
    // A tiny up is a problem of `up`, reported as such (not overflowing into "parallel").
    const std::string up = bad(sceneWith(R"("camera": { "up": [0, 1e-300, 0] })"));
    EXPECT_NE(up.find("camera.up: must be at least"), std::string::npos) << up;
    // Up along the view direction, at any scale.
    const std::string parallel = bad(sceneWith(R"("camera": { "up": [0, 0, -1e11] })"));
    EXPECT_NE(parallel.find("camera.up: must not be parallel"), std::string::npos) << parallel;
}

TEST(ProjectDuplicateKeys, RepeatedKeysAreRefusedWithTheirPath) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({ "format": "speculum-scene", "version": 1, "format": "speculum-scene" })",
         "duplicate key 'format' at the top level"},
        {sceneWith(
             R"("nodes": [ { "name": "a" }, { "name": "b" }, { "name": "c", "mesh": {}, "name": "d" } ])"),
         "nodes[2]: duplicate key 'name'"},
        {sceneWith(
             R"("nodes": [ { "transform": { "scale": [1, 1, 1], "translate": [0, 0, 0], "scale": [2, 2, 2] } } ])"),
         "nodes[0].transform: duplicate key 'scale'"},
        {sceneWith(R"("nodes": [ { "children": [ { "light": { "shadows": { "pcf": 3, "pcf": 5 } } } ] } ])"),
         "nodes[0].children[0].light.shadows: duplicate key 'pcf'"},
        {sceneWith(R"("camera": { "near": 1 }, "camera": { "near": 2 })"),
         "duplicate key 'camera' at the top level"},
        // Unknown fields are kept and written back: a repeat there would lose data on saving just the same.
        {sceneWith(R"("future": { "list": [ { "x": 1 }, { "x": 1, "x": 2 } ] })"),
         "future.list[1]: duplicate key 'x'"},
        // Spelled differently, the same key once decoded.
        {sceneWith(R"("nodes": [ { "name": "a", "n\u0061me": "b" } ])"), "nodes[0]: duplicate key 'name'"},
        {sceneWith(R"("nodes": [ { "\u006E\u0061\u006D\u0065": "a", "name": "b" } ])"),
         "nodes[0]: duplicate key 'name'"},
        {sceneWith(R"("extra": { "a/b": 1, "a\/b": 2 })"), "extra: duplicate key 'a/b'"},
        {sceneWith(R"("extra": { "caf\u00e9": 1, "café": 2 })"), "extra: duplicate key 'café'"},
        {sceneWith(R"("extra": { "\ud83d\ude00": 1, "😀": 2 })"), "extra: duplicate key '😀'"},
        // A key with control characters is shown escaped.
        {sceneWith(R"("extra": { "\u001b[31m\n": 1, "\u001b[31m\u000a": 2 })"),
         "extra: duplicate key '\\x1b[31m\\n'"},
    };
    for (const auto& [json, expected] : cases) {
        const std::string m = bad(json);
        EXPECT_NE(m.find(expected), std::string::npos) << m << "\n  expected: " << expected;
        EXPECT_FALSE(hasRawControl(m)) << m;
    }
}

TEST(ProjectDuplicateKeys, SimilarButDifferentKeysAndKeyLikeStringsLoad) {
    const std::vector<std::string> fine = {
        // Different keys that only look alike, and the same key in different objects.
        sceneWith(
            R"("extra": { "a": 1, "A": 2, "a ": 3, "\u00e9": 4, "e\u0301": 5, "\ud800": 6, "\udc00": 7 })"),
        sceneWith(R"("nodes": [ { "name": "a" }, { "name": "a" } ], "extra": { "name": { "name": 1 } })"),
        // Strings holding JSON-like text, escaped quotes and backslashes are values, not keys.
        sceneWith(
            R"("nodes": [ { "name": "{\"name\": 1, \"name\": 2}" }, { "name": "\\\", \"name\": \"" } ])"),
        sceneWith(R"("extra": [ "k", "k", { "k": 1 }, { "k": 2 } ])"),
    };
    for (const std::string& json : fine) {
        EXPECT_EQ(bad(json), "<loaded>") << json;
    }
}

TEST(ProjectDuplicateKeys, DeepNestingIsScannedWithoutRecursion) {
    // Deeper than anything real; the parser's own limit decides whether it loads, never a stack overflow.
    std::string deep;
    for (int i = 0; i < 5000; ++i) {
        deep += R"({"a":)";
    }
    deep += "1";
    for (int i = 0; i < 5000; ++i) {
        deep += "}";
    }
    const std::string m = bad(sceneWith(R"("extra": )" + deep));
    EXPECT_FALSE(m.empty());
}

// ---- the project path is not a regular file: refused at once, never read, never blocking ----

// Runs load on another thread; a regression that blocks fails the test instead of hanging it: the FIFO's
// other end, held open here, is closed after the timeout, which ends any blocked read.
std::string loadWithTimeout(const std::function<std::string()>& load, int fifoWriter) {
    auto done = std::make_shared<std::atomic<bool>>(false);
    auto result = std::make_shared<std::string>();
    std::thread([load, done, result] {
        *result = load();
        done->store(true);
    }).detach();
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!done->load() && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (fifoWriter >= 0) {
        ::close(fifoWriter);
    }
    if (!done->load()) {
        ADD_FAILURE() << "loading blocked for 5 s";
        while (!done->load()) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    return *result;
}

std::string projectError(const QString& path) {
    std::vector<std::string> warnings;
    auto result = scene::loadProject(path, warnings);
    return result.ok() ? std::string("<loaded>") : result.error();
}

TEST(ProjectPaths, AFifoIsRefusedWithoutBlocking) {
    const auto folder = test::freshTestFolder();
    const std::string fifo = (folder / "x.speculum.json").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // A writer that has written a valid scene and keeps the pipe open: a blocking reader would wait for EOF.
    const int writer = ::open(fifo.c_str(), O_RDWR | O_NONBLOCK);
    ASSERT_GE(writer, 0);
    const std::string scene = R"({ "format": "speculum-scene", "version": 1 })";
    ASSERT_EQ(::write(writer, scene.data(), scene.size()), static_cast<ssize_t>(scene.size()));
    const auto start = std::chrono::steady_clock::now();
    const std::string m = loadWithTimeout([&] { return projectError(QString::fromStdString(fifo)); }, writer);
    EXPECT_EQ(m, "x.speculum.json: it is a FIFO (named pipe), not a regular file");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));

    // The same for the bench results the accuracy panel opens.
    const std::string results = (folder / "results.json").string();
    ASSERT_EQ(::mkfifo(results.c_str(), 0600), 0);
    const int resultsWriter = ::open(results.c_str(), O_RDWR | O_NONBLOCK);
    ASSERT_GE(resultsWriter, 0);
    const std::string r = loadWithTimeout(
        [&] {
            auto loaded = loadSweepResults(QString::fromStdString(results));
            return loaded.ok() ? std::string("<loaded>") : loaded.error();
        },
        resultsWriter);
    EXPECT_EQ(r, "results.json: it is a FIFO (named pipe), not a regular file");
}

TEST(ProjectPaths, DevicesFoldersAndMissingFilesAreRefused) {
    const auto folder = test::freshTestFolder();
    EXPECT_EQ(loadWithTimeout([] { return projectError(QStringLiteral("/dev/null")); }, -1),
              "null: it is a device, not a regular file");
    EXPECT_EQ(loadWithTimeout([] { return projectError(QStringLiteral("/dev/zero")); }, -1),
              "zero: it is a device, not a regular file");
    std::filesystem::create_directories(folder / "folder.speculum.json");
    EXPECT_EQ(projectError(test::qpath(folder / "folder.speculum.json")),
              "folder.speculum.json: it is a folder, not a file");
    EXPECT_EQ(projectError(test::qpath(folder / "missing.speculum.json")),
              "missing.speculum.json: file not found");
    // A file name with control characters is named escaped.
    EXPECT_EQ(projectError(test::qpath(folder / "a\nb\x1b.json")), "a\\nb\\x1b.json: file not found");
    // A regular file still loads, through a symbolic link too.
    test::writeBytes(test::qpath(folder / "ok.speculum.json"),
                     R"({ "format": "speculum-scene", "version": 1 })");
    std::filesystem::create_symlink(folder / "ok.speculum.json", folder / "link.speculum.json");
    EXPECT_EQ(projectError(test::qpath(folder / "link.speculum.json")), "<loaded>");
}

TEST(ProjectPaths, BenchResultsRefuseRepeatedKeys) {
    const auto folder = test::freshTestFolder();
    const QString path = test::qpath(folder / "results.json");
    test::writeBytes(path, R"({ "format": "speculum-bench", "results": [
        { "id": "a", "family": "envmap", "cpuMs": 1, "psnr": 30, "rmse": 0.1 },
        { "id": "b", "family": "envmap", "cpuMs": 2, "psnr": 31, "psnr": 99, "rmse": 0.1 } ] })");
    auto loaded = loadSweepResults(path);
    ASSERT_FALSE(loaded.ok());
    EXPECT_EQ(loaded.error(), "results.json: results[1]: duplicate key 'psnr'");
}

} // namespace
} // namespace speculum::document
