#pragma once

// A full disk without root: a forked child lowers its file-size limit (RLIMIT_FSIZE) and ignores
// SIGXFSZ, so a write past the limit fails part-way with EFBIG exactly where a full disk fails with
// ENOSPC. With root, a child in its own mount namespace can also mount a real, small tmpfs and fill it.
// The child reports through a pipe; an alarm ends it if a regression made it hang.
//
// fork() copies only the calling thread. A worker thread of OpenImageIO's or OpenEXR's pool that held a
// lock at that moment leaves it held for ever in the child, and a pool the child inherits has no threads
// behind it: an EXR write there can wait for ever. So a program that includes this header does its image
// I/O on the calling thread from its first line, and inChild refuses to fork once a test started threads.
//
// Two more ways a child could inherit a held lock, both closed before the first test runs: a library's
// first use (OIIO cataloguing its plugins, a codec building its tables) is done in the parent, so no child
// ever initialises a library; and the threads that libraries start as they load (OpenVDB's log4cplus
// pool) are waited for until they sleep, since a fork while one of them is still starting, holding its
// pool's lock, would leave that lock held for ever in the child.

#include <OpenImageIO/imageio.h>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sched.h>
#include <string>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace speculum::render::test {

struct ChildOutcome {
    int exitCode = -1; // the child's exit status; -1 when it died of a signal (see signal)
    int signal = 0;    // what killed it, if anything
    std::string text;  // what the child reported
};

// The threads of this process (1 when only the calling one runs), from /proc/self/task.
inline int threadsAlive() {
    int count = 0;
    std::error_code ec;
    for (auto it = std::filesystem::directory_iterator("/proc/self/task", ec);
         !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
        ++count;
    }
    return count;
}

// Whether every thread but the calling one is asleep (state S in /proc/self/task/N/stat).
inline bool otherThreadsAsleep() {
    const std::string self = std::to_string(::gettid());
    std::error_code ec;
    for (auto it = std::filesystem::directory_iterator("/proc/self/task", ec);
         !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
        if (it->path().filename() == self) {
            continue;
        }
        std::ifstream stat(it->path() / "stat");
        std::string line;
        std::getline(stat, line);
        const std::size_t afterName = line.rfind(')');
        if (afterName != std::string::npos && afterName + 2 < line.size() && line[afterName + 2] != 'S') {
            return false;
        }
    }
    return true;
}

// Set during static initialisation, before any test can start a pool: image I/O on the calling thread,
// and every image library this program can reach initialised here, in the parent.
inline const bool kImageIoOnTheCallingThread = [] {
    OIIO::attribute("threads", 1);      // no workers in OIIO's own pool
    OIIO::attribute("exr_threads", -1); // and none in OpenEXR's
    std::string formats;
    OIIO::getattribute("format_list", formats); // catalogues every plugin
    for (const char* name : {"x.png", "x.jpg", "x.tif", "x.exr"}) {
        (void)OIIO::ImageOutput::create(name);
        (void)OIIO::ImageInput::create(name, /*do_open=*/false);
    }
    return true;
}();

// Threads that the libraries start as they load (a few, idle, before main): they never run a test's work,
// so once asleep they hold no lock a child could need. Any thread beyond them was started by a test.
inline const int kThreadsAtStart = [] {
    for (int tries = 0; tries < 500 && !otherThreadsAsleep(); ++tries) {
        ::usleep(2000);
    }
    return threadsAlive();
}();

// Runs `body` in a forked child; what it puts in `text` comes back. Exit code is body's return value.
// With a thread alive that a test started (a pool that did work), it does not fork: the outcome says so,
// and the test fails on it instead of hanging.
inline ChildOutcome inChild(const std::function<int(std::string& text)>& body, unsigned timeoutSeconds = 30) {
    if (const int threads = threadsAlive(); threads > kThreadsAtStart) {
        return {-1, 0,
                std::to_string(threads - kThreadsAtStart) +
                    " threads started since the program began: a forked child could wait for ever on a lock "
                    "one of them held"};
    }
    int fds[2];
    if (::pipe(fds) != 0) {
        return {-1, 0, "pipe() failed"};
    }
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        ::alarm(timeoutSeconds);
        std::string text;
        const int code = body(text);
        const char* p = text.data();
        std::size_t left = text.size();
        while (left > 0) {
            const ssize_t n = ::write(fds[1], p, left);
            if (n <= 0) {
                break;
            }
            p += n;
            left -= static_cast<std::size_t>(n);
        }
        ::close(fds[1]);
        std::_Exit(code);
    }
    ::close(fds[1]);
    ChildOutcome outcome;
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            break;
        }
        outcome.text.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status)) {
        outcome.exitCode = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        outcome.signal = WTERMSIG(status);
    }
    return outcome;
}

// In a child: every later write past `bytes` fails with EFBIG (the signal that would kill is ignored).
inline bool limitFileSize(rlim_t bytes) {
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{};
    limit.rlim_cur = limit.rlim_max = bytes;
    return ::setrlimit(RLIMIT_FSIZE, &limit) == 0;
}

// In a child: mounts a tmpfs of `sizeOption` ("64k") over `folder` in a private mount namespace, so the
// rest of the machine never sees it. Returns why it cannot (not root, no namespaces), empty when done.
inline std::string mountSmallFileSystem(const std::filesystem::path& folder, const char* sizeOption) {
    if (::geteuid() != 0) {
        return "not running as root: no tmpfs can be mounted";
    }
    if (::unshare(CLONE_NEWNS) != 0) {
        return std::string("unshare(CLONE_NEWNS) failed: ") + std::strerror(errno);
    }
    if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) {
        return std::string("cannot make the mounts private: ") + std::strerror(errno);
    }
    const std::string options = std::string("size=") + sizeOption;
    if (::mount("tmpfs", folder.c_str(), "tmpfs", 0, options.c_str()) != 0) {
        return std::string("mount -t tmpfs failed: ") + std::strerror(errno);
    }
    return {};
}

inline std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Every entry of a folder (hidden ones included), by name.
inline std::vector<std::string> folderEntries(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        names.push_back(entry.path().filename().string());
    }
    return names;
}

} // namespace speculum::render::test
