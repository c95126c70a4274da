#include "scene/import/ModelImportProcess.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <new>
#include <poll.h>
#include <string_view>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define SPECULUM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SPECULUM_ASAN 1
#endif
#endif
#if defined(SPECULUM_ASAN)
#include <sanitizer/common_interface_defs.h>
#endif

namespace speculum::scene::detail {
namespace {

std::atomic<void (*)()> g_testAction{nullptr};

// The pipe carries frames: one byte of kind, eight of payload length, the payload.
enum FrameKind : std::uint8_t { kProgressFrame = 1, kAnswerFrame = 2 };
constexpr std::size_t kFrameHeader = 9;

// The phases importChecked reports, so that the parent hands on the same string literals (a receiver may
// keep the pointer) rather than pointers into its buffer.
constexpr const char* kPhases[] = {"reading",   "materials", "converting", "welding",
                                   "repairing", "bounds",    "done"};

const char* internPhase(std::string_view phase) {
    for (const char* known : kPhases) {
        if (phase == known) {
            return known;
        }
    }
    return kPhases[0];
}

// Child side: all of it, or _exit — the parent treats a short stream as no answer.
void writeAll(int fd, const void* data, std::size_t size) {
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t written = ::write(fd, bytes, size);
        if (written < 0 && errno == EINTR) {
            continue;
        }
        if (written <= 0) {
            ::_exit(3);
        }
        bytes += written;
        size -= static_cast<std::size_t>(written);
    }
}

void writeFrame(int fd, FrameKind kind, std::string_view payload) {
    char header[kFrameHeader];
    header[0] = static_cast<char>(kind);
    const std::uint64_t length = payload.size();
    std::memcpy(header + 1, &length, sizeof length);
    writeAll(fd, header, sizeof header);
    writeAll(fd, payload.data(), payload.size());
}

// Physical memory: the most the child may map beyond what it inherited; past it the machine would only
// swap.
rlim_t physicalMemory() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    return pages > 0 && pageSize > 0 ? static_cast<rlim_t>(pages) * static_cast<rlim_t>(pageSize)
                                     : rlim_t(8) << 30;
}

// The address space the child inherited from the editor (its libraries, driver mappings, heap).
rlim_t inheritedAddressSpace() {
    const int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        return 0;
    }
    char text[64] = {};
    const ssize_t got = ::read(fd, text, sizeof text - 1);
    ::close(fd);
    const unsigned long long pages = got > 0 ? std::strtoull(text, nullptr, 10) : 0;
    return static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE));
}

void limitChild(int cpuSeconds) {
    // A crash inside the reader is expected here: no core file for it.
    const rlimit noCore{0, 0};
    ::setrlimit(RLIMIT_CORE, &noCore);
    rlimit cpu{};
    ::getrlimit(RLIMIT_CPU, &cpu);
    const rlim_t soft = static_cast<rlim_t>(cpuSeconds);
    if (cpu.rlim_max == RLIM_INFINITY || soft + 2 <= cpu.rlim_max) {
        // SIGXCPU at the soft limit; SIGKILL two seconds on should it be caught or ignored.
        const rlimit wanted{soft, soft + 2};
        ::setrlimit(RLIMIT_CPU, &wanted);
    }
#if !defined(SPECULUM_ASAN)
    // AddressSanitizer reserves terabytes of shadow address space: no address space limit under it.
    if (const rlim_t inherited = inheritedAddressSpace(); inherited > 0) {
        rlimit memory{};
        ::getrlimit(RLIMIT_AS, &memory);
        const rlim_t wanted = inherited + physicalMemory();
        if (memory.rlim_cur == RLIM_INFINITY || wanted < memory.rlim_cur) {
            memory.rlim_cur = wanted;
            ::setrlimit(RLIMIT_AS, &memory);
        }
    }
#endif
    // If memory runs out anyway, the OOM killer takes the child, not the editor.
    const int fd = ::open("/proc/self/oom_score_adj", O_WRONLY | O_CLOEXEC);
    if (fd >= 0) {
        const char kMost[] = "1000";
        (void)!::write(fd, kMost, sizeof kMost - 1);
        ::close(fd);
    }
}

// The editor's (or a fuzzer's, or a sanitizer's) handlers would run in the child: a crash there must just
// end the child, and the parent reports it.
void restoreDefaultSignals() {
    for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGXCPU, SIGTERM, SIGINT, SIGPIPE,
                             SIGALRM, SIGUSR1, SIGUSR2, SIGTRAP}) {
        struct sigaction action {};
        action.sa_handler = SIG_DFL;
        sigemptyset(&action.sa_mask);
        ::sigaction(signal, &action, nullptr);
    }
    sigset_t none;
    sigemptyset(&none);
    ::pthread_sigmask(SIG_SETMASK, &none, nullptr);
    ::alarm(0);
#if defined(SPECULUM_ASAN)
    // A sanitizer report in the child still prints, but the fuzzer's "crash" callback (which would save
    // the input as a crash of the fuzzing process) must not run: the parent turns it into a refusal.
    __sanitizer_set_death_callback(nullptr);
#endif
}

[[noreturn]] void runChild(int fd, const std::function<std::string(const ChildProgress&)>& body,
                           int cpuSeconds) {
    restoreDefaultSignals();
    limitChild(cpuSeconds);
    if (void (*action)() = g_testAction.load()) {
        action();
    }
    const ChildProgress progress = [fd](double fraction, const char* phase) {
        std::string payload(sizeof fraction, '\0');
        std::memcpy(payload.data(), &fraction, sizeof fraction);
        payload += phase != nullptr ? phase : "";
        writeFrame(fd, kProgressFrame, payload);
    };
    std::string answer;
    try {
        answer = body(progress);
    } catch (...) {
        ::_exit(4); // the body catches what it can; anything else is "no answer"
    }
    writeFrame(fd, kAnswerFrame, answer);
    ::close(fd);
    ::_exit(0); // no atexit handlers, no static destructors: they belong to the editor
}

std::string signalName(int signal) {
    const char* abbreviation = ::sigabbrev_np(signal);
    return abbreviation != nullptr ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
}

double cpuSecondsOf(const rusage& usage) {
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// False when the child was reaped elsewhere (SIGCHLD ignored): its exit status is then unknown.
bool reap(pid_t pid, int& status, rusage& usage) {
    for (;;) {
        if (::wait4(pid, &status, 0, &usage) == pid) {
            return true;
        }
        if (errno != EINTR) {
            return false;
        }
    }
}

// Parent side: hands on every complete frame in buffer[parsed..], progress to control.progress. True once
// the answer (the last frame) is in: the buffer becomes it rather than a copy, as it can be hundreds of
// megabytes.
bool handOnFrames(std::string& buffer, std::size_t& parsed, const ImportControl& control,
                  std::string& answer) {
    while (buffer.size() - parsed >= kFrameHeader) {
        std::uint64_t length = 0;
        std::memcpy(&length, buffer.data() + parsed + 1, sizeof length);
        if (buffer.size() - parsed - kFrameHeader < length) {
            break; // not all here yet
        }
        const auto kind = static_cast<FrameKind>(buffer[parsed]);
        const std::string_view payload(buffer.data() + parsed + kFrameHeader, length);
        if (kind == kProgressFrame && payload.size() >= sizeof(double)) {
            double fraction = 0;
            std::memcpy(&fraction, payload.data(), sizeof fraction);
            if (control.progress) {
                control.progress(fraction, internPhase(payload.substr(sizeof fraction)));
            }
        } else if (kind == kAnswerFrame) {
            buffer.erase(0, parsed + kFrameHeader);
            buffer.resize(length);
            answer = std::move(buffer);
            return true;
        }
        parsed += kFrameHeader + length;
    }
    if (parsed > 0 && parsed == buffer.size()) {
        buffer.clear();
        parsed = 0;
    }
    return false;
}

// How reading the child's stream ended.
struct ChildReading {
    bool answered = false;
    bool killed = false;      // the child was killed: cancelled, timed out or out of memory here
    bool timedOut = false;    // past the wall-clock limit
    bool outOfMemory = false; // no room here for what the child sent
};

// Parent side: reads the child's frames until its answer or the end of its stream, or kills it when the
// caller cancels, when it runs past `wallLimit`, or when what it sends does not fit here.
ChildReading readChild(pid_t pid, int fd, const ImportControl& control, std::chrono::seconds wallLimit,
                       std::string& answer) {
    ChildReading reading;
    const auto started = std::chrono::steady_clock::now();
    std::string buffer;
    std::size_t parsed = 0;
    char chunk[1 << 16];
    for (;;) {
        if (control.cancel != nullptr && control.cancel->load()) {
            ::kill(pid, SIGKILL);
            reading.killed = true;
            break;
        }
        if (std::chrono::steady_clock::now() - started > wallLimit) {
            ::kill(pid, SIGKILL);
            reading.killed = reading.timedOut = true;
            break;
        }
        pollfd waiting{fd, POLLIN, 0};
        const int ready = ::poll(&waiting, 1, 50);
        if (ready < 0 && errno != EINTR) {
            break;
        }
        if (ready <= 0) {
            continue;
        }
        const ssize_t got = ::read(fd, chunk, sizeof chunk);
        if (got < 0 && (errno == EINTR || errno == EAGAIN)) {
            continue;
        }
        if (got <= 0) {
            break; // the child closed its end: finished or died
        }
        try {
            buffer.append(chunk, static_cast<std::size_t>(got));
        } catch (const std::bad_alloc&) {
            // No room here for what the child sends: stop it rather than let the editor fail.
            ::kill(pid, SIGKILL);
            reading.killed = reading.outOfMemory = true;
            break;
        }
        if (handOnFrames(buffer, parsed, control, answer)) {
            reading.answered = true;
            break; // the last frame; the child exits next
        }
    }
    return reading;
}

// How many processes the kernel's out-of-memory killer has ended since boot (/proc/vmstat's oom_kill,
// which counts a memory cgroup's kills too), or -1 where the kernel does not say.
long long oomKillsSoFar() {
    std::ifstream in("/proc/vmstat");
    std::string key;
    long long value = 0;
    while (in >> key >> value) {
        if (key == "oom_kill") {
            return value;
        }
    }
    return -1;
}

// Why SIGKILL ended the child: the out-of-memory killer only when it killed something meanwhile.
std::string killedBecause(long long oomKillsBefore) {
    if (oomKillsBefore < 0) {
        return "the model reader was killed (SIGKILL): it ran out of memory, or was stopped from outside";
    }
    if (oomKillsSoFar() > oomKillsBefore) {
        return "ran out of memory reading the model"; // the kernel's out-of-memory killer ended it
    }
    return "the model reader was killed from outside (SIGKILL) before it finished; not read";
}

// Why a child that gave no usable answer failed, for the user: from how the reading ended and, where the
// child was reaped here, how it ended.
std::string childFailure(const ChildReading& reading, bool reaped, int status, const rusage& usage,
                         int cpuSeconds, std::chrono::seconds wallLimit, long long oomKillsBefore) {
    const std::string limit = std::to_string(cpuSeconds);
    if (reading.outOfMemory) {
        return "ran out of memory reading the model";
    }
    if (!reaped) {
        return "the model reader stopped without an answer";
    }
    if (reading.timedOut) {
        return "took more than " + std::to_string(wallLimit.count()) + " s to read; stopped";
    }
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        const bool outOfCpu = signal == SIGXCPU || (signal == SIGKILL && cpuSecondsOf(usage) >= cpuSeconds);
        if (outOfCpu) {
            return "took more than " + limit + " s of CPU to read; stopped";
        }
        if (signal == SIGKILL) {
            return killedBecause(oomKillsBefore);
        }
        return "the model reader crashed on this file (" + signalName(signal) + "); it is probably damaged";
    }
    if (WIFEXITED(status)) {
        return "the model reader stopped without an answer (exit status " +
               std::to_string(WEXITSTATUS(status)) + "); the file is probably damaged";
    }
    return "the model reader stopped without an answer";
}

} // namespace

void setImportChildTestAction(void (*action)()) {
    g_testAction.store(action);
}

ChildRun runInChildProcess(const std::function<std::string(const ChildProgress&)>& body,
                           const ImportControl& control, int cpuSeconds) {
    ChildRun run;
    const long long oomKillsBefore = oomKillsSoFar();
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) {
        run.outcome = ChildRun::Outcome::NotStarted;
        return run;
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        run.outcome = ChildRun::Outcome::NotStarted;
        return run;
    }
    if (pid == 0) {
        ::close(fds[0]);
        runChild(fds[1], body, cpuSeconds);
    }
    ::close(fds[1]);
    const int fd = fds[0];

    // A child that waits forever (a lock it inherited held) spends no CPU time: a wall-clock limit too.
    const auto wallLimit = std::chrono::seconds(2 * static_cast<long long>(cpuSeconds) + 5);
    const ChildReading reading = readChild(pid, fd, control, wallLimit, run.answer);
    ::close(fd);
    int status = 0;
    rusage usage{};
    const bool reaped = reap(pid, status, usage);

    if (reading.killed && !reading.timedOut && !reading.outOfMemory) {
        run.outcome = ChildRun::Outcome::Cancelled;
        run.answer.clear();
        return run;
    }
    if (reading.answered && (!reaped || (WIFEXITED(status) && WEXITSTATUS(status) == 0))) {
        run.outcome = ChildRun::Outcome::Answered;
        return run;
    }
    run.outcome = ChildRun::Outcome::Failed;
    run.answer.clear();
    run.error = childFailure(reading, reaped, status, usage, cpuSeconds, wallLimit, oomKillsBefore);
    return run;
}

} // namespace speculum::scene::detail
