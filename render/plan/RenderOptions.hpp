#pragma once

#include "render/frame/Guides.hpp"

#include <glm/vec2.hpp>
#include <optional>
#include <vector>

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

// The smallest shadow map a preview shrinks a light's to (texels a side): smaller, the shadow of a dragged
// object blurs away.
inline constexpr int kMinPreviewShadowMapSize = 256;

// What an interactive preview gives up to keep up with the view (the editor's viewport while it is navigated
// or a handle dragged): pixels, levels of mirror nesting, the environment map's updates and, while a handle
// is dragged, shadow map texels. The renderer draws at the scale; the planner applies the rest and lists
// each effect among the frame's skips, with a preview code (isPreview). The default gives up nothing: a
// frame at rest.
struct PreviewPolicy {
    // The fraction of the target's width and height drawn, scaled up by the composite pass (as
    // resolutionScale: the smaller of the two applies).
    double scale = 1.0;
    // Levels of mirror nesting left out: settings.mirrorDepth less this, but never less than one level.
    int mirrorDepthCut = 0;
    // A handle is dragged: what casts shadows changes every frame, so every shadow map is drawn again anyway,
    // a power of two smaller per halving of `scale` (never under kMinPreviewShadowMapSize², nor larger than
    // the light's own). Navigating changes no shadow: the maps are reused as they are.
    bool redrawsShadows = false;

    // Something is given up. The environment map is then held as it is, drawn only where there is none
    // yet: an orbit never changes it, and a handle drag would draw it again every frame.
    bool active() const { return scale < 1.0 || mirrorDepthCut > 0; }
};

struct RenderOptions {
    glm::dvec2 jitterPixels{0.0}; // sub-pixel image offset, for supersampling
    bool gpuTimings = true;       // timer queries per pass (waits for the GPU at the end of the frame)
    // Each screen-space mirror's trace counts its pixels by where their reflection came from (the image,
    // the reflector's map or the background) and says so in its pass's outcome. Reads the trace back:
    // stills and explain.
    bool countScreenSpace = false;
    // Each screen-space mirror's pixels are drawn in the colour of where their reflection came from (the
    // editor's debug view): green, met in the image; blue, the reflector's map; red, the background;
    // blended as the trace's confidence blends them.
    bool showScreenSpaceSources = false;
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
    // An interactive view's bound on drawing the reflectors' maps, all bounces together
    // (PlanOptions::maxMapSeconds); 0, the default: the maps as the scene asks.
    double maxMapSeconds = 0.0;
    // Draws the camera's view in half float and resolves it in the composite pass even where the plan
    // would draw it in 8-bit sRGB (FramePlan::cameraBuffer): the reference the tests and `speculum time
    // --half-float` compare the cheaper path with.
    bool halfFloatCameraBuffer = false;
    // An interactive preview (see PreviewPolicy); the default is a frame at rest. Ignored for tiles.
    PreviewPolicy preview;
    // Lines drawn over the camera's view after its mirrors, depth-tested against them (PassKind::Guides):
    // the editor's grid and camera wireframe. Ignored for tiles, which are parts of stills.
    std::vector<GuideLine> guides;
    // Explaining a pixel: after each pass, the value it left at this pixel of the target (x from the
    // left, y from the top, in the target's pixels) is read back into FrameReport::probes. Each read waits
    // for the GPU: only for one frame on request, never in a frame that is only drawn.
    std::optional<glm::ivec2> probePixel;
};

} // namespace speculum::render
