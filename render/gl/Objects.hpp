#pragma once

#include <array>
#include <cstddef>
#include <epoxy/gl.h>
#include <utility>

namespace speculum::render::gl {

// Move-only owner of one GL object name. Objects are created only with a current context and must be
// destroyed while that context (or one sharing with it) is still current.
template <void (*Delete)(GLuint)>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id)
        : m_id(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept
        : m_id(std::exchange(other.m_id, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            m_id = std::exchange(other.m_id, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    GLuint id() const { return m_id; }
    explicit operator bool() const { return m_id != 0; }
    void reset() {
        if (m_id)
            Delete(m_id);
        m_id = 0;
    }

private:
    GLuint m_id = 0;
};

namespace detail {
inline void deleteBuffer(GLuint id) {
    glDeleteBuffers(1, &id);
}
inline void deleteVertexArray(GLuint id) {
    glDeleteVertexArrays(1, &id);
}
inline void deleteTexture(GLuint id) {
    glDeleteTextures(1, &id);
}
inline void deleteFramebuffer(GLuint id) {
    glDeleteFramebuffers(1, &id);
}
inline void deleteRenderbuffer(GLuint id) {
    glDeleteRenderbuffers(1, &id);
}
inline void deleteQuery(GLuint id) {
    glDeleteQueries(1, &id);
}
inline void deleteProgram(GLuint id) {
    glDeleteProgram(id);
}
inline void deleteShader(GLuint id) {
    glDeleteShader(id);
}
} // namespace detail

using Buffer = Handle<detail::deleteBuffer>;
using VertexArray = Handle<detail::deleteVertexArray>;
using Texture = Handle<detail::deleteTexture>;
using Framebuffer = Handle<detail::deleteFramebuffer>;
using Renderbuffer = Handle<detail::deleteRenderbuffer>;
using Query = Handle<detail::deleteQuery>;
using ProgramHandle = Handle<detail::deleteProgram>;
using ShaderHandle = Handle<detail::deleteShader>;

inline Buffer makeBuffer() {
    GLuint id = 0;
    glGenBuffers(1, &id);
    return Buffer(id);
}
inline VertexArray makeVertexArray() {
    GLuint id = 0;
    glGenVertexArrays(1, &id);
    return VertexArray(id);
}
inline Texture makeTexture() {
    GLuint id = 0;
    glGenTextures(1, &id);
    return Texture(id);
}
inline Framebuffer makeFramebuffer() {
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    return Framebuffer(id);
}
inline Renderbuffer makeRenderbuffer() {
    GLuint id = 0;
    glGenRenderbuffers(1, &id);
    return Renderbuffer(id);
}
inline Query makeQuery() {
    GLuint id = 0;
    glGenQueries(1, &id);
    return Query(id);
}

// Restores the framebuffer binding it found, so passes never leave the caller's target unbound.
class FramebufferBinding {
public:
    FramebufferBinding() { glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &m_previous); }
    ~FramebufferBinding() { glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(m_previous)); }
    FramebufferBinding(const FramebufferBinding&) = delete;
    FramebufferBinding& operator=(const FramebufferBinding&) = delete;

private:
    GLint m_previous = 0;
};

// For passes that fill targets of their own with full-screen draws (filters, pre-filters): turns off the
// depth and stencil tests, blending and the scissor, and puts them, the viewport and the scissor box back as
// it found them.
class PlainDrawState {
public:
    PlainDrawState() {
        glGetIntegerv(GL_VIEWPORT, m_viewport);
        glGetIntegerv(GL_SCISSOR_BOX, m_scissor);
        for (std::size_t i = 0; i < kCapabilities.size(); ++i) {
            m_enabled[i] = glIsEnabled(kCapabilities[i]);
            glDisable(kCapabilities[i]);
        }
    }
    ~PlainDrawState() {
        glViewport(m_viewport[0], m_viewport[1], m_viewport[2], m_viewport[3]);
        glScissor(m_scissor[0], m_scissor[1], m_scissor[2], m_scissor[3]);
        for (std::size_t i = 0; i < kCapabilities.size(); ++i)
            (m_enabled[i] ? glEnable : glDisable)(kCapabilities[i]);
    }
    PlainDrawState(const PlainDrawState&) = delete;
    PlainDrawState& operator=(const PlainDrawState&) = delete;

private:
    static constexpr std::array<GLenum, 4> kCapabilities{GL_DEPTH_TEST, GL_BLEND, GL_SCISSOR_TEST,
                                                         GL_STENCIL_TEST};
    GLint m_viewport[4] = {};
    GLint m_scissor[4] = {};
    std::array<GLboolean, 4> m_enabled{};
};

} // namespace speculum::render::gl
