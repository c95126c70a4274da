// The scene-file fields imported models use: material textures, wrap, alpha, a mesh's `part`.
// Defaults are not written, so files without them keep their exact bytes.
#include "editor/document/Properties.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/DocumentTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QDir>

namespace speculum::document {
namespace {

using test::demoScenePath;
using test::freshTestFolder;
using test::qpath;
using test::readBytes;

scene::SceneData importedScene(const QDir& folder) {
    scene::SceneData scene;
    scene::NodeTree part;
    part.data.name = "Wheel";
    part.data.mesh = scene::MeshComponent::fromFile(folder.absoluteFilePath("models/car.glb").toStdString());
    part.data.mesh->part = 3;
    scene::MaterialComponent m;
    m.color = {0.9, 0.1, 0.1};
    m.specular = 1.0;
    m.shininess = 30.0;
    m.specularColor = {0.9, 0.1, 0.1};
    m.texture.path = folder.absoluteFilePath("models/car.glb#*0").toStdString();
    m.emissionTexture.path = folder.absoluteFilePath("textures/glow.png").toStdString();
    m.normalTexture.path = folder.absoluteFilePath("models/car.glb#*1").toStdString();
    m.normalScale = 0.75;
    m.wrap = {scene::TextureWrap::ClampToEdge, scene::TextureWrap::MirroredRepeat};
    m.opacity = 0.5;
    m.alphaMode = scene::AlphaMode::Mask;
    m.alphaCutoff = 0.25;
    part.data.material = m;

    scene::NodeTree whole;
    whole.data.name = "Whole";
    whole.data.mesh = scene::MeshComponent::fromFile(folder.absoluteFilePath("models/car.glb").toStdString());
    scene::MaterialComponent clamped;
    clamped.wrap = {scene::TextureWrap::ClampToEdge, scene::TextureWrap::ClampToEdge};
    clamped.alphaMode = scene::AlphaMode::Blend;
    whole.data.material = clamped;
    scene.nodes = {part, whole};
    return scene;
}

TEST(ProjectMaterials, NewFieldsRoundTrip) {
    const auto folder = freshTestFolder();
    const QDir dir(qpath(folder));
    const scene::SceneData scene = importedScene(dir);
    const QString path = qpath(folder / "imported.speculum.json");
    ASSERT_TRUE(scene::saveProject(scene, path).ok());
    std::vector<std::string> warnings;
    auto loaded = scene::loadProject(path, warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_TRUE(warnings.empty()) << ::testing::PrintToString(warnings);
    EXPECT_EQ(*loaded, scene);

    const QByteArray bytes = readBytes(path);
    EXPECT_TRUE(bytes.contains("\"part\": 3")) << bytes.toStdString();
    // Embedded texture names are paths like any other: relative to the project.
    EXPECT_TRUE(bytes.contains("\"texture\": \"models/car.glb#*0\"")) << bytes.toStdString();
    EXPECT_TRUE(bytes.contains("\"normalTexture\": \"models/car.glb#*1\"")) << bytes.toStdString();
    EXPECT_TRUE(bytes.contains("\"emissionTexture\": \"textures/glow.png\"")) << bytes.toStdString();
    EXPECT_TRUE(bytes.contains("\"alphaMode\": \"mask\"")) << bytes.toStdString();
    EXPECT_TRUE(bytes.contains("\"alphaMode\": \"blend\"")) << bytes.toStdString();
    EXPECT_TRUE(bytes.contains("\"wrap\": \"clamp\"")) << bytes.toStdString();
    EXPECT_EQ(scene::serializeProject(*loaded, dir), bytes);
}

TEST(ProjectMaterials, DefaultsAreNotWritten) {
    scene::SceneData scene;
    scene::NodeTree node;
    node.data.mesh = scene::MeshComponent::fromFile("/tmp/models/a.obj");
    node.data.material = scene::MaterialComponent{};
    scene.nodes = {node};
    const std::string text = scene::serializeProject(scene, QDir("/tmp")).toStdString();
    for (const char* key : {"part", "specularColor", "emissionTexture", "normalTexture", "normalScale",
                            "wrap", "opacity", "alphaMode", "alphaCutoff"}) {
        EXPECT_EQ(text.find(std::string("\"") + key + "\""), std::string::npos) << key << " in\n" << text;
    }
}

TEST(ProjectMaterials, DemoScenesStillRoundTripByteForByte) {
    // The scenes written before the new fields existed (in canonical form).
    for (const QString& name :
         {QStringLiteral("teapot.speculum.json"), QStringLiteral("mirrors.speculum.json"),
          QStringLiteral("chrome.speculum.json"), QStringLiteral("glossy.speculum.json")}) {
        const QString path = QString::fromStdString(speculum::testSourcePath("resources/scenes/")) + name;
        std::vector<std::string> warnings;
        auto loaded = scene::loadProject(path, warnings);
        ASSERT_TRUE(loaded.ok()) << name.toStdString() << ": " << loaded.error();
        EXPECT_TRUE(scene::serializeProject(*loaded, QFileInfo(path).absoluteDir()) == readBytes(path))
            << name.toStdString();
    }
}

std::string loadError(const std::string& node) {
    const std::string json = R"({ "format": "speculum-scene", "version": 1, "nodes": [ { "name": "a" }, )"
                             R"({ "name": "b" }, )" +
                             node + "] }";
    std::vector<std::string> warnings;
    auto result = scene::parseProject(QByteArray::fromStdString(json), QDir("/tmp"), warnings);
    return result.ok() ? std::string("<loaded>") : result.error();
}

TEST(ProjectMaterials, BadValuesNameTheirPath) {
    const std::pair<const char*, const char*> cases[] = {
        {R"({ "material": { "alphaMode": "glass" } })",
         R"(nodes[2].material.alphaMode: unknown alpha mode "glass" (expected opaque, mask or blend))"},
        {R"({ "material": { "alphaMode": 1 } })", "nodes[2].material.alphaMode: expected a string"},
        {R"({ "material": { "alphaCutoff": 1.5 } })", "nodes[2].material.alphaCutoff: must be in 0..1"},
        {R"({ "material": { "opacity": -0.1 } })", "nodes[2].material.opacity: must be in 0..1"},
        {R"({ "material": { "specularColor": [2, 0, 0] } })",
         "nodes[2].material.specularColor: colour components must be in 0..1"},
        {R"({ "material": { "normalScale": "x" } })", "nodes[2].material.normalScale: expected a number"},
        {R"({ "material": { "normalTexture": "" } })",
         "nodes[2].material.normalTexture: expected a file path"},
        {R"({ "material": { "emissionTexture": 3 } })",
         "nodes[2].material.emissionTexture: expected a string"},
        {R"({ "material": { "wrap": "tile" } })", "nodes[2].material.wrap: unknown wrap mode \"tile\""},
        {R"({ "material": { "wrap": ["clamp"] } })",
         "nodes[2].material.wrap: expected a wrap mode or [u, v]"},
        {R"({ "material": { "wrap": ["clamp", "x"] } })",
         "nodes[2].material.wrap[1]: unknown wrap mode \"x\""},
        {R"({ "mesh": { "file": "a.glb", "part": -1 } })", "nodes[2].mesh.part: must not be negative"},
        {R"({ "mesh": { "file": "a.glb", "part": 1.5 } })", "nodes[2].mesh.part: expected an integer"},
        {R"({ "mesh": { "builtin": "box", "part": 0 } })",
         "nodes[2].mesh.part: only file meshes have a part"},
    };
    for (const auto& [node, expected] : cases) {
        const std::string m = loadError(node);
        EXPECT_NE(m.find(expected), std::string::npos)
            << node << "\n  gave: " << m << "\n  wanted: " << expected;
    }
}

TEST(ProjectMaterials, WrapReadsOneNameOrAPair) {
    std::vector<std::string> warnings;
    auto scene = scene::parseProject(R"({ "format": "speculum-scene", "version": 1, "nodes": [
        { "material": { "wrap": "mirror" } }, { "material": { "wrap": ["clamp", "repeat"] } } ] })",
                                     QDir("/tmp"), warnings);
    ASSERT_TRUE(scene.ok()) << scene.error();
    EXPECT_EQ(scene->nodes[0].data.material->wrap,
              (std::array{scene::TextureWrap::MirroredRepeat, scene::TextureWrap::MirroredRepeat}));
    EXPECT_EQ(scene->nodes[1].data.material->wrap,
              (std::array{scene::TextureWrap::ClampToEdge, scene::TextureWrap::Repeat}));
}

// The inspector edits the new fields: a file mesh's part (-1 for the whole file), alpha mode, wrap modes.
TEST(ProjectMaterials, InspectorEditsPartAlphaAndWrap) {
    scene::NodeData d;
    d.mesh = scene::MeshComponent::fromFile("/tmp/models/car.glb");
    d.material = scene::MaterialComponent{};
    const auto* part = findNodeProperty(QStringLiteral("mesh.part"));
    ASSERT_NE(part, nullptr);
    EXPECT_TRUE(part->isVisible(d));
    EXPECT_EQ(part->get(d).toInt(), -1);
    ASSERT_TRUE(part->set(d, 2).ok());
    EXPECT_EQ(d.mesh->part, 2);
    ASSERT_TRUE(part->set(d, -1).ok());
    EXPECT_FALSE(d.mesh->part.has_value());
    EXPECT_FALSE(part->set(d, 1.5).ok());
    EXPECT_FALSE(part->set(d, -2).ok());
    scene::NodeData builtin;
    builtin.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Box);
    EXPECT_FALSE(part->isVisible(builtin));
    EXPECT_FALSE(part->set(builtin, 0).ok());

    const auto* alpha = findNodeProperty(QStringLiteral("material.alphaMode"));
    ASSERT_NE(alpha, nullptr);
    ASSERT_TRUE(alpha->set(d, 1).ok());
    EXPECT_EQ(d.material->alphaMode, scene::AlphaMode::Mask);
    const auto* wrapV = findNodeProperty(QStringLiteral("material.wrapV"));
    ASSERT_NE(wrapV, nullptr);
    ASSERT_TRUE(wrapV->set(d, 2).ok());
    EXPECT_EQ(d.material->wrap[1], scene::TextureWrap::MirroredRepeat);
    EXPECT_EQ(d.material->wrap[0], scene::TextureWrap::Repeat);
    const auto* opacity = findNodeProperty(QStringLiteral("material.opacity"));
    ASSERT_NE(opacity, nullptr);
    EXPECT_FALSE(opacity->set(d, 1.5).ok());
    ASSERT_TRUE(opacity->set(d, 0.25).ok());
    EXPECT_EQ(d.material->opacity, 0.25);
}

} // namespace
} // namespace speculum::document
