#include "scene/project/ProjectFile.hpp"

#include "../../editor/document/ThreeNodeScene.hpp"
#include "../../editor/document/UndoStackState.hpp"
#include "editor/document/Commands.hpp"
#include "editor/document/DocumentSession.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "support/DocumentTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QDir>
#include <QFileInfo>
#include <QUndoStack>
#include <cmath>
#include <filesystem>

namespace speculum::document {
namespace {

using test::demoScenePath;
using test::freshTestFolder;
using test::qpath;
using test::readBytes;
using test::writeBytes;

// A scene that uses every component and every non-default value the format has.
scene::SceneData everythingScene(const QDir& folder) {
    scene::SceneData scene;
    scene.settings.background = {0.05, 0.2, 0.3};
    scene.settings.mirrorDepth = 5;
    scene.settings.ambient = 0.35;
    scene.settings.simplifyReflections = false;
    scene.settings.glossyFilter = scene::GlossyFilter::Mip;
    scene.settings.glossyTaps = 7;
    scene.settings.prefilterSamples = 333;
    scene.camera.position = {1e5 + 0.125, -2.5, 7};
    scene.camera.target = {1e5, 0, 0};
    scene.camera.up = {0, 0, 1};
    scene.camera.fovY = 47.5;
    scene.camera.near = 0.001;
    scene.camera.far = 999.875; // within render::kMaxFarNearRatio of near

    scene::NodeTree ball;
    ball.data.name = "Chrome \"ball\" \u00e9\t";
    ball.data.transform = {{1, -0.5, -3}, {10, 20, 30}, {0.4, 0.4, -0.4}};
    ball.data.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere, 48);
    ball.data.reflector = scene::ReflectorComponent{
        scene::ReflectorMap::TennisBall,
        512,
        0.75,
        true,
        scene::ReflectorFill::Direct,
        scene::ReflectorParallax{scene::ParallaxShape::Box, 5, {-1, -2, -3}, {4, 5, 6}},
        scene::ReflectorUpdate::Once,
        3,
        0.25};
    ball.data.material =
        scene::MaterialComponent{{0.1, 0.2, 0.3},
                                 0.5,
                                 0.25,
                                 0.75,
                                 100,
                                 {0.01, 0.02, 0.03},
                                 folder.absoluteFilePath("textures/chrome.png").toStdString()};

    scene::NodeTree mirror;
    mirror.data.name = "Wall mirror";
    mirror.data.transform.rotate = {90, 0, 0};
    mirror.data.mirror = scene::MirrorComponent{{3, 1.5}, 0.9, scene::MirrorTechnique::Texture, {}};

    scene::NodeTree spot;
    spot.data.name = "Spot";
    spot.data.light = scene::LightComponent{scene::LightType::Spot,         {1, 0.9, 0.8}, 2.5, 40, 0.3,
                                            scene::ShadowComponent{2048, 7}};
    spot.data.animation = scene::AnimationComponent{scene::BounceAnimation{0.3, 1.5},
                                                    scene::OrbitAnimation{{0, 2, -3}, 1.5, 6}};

    scene::NodeTree sun;
    sun.data.name = "Sun";
    sun.data.light =
        scene::LightComponent{scene::LightType::Directional, {1, 1, 1}, 0.5, 30, 0.15, std::nullopt};

    scene::NodeTree model;
    model.data.name = "Imported";
    model.data.mesh =
        scene::MeshComponent::fromFile(folder.absoluteFilePath("models/bunny.obj").toStdString());
    model.children = {spot, sun};

    scene::NodeTree group;
    group.data.name = "Group";
    group.children = {mirror, model};

    scene.nodes = {ball, group};
    return scene;
}

TEST(ProjectFile, DemoSceneLoadsWithoutWarnings) {
    std::vector<std::string> warnings;
    auto loaded = scene::loadProject(demoScenePath(), warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_TRUE(warnings.empty());
    const scene::SceneData& scene = *loaded;
    ASSERT_EQ(scene.nodes.size(), 3u);
    EXPECT_EQ(scene.nodes[0].data.name, "Teapot");
    ASSERT_TRUE(scene.nodes[0].data.mesh && scene.nodes[0].data.mesh->builtin);
    EXPECT_EQ(*scene.nodes[0].data.mesh->builtin, scene::BuiltinMesh::Teapot);
    EXPECT_EQ(scene.nodes[0].data.mesh->tessellation, 8);
    EXPECT_EQ(scene.camera.fovY, 65.0);
    // The texture path is relative in the file and absolute in the model.
    ASSERT_TRUE(scene.nodes[1].data.material);
    const QString texture = QString::fromStdString(scene.nodes[1].data.material->texture.path);
    EXPECT_TRUE(QFileInfo(texture).isAbsolute());
    EXPECT_EQ(texture, QDir::cleanPath(QString::fromStdString(
                           speculum::testSourcePath("resources/scenes/textures/marble.png"))));
    ASSERT_TRUE(scene.nodes[2].data.light && scene.nodes[2].data.light->shadows);
    EXPECT_EQ(scene.nodes[2].data.light->shadows->pcf, 5);
}

// A model path is written relative where the model lies in the project's folder or beside it, absolute
// where the two share only the root: moving such a project keeps its models found.
TEST(ProjectFile, PathsAreRelativeInsideAndBesideTheProjectAndAbsoluteElsewhere) {
    scene::SceneData data;
    const std::pair<const char*, const char*> cases[] = {
        {"/home/ada/project/models/duck.obj", "models/duck.obj"},
        {"/home/ada/models/duck.obj", "../models/duck.obj"},
        {"/usr/share/assimp/models/OBJ/box.obj", "/usr/share/assimp/models/OBJ/box.obj"},
    };
    for (const auto& [file, written] : cases) {
        scene::NodeTree node;
        node.data.name = file;
        node.data.mesh = scene::MeshComponent::fromFile(file);
        data.nodes.push_back(node);
    }
    const QByteArray json = scene::serializeProject(data, QDir(QStringLiteral("/home/ada/project")));
    for (const auto& [file, written] : cases) {
        EXPECT_TRUE(json.contains(QByteArray("\"file\": \"") + written + "\"")) << file << "\n"
                                                                                << json.toStdString();
    }
    // And it reads back to the same absolute paths.
    std::vector<std::string> warnings;
    auto reread = scene::parseProject(json, QDir(QStringLiteral("/home/ada/project")), warnings);
    ASSERT_TRUE(reread) << reread.error();
    for (std::size_t i = 0; i < std::size(cases); ++i) {
        EXPECT_EQ(reread->nodes[i].data.mesh->file, cases[i].first);
    }
}

TEST(ProjectFile, DemoSceneSavesTwiceToIdenticalBytes) {
    const auto folder = freshTestFolder();
    std::vector<std::string> warnings;
    auto original = scene::loadProject(demoScenePath(), warnings);
    ASSERT_TRUE(original.ok()) << original.error();

    const QString first = qpath(folder / "first.speculum.json");
    const QString second = qpath(folder / "second.speculum.json");
    ASSERT_TRUE(scene::saveProject(*original, first).ok());
    auto reloaded = scene::loadProject(first, warnings);
    ASSERT_TRUE(reloaded.ok()) << reloaded.error();
    EXPECT_EQ(*reloaded, *original); // the texture resolves to the same file from the other folder
    ASSERT_TRUE(scene::saveProject(*reloaded, second).ok());
    EXPECT_EQ(readBytes(first), readBytes(second));
    EXPECT_TRUE(warnings.empty());
}

TEST(ProjectFile, DemoSceneIsWrittenInCanonicalForm) {
    // Saving the demo next to itself reproduces the committed file byte for byte, so the committed file
    // shows exactly what speculum writes.
    std::vector<std::string> warnings;
    auto scene = scene::loadProject(demoScenePath(), warnings);
    ASSERT_TRUE(scene.ok()) << scene.error();
    const QByteArray written = scene::serializeProject(*scene, QFileInfo(demoScenePath()).absoluteDir());
    EXPECT_EQ(written.toStdString(), readBytes(demoScenePath()).toStdString());
}

TEST(ProjectFile, EveryComponentRoundTrips) {
    const auto folder = freshTestFolder();
    const QDir dir(qpath(folder));
    const scene::SceneData scene = everythingScene(dir);
    const QString path = qpath(folder / "all.speculum.json");
    ASSERT_TRUE(scene::saveProject(scene, path).ok());

    std::vector<std::string> warnings;
    auto loaded = scene::loadProject(path, warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(*loaded, scene);

    const QByteArray bytes = readBytes(path);
    EXPECT_TRUE(bytes.contains("\"texture\": \"textures/chrome.png\"")) << bytes.toStdString();
    EXPECT_TRUE(bytes.contains("\"file\": \"models/bunny.obj\"")) << bytes.toStdString();
    EXPECT_TRUE(bytes.contains("\"far\": 999.875"));
    EXPECT_TRUE(bytes.contains("\"mapSize\": 2048"));
    EXPECT_FALSE(bytes.contains(".0,")) << "integers are written without a fraction";
    EXPECT_EQ(scene::serializeProject(*loaded, dir), bytes);
}

TEST(ProjectFile, ReflectorOptionsHaveDefaultsAndAreWrittenInAFixedOrder) {
    const QByteArray json = R"({ "format": "speculum-scene", "version": 1, "nodes": [
        { "name": "Ball", "mesh": { "builtin": "sphere" }, "reflector": { "map": "dual-paraboloid" } } ] })";
    std::vector<std::string> warnings;
    auto loaded = scene::parseProject(json, QDir("/tmp"), warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    const scene::ReflectorComponent& r = *loaded->nodes[0].data.reflector;
    EXPECT_FALSE(r.fresnel);
    EXPECT_EQ(r.fill, scene::ReflectorFill::Resampled);
    EXPECT_FALSE(r.parallax.has_value()) << "parallax correction is off by default";
    EXPECT_EQ(r.update, scene::ReflectorUpdate::OnChange);
    EXPECT_EQ(r.mirrorDepth, 1);

    const std::string written = scene::serializeProject(*loaded, QDir("/tmp")).toStdString();
    std::size_t last = 0;
    for (const char* key : {"\"map\"", "\"resolution\"", "\"reflectivity\"", "\"fresnel\"", "\"fill\"",
                            "\"update\"", "\"mirrorDepth\""}) {
        const std::size_t at = written.find(key, written.find("\"reflector\""));
        ASSERT_NE(at, std::string::npos) << key;
        EXPECT_GT(at, last) << key << " out of order";
        last = at;
    }
    EXPECT_EQ(written.find("parallax"), std::string::npos);

    // A sphere proxy round-trips with its radius only.
    scene::SceneData withProxy = *loaded;
    withProxy.nodes[0].data.reflector->parallax =
        scene::ReflectorParallax{scene::ParallaxShape::Sphere, 7.5, {}};
    withProxy.nodes[0].data.reflector->parallax->min = scene::ReflectorParallax{}.min;
    withProxy.nodes[0].data.reflector->parallax->max = scene::ReflectorParallax{}.max;
    const QByteArray bytes = scene::serializeProject(withProxy, QDir("/tmp"));
    EXPECT_TRUE(bytes.contains("\"parallax\": {\n")) << bytes.toStdString();
    EXPECT_TRUE(bytes.contains("\"radius\": 7.5")) << bytes.toStdString();
    EXPECT_FALSE(bytes.contains("\"min\"")) << bytes.toStdString();
    auto again = scene::parseProject(bytes, QDir("/tmp"), warnings);
    ASSERT_TRUE(again.ok()) << again.error();
    EXPECT_EQ(*again, withProxy);
    EXPECT_TRUE(warnings.empty());
}

TEST(ProjectFile, SavingIntoAnotherFolderKeepsPathsPointingAtTheSameFiles) {
    const auto folder = freshTestFolder();
    const QDir dir(qpath(folder));
    const scene::SceneData scene = everythingScene(dir);
    std::filesystem::create_directories(folder / "sub" / "deeper");
    const QString path = qpath(folder / "sub" / "deeper" / "moved.speculum.json");
    ASSERT_TRUE(scene::saveProject(scene, path).ok());
    EXPECT_TRUE(readBytes(path).contains("\"texture\": \"../../textures/chrome.png\""));
    std::vector<std::string> warnings;
    auto loaded = scene::loadProject(path, warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(*loaded, scene);
}

TEST(ProjectFile, KeyOrderAndLayoutFollowTheDesign) {
    const QByteArray bytes = scene::serializeProject(everythingScene(QDir("/tmp")), QDir("/tmp"));
    const std::string text = bytes.toStdString();
    auto at = [&](const char* key) { return text.find(std::string("\"") + key + "\""); };
    EXPECT_EQ(text.rfind("{\n  \"format\": \"speculum-scene\",\n  \"version\": 1,\n  \"settings\": {", 0),
              0u);
    EXPECT_LT(at("settings"), at("camera"));
    EXPECT_LT(at("camera"), at("nodes"));
    // Within the first node: name, transform, mesh, material, ..., reflector.
    EXPECT_LT(at("name"), at("transform"));
    EXPECT_LT(at("transform"), at("mesh"));
    EXPECT_LT(at("mesh"), at("material"));
    EXPECT_LT(at("material"), at("reflector"));
    EXPECT_NE(text.find("\n    {\n      \"name\": "), std::string::npos) << "2-space indentation";
    EXPECT_NE(text.find("\"translate\": [1, -0.5, -3]"), std::string::npos);
    EXPECT_EQ(text.back(), '\n');
}

TEST(ProjectFile, NumbersRoundTripExactly) {
    const auto folder = freshTestFolder();
    scene::SceneData scene;
    scene::NodeTree node;
    node.data.name = "n";
    node.data.transform.translate = {0.1, 1.0 / 3.0, -1e-7};
    node.data.transform.rotate = {123456789.123, 2.5e-300, -0.0};
    node.data.transform.scale = {1e9, 3.0000000000000004e-9, -7}; // render::kMaxScale, near kMinScale
    scene.nodes.push_back(node);
    const QString path = qpath(folder / "numbers.speculum.json");
    ASSERT_TRUE(scene::saveProject(scene, path).ok());
    std::vector<std::string> warnings;
    auto loaded = scene::loadProject(path, warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    const scene::Transform& t = loaded->nodes[0].data.transform;
    EXPECT_EQ(t.translate, node.data.transform.translate);
    EXPECT_EQ(t.rotate, node.data.transform.rotate);
    EXPECT_EQ(t.scale, node.data.transform.scale);
    EXPECT_TRUE(readBytes(path).contains("\"translate\": [0.1, 0.3333333333333333, -1e-07]"));
}

TEST(ProjectFile, UnknownFieldsWarnWithTheirPathAndSurviveASave) {
    const QByteArray json = R"({
  "format": "speculum-scene", "version": 1, "comment": "made by hand",
  "settings": { "fog": { "density": 0.5 } },
  "nodes": [
    { "name": "A", "transfrom": { "translate": [1, 2, 3] },
      "light": { "type": "point", "shadows": { "bias": 0.002 }, "ies": "lamp.ies" },
      "physics": { "mass": 2, "tags": ["x", 1, null, true] },
      "children": [ { "name": "B", "mesh": { "builtin": "box", "lod": [1, 2] } } ] }
  ]
})";
    std::vector<std::string> warnings;
    auto loaded = scene::parseProject(json, QDir("/tmp"), warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    const std::vector<std::string> expected = {"comment",
                                               "settings.fog",
                                               "nodes[0].transfrom",
                                               "nodes[0].physics",
                                               "nodes[0].light.ies",
                                               "nodes[0].light.shadows.bias",
                                               "nodes[0].children[0].mesh.lod"};
    for (const std::string& path : expected) {
        const bool found = std::any_of(warnings.begin(), warnings.end(), [&](const std::string& w) {
            return w.rfind(path + ": unknown field", 0) == 0;
        });
        EXPECT_TRUE(found) << "no warning for " << path;
    }
    EXPECT_EQ(warnings.size(), expected.size());

    const QByteArray saved = scene::serializeProject(*loaded, QDir("/tmp"));
    std::vector<std::string> again;
    auto reloaded = scene::parseProject(saved, QDir("/tmp"), again);
    ASSERT_TRUE(reloaded.ok()) << reloaded.error();
    EXPECT_EQ(*reloaded, *loaded);
    EXPECT_EQ(again.size(), expected.size()) << "unknown fields are written back";
    EXPECT_EQ(scene::serializeProject(*reloaded, QDir("/tmp")), saved);
    EXPECT_TRUE(saved.contains("\"tags\": [\n")) << saved.toStdString();
    EXPECT_TRUE(saved.contains("\"lod\": [1, 2]")) << saved.toStdString();
}

TEST(ProjectFile, FailedOpenLeavesTheSceneUntouched) {
    const auto folder = freshTestFolder();
    scene::Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::openProject(scene, demoScenePath(), warnings).ok());
    const scene::SceneData before = scene.toData();
    const QString pathBefore = scene.projectPath();
    const std::vector<scene::NodeId> idsBefore = {scene.topLevelNodes()[0]->id(),
                                                  scene.topLevelNodes()[2]->id()};
    int resets = 0;
    QObject::connect(&scene, &scene::Scene::aboutToReset, [&] { ++resets; });

    // A file that is valid up to its last node: nothing of it may leak into the scene.
    QByteArray broken = readBytes(demoScenePath());
    broken.replace("\"type\": \"point\"", "\"type\": \"lamp\"");
    const QString brokenPath = qpath(folder / "broken.speculum.json");
    writeBytes(brokenPath, broken);
    warnings.clear();
    auto status = scene::openProject(scene, brokenPath, warnings);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("nodes[2].light.type"), std::string::npos) << status.error();
    auto missing = scene::openProject(scene, qpath(folder / "nope.speculum.json"), warnings);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("nope.speculum.json"), std::string::npos) << missing.error();

    EXPECT_EQ(scene.toData(), before);
    EXPECT_EQ(scene.projectPath(), pathBefore);
    EXPECT_EQ(scene.topLevelNodes()[0]->id(), idsBefore[0]);
    EXPECT_EQ(scene.topLevelNodes()[2]->id(), idsBefore[1]);
    EXPECT_EQ(resets, 0);
    EXPECT_TRUE(warnings.empty());
}

TEST(ProjectFile, SaveIntoAMissingFolderFails) {
    const auto folder = freshTestFolder();
    const QString path = qpath(folder / "no" / "such" / "folder" / "x.speculum.json");
    auto status = scene::saveProject(scene::SceneData{}, path);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("x.speculum.json"), std::string::npos) << status.error();
    EXPECT_FALSE(QFileInfo::exists(path));
}

TEST(ProjectFile, SaveIntoAReadOnlyFolderFailsAndKeepsTheOldFile) {
    const auto folder = freshTestFolder() / "locked";
    std::filesystem::create_directories(folder);
    const QString path = qpath(folder / "scene.speculum.json");
    writeBytes(path, "old contents");
    std::filesystem::permissions(folder,
                                 std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    const bool permissionsBite = !QFile(qpath(folder / "probe")).open(QIODevice::WriteOnly);
    if (!permissionsBite) {
        std::filesystem::remove(folder / "probe");
        std::filesystem::permissions(folder, std::filesystem::perms::owner_all);
        GTEST_SKIP() << "running with privileges that ignore folder permissions (root)";
    }
    auto status = scene::saveProject(scene::SceneData{}, path);
    std::filesystem::permissions(folder, std::filesystem::perms::owner_all);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("scene.speculum.json"), std::string::npos) << status.error();
    EXPECT_EQ(readBytes(path), QByteArray("old contents"));
}

TEST(ProjectFile, AModelTheReaderWouldRejectIsNotSavedAndTheOldFileStays) {
    const auto folder = freshTestFolder();
    const QString path = qpath(folder / "scene.speculum.json");
    ASSERT_TRUE(scene::saveProject(scene::SceneData{}, path).ok());
    const QByteArray before = readBytes(path);
    scene::SceneData bad;
    bad.camera.far = bad.camera.near / 2;
    auto status = scene::saveProject(bad, path);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("camera.far"), std::string::npos) << status.error();
    EXPECT_EQ(readBytes(path), before);
    EXPECT_EQ(QDir(qpath(folder)).entryList(QDir::Files).size(), 1) << "no temporary file left behind";
}

TEST(ProjectFile, OpenSetsTheProjectPathAndFreshIds) {
    scene::Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::openProject(scene, demoScenePath(), warnings).ok());
    EXPECT_EQ(scene.projectPath(), QFileInfo(demoScenePath()).absoluteFilePath());
    std::vector<scene::NodeId> ids;
    scene.forEachNode([&](const scene::Node& node) { ids.push_back(node.id()); });
    ASSERT_EQ(ids.size(), 3u);
    EXPECT_NE(ids[0], ids[1]);
    EXPECT_NE(ids[1], ids[2]);
    EXPECT_EQ(scene.findNode(ids[1])->name(), "Table");
}

// ---- the editor's view: saved with the project, never the scene camera ----

scene::EditorView someEditorView() {
    scene::EditorView view;
    view.position = {0.1, 1.0 / 3.0, -1e-7};
    view.target = {1e5 + 0.125, -2.5, 7};
    return view;
}

TEST(ProjectFile, TheEditorViewRoundTripsWithItsUnknownFields) {
    const auto folder = freshTestFolder();
    const QDir dir(qpath(folder));
    scene::SceneData scene = everythingScene(dir);
    scene.editorView = someEditorView();
    scene.unknown["editorView"].insert(QStringLiteral("orthographic"), false); // a later version's field
    const QString path = qpath(folder / "view.speculum.json");
    ASSERT_TRUE(scene::saveProject(scene, path).ok());

    std::vector<std::string> warnings;
    auto loaded = scene::loadProject(path, warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(*loaded, scene);
    ASSERT_TRUE(loaded->editorView.has_value());
    EXPECT_EQ(loaded->editorView->position, scene.editorView->position) << "numbers round-trip exactly";
    EXPECT_EQ(warnings, std::vector<std::string>{"editorView.orthographic: unknown field, ignored"});

    // After the camera, before the nodes; numbers as the camera writes them; unknown fields last.
    const QByteArray bytes = readBytes(path);
    const std::string text = bytes.toStdString();
    EXPECT_NE(text.find("  \"editorView\": {\n"
                        "    \"position\": [0.1, 0.3333333333333333, -1e-07],\n"
                        "    \"target\": [100000.125, -2.5, 7],\n"
                        "    \"orthographic\": false\n"
                        "  },\n"
                        "  \"nodes\": ["),
              std::string::npos)
        << text;
    EXPECT_LT(text.find("\"camera\""), text.find("\"editorView\""));
    EXPECT_EQ(scene::serializeProject(*loaded, dir), bytes) << "saving a loaded file gives the same bytes";
}

TEST(ProjectFile, AFileWithoutAnEditorViewLoadsWithNoneAndIsWrittenWithout) {
    std::vector<std::string> warnings;
    auto demo = scene::loadProject(demoScenePath(), warnings);
    ASSERT_TRUE(demo.ok()) << demo.error();
    EXPECT_FALSE(demo->editorView.has_value());
    EXPECT_FALSE(readBytes(demoScenePath()).contains("editorView"));
    const QByteArray written = scene::serializeProject(*demo, QFileInfo(demoScenePath()).absoluteDir());
    EXPECT_FALSE(written.contains("editorView")) << written.toStdString();

    // Through a Scene too: nothing appears on the way.
    scene::Scene scene;
    scene.reset(*demo);
    EXPECT_FALSE(scene.editorView().has_value());
    EXPECT_EQ(scene.toData(), *demo);
    EXPECT_TRUE(warnings.empty());
}

TEST(ProjectFile, TheEditorViewLeavesTheSceneCameraAndWhatRenderDrawsAlone) {
    // `speculum render` draws snapshot(scene): its camera is SceneData::camera, whatever the editor saved.
    const QByteArray withoutView = scene::serializeProject(everythingScene(QDir("/tmp")), QDir("/tmp"));
    scene::SceneData viewed = everythingScene(QDir("/tmp"));
    viewed.editorView = scene::EditorView{{5, 6, 7}, {-1, -2, -3}};
    const QByteArray withView = scene::serializeProject(viewed, QDir("/tmp"));
    ASSERT_NE(withView, withoutView);

    std::vector<std::string> warnings;
    auto plain = scene::parseProject(withoutView, QDir("/tmp"), warnings);
    auto loaded = scene::parseProject(withView, QDir("/tmp"), warnings);
    ASSERT_TRUE(plain.ok()) << plain.error();
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(loaded->camera, plain->camera);
    EXPECT_EQ(loaded->camera, everythingScene(QDir("/tmp")).camera);

    scene::Scene plainScene;
    plainScene.reset(*plain);
    scene::Scene viewedScene;
    viewedScene.reset(*loaded);
    ASSERT_TRUE(viewedScene.editorView().has_value());
    EXPECT_EQ(viewedScene.camera(), plainScene.camera());
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> snapshotWarnings;
    const render::Camera drawn = scene::snapshot(viewedScene, 0.0, meshes, snapshotWarnings).camera;
    const render::Camera expected = plain->camera;
    EXPECT_EQ(drawn.position, expected.position);
    EXPECT_EQ(drawn.target, expected.target);
    EXPECT_EQ(drawn.up, expected.up);
    EXPECT_EQ(drawn.fovY, expected.fovY);
    EXPECT_EQ(drawn.near, expected.near);
    EXPECT_EQ(drawn.far, expected.far);
    EXPECT_NE(drawn.position, viewed.editorView->position);
}

TEST(SceneEditorView, ResetTakesItAndToDataGivesItBack) {
    scene::SceneData data;
    data.editorView = someEditorView();
    scene::Scene scene;
    std::optional<scene::EditorView> seenAtReset;
    QObject::connect(&scene, &scene::Scene::sceneReset, [&] { seenAtReset = scene.editorView(); });
    scene.reset(data);
    EXPECT_EQ(seenAtReset, data.editorView) << "in place when views hear of the new document";
    EXPECT_EQ(scene.editorView(), data.editorView);
    EXPECT_EQ(scene.toData(), data);

    scene.reset(scene::SceneData{});
    EXPECT_FALSE(scene.editorView().has_value()) << "a new document brings its own view, or none";
}

TEST(SceneEditorView, SettingItIsNoEditAndMarksNothingModified) {
    DocumentSession session;
    scene::Scene& scene = session.scene();
    QUndoStack& stack = session.undoStack();
    session.replace(test::threeNodeScene(), QStringLiteral("/projects/room.speculum.json"));
    int emitted = 0;
    for (auto signal : {&scene::Scene::changed, &scene::Scene::cameraChanged, &scene::Scene::settingsChanged,
                        &scene::Scene::sceneReset, &scene::Scene::aboutToReset}) {
        QObject::connect(&scene, signal, [&] { ++emitted; });
    }
    const scene::CameraData camera = scene.camera();

    scene.setEditorView(someEditorView());
    EXPECT_EQ(scene.editorView(), someEditorView());
    EXPECT_EQ(test::undoStackState(stack), (test::UndoStackState{0, 0, 0, true}));
    EXPECT_FALSE(session.isModified());
    EXPECT_EQ(emitted, 0);
    EXPECT_EQ(scene.camera(), camera);
    EXPECT_EQ(scene.toData().editorView, someEditorView());

    // After an edit and a save, moving the view leaves the stack where it is: still clean, one step.
    scene::CameraData edited = camera;
    edited.fovY = 40;
    stack.push(new SetCameraCommand(scene, edited));
    stack.setClean();
    const test::UndoStackState saved = test::undoStackState(stack);
    const int emittedBefore = emitted;
    scene.setEditorView(scene::EditorView{{3, 3, 3}, {0, 0, 0}});
    scene.setEditorView(std::nullopt);
    EXPECT_EQ(test::undoStackState(stack), saved);
    EXPECT_TRUE(stack.isClean());
    EXPECT_FALSE(session.isModified());
    EXPECT_EQ(emitted, emittedBefore) << "no signal: views do not redraw, nothing is marked modified";
    EXPECT_FALSE(scene.editorView().has_value());

    // Undoing the edit does not touch the view either.
    scene.setEditorView(someEditorView());
    stack.undo();
    EXPECT_EQ(scene.camera(), camera);
    EXPECT_EQ(scene.editorView(), someEditorView());
}

TEST(SceneEditorView, AViewTheReaderWouldRefuseIsNotKeptSoTheFileStillSaves) {
    const auto folder = freshTestFolder();
    scene::Scene scene;
    scene.setEditorView(someEditorView());
    scene.setEditorView(scene::EditorView{{1, 2, 3}, {1, 2, 3}}); // panned into one point
    EXPECT_FALSE(scene.editorView().has_value());
    scene.setEditorView(scene::EditorView{{2e300, 0, 0}, {0, 0, 0}}); // panned out of range
    EXPECT_FALSE(scene.editorView().has_value());
    // JSON has no such numbers (the parser refuses 1e999), but a view computed into one is not kept either.
    scene.setEditorView(scene::EditorView{{0, 0, 1}, {0, std::nan(""), 0}});
    EXPECT_FALSE(scene.editorView().has_value());
    scene.setEditorView(scene::EditorView{{0, 0, 1}, {0, 0, HUGE_VAL}});
    EXPECT_FALSE(scene.editorView().has_value());
    ASSERT_TRUE(scene::saveProject(scene, qpath(folder / "scene.speculum.json")).ok());
    std::vector<std::string> warnings;
    auto loaded = scene::loadProject(qpath(folder / "scene.speculum.json"), warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_FALSE(loaded->editorView.has_value());
}

// Roughness (GGX, on mirrors and the reflector) replaced the mirror's `blur`: an older file's blur loads as
// the same roughness and is saved as `roughness`; both fields given, roughness wins. The glossy settings
// are written only where they differ from the defaults, so files without rough surfaces stay as they were.
TEST(ProjectFile, BlurLoadsAsRoughnessAndGlossySettingsRoundTrip) {
    auto load = [](const std::string& text) {
        std::vector<std::string> warnings;
        auto scene = scene::parseProject(QByteArray::fromStdString(text), QDir("/tmp"), warnings);
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        return scene;
    };
    const std::string head = R"({ "format": "speculum-scene", "version": 1, )";
    auto old = load(head + R"("nodes": [ { "name": "M", "mirror": { "blur": 0.15 } } ] })");
    ASSERT_TRUE(old) << old.error();
    EXPECT_DOUBLE_EQ(old->nodes.at(0).data.mirror->roughness, 0.15);
    const QByteArray saved = scene::serializeProject(*old, QDir("/tmp"));
    EXPECT_TRUE(saved.contains("\"roughness\": 0.15")) << saved.toStdString();
    EXPECT_FALSE(saved.contains("\"blur\"")) << saved.toStdString();
    EXPECT_FALSE(saved.contains("glossy")) << saved.toStdString();
    EXPECT_FALSE(saved.contains("prefilterSamples")) << saved.toStdString();

    auto both = load(head + R"("nodes": [ { "name": "M", "mirror": { "blur": 0.9, "roughness": 0.2 } } ] })");
    ASSERT_TRUE(both) << both.error();
    EXPECT_DOUBLE_EQ(both->nodes.at(0).data.mirror->roughness, 0.2);

    auto settings =
        load(head + R"("settings": { "glossyFilter": "mip", "glossyTaps": 5, "prefilterSamples": 9 },
        "nodes": [ { "name": "B", "mesh": { "builtin": "sphere" }, "reflector": { "roughness": 0.5 } } ] })");
    ASSERT_TRUE(settings) << settings.error();
    EXPECT_EQ(settings->settings.glossyFilter, scene::GlossyFilter::Mip);
    EXPECT_EQ(settings->settings.glossyTaps, 5);
    EXPECT_EQ(settings->settings.prefilterSamples, 9);
    EXPECT_DOUBLE_EQ(settings->nodes.at(0).data.reflector->roughness, 0.5);
    scene::Scene scene;
    scene.reset(*settings);
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> snapshotWarnings;
    const render::FrameInput frame = scene::snapshot(scene, 0.0, meshes, snapshotWarnings);
    EXPECT_EQ(frame.settings.glossyFilter, render::GlossyFilter::Mip);
    EXPECT_EQ(frame.settings.glossyTaps, 5);
    EXPECT_EQ(frame.settings.prefilterSamples, 9);
    EXPECT_DOUBLE_EQ(frame.reflectors[0].roughness, 0.5);
    auto again = load(scene::serializeProject(*settings, QDir("/tmp")).toStdString());
    ASSERT_TRUE(again) << again.error();
    EXPECT_EQ(again->settings, settings->settings);

    auto refused = [&](const std::string& settingsJson, const std::string& path) {
        std::vector<std::string> warnings;
        auto bad = scene::parseProject(
            QByteArray::fromStdString(head + R"("settings": )" + settingsJson + "}"), QDir("/tmp"), warnings);
        ASSERT_FALSE(bad) << settingsJson;
        EXPECT_NE(bad.error().find(path), std::string::npos) << bad.error();
    };
    refused(R"({ "glossyFilter": "blurry" })", "settings.glossyFilter");
    refused(R"({ "glossyTaps": 0 })", "settings.glossyTaps");
}

} // namespace
} // namespace speculum::document
