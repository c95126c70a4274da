#pragma once

#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/image/Image.hpp"
#include "render/plan/FrameReport.hpp"
#include "render/reference/Tracer.hpp"

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace speculum::render::inspect {

// One step of the rasterizer's recipe for a pixel: a pass that wrote the pixel, or drew a map a later
// step reads there, in the order the frame ran them.
struct RecipeStep {
    int run = -1;           // index into FrameReport::ran
    std::string pass;       // the pass kind ("mirror", "main", "envmap")
    std::string target;     // the node it draws for (a mirror, a reflector, a light); empty: the frame
    std::string what;       // what it did at this pixel, in words
    std::string why;        // the plan's reason for running it
    bool wrote = false;     // it changed the pixel of the buffer it drew into (or cleared it and drew there)
    bool cleared = false;   // it cleared the pixel before drawing: what the buffer held there before is gone
    bool feeds = false;     // it drew a map (shadow, environment, GGX chain) a later step reads here
    bool readable = false;  // `colour` and `stencil` were read back from its buffer
    glm::dvec3 colour{0.0}; // what its buffer held at the pixel after it (linear)
    int stencil = -1;       // the stencil value there after it (-1: its buffer has none)
    int mirrorLevel = -1;   // mirror passes: the view's nesting depth (1: seen by the camera)
    std::string buffer;     // which buffer it drew into ("camera", "reflection texture 0", "output", "map")
};

// Where the environment-map lookup of a reflector pixel reads, as reflector.frag computes it.
struct MapLookup {
    std::string reflector;
    int reflectorIndex = -1;
    std::string layout;         // "cube", "dual-paraboloid", …
    int resolution = 0;         // as the frame planned it
    int component = 0;          // cube face (GL order) or component
    std::string componentLabel; // "+X face", "−Z half", "part 1", "square"
    int texelX = 0; // texel in the component (cube: GL's s; others: the texture's, guard band included)
    int texelY = 0;
    double mipLevel =
        0.0; // the level read: roughness × (levels − 1) when rough; 0 (plus the pixel's footprint) when sharp
    std::string filter;       // "sharp", "GGX chain", "mip chain"
    glm::dvec3 position{0.0}; // world point of the reflector the lookup is for
    glm::dvec3 normal{0.0};
    glm::dvec3 reflected{0.0};   // the reflected direction about the interpolated normal
    glm::dvec3 lookup{0.0};      // the direction looked up in the map (after the parallax proxy, if any)
    glm::dvec3 texelCentre{0.0}; // the direction of the texel's centre
    glm::dvec3 centre{0.0};      // the capture point
    bool parallax = false;
    double texelSolidAngle = 0.0;     // steradians of the texel read
    double cubeTexelSolidAngle = 0.0; // of a cube map's texel at the same resolution and direction
    // How far the lookup lies from its component's edge (a cube face's side, a paraboloid's rim, the tennis
    // ball's or the octahedral square's side), in texels: a seam where it is below 2.
    double seamTexels = 0.0;
    int guard = 0; // the layout's guard band, texels
};

// A named cause of a difference between the two, where the recipe knows one.
struct Cause {
    std::string code; // "capture-point", "texel-size", "depth-limit", "glossy-noise", "shadow", …
    std::string text;
};

struct PixelExplanation {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    glm::dvec3 rasterColour{0.0}; // the rasterized still's pixel (linear)
    glm::dvec3 exactColour{0.0};  // the traced still's pixel (linear)
    // |raster − exact| per channel in sRGB-encoded values (what the eye and the PNG see), and its RMS.
    glm::dvec3 error{0.0};
    double errorRms = 0.0;
    // The same over the window of ±windowRadius pixels around it (clipped to the image): RMSE and PSNR.
    int windowRadius = 2;
    double windowRmse = 0.0;
    double windowPsnr = 0.0;
    double exactStandardError = 0.0; // √(the exact pixel's noise), mean over RGB: 0 for an exact pixel
    // A rough first lobe: the mean angle of its sampled directions from the mirror direction (0: none).
    double lobeSpreadDegrees = 0.0;
    reference::PixelPaths exact;
    std::vector<RecipeStep> recipe;
    std::optional<MapLookup> lookup;
    std::vector<Cause> causes;
    // A screen-space mirror or reflector pixel: the share of its reflection the trace met in the camera's
    // image (0..1), and where the rest came from ("the reflector's map", "the background"). -1: not one.
    double screenSpaceHit = -1.0;
    std::string screenSpaceFallback;
    std::vector<std::string> notes; // what the recipe could not record (a tiled still, a preview)
};

// The name of the node a ray met (an item, a mirror, a reflector); empty for the background.
std::string nodeName(const FrameInput& input, const reference::PixelId& id);

// The raster recipe of pixel (x, y) from a frame's report and its probes (RenderOptions::probePixel).
std::vector<RecipeStep> rasterRecipe(const FrameInput& input, const FrameReport& report);

// The map lookup of the first reflector the exact path meets, as the raster reads it (none: the path meets
// no reflector, or the reflector got no map this frame).
std::optional<MapLookup> mapLookup(const FrameInput& input, const FramePlan& plan,
                                   const reference::TracedPath& path);

// Puts the two side by side: the colours, their error at the pixel and over the window, the recipe, the
// lookup, and the causes the two name. `raster` is the rasterized still (the report's frame), `exact` the
// tracer's explanation of the same pixel at the same size, `tracer` the tracer that made it (for what the
// map sees from its capture point). `screenSpaceSource`, where the scene has screen-space reflections: the
// pixel's colour in the sources view (render::screenSpaceSourceAt), which says where its trace took the
// reflection from.
base::Result<PixelExplanation> explainPixel(const FrameInput& input, const FrameReport& report,
                                            const Image& raster, const reference::PixelPaths& exact,
                                            const reference::Tracer& tracer,
                                            const std::optional<glm::dvec3>& screenSpaceSource = {});

} // namespace speculum::render::inspect
