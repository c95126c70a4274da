#include "render/renderer/StillRenderer.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/gl/Objects.hpp"

#include <algorithm>
#include <chrono>
#include <new>

namespace speculum::render {

namespace {

std::string sizeText(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

// The tiles of a still: a grid of equal tiles from the image's bottom-left corner (GL window
// coordinates), so every tile renders into the same buffers; the top row and the right column may reach
// past the image's edge, by a few pixels. Tile sides are even: the GPU shades pixels in 2×2 quads aligned
// to the target's origin and takes texture-LOD derivatives within them, so a tile starting at an odd
// pixel would group pixels differently from the untiled image and sample textures differently.
struct TileGrid {
    int columns = 1, rows = 1;
    int width = 0, height = 0; // of each tile
    int count() const { return columns * rows; }
};

TileGrid tileGrid(int width, int height, int tileSize) {
    TileGrid grid;
    if (width <= tileSize && height <= tileSize) { // one tile: exactly the image
        grid.width = width;
        grid.height = height;
        return grid;
    }
    const int side = std::max(2, tileSize & ~1);
    grid.columns = (width + side - 1) / side;
    grid.rows = (height + side - 1) / side;
    auto evenShare = [](int size, int parts) { return ((size + parts - 1) / parts + 1) & ~1; };
    grid.width = std::min(side, evenShare(width, grid.columns));
    grid.height = std::min(side, evenShare(height, grid.rows));
    return grid;
}

// The still's result with its image allocated (black); an error where that does not fit in memory.
base::Result<StillResult> blankStill(const StillSettings& settings, int n, const TileGrid& grid) {
    StillResult result;
    result.samples = n * n;
    result.tiles = grid.count();
    result.image.width = settings.width;
    result.image.height = settings.height;
    try {
        result.image.rgba.resize(std::size_t(settings.width) * std::size_t(settings.height) * 4);
    } catch (const std::bad_alloc&) {
        return base::Error{"not enough memory for a " + sizeText(settings.width, settings.height) + " still"};
    }
    return result;
}

// A float target keeps the samples linear and unclamped until they are averaged.
struct FloatTarget {
    gl::Texture color;
    gl::Framebuffer framebuffer; // left bound to GL_FRAMEBUFFER
};

base::Result<FloatTarget> makeFloatTarget(const TileGrid& grid) {
    FloatTarget target;
    target.color = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, target.color.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, grid.width, grid.height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    target.framebuffer = gl::makeFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.color.id(), 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return base::Error{"cannot create a " + sizeText(grid.width, grid.height) +
                           " float render target on this GPU"};
    return target;
}

// "sample 2/4", or "tile 3/6, sample 2/4" for a tiled still.
std::string stageText(const TileGrid& grid, int tile, int sample, int n) {
    std::string stage = "sample " + std::to_string(sample + 1) + "/" + std::to_string(n * n);
    if (grid.count() > 1)
        stage = "tile " + std::to_string(tile + 1) + "/" + std::to_string(grid.count()) + ", " + stage;
    return stage;
}

// The frame options of sample k of the tile at (x0, y0): its sub-pixel offset on the N×N ordered grid,
// the tile, and whether maps drawn for an earlier step are reused.
RenderOptions sampleOptions(const StillSettings& settings, const TileGrid& grid, int x0, int y0, int k, int n,
                            int step) {
    RenderOptions options;
    options.jitterPixels = {(k % n + 0.5) / n - 0.5, (k / n + 0.5) / n - 0.5};
    if (grid.count() > 1)
        options.tile = ImageTile{settings.width, settings.height, x0, y0};
    options.reuseMaps = settings.reuseMaps || step > 0;
    options.lightingVariants = settings.lightingVariants;
    options.boundShadowLookups = settings.boundShadowLookups;
    options.cullHiddenBackFaces = settings.cullHiddenBackFaces;
    options.preview = settings.preview;
    options.countScreenSpace = true;
    options.showScreenSpaceSources = settings.showScreenSpaceSources;
    // The first sample is the one StillResult::firstSample reports; a tiled still probes nothing.
    if (step == 0 && grid.count() == 1)
        options.probePixel = settings.probePixel;
    return options;
}

void readTile(GLuint framebuffer, const TileGrid& grid, std::vector<float>& sample) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, grid.width, grid.height, GL_RGBA, GL_FLOAT, sample.data());
}

// Into the image: GL rows run bottom to top, image rows top to bottom; the parts of the tile past the
// image's edge are dropped.
void copyTileIntoImage(const std::vector<float>& tile, const TileGrid& grid, int x0, int y0, Image& image) {
    const int columns = std::min(grid.width, image.width - x0);
    const std::size_t tileRow = std::size_t(grid.width) * 4;
    for (int row = 0; row < grid.height; ++row) {
        const int y = y0 + row; // GL row in the image
        if (y >= image.height)
            break;
        const std::size_t from = std::size_t(row) * tileRow;
        const std::size_t to =
            (std::size_t(image.height - 1 - y) * std::size_t(image.width) + std::size_t(x0)) * 4;
        std::copy_n(tile.begin() + std::ptrdiff_t(from), std::size_t(columns) * 4,
                    image.rgba.begin() + std::ptrdiff_t(to));
    }
}

// A screen-space mirror or reflector traces the image it is drawn in, and a tile holds only its own
// pixels: such a still is drawn in one piece up to this side, in tiles (with a warning) only beyond it.
constexpr int kScreenSpaceTileSize = 4096;

bool tracesTheImage(const FrameInput& input) {
    return std::any_of(input.mirrors.begin(), input.mirrors.end(),
                       [](const Mirror& m) { return m.technique == MirrorTechnique::ScreenSpace; }) ||
           std::any_of(input.reflectors.begin(), input.reflectors.end(),
                       [](const Reflector& r) { return r.technique == ReflectorTechnique::ScreenSpace; });
}

} // namespace

int maxStillSize() {
    GLint renderbuffer = 0, texture = 0, viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    return std::min({renderbuffer, texture, viewport[0], viewport[1]});
}

base::Result<StillResult> renderStill(Renderer& renderer, const FrameInput& input,
                                      const StillSettings& settings, const ProgressCallback& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (base::Status size = checkStillSize(settings.width, settings.height); !size)
        return base::Error{size.error()};
    const int n = std::clamp(settings.ssaa, kMinSsaa, kMaxSsaa);
    const int limit = maxStillSize();
    const int wanted = settings.tileSize > 0   ? settings.tileSize
                       : tracesTheImage(input) ? std::max(kScreenSpaceTileSize, kDefaultTileSize)
                                               : kDefaultTileSize;
    const int tileSize = std::min(wanted, limit);
    if (tileSize < 1)
        return base::Error{"this OpenGL context cannot render any image (its size limit is " +
                           std::to_string(limit) + ")"};
    const TileGrid grid = tileGrid(settings.width, settings.height, tileSize);

    base::Result<StillResult> blank = blankStill(settings, n, grid);
    if (!blank)
        return base::Error{blank.error()};
    StillResult result = std::move(blank).value();

    gl::FramebufferBinding keepBinding;
    base::Result<FloatTarget> floatTarget = makeFloatTarget(grid);
    if (!floatTarget)
        return base::Error{floatTarget.error()};
    const GLuint framebuffer = floatTarget->framebuffer.id();
    const std::size_t tilePixels = std::size_t(grid.width) * std::size_t(grid.height);
    std::vector<float> sample(tilePixels * 4);
    std::vector<double> sum(n > 1 ? tilePixels * 4 : 0);
    const RenderTarget target{framebuffer, grid.width, grid.height, false};
    const int steps = grid.count() * n * n;

    for (int t = 0; t < grid.count(); ++t) {
        // Tiles in reading order: the top row first (GL rows count from the bottom).
        const int x0 = (t % grid.columns) * grid.width;
        const int y0 = (grid.rows - 1 - t / grid.columns) * grid.height;
        std::fill(sum.begin(), sum.end(), 0.0);
        for (int k = 0; k < n * n; ++k) {
            const int step = t * n * n + k;
            if (progress && !progress(double(step) / steps, stageText(grid, t, k, n)))
                return base::Error{"render cancelled"};
            const RenderOptions options = sampleOptions(settings, grid, x0, y0, k, n, step);
            FrameReport report = renderer.render(input, target, options);
            if (report.drawAgain) // planned again with the map sizes that fit, which the renderer now knows
                report = renderer.render(input, target, options);
            // A frame the renderer could not draw at all (its colour buffer did not fit) is no still.
            if (!report.error.empty())
                return base::Error{report.error};
            if (step == 0)
                result.firstSample = std::move(report);
            readTile(framebuffer, grid, sample);
            if (n > 1)
                for (std::size_t i = 0; i < sample.size(); ++i)
                    sum[i] += sample[i];
        }
        if (n > 1)
            for (std::size_t i = 0; i < sample.size(); ++i)
                sample[i] = static_cast<float>(sum[i] / (n * n));
        copyTileIntoImage(sample, grid, x0, y0, result.image);
    }
    if (grid.count() > 1 && tracesTheImage(input))
        result.firstSample.warnings.push_back(
            "screen-space reflections are traced tile by tile (the still is drawn in " +
            std::to_string(grid.count()) +
            " tiles): near a tile's edge they show their fallback where the whole image holds what they "
            "reflect");
    if (progress)
        progress(1.0, "done");
    result.totalMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

base::Result<std::optional<glm::dvec3>> screenSpaceSourceAt(Renderer& renderer, const FrameInput& input,
                                                            StillSettings settings, glm::ivec2 pixel) {
    if (!tracesTheImage(input))
        return std::optional<glm::dvec3>();
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= settings.width || pixel.y >= settings.height)
        return base::Error{"the pixel is outside the image"};
    settings.showScreenSpaceSources = true;
    settings.probePixel.reset();
    auto still = renderStill(renderer, input, settings);
    if (!still)
        return base::Error{still.error()};
    const std::size_t p = (std::size_t(pixel.y) * std::size_t(settings.width) + std::size_t(pixel.x)) * 4;
    return std::optional<glm::dvec3>(
        glm::dvec3(still->image.rgba[p], still->image.rgba[p + 1], still->image.rgba[p + 2]));
}

} // namespace speculum::render
