#include "render/passes/EnvironmentCapture.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/gl/Allocation.hpp"
#include "render/gl/Memory.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>
#include <string>

namespace speculum::render::envmap {

namespace {

int mipLevels(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2)
        ++levels;
    return levels;
}

void allocateCube(GLuint texture, int size, GLenum format, bool mipmaps) {
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture);
    const int levels = mipmaps ? mipLevels(size, size) : 1;
    for (int level = 0; level < levels; ++level)
        for (int face = 0; face < 6; ++face)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, level, static_cast<GLint>(format),
                         std::max(1, size >> level), std::max(1, size >> level), 0, GL_RGBA, GL_FLOAT,
                         nullptr);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER,
                    mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

void allocateArray(GLuint texture, int width, int height, int layers, GLenum format, int levels) {
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
    for (int level = 0; level < levels; ++level)
        glTexImage3D(GL_TEXTURE_2D_ARRAY, level, static_cast<GLint>(format), std::max(1, width >> level),
                     std::max(1, height >> level), layers, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER,
                    levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // Clamp: the guard band, not wrapping, supplies the texels past a component's nominal square.
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

// Depth and 8 stencil bits: planar mirrors inside the map nest their reflections in the stencil buffer, as
// the main pass's do.
gl::Renderbuffer makeDepth(int width, int height) {
    gl::Renderbuffer depth = gl::makeRenderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, depth.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    return depth;
}

// Runs one allocation checked (gl::beginAllocation / finishAllocation); the error names `what`.
template <typename Allocate>
base::Status checked(std::size_t bytes, const std::string& what, Allocate allocate) {
    if (base::Status fits = gl::beginAllocation(bytes); !fits)
        return base::Error{fits.error() + " (" + what + ")"};
    allocate();
    if (base::Status done = gl::finishAllocation(); !done)
        return base::Error{done.error() + " (" + what + ")"};
    return base::Done{};
}

base::Status complete(const std::string& what) {
    if (base::Status s = gl::checkFramebuffer(); !s)
        return base::Error{s.error() + " (" + what + ")"};
    return base::Done{};
}

std::string sizeText(int width, int height) {
    return std::to_string(width) + "×" + std::to_string(height);
}

// The GL state update() and resample() set or that callbacks may change, put back when they end.
class SavedState {
public:
    SavedState() {
        glGetIntegerv(GL_VIEWPORT, m_viewport);
        glGetFloatv(GL_COLOR_CLEAR_VALUE, m_clear);
        glGetIntegerv(GL_FRONT_FACE, &m_frontFace);
        glGetIntegerv(GL_DEPTH_FUNC, &m_depthFunc);
        glGetBooleanv(GL_DEPTH_WRITEMASK, &m_depthMask);
        glGetBooleanv(GL_COLOR_WRITEMASK, m_colorMask);
        glGetIntegerv(GL_STENCIL_WRITEMASK, &m_stencilMask);
        for (std::size_t i = 0; i < kCaps.size(); ++i)
            m_enabled[i] = glIsEnabled(kCaps[i]);
    }
    ~SavedState() {
        glViewport(m_viewport[0], m_viewport[1], m_viewport[2], m_viewport[3]);
        glClearColor(m_clear[0], m_clear[1], m_clear[2], m_clear[3]);
        glFrontFace(static_cast<GLenum>(m_frontFace));
        glDepthFunc(static_cast<GLenum>(m_depthFunc));
        glDepthMask(m_depthMask);
        glColorMask(m_colorMask[0], m_colorMask[1], m_colorMask[2], m_colorMask[3]);
        glStencilMask(static_cast<GLuint>(m_stencilMask));
        for (std::size_t i = 0; i < kCaps.size(); ++i)
            (m_enabled[i] ? glEnable : glDisable)(kCaps[i]);
    }
    SavedState(const SavedState&) = delete;
    SavedState& operator=(const SavedState&) = delete;

private:
    static constexpr std::array<GLenum, 6> kCaps{GL_DEPTH_TEST,   GL_CULL_FACE,    GL_BLEND,
                                                 GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_CLIP_DISTANCE0};
    GLint m_viewport[4] = {};
    GLfloat m_clear[4] = {};
    GLint m_frontFace = GL_CCW;
    GLint m_depthFunc = GL_LESS;
    GLboolean m_depthMask = GL_TRUE;
    GLboolean m_colorMask[4] = {};
    GLint m_stencilMask = 0xFF;
    std::array<GLboolean, kCaps.size()> m_enabled{};
};

// A clean target for a callback: whatever the previous callback left enabled is off again.
void prepareTarget(int width, int height, const glm::dvec3& background) {
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_CLIP_DISTANCE0);
    glFrontFace(GL_CCW);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilMask(0xFF);
    glClearColor(float(background.r), float(background.g), float(background.b), 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}
} // namespace

void setWarpUniforms(const gl::Program& program, const WarpPass& pass) {
    program.set("uEnvWarpType", static_cast<int>(pass.warp.type));
    program.set("uEnvWarpComponent", pass.warp.component);
    program.set("uEnvWarpView", glm::mat4(pass.view));
    program.set("uEnvWarpParams", glm::vec4(pass.warp.packed()));
    program.set("uEnvWarpFar", static_cast<float>(pass.warp.far));
}

base::Result<EnvironmentCapture> EnvironmentCapture::create(const CaptureSettings& settings,
                                                            bool* sizeFailure) {
    assert(settings.resolution >= kMinEnvironmentMapSize &&
           "EnvironmentCapture::create(): resolution below the scene limit");
    if (sizeFailure)
        *sizeFailure = false;
    EnvironmentCapture capture;
    capture.m_settings = settings;
    if (settings.type == MapType::Octahedral) // a triangle cannot be warped across the octahedron's folds
        capture.m_settings.fill = FillMethod::Resampled;
    capture.m_layout = makeLayout(settings.type, settings.resolution);
    const MapLayout& layout = capture.m_layout;
    // The resampling shader first: a shader that does not build is no reason to try a smaller map.
    if (settings.type != MapType::Cube) {
        auto program = gl::Program::build("fullscreen.vert", "envmap_resample.glsl");
        if (!program)
            return base::Error{program.error()};
        capture.m_resample = std::move(*program);
        capture.m_emptyVao = gl::makeVertexArray();
    }
    // Every allocation is checked: one that fails leaves a map every draw into silently ignores.
    auto sizeError = [&](base::Status s) -> base::Result<EnvironmentCapture> {
        if (sizeFailure)
            *sizeFailure = true;
        return base::Error{s.error()};
    };
    // Seamless filtering across cube faces is a context-wide switch (core since 3.2); pass 2 and the
    // resampling both rely on it.
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    gl::FramebufferBinding keepBinding;
    capture.m_framebuffer = gl::makeFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, capture.m_framebuffer.id());

    const std::size_t colour = gl::bytesPerTexel(settings.colorFormat);
    const std::size_t depthTexel = gl::bytesPerTexel(GL_DEPTH24_STENCIL8);
    // The intermediate cube first: the largest part (six faces), so a map that does not fit fails before
    // gigabytes of the rest were allocated (and cleared) for nothing.
    if (settings.type != MapType::Cube && capture.m_settings.fill == FillMethod::Resampled) {
        const int size = settings.cubeResolution > 0 ? settings.cubeResolution : settings.resolution;
        const int cubeLevels = settings.mipmaps ? mipLevels(size, size) : 1;
        const std::string cube = "its " + sizeText(size, size) + " intermediate cube";
        capture.m_cube = gl::makeTexture();
        if (base::Status s = checked(
                6 * gl::mipChainTexels(size, size, cubeLevels) * colour, cube,
                [&] { allocateCube(capture.m_cube.id(), size, settings.colorFormat, settings.mipmaps); });
            !s)
            return sizeError(s);
        if (base::Status s =
                checked(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * depthTexel,
                        cube + "'s depth buffer", [&] { capture.m_cubeDepth = makeDepth(size, size); });
            !s)
            return sizeError(s);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  capture.m_cubeDepth.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                               capture.m_cube.id(), 0);
        if (base::Status s = complete(cube); !s)
            return sizeError(s);
    }

    const std::size_t faceTexels =
        static_cast<std::size_t>(layout.width) * static_cast<std::size_t>(layout.height);
    const int levels = settings.mipmaps ? usableMipLevels(layout) : 1;
    capture.m_map = gl::makeTexture();
    if (base::Status s = checked(static_cast<std::size_t>(layout.components) *
                                     gl::mipChainTexels(layout.width, layout.height, levels) * colour,
                                 "the map's " + std::to_string(layout.components) + " × " +
                                     sizeText(layout.width, layout.height) + " colour texels",
                                 [&] {
                                     if (settings.type == MapType::Cube)
                                         allocateCube(capture.m_map.id(), layout.width, settings.colorFormat,
                                                      settings.mipmaps);
                                     else
                                         allocateArray(capture.m_map.id(), layout.width, layout.height,
                                                       layout.components, settings.colorFormat, levels);
                                 });
        !s)
        return sizeError(s);
    if (base::Status s =
            checked(faceTexels * depthTexel, "its " + sizeText(layout.width, layout.height) + " depth buffer",
                    [&] { capture.m_depth = makeDepth(layout.width, layout.height); });
        !s)
        return sizeError(s);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              capture.m_depth.id());
    if (settings.type == MapType::Cube)
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                               capture.m_map.id(), 0);
    else
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, capture.m_map.id(), 0, 0);
    if (base::Status s = complete("the map"); !s)
        return sizeError(s);

    return capture;
}

std::size_t EnvironmentCapture::bytes() const {
    if (!m_map)
        return 0;
    const std::size_t colour = gl::bytesPerTexel(m_settings.colorFormat);
    const std::size_t depth = gl::bytesPerTexel(GL_DEPTH_COMPONENT24);
    const MapLayout& l = m_layout;
    const int levels = m_settings.mipmaps ? usableMipLevels(l) : 1;
    // One depth buffer of a face's (or a layer's) size serves every face in turn.
    std::size_t total =
        static_cast<std::size_t>(l.components) * gl::mipChainTexels(l.width, l.height, levels) * colour +
        static_cast<std::size_t>(l.width) * static_cast<std::size_t>(l.height) * depth;
    if (m_cube) {
        const int size = intermediateCubeSize();
        const int cubeLevels = m_settings.mipmaps ? mipLevels(size, size) : 1;
        total += 6 * gl::mipChainTexels(size, size, cubeLevels) * colour +
                 static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * depth;
    }
    return total;
}

glm::ivec2 EnvironmentCapture::targetSize() const {
    if (m_settings.type == MapType::Cube)
        return {m_layout.width, m_layout.width};
    if (m_settings.fill == FillMethod::Resampled)
        return glm::ivec2(intermediateCubeSize());
    return {m_layout.width, m_layout.height};
}

void EnvironmentCapture::renderCube(GLuint cube, int size, GLuint depth, const CaptureView& view,
                                    const DrawCubeFace& drawFace) {
    assert(drawFace && "EnvironmentCapture::update(): cube faces need a drawFace callback");
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth);
    for (int face = 0; face < 6; ++face) {
        const bool draw = (view.faces & (1u << face)) != 0;
        if (!draw && m_drawn)
            continue;                                          // it keeps what an earlier update drew
        glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id()); // the callback may have bound another
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + face,
                               cube, 0);
        prepareTarget(size, size, view.background);
        if (draw)
            drawFace(cubeFaceViewProjection(face, view.mapFromWorld, view.near, view.far), face);
    }
}

void EnvironmentCapture::renderWarped(const CaptureView& view, const DrawWarped& drawWarped) {
    assert(drawWarped && "EnvironmentCapture::update(): the direct fill needs a drawWarped callback");
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, m_depth.id());
    for (int component = 0; component < 2; ++component) {
        const bool draw = (view.faces & (1u << component)) != 0;
        if (!draw && m_drawn)
            continue;
        glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, m_map.id(), 0, component);
        prepareTarget(m_layout.width, m_layout.height, view.background);
        if (draw)
            drawWarped({warpParameters(m_layout, component, view.far), glm::dmat4(view.mapFromWorld)});
    }
}

void EnvironmentCapture::finish(GLenum target, GLuint texture) {
    if (!m_settings.mipmaps)
        return;
    glBindTexture(target, texture);
    glGenerateMipmap(target);
    glBindTexture(target, 0);
}

void EnvironmentCapture::update(const CaptureView& view, const DrawCubeFace& drawFace,
                                const DrawWarped& drawWarped) {
    assert(m_map && "EnvironmentCapture::update(): not created");
    gl::FramebufferBinding keepBinding;
    SavedState keepState;
    if (m_settings.type == MapType::Cube) {
        renderCube(m_map.id(), m_layout.width, m_depth.id(), view, drawFace);
        finish(GL_TEXTURE_CUBE_MAP, m_map.id());
    } else if (m_settings.fill == FillMethod::Resampled) {
        const int size = intermediateCubeSize();
        renderCube(m_cube.id(), size, m_cubeDepth.id(), view, drawFace);
        finish(GL_TEXTURE_CUBE_MAP, m_cube.id());
        resample(m_cube.id()); // the cube was rendered in the map frame
    } else {
        renderWarped(view, drawWarped);
        finish(GL_TEXTURE_2D_ARRAY, m_map.id());
    }
    m_drawn = true;
}

void EnvironmentCapture::resample(GLuint cubeTexture, const glm::dmat3& cubeFromMap) {
    assert(m_settings.type != MapType::Cube && "EnvironmentCapture::resample(): a cube map is not resampled");
    gl::FramebufferBinding keepBinding;
    SavedState keepState;
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
    // The map's own layer before the clear: the colour attachment left from update() is a face of the
    // very cube about to be read, and clearing that wiped its level 0.
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, m_map.id(), 0, 0);
    prepareTarget(m_layout.width, m_layout.height, glm::dvec3(0.0)); // every texel is written below
    glDisable(GL_DEPTH_TEST);
    m_resample.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cubeTexture);
    m_resample.set("uEnvCube", 0);
    m_resample.set("uEnvType", static_cast<int>(m_settings.type));
    m_resample.set("uEnvLayout", m_layout.packed());
    m_resample.set("uEnvSize", glm::vec2(m_layout.width, m_layout.height));
    m_resample.set("uEnvWorldFromMap", glm::mat3(cubeFromMap));
    glBindVertexArray(m_emptyVao.id());
    for (int component = 0; component < m_layout.components; ++component) {
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, m_map.id(), 0, component);
        m_resample.set("uEnvComponent", component);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    finish(GL_TEXTURE_2D_ARRAY, m_map.id());
}

} // namespace speculum::render::envmap
