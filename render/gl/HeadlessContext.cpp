#include "render/gl/HeadlessContext.hpp"

#include <cstdlib>
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <vector>

namespace speculum::render::gl {

struct HeadlessContext::Egl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

namespace {

std::string eglErrorName(EGLint code) {
    switch (code) {
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
        return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    default:
        return "EGL error " + std::to_string(code);
    }
}

// Surfaceless first (no X, no DRM device needed); the default display as a fallback for drivers
// that only expose devices through it.
EGLDisplay openDisplay() {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY)
            return display;
        auto queryDevices =
            reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        if (queryDevices) {
            EGLDeviceEXT devices[8];
            EGLint count = 0;
            if (queryDevices(8, devices, &count) && count > 0) {
                display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
                if (display != EGL_NO_DISPLAY)
                    return display;
            }
        }
    }
    return eglGetDisplay(EGL_DEFAULT_DISPLAY);
}

} // namespace

HeadlessContext::~HeadlessContext() {
    if (m_egl && m_egl->display != EGL_NO_DISPLAY) {
        eglMakeCurrent(m_egl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (m_egl->context != EGL_NO_CONTEXT)
            eglDestroyContext(m_egl->display, m_egl->context);
#if !defined(__SANITIZE_ADDRESS__)
        // (Sanitizer builds keep the display: terminating it unloads the driver, and LeakSanitizer could then
        // no longer name the driver's own leftovers to match them against scripts/lsan-suppressions.txt.)
        eglTerminate(m_egl->display);
#endif
    }
}

base::Result<std::unique_ptr<HeadlessContext>> HeadlessContext::create() {
    std::unique_ptr<HeadlessContext> self(new HeadlessContext);
    self->m_egl = std::make_unique<Egl>();
    Egl& egl = *self->m_egl;

    egl.display = openDisplay();
    if (egl.display == EGL_NO_DISPLAY)
        return base::Error{"cannot open an EGL display (is Mesa's libegl-mesa0 installed?)"};
    EGLint major = 0, minor = 0;
    if (!eglInitialize(egl.display, &major, &minor)) {
        const std::string reason = eglErrorName(eglGetError());
        egl.display = EGL_NO_DISPLAY;
        return base::Error{"cannot initialise EGL: " + reason};
    }
    if (!eglBindAPI(EGL_OPENGL_API))
        return base::Error{"EGL has no desktop OpenGL API: " + eglErrorName(eglGetError())};

    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                    EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!eglChooseConfig(egl.display, configAttribs, &config, 1, &configCount) || configCount == 0) {
        // Surfaceless contexts need no config at all where EGL_KHR_no_config_context is offered.
        config = EGL_NO_CONFIG_KHR;
    }

    const std::pair<int, int> versions[] = {{4, 5}, {4, 3}, {3, 3}};
    std::string lastError;
    for (auto [glMajor, glMinor] : versions) {
        const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         glMajor,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         glMinor,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
        egl.context = eglCreateContext(egl.display, config, EGL_NO_CONTEXT, contextAttribs);
        if (egl.context != EGL_NO_CONTEXT)
            break;
        lastError = eglErrorName(eglGetError());
    }
    if (egl.context == EGL_NO_CONTEXT)
        return base::Error{"cannot create an OpenGL 3.3 core context: " + lastError};
    if (!eglMakeCurrent(egl.display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl.context))
        return base::Error{"cannot make the OpenGL context current: " + eglErrorName(eglGetError())};
    if (epoxy_gl_version() < 33)
        return base::Error{"OpenGL 3.3 is required, the driver offers " +
                           std::to_string(epoxy_gl_version() / 10) + "." +
                           std::to_string(epoxy_gl_version() % 10)};
    return self;
}

std::string HeadlessContext::description() const {
    return contextDescription();
}

std::string contextDescription() {
    auto text = [](GLenum name) {
        const auto* s = reinterpret_cast<const char*>(glGetString(name));
        return std::string(s ? s : "?");
    };
    return "OpenGL " + text(GL_VERSION) + ", " + text(GL_RENDERER);
}

} // namespace speculum::render::gl
