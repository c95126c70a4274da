// Writes that fail half-way, as a user meets them: `speculum` run under a tiny file-size limit (`ulimit -f`,
// with SIGXFSZ ignored, so a write past it fails with EFBIG as a full disk fails with ENOSPC). Every output
// (a still in each format, a reference EXR, the bench folder, a glTF export) must end in a non-zero exit
// and one error line naming the file and the cause, the previous file byte-identical, no temporary left.
#include "support/TestPaths.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct LimitedRun {
    int status = -1;
    std::string err;
};

// `ulimit -f` counts 512-byte blocks in dash (/bin/sh here) and 1 KiB blocks in bash: either way a few KiB,
// far below any image or file the commands write, and above the error line itself.
LimitedRun underFileSizeLimit(const std::string& arguments, const fs::path& errFile, int blocks = 4) {
    const std::string command = "trap '' XFSZ; ulimit -f " + std::to_string(blocks) + "; exec " +
                                speculum::testCliBinary() + " " + arguments + " 2>" + errFile.string() +
                                " >/dev/null";
    LimitedRun run;
    const int raw = std::system(("/bin/sh -c \"" + command + "\"").c_str());
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(errFile);
    run.err.assign(std::istreambuf_iterator<char>(in), {});
    fs::remove(errFile);
    return run;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> entries(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string demo() {
    return speculum::testSourcePath("resources/scenes/teapot.speculum.json");
}

// Only error lines (progress lines start "speculum: " too, but never say "error").
std::vector<std::string> errorLines(const std::string& err) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < err.size()) {
        const std::size_t end = err.find('\n', start);
        const std::string line =
            err.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (line.find("error") != std::string::npos || line.find("cannot") != std::string::npos ||
            line.find("disk") != std::string::npos)
            lines.push_back(line);
        if (end == std::string::npos)
            break;
        start = end + 1;
    }
    return lines;
}

class CliWriteFailures : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::path(speculum::testDataPath()) /
                ("cli-write-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        m_errDir = m_dir.string() + "-err";
        fs::remove_all(m_dir);
        fs::remove_all(m_errDir);
        fs::create_directories(m_dir);
        fs::create_directories(m_errDir);
    }
    void TearDown() override { fs::remove_all(m_errDir); }

    // Runs `arguments` under the limit with `target` (in m_dir) holding `previous`; checks everything.
    void expectFailureKeeps(const std::string& arguments, const fs::path& target,
                            const std::string& previous) {
        std::ofstream(target, std::ios::binary) << previous;
        const std::vector<std::string> before = entries(m_dir);
        const LimitedRun run = underFileSizeLimit(arguments, m_errDir / "err.txt");
        EXPECT_NE(run.status, 0) << arguments << "\n" << run.err;
        EXPECT_NE(run.status, -1) << "killed by a signal rather than failing: " << run.err;
        const std::vector<std::string> lines = errorLines(run.err);
        ASSERT_EQ(lines.size(), 1u) << "one error line: " << run.err;
        EXPECT_NE(lines[0].find(target.filename().string()), std::string::npos) << lines[0];
        EXPECT_NE(lines[0].find("File too large"), std::string::npos) << lines[0];
        EXPECT_NE(lines[0].find("unchanged"), std::string::npos) << lines[0];
        EXPECT_EQ(readFile(target), previous) << "the previous file must stay byte-identical";
        EXPECT_EQ(entries(m_dir), before) << "no temporary (or anything else) may be left";
    }

    fs::path m_dir;
    fs::path m_errDir;
};

TEST_F(CliWriteFailures, RenderInEveryFormatKeepsThePreviousFile) {
    for (const char* ext : {"png", "jpg", "exr", "tif"}) {
        SCOPED_TRACE(ext);
        const fs::path out = m_dir / (std::string("still.") + ext);
        expectFailureKeeps("render " + demo() + " -o " + out.string() + " --size 160x90", out,
                           std::string("previous ") + ext + " bytes");
        fs::remove(out);
    }
}

TEST_F(CliWriteFailures, ReferenceExrKeepsThePreviousFile) {
    const fs::path out = m_dir / "reference.exr";
    expectFailureKeeps("render " + demo() + " --reference -o " + out.string() + " --size 48x27", out,
                       "previous reference bytes");
}

TEST_F(CliWriteFailures, ExportGlbKeepsThePreviousFile) {
    const fs::path out = m_dir / "scene.glb";
    expectFailureKeeps("export " + demo() + " -o " + out.string(), out, "previous glb bytes");
}

TEST_F(CliWriteFailures, BenchKeepsThePreviousRunsOutput) {
    const fs::path scene = m_errDir / "tiny.speculum.json";
    std::ofstream(scene) << R"({"format": "speculum-scene", "version": 1,
  "camera": {"position": [0, 1.5, 4], "target": [0, 0.6, 0], "up": [0, 1, 0], "fovY": 60, "near": 0.1, "far": 30},
  "nodes": [{"name": "Floor", "transform": {"scale": [3, 1, 3]}, "mesh": {"builtin": "plane", "tessellation": 1}},
            {"name": "Lamp", "transform": {"translate": [1, 3, 2]}, "light": {"type": "point"}}]})";
    const fs::path out = m_dir / "results.csv";
    std::ofstream(m_dir / "report.md") << "previous report";
    const std::vector<std::string> before = {"report.md", "results.csv"};
    std::ofstream(out) << "previous results";
    const LimitedRun run =
        underFileSizeLimit("bench " + scene.string() + " --out " + m_dir.string() + " --quick --size 64x36",
                           m_errDir / "err.txt");
    EXPECT_NE(run.status, 0) << run.err;
    EXPECT_NE(run.status, -1) << run.err;
    const std::vector<std::string> lines = errorLines(run.err);
    ASSERT_EQ(lines.size(), 1u) << run.err;
    EXPECT_NE(lines[0].find(m_dir.string()), std::string::npos) << "names the output folder: " << lines[0];
    EXPECT_EQ(lines[0].find(".partial"), std::string::npos) << "not the staging folder: " << lines[0];
    EXPECT_NE(lines[0].find("File too large"), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("the previous output is unchanged"), std::string::npos) << lines[0];
    EXPECT_EQ(readFile(out), "previous results");
    EXPECT_EQ(readFile(m_dir / "report.md"), "previous report");
    EXPECT_EQ(entries(m_dir), before) << "no staging folder or temporary left";
}

// Standard output on a full disk (/dev/full): the report, the JSON or the written file's path never arrives,
// and every command says so in one line and fails, where it used to print half and exit 0.
TEST_F(CliWriteFailures, OutputThatCannotReachStandardOutputFailsTheCommand) {
    const std::string still = (m_dir / "still.png").string();
    for (const std::string& arguments :
         {"explain '" + demo() + "' --json", "explain '" + demo() + "'",
          "time '" + demo() + "' --json --frames 2 -q", "time '" + demo() + "' --frames 2 -q",
          "render '" + demo() + "' --size 32x18 -q -o '" + still + "'", std::string("--version"),
          std::string("--help")}) {
        const std::string command = speculum::testCliBinary() + " " + arguments + " >/dev/full 2>'" +
                                    (m_errDir / "err.txt").string() + "'";
        const int raw = std::system(("/bin/sh -c \"" + command + "\"").c_str());
        const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
        const std::string err = readFile(m_errDir / "err.txt");
        EXPECT_EQ(status, 1) << arguments << "\n" << err;
        EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << arguments << ": one line\n" << err;
        EXPECT_NE(err.find("could not write the output to standard output: No space left on device"),
                  std::string::npos)
            << arguments << "\n"
            << err;
    }
}

} // namespace
