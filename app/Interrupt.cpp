#include "app/Interrupt.hpp"

#include <iostream>

namespace speculum::app {

namespace {

volatile std::sig_atomic_t g_stopSignal = 0;
bool g_reported = false;

extern "C" void requestStop(int signal) {
    g_stopSignal = signal;
    // The next one of this kind is not asked politely: it takes the default action.
    struct sigaction fallback {};
    fallback.sa_handler = SIG_DFL;
    sigemptyset(&fallback.sa_mask);
    ::sigaction(signal, &fallback, nullptr);
}

} // namespace

StopOnSignal::StopOnSignal() {
    struct sigaction action {};
    action.sa_handler = requestStop;
    sigemptyset(&action.sa_mask);
    // Restarted system calls: a read or write under way is not cut short by the signal, only the steps
    // after it see the request.
    action.sa_flags = SA_RESTART;
    ::sigaction(SIGINT, &action, &m_previousInt);
    ::sigaction(SIGTERM, &action, &m_previousTerm);
}

StopOnSignal::~StopOnSignal() {
    ::sigaction(SIGINT, &m_previousInt, nullptr);
    ::sigaction(SIGTERM, &m_previousTerm, nullptr);
}

bool StopOnSignal::requested() {
    return g_stopSignal != 0;
}

int interrupted(const std::string& command, const std::string& outcome) {
    if (!g_reported) {
        g_reported = true;
        std::cerr << "speculum: " << command << ": interrupted; " << outcome << "\n";
    }
    return kInterruptedStatus;
}

bool interruptionReported() {
    return g_reported;
}

} // namespace speculum::app
