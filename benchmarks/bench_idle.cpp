// Idle cost of the editor: the real `speculum PROJECT` on each static demo, left alone under a
// display. After it has settled it must use almost nothing: the check is under 3% of one core (CPU time of
// the whole process, every thread, from /proc/PID/stat). The teapot demo is animated; it is measured too,
// for comparison (the editor plays a scene with animation when it opens it, so it keeps drawing).
// Run: scripts/with-display build/release/benchmarks/speculum_bench_idle [--settle S] [--sample S] [PROJECT…]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <signal.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr double kIdleLimitPercent = 3.0;

// utime + stime of a process in seconds, or a negative number when it is gone.
double cpuSeconds(pid_t pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto close = text.rfind(')'); // the command name may hold spaces
    if (close == std::string::npos) {
        return -1.0;
    }
    std::istringstream fields(text.substr(close + 2));
    std::string field;
    unsigned long long utime = 0, stime = 0;
    // Fields after the name start at 3 (state); utime is 14 and stime 15.
    for (int index = 3; index <= 15 && (fields >> field); ++index) {
        if (index == 14) {
            utime = std::stoull(field);
        } else if (index == 15) {
            stime = std::stoull(field);
        }
    }
    return double(utime + stime) / double(sysconf(_SC_CLK_TCK));
}

struct Measurement {
    bool ok = false;
    double percent = 0.0;
    std::string error;
};

Measurement measure(const std::string& project, const fs::path& home, double settleSeconds,
                    double sampleSeconds) {
    Measurement m;
    std::fflush(stdout); // the child must not write what is still buffered here
    const pid_t pid = fork();
    if (pid < 0) {
        m.error = "fork failed";
        return m;
    }
    if (pid == 0) {
        // Settings and recovery files of its own: no layout or crashed session of the user's.
        setenv("XDG_CONFIG_HOME", (home / "config").c_str(), 1);
        setenv("XDG_DATA_HOME", (home / "data").c_str(), 1);
        setenv("XDG_CACHE_HOME", (home / "cache").c_str(), 1);
        std::freopen("/dev/null", "w", stdout);
        std::freopen("/dev/null", "w", stderr);
        execl(SPECULUM_BINARY, SPECULUM_BINARY, project.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(settleSeconds));
    const auto start = Clock::now();
    const double before = cpuSeconds(pid);
    std::this_thread::sleep_for(std::chrono::duration<double>(sampleSeconds));
    const double after = cpuSeconds(pid);
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid || before < 0.0 || after < 0.0) {
        m.error = "the editor exited early (no display? run under scripts/with-display)";
        return m;
    }
    kill(pid, SIGTERM);
    waitpid(pid, &status, 0);
    m.ok = true;
    m.percent = 100.0 * (after - before) / wall;
    return m;
}

} // namespace

int main(int argc, char** argv) {
    double settle = 6.0, sample = 5.0;
    std::vector<std::string> projects;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--settle" && i + 1 < argc) {
            settle = std::atof(argv[++i]);
        } else if (arg == "--sample" && i + 1 < argc) {
            sample = std::atof(argv[++i]);
        } else {
            projects.push_back(arg);
        }
    }
    const fs::path scenes = fs::path(SPECULUM_SOURCE_DIR) / "resources" / "scenes";
    bool defaults = projects.empty();
    if (defaults) {
        for (const char* name : {"chrome", "mirrors", "models", "teapot"}) {
            projects.push_back((scenes / (std::string(name) + ".speculum.json")).string());
        }
    }
    if (!std::getenv("DISPLAY")) {
        std::fprintf(stderr, "speculum_bench_idle needs a display: run it under scripts/with-display\n");
        return 2;
    }
    const fs::path home = fs::temp_directory_path() / ("speculum-bench-idle-" + std::to_string(getpid()));
    fs::create_directories(home);
    std::printf("idle CPU of `speculum PROJECT` after %.0f s, over %.0f s (%% of one core; limit %.0f%% for "
                "static scenes)\n",
                settle, sample, kIdleLimitPercent);
    bool pass = true;
    for (const std::string& project : projects) {
        const Measurement m = measure(project, home, settle, sample);
        const std::string name = fs::path(project).filename().string();
        const bool animated = name.rfind("teapot", 0) == 0; // the one demo with animation
        if (!m.ok) {
            std::printf("%-28s error: %s\n", name.c_str(), m.error.c_str());
            pass = false;
            continue;
        }
        const bool over = !animated && m.percent >= kIdleLimitPercent;
        std::printf("%-28s %6.2f %%%s\n", name.c_str(), m.percent,
                    animated ? "  (animated: the editor plays it from start-up)"
                    : over   ? "  OVER THE LIMIT"
                             : "");
        pass = pass && !over;
    }
    std::error_code ignored;
    fs::remove_all(home, ignored);
    return pass ? 0 : 1;
}
