#pragma once

#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/image/Image.hpp"
#include "render/reference/IdBuffer.hpp"
#include "render/reference/PathRecord.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace speculum::render::reference {

// How the tracer decides whether a point sees a shadowed light.
enum class ShadowMode {
    // One shadow ray to the light (a point on a directional light's far side): the exact hard shadow.
    Hard,
    // The shadow map's footprint: the lookup point gets the same normal and slope offsets as
    // lighting.glsl, then k×k shadow rays (k = the light's pcf) start from points one shadow-map texel
    // apart in the plane across the light's direction, and their visibilities are averaged. Texel sizes
    // come from the same frusta (math::shadowFrustum). What it leaves out: the map's depth quantisation
    // and the snapping of taps to texel centres, so it matches the filtered edge's width and position,
    // not its exact staircase. Use it when comparing reflections, so shadow edges don't dominate the error.
    PcfFootprint,
};

// The range of TraceSettings::samples (and of `speculum render --reference --samples`).
inline constexpr int kMinTraceSamples = 1;
inline constexpr int kMaxTraceSamples = 65536;

struct TraceSettings {
    int width = 1280;
    int height = 720;
    int ssaa = 1; // N: N×N samples per pixel on the same ordered grid as renderStill
    ShadowMode shadows = ShadowMode::Hard;
    // Bounces off curved reflectors along one path: a reflected ray that meets a reflector beyond this
    // count sees its plain material, as a mirror beyond settings.mirrorDepth does. One that meets the
    // reflector it last left again (a concave one seeing itself, or itself through planar mirrors) sees
    // its plain material too: a reflector is not in its own environment map, and that is not an error of
    // the maps the comparison is about. Reflections between different reflectors are followed to the
    // depth, beyond what any count of map bounces draws.
    int reflectorDepth = 8;
    int threads = 0; // worker threads; 0: one per hardware thread
    // Paths per sub-sample (kMinTraceSamples..kMaxTraceSamples) where the first path meets a rough mirror
    // or reflector: the first path and samples − 1 more, averaged. Elsewhere a pixel is exact and traced
    // once.
    int samples = 16;
};

// Called from the calling thread with the finished fraction (0..1); returning false cancels the render.
using TraceProgress = std::function<bool(double fraction)>;

struct TraceResult {
    Image image;  // linear RGBA (alpha 1), row 0 at the top
    IdBuffer ids; // what the ray through each pixel's centre hit first
    double totalMs = 0.0;
    int samples = 1;                   // per pixel: the SSAA sub-samples
    int paths = 1;                     // per sub-sample that meets a rough surface (settings.samples)
    std::vector<std::string> warnings; // e.g. a texture that failed to load (shown as a checker)
    // The Monte Carlo noise of rough reflections. Per pixel (RGB; alpha 1): the squared standard error of
    // the pixel's value, i.e. its paths' sample variance over their number (summed over sub-samples / n⁴
    // with SSAA n), in linear radiance²; 0 for an exact pixel, NaN for a rough one traced with one path.
    Image noise;
    // √(mean over all pixels and RGB channels of `noise`): the typical error of a pixel; 0 for an exact
    // image, NaN when rough pixels had one path each. Halves when paths quadruple.
    double noiseRms = 0.0;
    int glossyPixels = 0; // pixels with a sub-sample that needed several paths
};

// One pixel explained: its colour exactly as the traced still has it, and the paths that made it.
struct PixelPaths {
    int x = 0;
    int y = 0;
    glm::dvec3 colour{0.0}; // the still's pixel (TraceResult::image) for the same settings
    glm::dvec3 noise{0.0};  // its squared standard error (TraceResult::noise)
    bool glossy = false;    // a sub-sample met a rough surface: the colour is an average of paths
    PixelId id;             // what the pixel's centre shows
    // The ray through the pixel's centre and the path it starts, recorded vertex by vertex.
    TracedPath centre;
    // Where the centre's path met a rough surface: further samples of the lobe through the same centre
    // (the paths the still averaged, without SSAA), each recorded the same way.
    std::vector<TracedPath> samples;
    // The traced colours of the window around the pixel (clipped to the image), row by row from the top.
    int windowX = 0;
    int windowY = 0;
    int windowWidth = 0;
    int windowHeight = 0;
    std::vector<glm::dvec3> window;
    std::vector<PixelId> windowIds; // what each window pixel's centre shows, in the same order
};

// What a ray from a world point meets first (Tracer::firstHit).
struct RayHit {
    PixelId id;               // Background: nothing
    double distance = 0.0;    // world units; infinite for nothing
    glm::dvec3 position{0.0}; // world
};

// The exact reference: renders a FrameInput by ray tracing (Embree 3) with the rasterizer's shading
// model (shaders/material.glsl, lighting.glsl, mirror.frag), so that every difference between the two
// images is an approximation of the rasterizer's, not a difference of models.
//
// - Camera: the same pinhole, field of view and aspect; primary rays are clipped to [near, far] in view
//   depth, and a path reflected in planar mirrors keeps the same far plane (its unfolded length).
// - Shading: Blinn-Phong with the constants of material.glsl; only the first 8 lights light
//   the scene, and only the lights the planner gives a shadow map cast shadows (shadow rays against
//   items that cast shadows and the reflector; mirrors cast none, as in the shadow pass). Surfaces are
//   two-sided like mesh.frag: a back face is lit with its normal turned towards the viewer.
// - Textures: bilinear with repeat and sRGB decoding before filtering, like the GL sampler, but from
//   the full-resolution image only: no mipmaps, so a texture seen far away aliases where GL blurs it
//   (supersample to compare).
// - Planar mirrors: surface·(1−R) + R·tint·reflection with Schlick's R when fresnel is on, exactly as
//   mirror.frag blends; a mirror seen at a depth beyond settings.mirrorDepth, or from behind, shows its
//   material.
// - Curved reflector: intersected as its real tessellated mesh and reflected about the interpolated
//   normal, from the point hit (no capture point, so no parallax error, and no map resolution);
//   surface·(1−R) + R·reflection with Schlick's R when fresnel is on, as reflector.frag blends. Inside
//   its reflection, planar mirrors recurse to the reflector's mirrorDepth (the levels its map holds).
// - Rough (glossy) reflections: with roughness > 0 a mirror's or the reflector's `reflection` above is
//   the GGX (Trowbridge–Reitz) lobe's integral ∫ f(v, l) (n·l) L(l) dl with α = roughness² and F = 1 in
//   the lobe (R, from the macro normal, and tint stay outside, as in the shaders), with the
//   height-correlated Smith G2 (render/math/Ggx.hpp). It is estimated by path tracing: at each rough
//   bounce a path takes one sample of the visible normals seen from v (Heitz 2018), follows
//   l = reflect(−v, h) with the weight G2/G1(v), and carries nothing if l is below the surface; mirrors
//   and the reflector recurse as above, to the same depths. Random numbers are a hash of (pixel, path,
//   bounce), so an image is reproducible whatever the threads, and samples are independent: the variance
//   halves when settings.samples doubles. A sub-sample whose first path meets no rough surface is exact
//   and traced once; roughness 0 samples nothing and gives the sharp image bit for bit.
// - Noise: TraceResult::noise is each pixel's squared standard error, estimated from the spread of its
//   own paths, and noiseRms its root mean square over the image: a difference between the rasterizer's
//   glossy image and this one much below noiseRms is not measurable at this sample count.
// - Misses show settings.background.
//
// Thread-safe once created: render() may run on any thread, several at once.
class Tracer {
public:
    // Builds the acceleration structures. Errors: Embree cannot start (no supported CPU).
    static base::Result<Tracer> create(const FrameInput& input);

    Tracer(Tracer&&) noexcept;
    Tracer& operator=(Tracer&&) noexcept;
    ~Tracer();

    // Renders width × height. Errors: a size that is not positive, or the caller cancelled.
    base::Result<TraceResult> render(const TraceSettings& settings, const TraceProgress& progress = {}) const;

    // Explains pixel (x, y) of the image `settings` describes: the traced paths through its centre, up to
    // `samplePaths` of them where it is glossy, its colour as render() gives it, and the colours of the
    // pixels up to `windowRadius` away. Errors: a pixel outside the image, a size that is not positive.
    base::Result<PixelPaths> explainPixel(const TraceSettings& settings, int x, int y, int windowRadius = 2,
                                          int samplePaths = 8) const;

    // The first surface a ray from `origin` (world) along `direction` meets, mirrors and reflectors
    // included but for reflector `ignoreReflector` (what its own map, captured from inside it, leaves out).
    RayHit firstHit(const glm::dvec3& origin, const glm::dvec3& direction, int ignoreReflector = -1) const;

    // The fraction of light `light` (index into FrameInput::lights) the shadow map's PCF footprint lets
    // reach the world point `position` with unit normal `normal` (ShadowMode::PcfFootprint): what the
    // rasterizer's filtered lookup gives there, up to the map's quantisation. 1 for a light without a
    // shadow map, or one behind the surface.
    double footprintVisibility(int light, const glm::dvec3& position, const glm::dvec3& normal) const;

    // Warnings from building the scene: textures that failed to load, triangles dropped as invalid.
    const std::vector<std::string>& warnings() const;

private:
    struct Impl;
    explicit Tracer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

} // namespace speculum::render::reference
