#include "support/DebugOutput.hpp"

#include "render/gl/Allocation.hpp"

#include <cstring>
#include <epoxy/gl.h>
#include <utility>

namespace speculum::render::gl {

namespace {
const char* typeName(GLenum type) {
    switch (type) {
    case GL_DEBUG_TYPE_ERROR:
        return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
        return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
        return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY:
        return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE:
        return "performance";
    default:
        return "other";
    }
}
} // namespace

bool DebugOutput::install() {
    if (!(epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_KHR_debug")))
        return false;
    glEnable(GL_DEBUG_OUTPUT);
    // Synchronous so the message arrives inside the call that caused it (easier to attribute in tests).
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(reinterpret_cast<GLDEBUGPROC>(&DebugOutput::callback), this);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    m_installed = true;
    return true;
}

void DebugOutput::uninstall() {
    if (!m_installed)
        return;
    glDebugMessageCallback(nullptr, nullptr);
    glDisable(GL_DEBUG_OUTPUT);
    m_installed = false;
}

void DebugOutput::callback(unsigned, unsigned type, unsigned id, unsigned severity, int length,
                           const char* message, const void* user) {
    auto* self = const_cast<DebugOutput*>(static_cast<const DebugOutput*>(user));
    // An allocation that did not fit is checked and handled by its caller (gl/Allocation.hpp): reported,
    // but not as an error.
    const bool handled = allocationBeingChecked();
    const bool isError =
        !handled && (type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR ||
                     severity == GL_DEBUG_SEVERITY_HIGH);
    std::string text =
        std::string(handled ? "GL (handled allocation failure) " : "GL ") + typeName(type) + " #" +
        std::to_string(id) + ": " +
        std::string(message, length > 0 ? static_cast<std::size_t>(length) : std::strlen(message));
    std::lock_guard lock(self->m_mutex);
    if (self->m_messages.size() < 1000)
        self->m_messages.push_back({isError, std::move(text)});
}

std::vector<DebugOutput::Message> DebugOutput::takeMessages() {
    std::lock_guard lock(m_mutex);
    return std::exchange(m_messages, {});
}

std::vector<std::string> DebugOutput::errors() const {
    std::lock_guard lock(m_mutex);
    std::vector<std::string> result;
    for (const Message& m : m_messages)
        if (m.isError)
            result.push_back(m.text);
    return result;
}

int DebugOutput::errorCount() const {
    return static_cast<int>(errors().size());
}

void DebugOutput::clear() {
    std::lock_guard lock(m_mutex);
    m_messages.clear();
}

void DebugOutput::pollGetError(const char* where) {
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
        std::lock_guard lock(m_mutex);
        m_messages.push_back({true, std::string("glGetError 0x") + std::to_string(e) + " at " + where});
    }
}

} // namespace speculum::render::gl
