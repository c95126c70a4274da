// The inspector's property descriptions: every property reads what the model holds, writes valid values,
// and refuses invalid ones with a message naming the property, leaving the value untouched (never clamps).
#include "editor/document/Properties.hpp"

#include "editor/document/NodeFactory.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/TestPaths.hpp"

#include <QDir>
#include <gtest/gtest.h>

namespace {

using namespace speculum::document;
using namespace speculum::scene;

speculum::scene::NodeData fullNode() {
    speculum::scene::NodeData d = makeNode(NewNodeKind::SpotLight).data;
    d.mesh = speculum::scene::MeshComponent::fromBuiltin(speculum::scene::BuiltinMesh::Sphere);
    d.material = speculum::scene::MaterialComponent{};
    d.mirror = speculum::scene::MirrorComponent{};
    d.reflector = speculum::scene::ReflectorComponent{};
    d.animation = speculum::scene::AnimationComponent{};
    d.animation->bounce = speculum::scene::BounceAnimation{};
    d.animation->orbit = speculum::scene::OrbitAnimation{};
    return d;
}

TEST(Properties, KeysAreUniqueAndEveryVisiblePropertyReadsAValue) {
    const speculum::scene::NodeData d = fullNode();
    QStringList keys;
    for (const ComponentInfo& c : nodeComponents()) {
        EXPECT_TRUE(c.present(d)) << c.key.toStdString();
        for (const auto& p : c.properties) {
            EXPECT_FALSE(keys.contains(p.info.key)) << p.info.key.toStdString();
            keys << p.info.key;
            EXPECT_FALSE(p.info.label.isEmpty());
            if (p.isVisible(d) && p.info.key != QStringLiteral("mesh.file") &&
                p.info.key != QStringLiteral("material.texture")) {
                EXPECT_TRUE(p.get(d).isValid()) << p.info.key.toStdString();
            }
        }
    }
    EXPECT_TRUE(keys.contains(QStringLiteral("mirror.reflectivity")));
    EXPECT_TRUE(keys.contains(QStringLiteral("light.shadows.mapSize")));
}

TEST(Properties, ValidValuesAreWrittenAndReadBack) {
    speculum::scene::NodeData d = fullNode();
    const auto* reflectivity = findNodeProperty(QStringLiteral("mirror.reflectivity"));
    ASSERT_TRUE(reflectivity);
    ASSERT_TRUE(reflectivity->set(d, 0.25).ok());
    EXPECT_DOUBLE_EQ(d.mirror->reflectivity, 0.25);
    EXPECT_DOUBLE_EQ(reflectivity->get(d).toDouble(), 0.25);

    const auto* translate = findNodeProperty(QStringLiteral("transform.translate"));
    ASSERT_TRUE(translate->set(d, QVariantList{1.0, -2.0, 3.5}).ok());
    EXPECT_EQ(d.transform.translate, glm::dvec3(1.0, -2.0, 3.5));

    const auto* color = findNodeProperty(QStringLiteral("material.color"));
    ASSERT_TRUE(color->set(d, QVariantList{1.0, 0.0, 0.5}).ok());
    EXPECT_EQ(d.material->color, glm::dvec3(1.0, 0.0, 0.5));

    const auto* type = findNodeProperty(QStringLiteral("light.type"));
    ASSERT_TRUE(type->set(d, 1).ok());
    EXPECT_EQ(d.light->type, speculum::scene::LightType::Directional);
    EXPECT_FALSE(findNodeProperty(QStringLiteral("light.spotAngle"))->isVisible(d))
        << "spot-only field shown";

    const auto* shadows = findNodeProperty(QStringLiteral("light.shadows"));
    ASSERT_TRUE(shadows->set(d, false).ok());
    EXPECT_FALSE(d.light->shadows);
    EXPECT_FALSE(findNodeProperty(QStringLiteral("light.shadows.mapSize"))->isVisible(d));

    const auto* shape = findNodeProperty(QStringLiteral("mesh.source"));
    ASSERT_TRUE(shape->set(d, 2).ok());
    EXPECT_EQ(d.mesh->builtin, speculum::scene::BuiltinMesh::Box);
}

TEST(Properties, InvalidValuesAreRefusedWithAMessageAndNotClamped) {
    speculum::scene::NodeData d = fullNode();
    const speculum::scene::NodeData before = d;
    struct Case {
        const char* key;
        QVariant value;
        const char* mentions;
    };
    const Case cases[] = {
        {"mirror.reflectivity", 2.0, "Reflectivity must be in 0..1, got 2"},
        {"mirror.reflectivity", -0.1, "Reflectivity"},
        {"mirror.size", QVariantList{1.0, 0.0}, "extents must be greater than 0"},
        {"transform.scale", QVariantList{1.0, 0.0, 1.0}, "non-zero"},
        {"material.color", QVariantList{1.5, 0.0, 0.0},
         "Colour components must be in 0..1 (linear RGB), got 1.5"},
        {"material.shininess", 20000.0, "Shininess"},
        {"light.spotAngle", 0.0, "Spot angle must be greater than 0, got 0"},
        {"light.shadows.mapSize", 1000, "power of two"},
        {"light.shadows.pcf", 4, "odd"},
        {"reflector.resolution", 4, "Resolution must be in 8..8192, got 4"},
        {"mesh.tessellation", 2.5, "whole number"},
        {"animation.bounce.period", 0.0, "Bounce period must be greater than 0, got 0"},
        {"node.name", QString(), "Name must not be empty"},
        {"material.texture", QStringLiteral("/no/such/texture.png"), "does not exist"},
        {"transform.translate", QVariantList{std::nan(""), 0.0, 0.0}, "finite"},
    };
    for (const Case& c : cases) {
        const auto* p = findNodeProperty(QString::fromLatin1(c.key));
        ASSERT_TRUE(p) << c.key;
        const auto status = p->set(d, c.value);
        ASSERT_FALSE(status.ok()) << c.key;
        EXPECT_NE(status.error().find(c.mentions), std::string::npos) << c.key << ": " << status.error();
        EXPECT_TRUE(d == before) << c.key << " changed the value although it was refused";
    }
}

TEST(Properties, TexturesMayNameAnImageEmbeddedInAModel) {
    speculum::scene::NodeData d = fullNode();
    const std::string model = speculum::testSourcePath("resources/models/toyset.glb");
    const auto* texture = findNodeProperty(QStringLiteral("material.texture"));
    ASSERT_TRUE(texture);
    const auto status = texture->set(d, QString::fromStdString(model + "#*0"));
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_EQ(d.material->texture.path, model + "#*0");
    // Only a real model file before the '#': anything else is still a missing file.
    EXPECT_FALSE(texture->set(d, QStringLiteral("/no/such/model.glb#*0")).ok());
    // And a mesh file is never an embedded name.
    EXPECT_FALSE(
        findNodeProperty(QStringLiteral("mesh.file"))->set(d, QString::fromStdString(model + "#*0")).ok());
}

TEST(Properties, CameraRulesCoverTheWholeCamera) {
    speculum::scene::CameraData camera;
    const auto* far = findCameraProperty(QStringLiteral("camera.far"));
    ASSERT_TRUE(far);
    auto status = far->set(camera, 0.05); // below near (0.1)
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("greater than near"), std::string::npos) << status.error();
    const auto* target = findCameraProperty(QStringLiteral("camera.target"));
    EXPECT_FALSE(target->set(camera, QVariantList{0.0, 0.0, 1.0}).ok()) << "target on the position";
    EXPECT_TRUE(camera == speculum::scene::CameraData{});
    const auto* depth = findSettingsProperty(QStringLiteral("settings.mirrorDepth"));
    speculum::scene::SceneSettings settings;
    EXPECT_FALSE(depth->set(settings, 17).ok());
    EXPECT_TRUE(depth->set(settings, 5).ok());
    EXPECT_EQ(settings.mirrorDepth, 5);
}

TEST(Properties, ComponentsAddAndRemoveKeepTheNodeLoadable) {
    speculum::scene::NodeData d;
    d.name = "Thing";
    const auto* reflector = findComponent(QStringLiteral("reflector"));
    ASSERT_TRUE(reflector->add(d).ok());
    EXPECT_TRUE(d.mesh) << "a reflector needs a mesh: adding one gives it a sphere";
    const auto* mesh = findComponent(QStringLiteral("mesh"));
    const auto refused = mesh->remove(d);
    EXPECT_FALSE(refused.ok());
    EXPECT_TRUE(d.mesh);
    // Whatever the components, the result saves and loads.
    for (const ComponentInfo& c : nodeComponents()) {
        if (c.optional && !c.present(d)) {
            ASSERT_TRUE(c.add(d).ok()) << c.key.toStdString();
        }
    }
    speculum::scene::SceneData scene;
    scene.nodes.push_back(speculum::scene::NodeTree{d, {}});
    std::vector<std::string> warnings;
    const auto loaded = speculum::scene::parseProject(speculum::scene::serializeProject(scene, QDir::temp()),
                                                      QDir::temp(), warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_TRUE(loaded->nodes.front().data == d);
}

} // namespace

namespace {

TEST(Properties, MirrorTintFresnelAndRoughnessAreEditable) {
    speculum::scene::NodeData d = fullNode();
    const auto* tint = findNodeProperty(QStringLiteral("mirror.tint"));
    const auto* fresnel = findNodeProperty(QStringLiteral("mirror.fresnel"));
    const auto* roughness = findNodeProperty(QStringLiteral("mirror.roughness"));
    ASSERT_TRUE(tint && fresnel && roughness);
    ASSERT_TRUE(tint->set(d, QVariantList{1.0, 0.9, 0.8}).ok());
    EXPECT_DOUBLE_EQ(d.mirror->tint.z, 0.8);
    ASSERT_TRUE(fresnel->set(d, true).ok());
    EXPECT_TRUE(d.mirror->fresnel);
    ASSERT_TRUE(roughness->set(d, 0.3).ok());
    EXPECT_DOUBLE_EQ(d.mirror->roughness, 0.3);
    // Out of range: refused with a message, the value untouched.
    const auto refused = roughness->set(d, 1.5);
    EXPECT_FALSE(refused.ok());
    EXPECT_DOUBLE_EQ(d.mirror->roughness, 0.3);
    EXPECT_FALSE(tint->set(d, QVariantList{2.0, 0.0, 0.0}).ok());
    EXPECT_DOUBLE_EQ(d.mirror->tint.x, 1.0);
}

TEST(Properties, ReflectorFresnelFillUpdateAndMirrorDepthAreEditable) {
    speculum::scene::NodeData d = fullNode();
    const auto* fresnel = findNodeProperty(QStringLiteral("reflector.fresnel"));
    const auto* fill = findNodeProperty(QStringLiteral("reflector.fill"));
    const auto* update = findNodeProperty(QStringLiteral("reflector.update"));
    const auto* depth = findNodeProperty(QStringLiteral("reflector.mirrorDepth"));
    ASSERT_TRUE(fresnel && fill && update && depth);
    ASSERT_TRUE(fresnel->set(d, true).ok());
    EXPECT_TRUE(d.reflector->fresnel);
    ASSERT_TRUE(fill->set(d, 0).ok());
    EXPECT_EQ(d.reflector->fill, speculum::scene::ReflectorFill::Direct);
    ASSERT_TRUE(update->set(d, 2).ok());
    EXPECT_EQ(d.reflector->update, speculum::scene::ReflectorUpdate::Once);
    ASSERT_TRUE(depth->set(d, 3).ok());
    EXPECT_EQ(d.reflector->mirrorDepth, 3);
    EXPECT_FALSE(depth->set(d, 17).ok());
    EXPECT_EQ(d.reflector->mirrorDepth, 3);
    EXPECT_TRUE(depth->info.tooltip.contains(QStringLiteral("mirrors seen in mirrors")))
        << depth->info.tooltip.toStdString();
}

} // namespace
