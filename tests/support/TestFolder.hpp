#pragma once

#include "support/TestPaths.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <string>

namespace speculum::render::test {

// A fresh, empty folder per test under the build's test-data folder, so tests never see each other's files.
inline std::filesystem::path freshTestFolder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path folder = std::filesystem::path(speculum::testDataPath()) / "render_image" /
                                         (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

} // namespace speculum::render::test
