#include "scene/evaluate/Snapshot.hpp"

#include "scene/evaluate/PickScene.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/DocumentTestSupport.hpp"

#include <QDir>
#include <QFileInfo>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <numbers>
#include <thread>

namespace speculum::document {
namespace {

using test::freshTestFolder;
using test::qpath;

constexpr double kTolerance = 1e-12;

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = kTolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

scene::NodeTree boxNode(const std::string& name, const scene::Transform& transform) {
    scene::NodeTree node;
    node.data.name = name;
    node.data.transform = transform;
    node.data.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Box);
    return node;
}

render::FrameInput snap(const scene::SceneData& data, double time, scene::MeshLibrary& meshes,
                        std::vector<scene::Warning>& warnings) {
    scene::Scene scene;
    scene.reset(data);
    return scene::snapshot(scene, time, meshes, warnings);
}

TEST(Snapshot, EulerAnglesApplyXThenYThenZ) {
    // +Y turned 90° about X is +Z; then 90° about Y is +X. The other order would give +Z.
    expectNear(apply(scene::rotationMatrix({90, 90, 0}), {0, 1, 0}), {1, 0, 0});
    // +X turned about Y (90°) is −Z; then about Z nothing changes for −Z.
    expectNear(apply(scene::rotationMatrix({0, 90, 90}), {1, 0, 0}), {0, 0, -1});
    // X then Z: +Y → +Z (X) → +Z (Z).
    expectNear(apply(scene::rotationMatrix({90, 0, 90}), {0, 1, 0}), {0, 0, 1});
}

TEST(Snapshot, LocalMatrixIsTranslateRotateScale) {
    // (1,0,0) scaled by 2 on X → (2,0,0), turned 90° about Z → (0,2,0), moved by (10,0,0).
    scene::SceneData data;
    data.nodes.push_back(boxNode("n", {{10, 0, 0}, {0, 0, 90}, {2, 1, 1}}));
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = snap(data, 0.0, meshes, warnings);
    ASSERT_EQ(frame.items.size(), 1u);
    expectNear(apply(frame.items[0].world, {1, 0, 0}), {10, 2, 0});
    EXPECT_TRUE(warnings.empty());
}

TEST(Snapshot, ChildWorldIsParentWorldTimesLocal) {
    scene::SceneData data;
    scene::NodeTree parent = boxNode("parent", {{0, 5, 0}, {0, 90, 0}, {2, 2, 2}});
    scene::NodeTree child = boxNode("child", {{1, 0, 0}, {0, 0, 0}, {1, 1, 1}});
    child.children.push_back(boxNode("grandchild", {{0, 0, 1}, {0, 0, 0}, {0.5, 0.5, 0.5}}));
    parent.children.push_back(child);
    data.nodes.push_back(parent);
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = snap(data, 0.0, meshes, warnings);
    ASSERT_EQ(frame.items.size(), 3u);
    EXPECT_EQ(frame.items[1].name, "child");
    // Child origin: (1,0,0) scaled by 2 → (2,0,0), turned 90° about Y → (0,0,-2), up 5.
    expectNear(apply(frame.items[1].world, {0, 0, 0}), {0, 5, -2});
    // Grandchild origin: child-space (0,0,1) → parent-space (1,0,1) → (2,0,2) → Y90: (2,0,-2) → (2,5,-2).
    expectNear(apply(frame.items[2].world, {0, 0, 0}), {2, 5, -2});
    // A unit along the grandchild's X is 2 · 0.5 = 1 long in the world, pointing along world −Z.
    expectNear(apply(frame.items[2].world, {1, 0, 0}) - apply(frame.items[2].world, {0, 0, 0}), {0, 0, -1});
}

TEST(Snapshot, WorldMatricesKeepDoublePrecisionFarFromTheOrigin) {
    scene::SceneData data;
    scene::NodeTree far = boxNode("far", {{1e8, 0, 0}, {0, 0, 0}, {1, 1, 1}});
    far.children.push_back(boxNode("near it", {{0.125 + 1e-6, 0, 0}, {0, 0, 0}, {1, 1, 1}}));
    data.nodes.push_back(far);
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = snap(data, 0.0, meshes, warnings);
    ASSERT_EQ(frame.items.size(), 2u);
    EXPECT_NEAR(frame.items[1].world[3].x - 1e8, 0.125 + 1e-6,
                1e-8); // a float matrix would be off by up to 4
}

TEST(Snapshot, BounceFollowsItsDefinition) {
    scene::SceneData data;
    scene::NodeTree node = boxNode("hopper", {{0, -1, -3}, {0, 0, 0}, {1, 1, 1}});
    node.data.animation = scene::AnimationComponent{scene::BounceAnimation{1.0, 2.0}, std::nullopt};
    data.nodes.push_back(node);
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    auto yAt = [&](double t) { return snap(data, t, meshes, warnings).items.at(0).world[3].y; };
    EXPECT_NEAR(yAt(0.0), -1.0, kTolerance);
    EXPECT_NEAR(yAt(1.0), 0.0, kTolerance);                                   // top of the hop at period/2
    EXPECT_NEAR(yAt(0.5), -1.0 + std::sin(std::numbers::pi / 4), kTolerance); // height·|sin(πt/T)|
    EXPECT_NEAR(yAt(2.0), -1.0, kTolerance);
    EXPECT_NEAR(yAt(2.5), yAt(0.5), kTolerance); // |sin| keeps it above its rest position
    EXPECT_EQ(snap(data, 0.75, meshes, warnings).time, 0.75);
}

TEST(Snapshot, OrbitFollowsItsDefinitionInTheParentsSpace) {
    scene::SceneData data;
    scene::NodeTree parent;
    parent.data.name = "pivot";
    parent.data.transform.translate = {100, 0, 0};
    scene::NodeTree light;
    light.data.name = "Light";
    light.data.transform.translate = {0, 2, -2}; // replaced by the orbit
    light.data.light = scene::LightComponent{};
    light.data.animation =
        scene::AnimationComponent{std::nullopt, scene::OrbitAnimation{{0, 2, -3}, 1.5, 6.0}};
    parent.children.push_back(light);
    data.nodes.push_back(parent);
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    auto at = [&](double t) { return snap(data, t, meshes, warnings).lights.at(0).position; };
    expectNear(at(0.0), {101.5, 2, -3});
    expectNear(at(1.5), {100, 2, -1.5}); // quarter turn: +Z
    expectNear(at(3.0), {98.5, 2, -3});
    expectNear(at(6.0), at(0.0), 1e-12);
}

TEST(Snapshot, BounceLiftsAnOrbit) {
    scene::NodeData node;
    node.animation = scene::AnimationComponent{scene::BounceAnimation{0.5, 2.0},
                                               scene::OrbitAnimation{{0, 0, 0}, 1.0, 4.0}};
    expectNear(scene::animatedTranslate(node, 1.0), {0, 0.5, 1});
}

TEST(Snapshot, LightsPointAlongTheirWorldMinusY) {
    scene::SceneData data;
    scene::NodeTree sun;
    sun.data.name = "Sun";
    sun.data.transform = {{3, 4, 5}, {0, 0, 90}, {1, 7, 1}};
    sun.data.light =
        scene::LightComponent{scene::LightType::Directional, {1, 0.5, 0.25}, 2.0, 30, 0.15, std::nullopt};
    scene::NodeTree spot;
    spot.data.name = "Spot";
    spot.data.light = scene::LightComponent{scene::LightType::Spot,        {1, 1, 1}, 1.0, 25, 0.2,
                                            scene::ShadowComponent{512, 3}};
    data.nodes = {sun, spot};
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = snap(data, 0.0, meshes, warnings);
    ASSERT_EQ(frame.lights.size(), 2u);
    EXPECT_TRUE(frame.items.empty());
    const render::Light& s = frame.lights[0];
    EXPECT_EQ(s.type, render::LightType::Directional);
    expectNear(s.position, {3, 4, 5});
    expectNear(s.direction, {1, 0, 0}); // −Y turned 90° about Z, unit length despite the scale
    expectNear(s.color, {1, 0.5, 0.25});
    EXPECT_EQ(s.intensity, 2.0);
    EXPECT_FALSE(s.shadows.has_value());
    const render::Light& p = frame.lights[1];
    EXPECT_EQ(p.type, render::LightType::Spot);
    expectNear(p.direction, {0, -1, 0});
    EXPECT_EQ(p.spotAngle, 25.0);
    EXPECT_EQ(p.spotBlend, 0.2);
    EXPECT_TRUE(p.shadows.has_value());
    EXPECT_EQ(p.shadows->mapSize, 512);
    EXPECT_EQ(p.shadows->pcf, 3);
}

TEST(Snapshot, MirrorsAndTheReflector) {
    scene::SceneData data;
    scene::NodeTree table;
    table.data.name = "Table";
    table.data.transform.translate = {0, -1, -3};
    table.data.mirror = scene::MirrorComponent{{4, 2}, 0.5, scene::MirrorTechnique::Texture, {}};
    table.data.material = scene::MaterialComponent{};
    table.data.material->texture.path = "/abs/marble.png";
    scene::NodeTree plain;
    plain.data.name = "Plain";
    plain.data.mirror = scene::MirrorComponent{};
    scene::NodeTree ball;
    ball.data.name = "Ball";
    ball.data.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere, 12);
    ball.data.reflector = scene::ReflectorComponent{scene::ReflectorMap::DualParaboloid, 128, 0.9};
    ball.data.reflector->fresnel = true;
    ball.data.reflector->fill = scene::ReflectorFill::Direct;
    ball.data.reflector->update = scene::ReflectorUpdate::Once;
    ball.data.reflector->mirrorDepth = 2;
    ball.data.reflector->parallax =
        scene::ReflectorParallax{scene::ParallaxShape::Box, 1, {-1, -2, -3}, {4, 5, 6}};
    data.nodes = {table, plain, ball};
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = snap(data, 0.0, meshes, warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_TRUE(frame.items.empty()) << "a reflector's mesh is not drawn a second time as an item";
    ASSERT_EQ(frame.mirrors.size(), 2u);
    const render::Mirror& m = frame.mirrors[0];
    EXPECT_EQ(m.name, "Table");
    expectNear(apply(m.world, {0, 0, 0}), {0, -1, -3});
    EXPECT_EQ(m.size, glm::dvec2(4, 2));
    EXPECT_EQ(m.reflectivity, 0.5);
    EXPECT_EQ(m.technique, render::MirrorTechnique::Texture);
    EXPECT_TRUE(m.hasMaterial);
    EXPECT_EQ(m.material.texture.path, "/abs/marble.png");
    EXPECT_FALSE(frame.mirrors[1].hasMaterial);
    EXPECT_EQ(frame.mirrors[1].technique, render::MirrorTechnique::Stencil);
    ASSERT_EQ(frame.reflectors.size(), 1u);
    EXPECT_EQ(frame.reflectors[0].name, "Ball");
    EXPECT_EQ(frame.reflectors[0].map, render::ReflectorMap::DualParaboloid);
    EXPECT_EQ(frame.reflectors[0].resolution, 128);
    EXPECT_EQ(frame.reflectors[0].reflectivity, 0.9);
    EXPECT_EQ(frame.reflectors[0].mesh, meshes.builtin(scene::BuiltinMesh::Sphere, 12));
    EXPECT_TRUE(frame.reflectors[0].fresnel);
    EXPECT_EQ(frame.reflectors[0].fill, render::ReflectorFill::Direct);
    EXPECT_EQ(frame.reflectors[0].update, render::ReflectorUpdate::Once);
    EXPECT_EQ(frame.reflectors[0].mirrorDepth, 2);
    ASSERT_TRUE(frame.reflectors[0].parallax);
    EXPECT_EQ(frame.reflectors[0].parallax->shape, render::ParallaxShape::Box);
    EXPECT_EQ(frame.reflectors[0].parallax->min, glm::dvec3(-1, -2, -3));
    EXPECT_EQ(frame.reflectors[0].parallax->max, glm::dvec3(4, 5, 6));
}

TEST(Snapshot, ABrokenReflectorBecomesAWarning) {
    scene::SceneData data;
    scene::NodeTree first;
    first.data.name = "First";
    first.data.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere, 8);
    first.data.reflector = scene::ReflectorComponent{};
    scene::NodeTree second = first;
    second.data.name = "Second";
    scene::NodeTree meshless;
    meshless.data.name = "Meshless";
    meshless.data.reflector = scene::ReflectorComponent{};
    data.nodes = {meshless, first, second};
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = snap(data, 0.0, meshes, warnings);
    ASSERT_EQ(frame.reflectors.size(), 2u) << "every reflector with a mesh, in file order";
    EXPECT_EQ(frame.reflectors[0].name, "First");
    EXPECT_EQ(frame.reflectors[1].name, "Second");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].code, scene::WarningCode::ReflectorWithoutMesh);
    EXPECT_EQ(warnings[0].node, "Meshless");
    EXPECT_EQ(warnings[0].file, "");
    EXPECT_EQ(warnings[0].message, "node 'Meshless': reflector skipped: it needs a mesh on the same node");
}

TEST(Snapshot, MaterialDefaultsAndAbsoluteTexturePaths) {
    std::vector<std::string> loadWarnings;
    scene::Scene scene;
    ASSERT_TRUE(scene::openProject(scene, test::demoScenePath(), loadWarnings).ok());
    std::vector<scene::Warning> warnings;
    scene::MeshLibrary meshes;
    const render::FrameInput frame = scene::snapshot(scene, 0.0, meshes, warnings);
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(frame.items.size(), 1u);
    EXPECT_EQ(frame.items[0].name, "Teapot");
    EXPECT_EQ(frame.items[0].material.specular, 0.5);
    EXPECT_EQ(frame.items[0].mesh->triangleCount(), 32u * 8u * 8u * 2u);
    // The marble table is a textured mirror.
    ASSERT_EQ(frame.mirrors.size(), 1u);
    EXPECT_EQ(frame.mirrors[0].name, "Table");
    EXPECT_TRUE(frame.mirrors[0].hasMaterial);
    EXPECT_EQ(frame.mirrors[0].reflectivity, 0.5);
    expectNear(glm::dvec3(frame.mirrors[0].size, 0.0), {4, 4, 0});
    const QString texture = QString::fromStdString(frame.mirrors[0].material.texture.path);
    EXPECT_TRUE(QFileInfo(texture).isAbsolute());
    EXPECT_TRUE(QFileInfo(texture).isFile()) << texture.toStdString();
    ASSERT_EQ(frame.lights.size(), 1u);
    expectNear(frame.lights[0].position, {1.5, 2, -3});
    EXPECT_EQ(frame.settings.mirrorDepth, 3);
    EXPECT_EQ(frame.camera.fovY, 65.0);

    // A mesh node without a material gets the default material.
    scene::SceneData data;
    data.nodes.push_back(boxNode("bare", {}));
    const render::FrameInput bare = snap(data, 0.0, meshes, warnings);
    const render::Material defaults;
    EXPECT_EQ(bare.items.at(0).material.color, defaults.color);
    EXPECT_EQ(bare.items.at(0).material.diffuse, 1.0);
    EXPECT_EQ(bare.items.at(0).material.specular, 0.0);
}

TEST(Snapshot, ARelativePathSetByCodeIsTakenRelativeToTheProject) {
    scene::SceneData data;
    scene::NodeTree node = boxNode("textured", {});
    node.data.material = scene::MaterialComponent{};
    node.data.material->texture.path = "textures/wood.png";
    data.nodes.push_back(node);
    scene::Scene scene;
    scene.reset(data);
    scene.setProjectPath("/projects/demo/scene.speculum.json");
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = scene::snapshot(scene, 0.0, meshes, warnings);
    EXPECT_EQ(frame.items.at(0).material.texture.path, "/projects/demo/textures/wood.png");
}

TEST(Snapshot, MeshHandlesAreStableAcrossFrames) {
    scene::SceneData data;
    data.nodes.push_back(boxNode("a", {}));
    scene::NodeTree teapot = boxNode("b", {});
    teapot.data.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Teapot, 3);
    data.nodes.push_back(teapot);
    scene::Scene scene;
    scene.reset(data);
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput one = scene::snapshot(scene, 0.0, meshes, warnings);
    const render::FrameInput two = scene::snapshot(scene, 1.0, meshes, warnings);
    EXPECT_EQ(one.items[0].mesh, two.items[0].mesh);
    EXPECT_EQ(one.items[1].mesh, two.items[1].mesh);
    EXPECT_NE(meshes.builtin(scene::BuiltinMesh::Teapot, 3), meshes.builtin(scene::BuiltinMesh::Teapot, 4));
    EXPECT_EQ(meshes.size(), 3u);
}

TEST(Snapshot, AMissingMeshFileIsAWarningNotACrash) {
    const auto folder = freshTestFolder();
    scene::SceneData data;
    scene::NodeTree missing;
    missing.data.name = "Ghost";
    missing.data.mesh = scene::MeshComponent::fromFile((folder / "ghost.obj").string());
    scene::NodeTree garbage;
    garbage.data.name = "Garbage";
    garbage.data.mesh = scene::MeshComponent::fromFile((folder / "garbage.obj").string());
    test::writeBytes(qpath(folder / "garbage.obj"), "this is not a model\n\x01\x02\x03");
    data.nodes = {missing, garbage, boxNode("Box", {})};
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = snap(data, 0.0, meshes, warnings);
    ASSERT_EQ(frame.items.size(), 1u);
    EXPECT_EQ(frame.items[0].name, "Box");
    const auto skipped = [&](const std::string& node, const std::filesystem::path& file) {
        return std::count_if(warnings.begin(), warnings.end(), [&](const scene::Warning& w) {
            return w.code == scene::WarningCode::MeshSkipped && w.node == node && w.file == file.string();
        });
    };
    EXPECT_EQ(skipped("Ghost", folder / "ghost.obj"), 1)
        << ::testing::PrintToString(scene::messages(warnings));
    EXPECT_EQ(skipped("Garbage", folder / "garbage.obj"), 1)
        << ::testing::PrintToString(scene::messages(warnings));
}

// The warning names its node and the model file by its absolute path (a relative one is the project's),
// whether the node draws the file's parts or the file as one mesh (under a material of its own).
TEST(Snapshot, AMissingModelFileIsAMeshSkippedWarningOnItsNodeAndFile) {
    const auto folder = freshTestFolder();
    scene::SceneData data;
    scene::NodeTree statue;
    statue.data.name = "Statue";
    statue.data.mesh = scene::MeshComponent::fromFile("models/statue.glb");
    scene::NodeTree plinth = statue;
    plinth.data.name = "Plinth";
    plinth.data.material = scene::MaterialComponent{};
    data.nodes = {statue, plinth};
    scene::Scene scene;
    scene.reset(data);
    scene.setProjectPath(qpath(folder / "scene.speculum.json"));
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = scene::snapshot(scene, 0.0, meshes, warnings);
    EXPECT_TRUE(frame.items.empty());
    const std::string file = (folder / "models" / "statue.glb").string();
    ASSERT_EQ(warnings.size(), 2u) << ::testing::PrintToString(scene::messages(warnings));
    EXPECT_EQ(warnings[0].code, scene::WarningCode::MeshSkipped);
    EXPECT_EQ(warnings[0].node, "Statue");
    EXPECT_EQ(warnings[0].file, file);
    EXPECT_EQ(warnings[1].code, scene::WarningCode::MeshSkipped);
    EXPECT_EQ(warnings[1].node, "Plinth");
    EXPECT_EQ(warnings[1].file, file);
    // What `speculum render --keep-going` prints and the editor lists.
    EXPECT_EQ(warnings[0].message, "node 'Statue': mesh skipped: '" + file + "': file not found");
}

TEST(Snapshot, MeshFilesAreImportedOnceAndAgainWhenTheyChange) {
    const auto folder = freshTestFolder();
    const QString path = qpath(folder / "tri.obj");
    test::writeBytes(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    auto first = meshes.file(path.toStdString(), warnings);
    ASSERT_TRUE(first.ok()) << first.error();
    EXPECT_EQ((*first)->triangleCount(), 1u);
    auto again = meshes.file(path.toStdString(), warnings);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(*first, *again);

    // Two triangles now; a different size is a change even if the clock did not tick.
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    test::writeBytes(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
    auto changed = meshes.file(path.toStdString(), warnings);
    ASSERT_TRUE(changed.ok()) << changed.error();
    EXPECT_NE(*changed, *first);
    EXPECT_EQ((*changed)->triangleCount(), 2u);
}

// An imported part's whole material reaches the renderer: the embedded texture as its decoded image (from
// the MeshLibrary), wrap modes on every texture, alpha mode, and the part's own mesh.
TEST(Snapshot, ImportedPartMaterialReachesTheRenderer) {
    const std::string glb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!std::filesystem::is_regular_file(glb)) {
        GTEST_SKIP() << "assimp-testmodels not installed";
    }
    scene::SceneData data;
    scene::NodeTree node;
    node.data.name = "box";
    node.data.mesh = scene::MeshComponent::fromFile(glb);
    node.data.mesh->part = 0;
    scene::MaterialComponent m;
    m.texture.path = glb + "#*0";
    m.normalTexture.path = "/nowhere/normal.png";
    m.specularColor = {0.5, 0.25, 1};
    m.wrap = {scene::TextureWrap::ClampToEdge, scene::TextureWrap::MirroredRepeat};
    m.alphaMode = scene::AlphaMode::Blend;
    m.alphaCutoff = 0.25;
    m.opacity = 0.75;
    m.normalScale = 0.5;
    node.data.material = m;
    data.nodes.push_back(node);
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = snap(data, 0.0, meshes, warnings);
    ASSERT_EQ(frame.items.size(), 1u) << ::testing::PrintToString(scene::messages(warnings));
    const render::Material& r = frame.items[0].material;
    ASSERT_TRUE(r.texture.image);
    EXPECT_GT(r.texture.image->width, 0);
    EXPECT_EQ(r.texture.path, glb + "#*0");
    EXPECT_FALSE(r.normalTexture.image); // a plain file: the renderer loads it itself
    EXPECT_EQ(r.normalTexture.path, "/nowhere/normal.png");
    EXPECT_EQ(r.wrap[0], render::TextureWrap::ClampToEdge);
    EXPECT_EQ(r.wrap[1], render::TextureWrap::MirroredRepeat);
    EXPECT_EQ(r.alphaMode, render::AlphaMode::Blend);
    EXPECT_EQ(r.alphaCutoff, 0.25);
    EXPECT_EQ(r.opacity, 0.75);
    EXPECT_EQ(r.normalScale, 0.5);
    EXPECT_EQ(r.specularColor, glm::dvec3(0.5, 0.25, 1));
    auto part = meshes.part(glb, 0, warnings);
    ASSERT_TRUE(part.ok());
    EXPECT_EQ(frame.items[0].mesh, part.value());
}

} // namespace
} // namespace speculum::document

namespace speculum::document {
namespace {

// A hidden node, and everything under it, is in no frame and under no click; the file keeps it (written
// only where set).
TEST(Snapshot, AHiddenNodeAndItsChildrenAreInNoFrameAndUnderNoClick) {
    scene::SceneData data;
    scene::NodeTree shown = boxNode("Shown", {});
    scene::NodeTree hidden = boxNode("Hidden", {{0.0, 0.0, -5.0}, {}, {1.0, 1.0, 1.0}});
    hidden.data.hidden = true;
    hidden.children.push_back(boxNode("Child", {{0.0, 3.0, 0.0}, {}, {1.0, 1.0, 1.0}}));
    data.nodes = {shown, hidden};
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> warnings;
    const render::FrameInput frame = snap(data, 0.0, meshes, warnings);
    ASSERT_EQ(frame.items.size(), 1u);
    EXPECT_EQ(frame.items.front().name, "Shown");

    scene::Scene scene;
    scene.reset(data);
    const scene::PickScene picks = scene::buildPickScene(scene, 0.0, meshes);
    ASSERT_EQ(picks.meshes.size(), 1u);
    EXPECT_EQ(scene.findNode(picks.meshes.front().id)->name(), "Shown");

    const QByteArray json = scene::serializeProject(data, QDir(QStringLiteral("/tmp")));
    EXPECT_EQ(json.count("\"hidden\": true"), 1) << "written where set, and only there";
    std::vector<std::string> notes;
    auto reread = scene::parseProject(json, QDir(QStringLiteral("/tmp")), notes);
    ASSERT_TRUE(reread) << reread.error();
    EXPECT_EQ(*reread, data);
}

} // namespace
} // namespace speculum::document
