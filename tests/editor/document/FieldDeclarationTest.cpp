// A field added to a declaration and nowhere else is read, written, shown, hashed and swept. This program
// is built against its own copies of the libraries, compiled with SPECULUM_FIELD_PROBE, which gives the
// planar mirror's parameters one more field, `probe` (render/frame/Mirror.hpp): the declaration is the
// only place that names it, so each check below fails if a reader, writer, inspector, hash or sweep
// spells out its fields instead of walking the declaration.
#include "accuracy/Sweep.hpp"
#include "accuracy/Variation.hpp"
#include "editor/document/Properties.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QDir>
#include <algorithm>
#include <gtest/gtest.h>

#ifndef SPECULUM_FIELD_PROBE
#error "the field-declaration test needs the probe build (SPECULUM_FIELD_PROBE)"
#endif

namespace speculum::document {
namespace {

std::string mirrorProject(const std::string& mirror) {
    return R"({ "format": "speculum-scene", "version": 1, "nodes": [ { "name": "Glass", "mirror": )" +
           mirror + " } ] }";
}

base::Result<scene::SceneData> parse(const std::string& json) {
    std::vector<std::string> warnings;
    return scene::parseProject(QByteArray::fromStdString(json), QDir("/tmp"), warnings);
}

TEST(FieldDeclaration, TheReaderReadsAndChecksIt) {
    auto data = parse(mirrorProject(R"({ "probe": 0.3 })"));
    ASSERT_TRUE(data.ok()) << data.error();
    ASSERT_TRUE(data->nodes.at(0).data.mirror);
    EXPECT_EQ(data->nodes[0].data.mirror->probe, 0.3);
    EXPECT_TRUE(data->nodes[0].data.unknown.empty()) << "a declared field is not kept as an unknown one";

    auto absent = parse(mirrorProject("{}"));
    ASSERT_TRUE(absent.ok()) << absent.error();
    EXPECT_EQ(absent->nodes.at(0).data.mirror->probe, 0.5) << "the member's initializer is the default";

    auto outOfRange = parse(mirrorProject(R"({ "probe": 2 })"));
    ASSERT_FALSE(outOfRange.ok());
    EXPECT_EQ(outOfRange.error(), "nodes[0].mirror.probe: must be in 0..1, got 2");
    auto wrongType = parse(mirrorProject(R"({ "probe": "high" })"));
    ASSERT_FALSE(wrongType.ok());
    EXPECT_NE(wrongType.error().find("nodes[0].mirror.probe: expected a number"), std::string::npos)
        << wrongType.error();
}

TEST(FieldDeclaration, TheWriterWritesItAndTheFileReadsBack) {
    auto data = parse(mirrorProject(R"({ "probe": 0.3 })"));
    ASSERT_TRUE(data.ok()) << data.error();
    const QByteArray bytes = scene::serializeProject(*data, QDir("/tmp"));
    EXPECT_TRUE(bytes.contains("\"probe\": 0.3")) << bytes.toStdString();
    std::vector<std::string> warnings;
    auto again = scene::parseProject(bytes, QDir("/tmp"), warnings);
    ASSERT_TRUE(again.ok()) << again.error();
    EXPECT_EQ(*again, *data);
    EXPECT_EQ(scene::serializeProject(*again, QDir("/tmp")), bytes) << "saving twice gives the same bytes";
}

TEST(FieldDeclaration, TheInspectorShowsItWithItsLabelRangeAndChecks) {
    const Property<scene::NodeData>* probe = findNodeProperty(QStringLiteral("mirror.probe"));
    ASSERT_NE(probe, nullptr) << "the mirror component has a `mirror.probe` property";
    EXPECT_EQ(probe->info.label, QStringLiteral("Probe"));
    EXPECT_EQ(probe->info.kind, PropertyKind::Number);
    EXPECT_EQ(probe->info.minimum, 0.0);
    EXPECT_EQ(probe->info.maximum, 1.0);
    EXPECT_TRUE(probe->info.slider);
    EXPECT_EQ(probe->info.tooltip, QStringLiteral("A setting of the field-declaration test's build"));

    scene::NodeData node;
    node.mirror = scene::MirrorComponent{};
    EXPECT_EQ(probe->get(node).toDouble(), 0.5);
    ASSERT_TRUE(probe->set(node, 0.75).ok());
    EXPECT_EQ(node.mirror->probe, 0.75);
    const base::Status refused = probe->set(node, 1.5);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error(), "Probe must be in 0..1, got 1.5");
    EXPECT_EQ(node.mirror->probe, 0.75) << "a refused value leaves the node as it was";
}

// A reflector whose environment map sees a planar mirror.
render::FrameInput mirrorSeenByAReflector() {
    render::FrameInput input;
    input.camera.position = {0.0, 0.0, 5.0};
    render::Mirror wall;
    wall.name = "Wall";
    wall.world = glm::dmat4(1.0);
    wall.world[3] = glm::dvec4(0.0, 0.0, -3.0, 1.0);
    input.mirrors.push_back(wall);
    render::Reflector ball;
    ball.name = "Ball";
    ball.mesh = std::make_shared<const render::MeshData>(render::makeSphere(8));
    input.reflectors = {ball};
    return input;
}

TEST(FieldDeclaration, TheEnvironmentMapsSignatureSeesIt) {
    const render::FrameInput base = mirrorSeenByAReflector();
    render::FrameInput changed = base;
    changed.mirrors[0].probe = 0.9;
    EXPECT_NE(render::envmapSignature(changed, 0), render::envmapSignature(base, 0))
        << "a mirror field drawn in maps changes what the reflector's map holds";
}

TEST(FieldDeclaration, TheSweepVariesItAndItsResultsApplyBack) {
    const render::FrameInput scene = mirrorSeenByAReflector();
    const auto configurations = accuracy::planSweep(scene, accuracy::sceneTraits(scene, std::nullopt), {});
    std::vector<double> swept;
    for (const accuracy::Configuration& c : configurations)
        if (const render::FieldValue* v = c.variation.find(accuracy::Part::Mirrors, "probe"))
            swept.push_back(std::get<double>(*v));
    EXPECT_EQ(swept, (std::vector<double>{0.25, 0.75}));

    accuracy::Variation variation;
    variation.set(accuracy::Part::Mirrors, "probe", 0.25);
    const render::FrameInput applied = accuracy::applyVariation(scene, variation, std::nullopt, {});
    EXPECT_EQ(applied.mirrors.at(0).probe, 0.25);

    const accuracy::Settings settings = accuracy::effectiveSettings(applied, std::nullopt, false);
    const auto column =
        std::find_if(settings.begin(), settings.end(), [](const auto& s) { return s.first == "probe"; });
    ASSERT_NE(column, settings.end()) << "bench results have a `probe` column";
    EXPECT_EQ(column->second, "0.25");

    auto back = accuracy::variationOf("probe", "0.75");
    ASSERT_TRUE(back.ok()) << back.error();
    const render::FieldValue* value = back->find(accuracy::Part::Mirrors, "probe");
    ASSERT_NE(value, nullptr);
    EXPECT_EQ(std::get<double>(*value), 0.75);
    EXPECT_FALSE(accuracy::variationOf("probe", "3").ok()) << "a results file's value is range-checked";
}

} // namespace
} // namespace speculum::document
