#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/frame/SceneLimits.hpp"

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace speculum::render {

// The sizes an OpenGL context can allocate and draw into, in pixels per side.
struct GpuLimits {
    int maxTextureSize = 16384;      // GL_MAX_TEXTURE_SIZE
    int maxCubeMapSize = 16384;      // GL_MAX_CUBE_MAP_TEXTURE_SIZE
    int maxRenderbufferSize = 16384; // GL_MAX_RENDERBUFFER_SIZE
    int maxViewportSize = 16384;     // the smaller of GL_MAX_VIEWPORT_DIMS
    // GL runs on the CPU (Mesa's llvmpipe or softpipe, by GL_RENDERER): the rates MapCost estimates with.
    bool software = true;
};

// How much faster a GPU draws and filters maps than llvmpipe on two cores, roughly: a bound on an
// interactive view's map work (RenderOptions::maxMapSeconds) allows this much more on one.
inline constexpr double kGpuOverSoftware = 100.0;

// Asks the current context. Defined by the GL library (render/gl/GpuLimitsQuery.cpp); the rest of this
// header is GL-free.
GpuLimits queryGpuLimits();

// Smallest sizes the passes work with (render/frame/SceneLimits.hpp): a shadow map below 16 texels is no map,
// and the environment maps' guard bands need a few texels each side.
inline constexpr int kMinEnvmapResolution = kMinEnvironmentMapSize;

// The kinds of map whose allocations succeed or fail alike at a given size: a light's depth map (2D, or a
// cube for a point light) and the reflector's map, per layout and fill (a cube map has no fill of its own).
enum class MapKind {
    Shadow2D,
    ShadowCube,
    EnvmapCube,
    EnvmapParaboloid,
    EnvmapParaboloidResampled,
    EnvmapTennisBall,
    EnvmapTennisBallResampled,
    EnvmapOctahedral, // always resampled
};

MapKind shadowMapKind(const Light& light);
MapKind envmapKind(const Reflector& reflector);

// FailedAllocation::size of a kind of map no allocation of which failed.
inline constexpr int kNoFailedSize = std::numeric_limits<int>::max();

// The smallest size of a kind of map whose allocation failed, and why ("did not fit in GPU memory"): a
// huge map that failed once is not asked for again every frame.
struct FailedAllocation {
    int size = kNoFailedSize;
    std::string reason;
};

// What the frame's map sizes are planned within: what the context can hold, and what allocation learnt in
// earlier frames (the passes remember every size that failed; the renderer hands them to the planner).
struct MapLimits {
    GpuLimits gpu;
    std::map<MapKind, FailedAllocation> failed;

    const FailedAllocation& failure(MapKind kind) const;
};

// The largest size from `size` down by halving that lies below the size that failed, and not below
// `minimum` (where `size` is smaller, `minimum`); 0 when even the minimum failed. Allocation's fallback
// halves the same way, so the planner plans the very size allocation settled on.
int belowFailure(int size, int minimum, const FailedAllocation& failed);

// A light's shadow map size as the frame draws it, from `asked` (the light's own, or a preview's): brought
// within the GPU's limits and above the smallest map, then below the sizes of its kind that failed to
// allocate. Each change adds a warning naming the light and both sizes. 0: not even the smallest map of its
// kind fits (also warned). Needs no GL.
int fitShadowMapSize(const Light& light, int lightIndex, int asked, const MapLimits& limits,
                     std::vector<std::string>& warnings);

// The reflector's map resolution as the frame draws it, the same way: within the GPU's limits for every
// texture its layout and fill need, then below the sizes of its layout that failed. 0: none fits.
int fitEnvmapResolution(const Reflector& reflector, const MapLimits& limits,
                        std::vector<std::string>& warnings);

// The warning for a map smaller than asked because `asked` failed to allocate (`reason`, as
// finishAllocation words it): "light 'Lamp': the 8192² cube shadow map did not fit in GPU memory; using
// 512²", or, `used` 0, that none down to the smallest fits. The planner says it for a size that failed
// before, allocation for one that fails now.
std::string shadowFallbackWarning(const Light& light, int lightIndex, int asked, const std::string& reason,
                                  int used);
std::string envmapFallbackWarning(const Reflector& reflector, int asked, const std::string& reason, int used);

} // namespace speculum::render
