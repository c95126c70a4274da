#pragma once

#include <glm/vec2.hpp>
#include <optional>

namespace speculum::render {

// Where a frame ends up: a framebuffer of the caller's (the editor widget's default framebuffer
// object, or an offscreen FBO). Never framebuffer 0 unless the caller owns a window surface.
struct RenderTarget {
    unsigned framebuffer = 0;
    int width = 0;
    int height = 0;
    bool encodeSrgb = true; // 8-bit targets get sRGB-encoded colour; float targets keep linear values
    // The colour attachment is 8-bit sRGB (GL_SRGB8_ALPHA8) and the target has a depth (24-bit) and stencil
    // (8-bit) attachment whose contents the frame may overwrite. A frame drawn in 8-bit sRGB at the
    // target's full size is then drawn straight into it: no buffer of the renderer's, no copy.
    bool srgbDepthStencil = false;
};

// Part of a larger image, for stills beyond what one framebuffer can hold: the target holds the pixels
// from (x, y) (GL window coordinates, y up) of an imageWidth × imageHeight image, as many as it is wide
// and high (it may reach past the image's edge).
struct ImageTile {
    int imageWidth = 0;
    int imageHeight = 0;
    int x = 0;
    int y = 0;
};

// The smallest RenderOptions::resolutionScale; less is drawn at this.
inline constexpr double kMinResolutionScale = 0.125;

struct RenderOptions {
    glm::dvec2 jitterPixels{0.0}; // sub-pixel image offset, for supersampling
    bool gpuTimings = true;       // timer queries per pass (waits for the GPU at the end of the frame)
    // false: plan as if no shadow or environment map existed yet, so every one is rendered this frame.
    // Benchmarks use it to time what an animated scene costs per frame; the maps are reused as usual
    // from the next frame on.
    bool reuseMaps = true;
    // Draw only this tile of the image (planned for the whole image, see restrictToTile); none: the
    // target is the whole image.
    std::optional<ImageTile> tile;
    // Lit shaders built for the frame's lights (passes/LightingVariant) and, for untextured materials,
    // without the texture lookup; false: the shaders that read both from uniforms alone. Both draw the
    // same image; tests and benchmarks compare them.
    bool lightingVariants = true;
    // A shadow lookup whose kernel cannot reach anything the map holds (ShadowMap::casterBounds) answers
    // "lit" without reading it; false: every lookup filters the map. Both draw the same image; tests
    // compare them.
    bool boundShadowLookups = true;
    // The camera's and the mirrors' views cull the back faces of closed meshes they can never see inside
    // (passes::hidesBackFaces), and draw those a near plane cuts only thinly back faces last
    // (passes::drawsBackFacesLast); false: every face is drawn in order. Both draw the same image (tests
    // compare them) but for a rare pixel on an edge where a back face won the depth tie with the front face
    // it meets.
    bool cullHiddenBackFaces = true;
    // Draws the frame at this fraction of the target's width and height (at least one pixel) and scales
    // it up to the whole target in the composite pass (bilinear): an interactive preview costs about the
    // square of it. In [1/8, 1]; 1 (the default) draws every pixel of the target. Ignored for tiles.
    double resolutionScale = 1.0;
    // Draws the camera's view in half float and resolves it in the composite pass even where the plan
    // would draw it in 8-bit sRGB (FramePlan::cameraBuffer): the reference the tests and `speculum time
    // --half-float` compare the cheaper path with.
    bool halfFloatCameraBuffer = false;
};

} // namespace speculum::render
