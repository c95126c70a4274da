// Inputs the fuzzer found: whatever loads must save and load back to the same bytes.
#include "scene/project/ProjectFile.hpp"
#include "scene/project/Recovery.hpp"

#include <QDir>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace speculum::document {
namespace {

void expectStableRoundTrip(const QByteArray& json) {
    const QDir base(QStringLiteral("/nonexistent/project"));
    std::vector<std::string> warnings;
    auto first = scene::parseProject(json, base, warnings);
    ASSERT_TRUE(first.ok()) << first.error();
    const QByteArray saved = scene::serializeProject(*first, base);
    auto second = scene::parseProject(saved, base, warnings);
    ASSERT_TRUE(second.ok()) << second.error();
    EXPECT_EQ(scene::serializeProject(*second, base), saved);
}

TEST(RoundTrip, ByteOrderMarkInsideAnUnknownFieldSurvivesSaving) {
    // Qt's parser drops a raw U+FEFF inside strings; written escaped it survives.
    expectStableRoundTrip(
        "{\"format\": \"speculum-scene\", \"version\": 1, \"nodes\": [],"
        " \"extra\": {\"\xEF\xBB\xBFkey\": 1, \"tint\": 2, \"a\\ufeffb\": \"x\xEF\xBB\xBFy\"}}");
}

TEST(RoundTrip, UnknownFieldsOfEveryKindAreKeptInOrder) {
    expectStableRoundTrip(
        R"({"format": "speculum-scene", "version": 1, "future": {"z": [1, {"b": null, "a": true}], "a": "é"},
        "nodes": [{"name": "N", "mirror": {"size": [1, 2], "later": 3}, "comment": "kept"}]})");
}

TEST(RoundTrip, TheEditorViewAndItsUnknownFieldsAreKept) {
    expectStableRoundTrip(
        R"({"format": "speculum-scene", "version": 1, "editorView": {"later": {"b": [1], "a": null},
        "target": [0, -0.1, 1e-300], "position": [1e-7, 12345.678, -3]}, "nodes": []})");
}

// An autosave carries the editor's view like a save does, so a restored document reopens where it looked.
TEST(RoundTrip, TheEditorViewSurvivesARecoveryFile) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    scene::SceneData data;
    data.camera.fovY = 40;
    data.editorView = scene::EditorView{{4, 5, 6}, {0.5, 0.25, -1.0 / 3.0}};
    data.unknown["editorView"].insert(QStringLiteral("later"), 2);
    scene::RecoveryStore store(dir.path(), 4244);
    ASSERT_TRUE(store.write(data, QStringLiteral("/projects/room.speculum.json")).ok());

    std::vector<std::string> warnings;
    auto restored = scene::RecoveryStore::load({store.scenePath(), QString(), QDateTime()}, warnings);
    ASSERT_TRUE(restored.ok()) << restored.error();
    EXPECT_EQ(*restored, data);
    EXPECT_EQ(restored->camera, data.camera);
}

} // namespace
} // namespace speculum::document
