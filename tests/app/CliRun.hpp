#pragma once

// Runs the real speculum binary (speculum::testCliBinary(), for tests registered with USES_CLI) as a user
// would, capturing its exit status, stdout and stderr.
#include "support/TestPaths.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace speculum::test {

struct CliRun {
    int status = -1;
    std::string out;
    std::string err;
};

// `setup`, when given, is shell commands run first in the same shell (a `ulimit`, say).
inline CliRun runSpeculum(const std::string& arguments, const std::string& setup = {}) {
    namespace fs = std::filesystem;
    static int counter = 0;
    const fs::path errFile = fs::temp_directory_path() / ("speculum-cli-" + std::to_string(::getpid()) + "-" +
                                                          std::to_string(++counter) + ".err");
    const std::string command = (setup.empty() ? std::string() : setup + "; exec ") +
                                speculum::testCliBinary() + " " + arguments + " 2>" + errFile.string();
    CliRun run;
    FILE* pipe = ::popen(command.c_str(), "r");
    std::array<char, 4096> buffer{};
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
        run.out.append(buffer.data(), n);
    const int raw = ::pclose(pipe);
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(errFile);
    run.err.assign(std::istreambuf_iterator<char>(in), {});
    fs::remove(errFile);
    return run;
}

// An empty folder for the running test's files, "PREFIX-<test name>" under the tests' data folder.
inline std::filesystem::path freshCliFolder(const std::string& prefix) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::path(speculum::testDataPath()) /
                            (prefix + "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

} // namespace speculum::test
