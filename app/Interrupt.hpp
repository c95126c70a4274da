#pragma once

#include <csignal>
#include <string>

namespace speculum::app {

// Ctrl-C (SIGINT) and a polite kill (SIGTERM) stop a command at its next step instead of killing it
// half-way: every staged file is then removed by its owner (base::AtomicFile), so nothing partial or
// hidden stays behind, and the command exits with the shell's status for an interrupt (130) after one
// line. A second signal while the first is being handled ends the process at once (the usual way out
// of a step that does not return). The previous handlers come back when the object goes.
class StopOnSignal {
public:
    StopOnSignal();
    ~StopOnSignal();
    StopOnSignal(const StopOnSignal&) = delete;
    StopOnSignal& operator=(const StopOnSignal&) = delete;

    static bool requested();

private:
    struct sigaction m_previousInt {};
    struct sigaction m_previousTerm {};
};

inline constexpr int kInterruptedStatus = 130;

// Says "speculum: COMMAND: interrupted; OUTCOME" once (later calls print nothing) and returns 130.
int interrupted(const std::string& command, const std::string& outcome = "nothing was written");
// Whether interrupted() has spoken already.
bool interruptionReported();

} // namespace speculum::app
