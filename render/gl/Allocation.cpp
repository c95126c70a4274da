#include "render/gl/Allocation.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>

namespace speculum::render::gl {

namespace {

std::atomic<std::size_t> g_testLimit{0};
thread_local bool t_checking = false;

std::string hex(GLenum value) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%x", static_cast<unsigned>(value));
    return text;
}

void drainErrors() {
    // glGetError returns GL_NO_ERROR once every flag is cleared; a lost context may keep answering
    // GL_CONTEXT_LOST, so the loop is bounded.
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
    }
}

} // namespace

void setAllocationLimitForTesting(std::size_t bytes) {
    g_testLimit = bytes;
}

std::size_t allocationLimitForTesting() {
    return g_testLimit;
}

base::Status beginAllocation(std::size_t bytes) {
    drainErrors();
    const std::size_t limit = g_testLimit;
    if (limit > 0 && bytes > limit)
        return base::Error{"did not fit in GPU memory (over the test limit of " + std::to_string(limit) +
                           " bytes)"};
    t_checking = true;
    return base::Done{};
}

bool allocationBeingChecked() {
    return t_checking;
}

base::Status finishAllocation() {
    t_checking = false;
    bool outOfMemory = false;
    GLenum other = GL_NO_ERROR;
    for (int i = 0; i < 16; ++i) {
        const GLenum e = glGetError();
        if (e == GL_NO_ERROR)
            break;
        if (e == GL_OUT_OF_MEMORY)
            outOfMemory = true;
        else if (other == GL_NO_ERROR)
            other = e;
    }
    if (outOfMemory)
        return base::Error{"did not fit in GPU memory"};
    if (other != GL_NO_ERROR)
        return base::Error{"was refused by the driver (GL error " + hex(other) + ")"};
    return base::Done{};
}

base::Status checkFramebuffer(GLenum target) {
    const GLenum status = glCheckFramebufferStatus(target);
    if (status == GL_FRAMEBUFFER_COMPLETE)
        return base::Done{};
    // An incomplete attachment after a silent allocation failure is the usual cause: report memory when
    // the driver flagged it.
    if (base::Status errors = finishAllocation(); !errors)
        return errors;
    return base::Error{"could not be drawn into (framebuffer incomplete, status " + hex(status) + ")"};
}

SizeFallback::Fitted SizeFallback::fit(int requested, int minimum,
                                       const std::function<base::Status(int)>& allocate) {
    Fitted fitted;
    int size = belowFailure(requested, minimum, m_failed);
    if (size != std::max(requested, minimum))
        fitted.reason = m_failed.reason;
    if (size == 0)
        return fitted; // even the minimum failed before
    for (;;) {
        base::Status done = allocate(size);
        if (done) {
            fitted.size = size;
            return fitted;
        }
        if (size < m_failed.size)
            m_failed = {size, done.error()};
        if (fitted.reason.empty())
            fitted.reason = done.error();
        if (size <= minimum)
            return fitted;
        size = std::max(minimum, size / 2);
    }
}

} // namespace speculum::render::gl
