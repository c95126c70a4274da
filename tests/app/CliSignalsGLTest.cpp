// Ctrl-C (SIGINT) and SIGTERM while a command works: it stops at its next step with the shell's status for
// an interrupt (130) and one line saying so, and leaves no output, partial file or hidden temporary
// behind, whatever the command. The commands run as real processes; the signal comes once each is under
// way (its progress line on stderr, or after a pause well past its start-up).
#include "app/CliRun.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <set>
#include <spawn.h>
#include <thread>

extern char** environ;

namespace {

namespace fs = std::filesystem;
using speculum::test::freshCliFolder;

std::string readFile(const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

struct Spawned {
    pid_t pid = 0;
    fs::path out, err;
};

Spawned spawnSpeculum(const std::vector<std::string>& arguments, const fs::path& folder) {
    Spawned run{0, folder / "stdout.txt", folder / "stderr.txt"};
    std::vector<std::string> args = {speculum::testCliBinary()};
    args.insert(args.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, run.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&files, 2, run.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    EXPECT_EQ(posix_spawn(&run.pid, argv[0], &files, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&files);
    return run;
}

// Whether the process catches SIGINT and SIGTERM yet (the SigCgt mask of /proc/PID/status): before its
// handlers are in place, a signal would end it the default way however correct the command. A build with
// sanitizers takes seconds to get there.
bool catchesStopSignals(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(status, line);) {
        if (line.rfind("SigCgt:", 0) == 0) {
            const unsigned long long caught = std::stoull(line.substr(7), nullptr, 16);
            const unsigned long long wanted = (1ull << (SIGINT - 1)) | (1ull << (SIGTERM - 1));
            return (caught & wanted) == wanted;
        }
    }
    return false;
}

// Waits until the process catches the stop signals and, where given, stderr contains `sign` (else a
// pause into its work); sends `signal`, and returns how it ended: its exit status, or -signal when the
// signal killed it.
int interruptWhenUnderWay(const Spawned& run, const std::string& sign, int signal) {
    const auto started = std::chrono::steady_clock::now();
    while (!catchesStopSignals(run.pid) &&
           std::chrono::steady_clock::now() - started < std::chrono::seconds(60))
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_TRUE(catchesStopSignals(run.pid)) << "no handlers after a minute: " << readFile(run.err);
    if (sign.empty()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    } else {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (readFile(run.err).find(sign) == std::string::npos &&
               std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        EXPECT_NE(readFile(run.err).find(sign), std::string::npos)
            << "never under way: " << readFile(run.err);
    }
    ::kill(run.pid, signal);
    int raw = 0;
    EXPECT_EQ(::waitpid(run.pid, &raw, 0), run.pid);
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -WTERMSIG(raw);
}

std::set<std::string> outputsIn(const fs::path& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().filename() != "stdout.txt" && entry.path().filename() != "stderr.txt")
            names.insert(entry.path().filename().string());
    return names;
}

std::string scene(const char* name) {
    return speculum::testSourcePath(std::string("resources/scenes/") + name);
}

std::string lastLine(std::string text) {
    while (!text.empty() && text.back() == '\n')
        text.pop_back();
    return text.substr(text.find_last_of('\n') == std::string::npos ? 0 : text.find_last_of('\n') + 1);
}

TEST(CliSignals, AnInterruptedTraceWritesNothingNotEvenATemporary) {
    const fs::path folder = freshCliFolder("signals");
    const Spawned run = spawnSpeculum({"render", scene("mirrors.speculum.json"), "--reference", "--samples",
                                       "4096", "--size", "320x180", "-o", (folder / "still.tif").string()},
                                      folder);
    EXPECT_EQ(interruptWhenUnderWay(run, "speculum: tracing", SIGINT), 130) << readFile(run.err);
    EXPECT_EQ(lastLine(readFile(run.err)), "speculum: render: interrupted; nothing was written");
    EXPECT_TRUE(outputsIn(folder).empty()) << "no still, no hidden temporary";
    EXPECT_TRUE(readFile(run.out).empty());
}

TEST(CliSignals, TimeAndExplainStopOnSigtermAndPrintNothing) {
    const fs::path folder = freshCliFolder("signals");
    const struct {
        std::vector<std::string> arguments;
        std::string said;
    } cases[] = {
        {{"time", scene("mirrors.speculum.json"), "--frames", "100000", "--size", "160x90"},
         "speculum: time: interrupted; nothing was printed"},
        {{"explain", scene("mirrors.speculum.json"), "--frame", "100", "--size", "1920x1080", "--json"},
         "speculum: explain: interrupted; nothing was printed"},
    };
    for (const auto& c : cases) {
        const Spawned run = spawnSpeculum(c.arguments, folder);
        for (const int signal : {SIGTERM}) {
            EXPECT_EQ(interruptWhenUnderWay(run, "", signal), 130)
                << c.arguments[0] << ": " << readFile(run.err);
        }
        EXPECT_EQ(lastLine(readFile(run.err)), c.said);
        EXPECT_TRUE(readFile(run.out).empty()) << c.arguments[0] << " printed " << readFile(run.out);
        EXPECT_TRUE(outputsIn(folder).empty());
    }
}

// A frame that will take minutes is said before the wait, with its estimate (the plan's warning, printed as
// soon as the frame is planned); and a second signal ends a command stuck in such a frame at once.
TEST(CliSignals, AMapThatTakesMinutesIsWarnedOfBeforeTheWorkAndASecondSignalEndsIt) {
    const fs::path folder = freshCliFolder("signals");
    QJsonObject project =
        QJsonDocument::fromJson(QByteArray::fromStdString(readFile(scene("chrome.speculum.json")))).object();
    QJsonArray nodes = project["nodes"].toArray();
    for (QJsonValueRef node : nodes) {
        QJsonObject o = node.toObject();
        if (!o.contains("reflector"))
            continue;
        QJsonObject reflector = o["reflector"].toObject();
        reflector["resolution"] = 2048;
        reflector["roughness"] = 0.5;
        reflector["update"] = "always";
        o["reflector"] = reflector;
        node = o;
    }
    project["nodes"] = nodes;
    QJsonObject settings = project["settings"].toObject();
    settings["prefilterSamples"] = 1024;
    project["settings"] = settings;
    const fs::path costly = folder / "costly.speculum.json";
    std::string text = QJsonDocument(project).toJson().toStdString();
    for (std::size_t at = text.find("\"textures/"); at != std::string::npos;
         at = text.find("\"textures/", at))
        text.replace(at + 1, 0, speculum::testSourcePath("resources/scenes") + "/");
    std::ofstream(costly) << text;

    const Spawned run = spawnSpeculum({"explain", costly.string(), "--size", "160x90"}, folder);
    const auto started = std::chrono::steady_clock::now();
    const std::string sign = "pre-filtered with 1024 samples a texel is about";
    while (readFile(run.err).find(sign) == std::string::npos &&
           std::chrono::steady_clock::now() - started < std::chrono::seconds(30))
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const std::string err = readFile(run.err);
    EXPECT_NE(err.find("speculum: warning: reflector"), std::string::npos) << err;
    EXPECT_NE(err.find("roughly"), std::string::npos) << err;
    int raw = 0;
    EXPECT_EQ(::waitpid(run.pid, &raw, WNOHANG), 0) << "the warning came before the frame was done";
    ::kill(run.pid, SIGTERM); // asks it to stop at its next step: the frame still runs
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    ::kill(run.pid, SIGTERM); // the second ends it
    ASSERT_EQ(::waitpid(run.pid, &raw, 0), run.pid);
    EXPECT_TRUE(WIFSIGNALED(raw) || (WIFEXITED(raw) && WEXITSTATUS(raw) == 130)) << readFile(run.err);
    EXPECT_TRUE(readFile(run.out).empty());
}

} // namespace
