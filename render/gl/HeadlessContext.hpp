#pragma once

#include "base/Result.hpp"

#include <memory>
#include <string>

namespace speculum::render::gl {

// An OpenGL core-profile context with no window and no X server: EGL on the surfaceless platform
// (Mesa's llvmpipe or a GPU driver). Current on the creating thread for its whole life.
class HeadlessContext {
public:
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    // Tries 4.5, then 3.3 core. The error says what EGL refused.
    static base::Result<std::unique_ptr<HeadlessContext>> create();

    std::string description() const; // "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (...)"

private:
    HeadlessContext() = default;
    struct Egl;
    std::unique_ptr<Egl> m_egl;
};

// The current context's version and renderer, as HeadlessContext::description() gives them: what stills
// record as the renderer that drew them.
std::string contextDescription();

} // namespace speculum::render::gl
