#pragma once

// What every GL benchmark needs: one headless context, one renderer, and an 8-bit target of a fixed size
// (like a window's, so the composite pass does what it does on screen). Created on first use.
#include "render/gl/HeadlessContext.hpp"
#include "render/gl/Objects.hpp"
#include "render/renderer/Renderer.hpp"

#include <memory>

namespace speculum::bench {

struct BenchGl {
    std::unique_ptr<render::gl::HeadlessContext> context;
    std::unique_ptr<render::Renderer> renderer;
    render::gl::Texture color;
    render::gl::Framebuffer framebuffer;
    int width = 0;
    int height = 0;

    render::RenderTarget target() const { return {framebuffer.id(), width, height, true}; }
};

// nullptr when there is no OpenGL here; the benchmark then reports an error instead of a time.
inline BenchGl* benchGl(int width, int height) {
    static std::unique_ptr<BenchGl> g;
    if (!g) {
        auto context = render::gl::HeadlessContext::create();
        if (!context)
            return nullptr;
        auto made = std::make_unique<BenchGl>();
        made->context = std::move(*context);
        auto renderer = render::Renderer::create();
        if (!renderer)
            return nullptr;
        made->renderer = std::move(*renderer);
        g = std::move(made);
    }
    if (g->width != width || g->height != height) {
        g->width = width;
        g->height = height;
        g->color = render::gl::makeTexture();
        glBindTexture(GL_TEXTURE_2D, g->color.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        g->framebuffer = render::gl::makeFramebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, g->framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g->color.id(), 0);
    }
    return g.get();
}

} // namespace speculum::bench
