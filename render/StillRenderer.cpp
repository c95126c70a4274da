#include "render/StillRenderer.hpp"

#include "render/gl/Objects.hpp"

#include <algorithm>
#include <chrono>

namespace speculum::render {

int maxStillSize() {
    GLint renderbuffer = 0, texture = 0, viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    return std::min({renderbuffer, texture, viewport[0], viewport[1]});
}

Result<StillResult> renderStill(Renderer& renderer, const FrameInput& input, const StillSettings& settings,
                                const ProgressCallback& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (settings.width <= 0 || settings.height <= 0)
        return Error{"image size must be positive, got " + std::to_string(settings.width) + "x" +
                     std::to_string(settings.height)};
    const int limit = maxStillSize();
    if (settings.width > limit || settings.height > limit)
        return Error{"image size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                     " exceeds this GPU's limit of " + std::to_string(limit) + " pixels per side"};
    const int n = std::clamp(settings.ssaa, 1, 16);

    // A float target keeps the samples linear and unclamped until they are averaged.
    gl::FramebufferBinding keepBinding;
    gl::Texture color = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, color.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, settings.width, settings.height, 0, GL_RGBA, GL_FLOAT,
                 nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    gl::Framebuffer framebuffer = gl::makeFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return Error{"cannot create a " + std::to_string(settings.width) + "x" +
                     std::to_string(settings.height) + " float render target on this GPU"};

    const std::size_t pixelCount = static_cast<std::size_t>(settings.width) * settings.height;
    std::vector<float> sample(pixelCount * 4);
    std::vector<double> sum(n > 1 ? pixelCount * 4 : 0, 0.0);
    StillResult result;
    result.samples = n * n;
    const RenderTarget target{framebuffer.id(), settings.width, settings.height, false};

    for (int k = 0; k < n * n; ++k) {
        if (progress &&
            !progress(double(k) / (n * n), "sample " + std::to_string(k + 1) + "/" + std::to_string(n * n)))
            return Error{"render cancelled"};
        RenderOptions options;
        options.jitterPixels = {(k % n + 0.5) / n - 0.5, (k / n + 0.5) / n - 0.5};
        options.reuseMaps = settings.reuseMaps || k > 0;
        FrameReport report = renderer.render(input, target, options);
        if (k == 0)
            result.firstSample = std::move(report);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, settings.width, settings.height, GL_RGBA, GL_FLOAT, sample.data());
        if (n > 1)
            for (std::size_t i = 0; i < sample.size(); ++i)
                sum[i] += sample[i];
    }
    if (n > 1)
        for (std::size_t i = 0; i < sample.size(); ++i)
            sample[i] = static_cast<float>(sum[i] / (n * n));

    // GL rows run bottom to top; images run top to bottom.
    result.image.width = settings.width;
    result.image.height = settings.height;
    result.image.rgba.resize(sample.size());
    const std::size_t row = static_cast<std::size_t>(settings.width) * 4;
    for (int y = 0; y < settings.height; ++y)
        std::copy_n(sample.begin() + static_cast<std::ptrdiff_t>((settings.height - 1 - y) * row), row,
                    result.image.rgba.begin() + static_cast<std::ptrdiff_t>(y * row));
    if (progress)
        progress(1.0, "done");
    result.totalMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace speculum::render
