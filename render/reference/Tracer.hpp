#pragma once

#include "render/FrameInput.hpp"
#include "render/Result.hpp"
#include "render/image/Image.hpp"
#include "render/reference/IdBuffer.hpp"

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

struct TraceSettings {
    int width = 1280;
    int height = 720;
    int ssaa = 1; // N: N×N samples per pixel on the same ordered grid as renderStill
    ShadowMode shadows = ShadowMode::Hard;
    // Bounces off the curved reflector along one path. 1 is what an environment map shows (the scene
    // seen from the reflector); a reflected ray that meets the reflector again beyond this count sees
    // its plain material, as a mirror beyond settings.mirrorDepth does.
    int reflectorDepth = 1;
    int threads = 0; // worker threads; 0: one per hardware thread
};

// Called from the calling thread with the finished fraction (0..1); returning false cancels the render.
using TraceProgress = std::function<bool(double fraction)>;

struct TraceResult {
    Image image;  // linear RGBA (alpha 1), row 0 at the top
    IdBuffer ids; // what the ray through each pixel's centre hit first
    double totalMs = 0.0;
    int samples = 1;                   // per pixel
    std::vector<std::string> warnings; // e.g. a texture that failed to load (shown as a checker)
};

// The exact reference: renders a FrameInput by ray tracing (Embree 3) with the rasterizer's shading
// model (shaders/material.glsl, lighting.glsl, mirror.frag), so that every difference between the two
// images is an approximation of the rasterizer's, not a difference of models.
//
// - Camera: the same pinhole, field of view and aspect; primary rays are clipped to [near, far] in view
//   depth, and a path reflected in planar mirrors keeps the same far plane (its unfolded length).
// - Shading: Blinn-Phong of DESIGN.md with the constants of material.glsl; only the first 8 lights light
//   the scene, and only the lights the planner gives a shadow map cast shadows (shadow rays against
//   items that cast shadows and the reflector; mirrors cast none, as in the shadow pass). Surfaces are
//   two-sided like mesh.frag: a back face is lit with its normal turned towards the viewer.
// - Textures: bilinear with repeat and sRGB decoding before filtering, like the GL sampler, but from
//   the full-resolution image only: no mipmaps, so a texture seen far away aliases where GL blurs it
//   (supersample to compare).
// - Planar mirrors: surface·(1−R) + R·tint·reflection with Schlick's R when fresnel is on, exactly as
//   mirror.frag blends; a mirror seen at a depth beyond settings.mirrorDepth, or from behind, shows its
//   material. Blur (a mip level of the texture technique) is not modelled: the reference is the sharp
//   reflection.
// - Curved reflector: intersected as its real tessellated mesh and reflected about the interpolated
//   normal, from the point hit (no capture point, so no parallax error, and no map resolution);
//   surface·(1−R) + R·reflection with Schlick's R when fresnel is on, as reflector.frag blends. Inside
//   its reflection, planar mirrors recurse to the reflector's mirrorDepth (the levels its map holds).
// - Misses show settings.background.
//
// Thread-safe once created: render() may run on any thread, several at once.
class Tracer {
public:
    // Builds the acceleration structures. Errors: Embree cannot start (no supported CPU).
    static Result<Tracer> create(const FrameInput& input);

    Tracer(Tracer&&) noexcept;
    Tracer& operator=(Tracer&&) noexcept;
    ~Tracer();

    // Renders width × height. Errors: a size that is not positive, or the caller cancelled.
    Result<TraceResult> render(const TraceSettings& settings, const TraceProgress& progress = {}) const;

    // Warnings from building the scene: textures that failed to load, triangles dropped as invalid.
    const std::vector<std::string>& warnings() const;

private:
    struct Impl;
    explicit Tracer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

} // namespace speculum::render::reference
