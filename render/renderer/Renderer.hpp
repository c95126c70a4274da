#pragma once

#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/plan/FramePlan.hpp"
#include "render/plan/FrameReport.hpp"
#include "render/plan/GpuLimits.hpp"
#include "render/plan/RenderOptions.hpp"

#include <cstddef>
#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace speculum::render {

// Draws FrameInput snapshots with OpenGL 3.3 core. Needs a current context for its whole life, from
// create() to destruction (or releaseGlResources() when the context is going away first).
class Renderer {
public:
    static base::Result<std::unique_ptr<Renderer>> create();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    FrameReport render(const FrameInput& input, const RenderTarget& target,
                       const RenderOptions& options = {});

    // Frees every GL object now, while the context is still current. The renderer is unusable after.
    void releaseGlResources();

    // What the context can hold (queried by create()); frames asking for more are planned within it, with
    // a warning (fitShadowMapSize, fitEnvmapResolution). Tests lower the limits to see that happen without
    // allocating gigabytes; each limit only ever goes down.
    const GpuLimits& gpuLimits() const;
    void lowerGpuLimits(const GpuLimits& limits);

    // Who builds a big mesh's simplified level when a reflected view first needs it. By default the frame
    // builds it at once and draws with it (a still or a benchmark waits the seconds that takes). With a
    // request set (the editor, whose frames must not stall), the frame hands the meshes to it and draws
    // them whole until their levels are ready (FramePlan::coarseLevelsWanted); the request is called again
    // each frame until then, so it ignores meshes it is already building.
    using CoarseLevelRequest = std::function<void(const std::vector<MeshHandle>&)>;
    void setCoarseLevelRequest(CoarseLevelRequest request);

    // Called with each frame's plan as soon as it is made, before any pass runs: a command prints the
    // plan's warnings (a map that will take minutes, a size the GPU cannot hold) before the wait, not
    // after it.
    using PlanObserver = std::function<void(const FramePlan&)>;
    void setPlanObserver(PlanObserver observer);

private:
    Renderer();
    struct State;
    std::unique_ptr<State> m_state;
};

// For a caller whose framebuffer's colour texture is 8-bit sRGB and is then drawn into a plain 8-bit window
// by a compositor that does not expect sRGB (Qt's widget compositor samples it as an ordinary texture):
// makes sampling that texture return the bytes it stores, already encoded (EXT_texture_sRGB_decode), so
// the window shows what a plain 8-bit target would. Rendering into it still encodes. The caller checks
// for the extension once per context (this runs every frame). False where the colour attachment is not an
// sRGB texture, or the parameter is refused (no extension after all): the caller should then not declare
// the target RenderTarget::srgbDepthStencil.
bool composeSrgbTextureAsStored(unsigned framebuffer);

} // namespace speculum::render
