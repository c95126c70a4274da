#pragma once

#include <mutex>
#include <string>
#include <vector>

namespace speculum::render::gl {

// Captures KHR_debug messages of the current context. Errors (and undefined behaviour reports) are
// collected so tests can fail on any of them; other messages go to an optional log.
class DebugOutput {
public:
    struct Message {
        bool isError = false;
        std::string text;
    };

    // Installs the callback on the current context; false if KHR_debug is unavailable.
    bool install();
    void uninstall();

    std::vector<Message> takeMessages();
    std::vector<std::string> errors() const;
    int errorCount() const;
    void clear();
    // Adds errors found by glGetError, for drivers without KHR_debug.
    void pollGetError(const char* where);

private:
    static void callback(unsigned source, unsigned type, unsigned id, unsigned severity, int length,
                         const char* message, const void* user);
    mutable std::mutex m_mutex;
    std::vector<Message> m_messages;
    bool m_installed = false;
};

} // namespace speculum::render::gl
