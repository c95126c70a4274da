// Debian's assimp-testmodels corpus, every file imported in a child process of its own under a time
// limit: a file that hangs the importer or crashes it fails the test naming the file, and the files
// after it are still tried. A file that imports gives a well-formed mesh; one that does not is refused
// with a message that names it. All 595 files take about 5 s (in-process imports alone about 1.5 s), so
// the whole corpus is part of the default run.
#include "scene/import/ModelImport.hpp"
#include "support/MeshChecks.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <gtest/gtest.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace speculum::document {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const fs::path kModels = "/usr/share/assimp/models";
constexpr std::chrono::seconds kLimitPerFile{20};

struct Outcome {
    enum class Kind { Imported, Refused, Malformed, Crashed, TimedOut };
    Kind kind = Kind::Crashed;
    std::string detail; // the refusal, what is malformed, or how the child died
    double seconds = 0.0;
};

// The child's whole answer in one write of at most PIPE_BUF bytes: atomic, and it never blocks.
std::string childReport(const fs::path& file) {
    std::vector<std::string> warnings;
    const auto mesh = scene::importModel(file.string(), warnings);
    std::string report;
    if (!mesh.ok()) {
        report = "R" + mesh.error();
    } else {
        const std::string problem = render::test::wellFormedProblem(*mesh);
        report = problem.empty() ? "I" : "M" + problem;
    }
    report.resize(std::min<std::size_t>(report.size(), PIPE_BUF));
    return report;
}

// Runs `work` in a child process and reads back its report ("I", "R<refusal>" or "M<problem>"), killing
// the child once `limit` has passed.
Outcome runInChild(const std::function<std::string()>& work, std::chrono::milliseconds limit) {
    Outcome outcome;
    const auto start = Clock::now();
    int fds[2];
    if (::pipe(fds) != 0) {
        outcome.detail = std::string("pipe: ") + std::strerror(errno);
        return outcome;
    }
    std::fflush(nullptr); // nothing buffered may be written twice
    const pid_t pid = ::fork();
    if (pid < 0) {
        outcome.detail = std::string("fork: ") + std::strerror(errno);
        return outcome;
    }
    if (pid == 0) {
        ::close(fds[0]);
        const rlimit noCore{0, 0}; // a crash is reported here, not left behind as a core file
        ::setrlimit(RLIMIT_CORE, &noCore);
        const std::string report = work();
        const ssize_t written = ::write(fds[1], report.data(), report.size());
        ::_exit(written == ssize_t(report.size()) ? 0 : 3);
    }
    ::close(fds[1]);
    // The child's end closes when it exits (or dies): poll wakes then, or at the deadline.
    std::string report;
    const auto deadline = start + limit;
    bool timedOut = false;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
        pollfd p{fds[0], POLLIN, 0};
        if (left.count() <= 0 || ::poll(&p, 1, int(left.count())) == 0) {
            timedOut = true;
            break;
        }
        char buffer[PIPE_BUF];
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n > 0) {
            report.append(buffer, std::size_t(n));
        } else if (n == 0 || errno != EINTR) {
            break; // end of file: the child is gone
        }
    }
    ::close(fds[0]);
    if (timedOut) {
        ::kill(pid, SIGKILL);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (timedOut) {
        outcome.kind = Outcome::Kind::TimedOut;
    } else if (WIFSIGNALED(status)) {
        outcome.detail = std::string("killed by ") + strsignal(WTERMSIG(status));
    } else if (WEXITSTATUS(status) != 0 || report.empty()) {
        outcome.detail = "exited with status " + std::to_string(WEXITSTATUS(status));
    } else {
        outcome.kind = report[0] == 'I'   ? Outcome::Kind::Imported
                       : report[0] == 'R' ? Outcome::Kind::Refused
                                          : Outcome::Kind::Malformed;
        outcome.detail = report.substr(1);
    }
    return outcome;
}

Outcome importInChild(const fs::path& file) {
    return runInChild([&] { return childReport(file); }, kLimitPerFile);
}

std::vector<fs::path> corpus() {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kModels)) {
        if (entry.is_regular_file()) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

void importEach(const std::vector<fs::path>& files) {
    int imported = 0, refused = 0;
    double total = 0.0, slowest = 0.0;
    fs::path slowestFile;
    for (const fs::path& file : files) {
        const std::string name = file.lexically_relative(kModels).string();
        const Outcome outcome = importInChild(file);
        total += outcome.seconds;
        if (outcome.seconds > slowest) {
            slowest = outcome.seconds;
            slowestFile = file;
        }
        switch (outcome.kind) {
        case Outcome::Kind::Imported:
            ++imported;
            break;
        case Outcome::Kind::Refused:
            ++refused;
            EXPECT_EQ(outcome.detail.rfind(file.filename().string() + ": ", 0), 0u)
                << name << ": the refusal does not name the file: " << outcome.detail;
            break;
        case Outcome::Kind::Malformed:
            ADD_FAILURE() << name << ": imported a malformed mesh: " << outcome.detail;
            break;
        case Outcome::Kind::Crashed:
            ADD_FAILURE() << name << ": the import crashed (" << outcome.detail << ")";
            break;
        case Outcome::Kind::TimedOut:
            ADD_FAILURE() << name << ": no result within " << kLimitPerFile.count() << " s";
            break;
        }
    }
    std::printf("[ corpus   ] %zu files: %d imported, %d refused, %zu failed; %.1f s in all, slowest %s "
                "(%.2f s)\n",
                files.size(), imported, refused, files.size() - std::size_t(imported + refused), total,
                slowestFile.lexically_relative(kModels).c_str(), slowest);
    EXPECT_GT(imported, 0);
}

// The harness itself: a child that crashes or hangs is reported as such, and a hang costs the limit, not
// the whole test.
TEST(ModelImportCorpus, ChildThatCrashesOrHangsIsReported) {
    const Outcome fine = runInChild([] { return std::string("Rbox.obj: refused"); }, std::chrono::seconds(5));
    EXPECT_EQ(fine.kind, Outcome::Kind::Refused);
    EXPECT_EQ(fine.detail, "box.obj: refused");

    const Outcome crash = runInChild(
        [] {
            std::signal(SIGSEGV, SIG_DFL); // as without a sanitizer's handler: the child dies of it
            std::raise(SIGSEGV);
            return std::string("I");
        },
        std::chrono::seconds(5));
    EXPECT_EQ(crash.kind, Outcome::Kind::Crashed);
    EXPECT_NE(crash.detail.find("killed by"), std::string::npos) << crash.detail;

    const Outcome hang = runInChild(
        [] {
            std::this_thread::sleep_for(std::chrono::seconds(60));
            return std::string("I");
        },
        std::chrono::milliseconds(300));
    EXPECT_EQ(hang.kind, Outcome::Kind::TimedOut);
    EXPECT_LT(hang.seconds, 5.0);
}

TEST(ModelImportCorpus, EveryFileImportsOrIsRefusedInTime) {
    if (!fs::is_directory(kModels)) {
        GTEST_SKIP() << kModels << " is missing; install the assimp-testmodels package";
    }
    importEach(corpus());
}

} // namespace
} // namespace speculum::document
