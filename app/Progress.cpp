#include "app/Progress.hpp"

#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace speculum::app {

namespace {
bool g_quiet = false;
} // namespace

void Progress::setQuiet(bool quiet) {
    g_quiet = quiet;
}

bool Progress::quiet() {
    return g_quiet;
}

Progress::Progress(std::string label)
    : m_label(std::move(label))
    , m_terminal(::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
    finish();
}

void Progress::update(double fraction, const std::string& stage) {
    const int percent = static_cast<int>(fraction * 100.0 + 0.5);
    const int tenth = percent / 10;
    std::string line = "speculum: " + m_label + " " + std::to_string(percent) + "%";
    if (!stage.empty())
        line += " (" + stage + ")";
    if (m_terminal) {
        show(line, percent >= 100);
    } else if (tenth != m_lastTenth) {
        m_lastTenth = tenth;
        show(line, true);
    }
}

void Progress::step(const std::string& text) {
    show("speculum: " + m_label + ": " + text, true);
}

void Progress::show(const std::string& line, bool force) {
    if (g_quiet)
        return;
    if (!m_terminal) {
        std::cerr << line << std::endl;
        return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (!force && m_open && now - m_lastShown < std::chrono::milliseconds(100))
        return;
    m_lastShown = now;
    // Back to the line's start, the new text, then erase what a longer earlier text left.
    std::cerr << '\r' << line << "\x1b[K" << std::flush;
    m_open = true;
}

void Progress::finish() {
    if (m_open && !g_quiet)
        std::cerr << '\n' << std::flush;
    m_open = false;
}

} // namespace speculum::app
