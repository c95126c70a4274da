#pragma once

#include "render/gl/HeadlessContext.hpp"
#include "render/renderer/Renderer.hpp"
#include "render/renderer/StillRenderer.hpp"
#include "support/DebugOutput.hpp"

#include <gtest/gtest.h>
#include <memory>

namespace speculum::test {

// Base of every GL test: one headless context for the whole binary, KHR_debug captured, and a test that
// produced any GL error fails.
class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        if (!s_context) {
            auto context = render::gl::HeadlessContext::create();
            ASSERT_TRUE(context.ok()) << context.error();
            s_context = std::move(*context).release();
        }
    }

    void SetUp() override {
        ASSERT_NE(s_context, nullptr);
        m_debug.install();
        m_debug.clear();
        auto renderer = render::Renderer::create();
        ASSERT_TRUE(renderer.ok()) << renderer.error();
        m_renderer = std::move(*renderer);
    }

    void TearDown() override {
        m_renderer.reset();
        m_debug.pollGetError("end of test");
        const auto errors = m_debug.errors();
        for (const std::string& e : errors)
            ADD_FAILURE() << e;
        EXPECT_TRUE(errors.empty()) << errors.size() << " GL errors";
        m_debug.uninstall();
    }

    render::Image renderImage(const render::FrameInput& input, int width, int height, int ssaa = 1) {
        return renderImage(input, render::StillSettings{width, height, ssaa});
    }
    render::Image renderImage(const render::FrameInput& input, const render::StillSettings& settings) {
        auto still = render::renderStill(*m_renderer, input, settings);
        EXPECT_TRUE(still.ok()) << (still.ok() ? "" : still.error());
        if (!still.ok())
            return {};
        m_lastReport = still->firstSample;
        return std::move(still->image);
    }

    render::Renderer& renderer() { return *m_renderer; }
    const render::FrameReport& lastReport() const { return m_lastReport; }

private:
    // Leaked on purpose: destroyed at exit after every test, when no GL object is left.
    static inline render::gl::HeadlessContext* s_context = nullptr;
    render::gl::DebugOutput m_debug;
    std::unique_ptr<render::Renderer> m_renderer;
    render::FrameReport m_lastReport;
};

} // namespace speculum::test
