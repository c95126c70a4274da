#pragma once

#include "base/Result.hpp"
#include "render/envmap/CaptureMath.hpp"
#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"

#include <functional>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace speculum::render::envmap {

enum class FillMethod {
    Direct,    // the scene drawn once per component through the vertex warps of envmap_warp.glsl
    Resampled, // the scene drawn into a cube map, then resampled per texel (exact up to the cube's size)
};

struct CaptureSettings {
    MapType type = MapType::Cube;
    int resolution = 256;                    // n: see MapLayout
    FillMethod fill = FillMethod::Resampled; // ignored by cube maps; octahedral maps are always resampled
    int cubeResolution = 0;                  // resampled fill: the intermediate cube's n (0: same n)
    bool mipmaps = true;                     // trilinear lookups with explicit LOD in pass 2
    GLenum colorFormat = GL_RGBA16F;         // linear colour, as the main pass writes it
};

// Where one update looks from.
struct CaptureView {
    glm::dmat3 mapFromWorld{1.0}; // rotates world axes into the map frame (identity: world-aligned map)
    double near = 0.01;           // cube faces: nothing nearer than near·√3 is ever clipped
    double far = 100.0;           // the furthest distance the map must see
    glm::dvec3 background{0.0};   // the clear colour: what the map shows where nothing is drawn
    // The cube faces (bit f: face f, GL order; the resampled fill's intermediate cube) or direct-fill
    // components (bit c) drawn; the others keep what an earlier update drew (a time-sliced update).
    unsigned faces = kAllFaces;
    static constexpr unsigned kAllFaces = 0x3Fu;
};

// One direct-warp draw: the callback draws the scene (without the reflector) with its warp program
// variant, a vertex shader that includes envmap_warp.glsl and writes gl_Position = envmapWarp(p) with p
// the vertex position relative to the capture point, after setWarpUniforms(program, pass).
struct WarpPass {
    WarpParameters warp;  // type, component, the clip terms; warp.mirrored: swap glFrontFace
    glm::dmat4 view{1.0}; // reflector-relative world → map frame (uEnvWarpView)
};

// Sets uEnvWarpType, uEnvWarpComponent, uEnvWarpView, uEnvWarpParams, uEnvWarpFar on the bound program.
void setWarpUniforms(const gl::Program& program, const WarpPass& pass);

// Owns one environment map's textures and framebuffers and renders it (pass 1).
//
// The map: cube → one GL_TEXTURE_CUBE_MAP, n×n faces; dual paraboloid / tennis ball → one
// GL_TEXTURE_2D_ARRAY with 2 layers (the two components), n×n or n×3n with the guard band inside. A
// depth renderbuffer with 8 stencil bits comes with each render target. The scene itself is drawn by
// callbacks, which find the target bound and cleared (stencil to 0), the viewport set, depth test on
// (GL_LESS, writes on), culling, blending, scissor and stencil tests and clip distance 0 off and the
// front face CCW; they may change any state and need not restore it. update() and resample() put back
// the framebuffer binding, viewport, clear colour, those enables, front face, depth function and write
// masks they found; program, VAO and texture bindings, stencil function and operations they do not.
class EnvironmentCapture {
public:
    using DrawCubeFace =
        std::function<void(const glm::dmat4& viewProjection /*reflector-relative*/, int face)>;
    using DrawWarped = std::function<void(const WarpPass& pass)>;

    EnvironmentCapture() = default;
    // Needs a current context. Every texture and renderbuffer is checked (GL_OUT_OF_MEMORY, framebuffer
    // completeness, gl::setAllocationLimitForTesting). Errors: a shader that does not build, or a part of
    // the map that did not fit ("did not fit in GPU memory (its 8192×8192 intermediate cube)"), when
    // *sizeFailure is set: a smaller resolution may work.
    static base::Result<EnvironmentCapture> create(const CaptureSettings& settings,
                                                   bool* sizeFailure = nullptr);

    const CaptureSettings& settings() const { return m_settings; }
    const MapLayout& layout() const { return m_layout; }

    // Renders the map. Cube maps and the resampled fill call drawFace for each of the six faces in
    // view.faces (into the map itself, or into the intermediate cube); the direct fill calls drawWarped
    // for each component in it. The mip chain is made again, and a resampled map resampled whole from its
    // cube. The callback the fill does not use may be empty. The first update after create() clears the
    // faces it does not draw to the background: they would hold nothing yet (the planner draws a new map
    // whole, so this is a guard, not a picture).
    void update(const CaptureView& view, const DrawCubeFace& drawFace, const DrawWarped& drawWarped);

    // The resampled fill alone: every texel of both components, guard band included, from a cube map
    // whose frame is cubeFromMap · (map frame). For the non-linear maps only.
    void resample(GLuint cubeTexture, const glm::dmat3& cubeFromMap = glm::dmat3(1.0));

    // For pass 2: bind texture() to target() and use envmapLookupCube / envmapLookup2D with
    // layout().packed().
    GLuint texture() const { return m_map.id(); }
    GLenum target() const {
        return m_settings.type == MapType::Cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D_ARRAY;
    }
    // The resampled fill's cube (0 if none).
    GLuint intermediateCube() const { return m_cube.id(); }

    // What update()'s callbacks draw into: the framebuffer they find bound, and its size in texels (a face
    // of the cube, the map's own or the resampled fill's, or a component of the direct fill).
    GLuint framebuffer() const { return m_framebuffer.id(); }
    glm::ivec2 targetSize() const;

    // GPU memory of everything the map owns: the map with its mip chain and depth buffer, and the
    // resampled fill's intermediate cube with its own.
    std::size_t bytes() const;

private:
    int intermediateCubeSize() const {
        return m_settings.cubeResolution > 0 ? m_settings.cubeResolution : m_settings.resolution;
    }
    void renderCube(GLuint cube, int size, GLuint depth, const CaptureView& view,
                    const DrawCubeFace& drawFace);
    void renderWarped(const CaptureView& view, const DrawWarped& drawWarped);
    void finish(GLenum target, GLuint texture);

    CaptureSettings m_settings;
    MapLayout m_layout;
    gl::Texture m_map;        // the map pass 2 reads
    gl::Renderbuffer m_depth; // for m_map (a face or a layer)
    gl::Texture m_cube;       // resampled fill: the intermediate cube
    gl::Renderbuffer m_cubeDepth;
    gl::Framebuffer m_framebuffer;
    gl::VertexArray m_emptyVao; // full-screen triangle without attributes
    gl::Program m_resample;
    bool m_drawn = false; // every face has been drawn (or cleared) once
};

} // namespace speculum::render::envmap
