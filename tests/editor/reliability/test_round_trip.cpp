// Inputs the fuzzer found: whatever loads must save and load back to the same bytes.
#include "editor/document/ProjectFile.hpp"

#include <QDir>
#include <gtest/gtest.h>

namespace speculum::document {
namespace {

void expectStableRoundTrip(const QByteArray& json) {
    const QDir base(QStringLiteral("/nonexistent/project"));
    std::vector<std::string> warnings;
    auto first = parseProject(json, base, warnings);
    ASSERT_TRUE(first.ok()) << first.error();
    const QByteArray saved = serializeProject(*first, base);
    auto second = parseProject(saved, base, warnings);
    ASSERT_TRUE(second.ok()) << second.error();
    EXPECT_EQ(serializeProject(*second, base), saved);
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

} // namespace
} // namespace speculum::document
