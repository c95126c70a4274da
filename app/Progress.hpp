#pragma once

#include <chrono>
#include <string>

namespace speculum::app {

// Progress of long work on stderr, the way terminals and logs each want it. On a terminal one line is
// rewritten in place (at most ten times a second, and the last state always); in a log or a pipe a line
// is printed per tenth of the work, so a log stays short. --quiet prints nothing (warnings and errors are
// not progress: they always print).
class Progress {
public:
    // Set once from --quiet, before any command runs.
    static void setQuiet(bool quiet);
    static bool quiet();

    explicit Progress(std::string label); // "rendering", "tracing": the line is "speculum: LABEL 42% (STAGE)"
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void update(double fraction, const std::string& stage = {});
    // A step of its own ("warming up"): rewritten in place on a terminal, a line of its own in a log.
    void step(const std::string& text);
    // Ends the rewritten line on a terminal, so what is printed next starts on a line of its own.
    void finish();

private:
    void show(const std::string& line, bool force);

    std::string m_label;
    bool m_terminal = false;
    bool m_open = false; // a rewritten line is on screen, not yet ended
    int m_lastTenth = -1;
    std::chrono::steady_clock::time_point m_lastShown{};
};

} // namespace speculum::app
