#pragma once

#include "scene/project/ProjectFile.hpp"
#include "support/TestPaths.hpp"

#include <QFile>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

namespace speculum::document::test {

// A fresh, empty folder per test under the build's test-data folder, so tests never see each other's files.
inline std::filesystem::path freshTestFolder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path folder = std::filesystem::path(speculum::testDataPath()) / "editor_document" /
                                         (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

inline QString qpath(const std::filesystem::path& p) {
    return QString::fromStdString(p.string());
}

inline QString demoScenePath() {
    return QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"));
}

inline QByteArray readBytes(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    return file.readAll();
}

inline void writeBytes(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate)) << path.toStdString();
    ASSERT_EQ(file.write(bytes), bytes.size());
}

} // namespace speculum::document::test
