#pragma once

#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/gl/Allocation.hpp"
#include "render/passes/EnvironmentCapture.hpp"
#include "render/passes/EnvironmentFaces.hpp"
#include "render/passes/GgxPrefilter.hpp"
#include "render/passes/MainPass.hpp"
#include "render/passes/WarpMeshes.hpp"
#include "render/plan/Planner.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace speculum::render::passes {

// The curved reflectors' two passes, each reflector with a map of its own (by index into
// FrameInput::reflectors).
// Pass 1 (capture): the scene without the reflector, lit and shadowed by the main pass's own drawing,
// from the capture point into the reflector's environment map: six cube faces (model matrices relative
// to the capture point, composed in double), or for the non-linear maps the direct warp (mesh.vert with
// ENVMAP_WARP, meshes split by the angle their edges span) or the resampling of such a cube. Planar
// mirrors reflect the scene in every fill, nested up to reflector.mirrorDepth levels: their passes run
// in each face (drawEnvironmentTarget). The other reflectors are in it: with their plain material at
// bounce 0, with their maps of the bounce before at a later bounce. The map frame is aligned with the
// world axes.
// Pass 2 (drawSurface): the reflector with shaders/reflector.frag, in any view the main pass draws
// (the camera's or a mirror's, whose virtual eye it uses).
class ReflectorPass {
public:
    // Builds the programs. Needs a current context.
    base::Status init();
    // Selects the lit shaders' variant for the frame's lights (gl::Program::select) in every program.
    base::Status selectLighting(const std::string& variant, bool drawVariants);

    // Allocates (or keeps) reflector `index`'s map at the resolution the frame planned, its own. The
    // planner plans below every resolution of its layout that failed before (failedSizes), so a failure
    // here is of one never tried: the largest that works is then found by halving and remembered, with a
    // warning naming the reflector and both sizes, for the next frame to plan; this frame has no map
    // (FellBack). Another error (a shader) is warned (Failed). The map is rendered by capture().
    gl::PlannedAllocation allocate(int index, const Reflector& reflector, std::vector<std::string>& warnings);
    // The smallest resolution of each layout that failed to allocate, for the planner.
    void failedSizes(std::map<MapKind, FailedAllocation>& failed) const;
    // Frees the maps of reflectors past the first `count` (the scene has fewer now).
    void keepMaps(std::size_t count);

    // Starts a frame: no map has been drawn in it yet (a bounce's maps read the bounce before's).
    void beginFrame();
    // Ends it: frees the maps of the bounce before where no bounce was drawn this frame.
    void endFrame();

    // Renders map plan.reflector for `input` (re-creating its textures when the map settings changed) as
    // `plan` says: from its capture point, each face or component with the mirror passes planned in it,
    // which runFacePasses runs there. A later bounce keeps the map of the bounce before for the other
    // maps of its bounce to read. `mirrors` are the cube faces' mirror programs (the warp's variants are
    // the pass's own).
    base::Status capture(const FrameInput& input, const EnvmapPlan& plan, MainPassContext& context,
                         const EnvironmentMirrorPrograms& mirrors, const RunFacePasses& runFacePasses);

    // Whether a map made with the reflector's current settings exists.
    bool hasMap(int index, const Reflector& reflector) const;

    // The Prefilter pass: convolves the map last captured with the GGX lobe into the pre-filtered chain
    // (envmap::GgxPrefilter), `samples` a texel. An error (the program, the chain's allocation) leaves no
    // chain: the reflector then reads the map's mip chain (GlossyFilter::Mip) and the caller warns.
    base::Status prefilter(int index, const Reflector& reflector, int samples);
    // Whether the chain holds the map as last captured (the surface reads it for Footprint).
    bool hasChain(int index, const Reflector& reflector) const;

    // Draws reflector `index` with its map in `view`; false (nothing changed) if there is no map for it.
    bool drawSurface(const FrameInput& input, int index, const ViewSetup& view, MainPassContext& context);

    // Binds reflector `index`'s sharp map and sets `p`'s map uniforms (shaders/parallax.glsl and the map's
    // type, layout and capture point), so that `p` can look it up as a probe from anywhere (the
    // screen-space fallback); false (nothing bound) if there is no map.
    bool bindAsProbe(const FrameInput& input, int index, const gl::Program& p) const;

    // Binds what reflector `index`'s surface reads (the sharp map, its mip chain or the pre-filtered chain,
    // by its roughness and the glossy filter) and sets `p`'s uniforms for it (shaders/reflector_lookup.glsl),
    // so that `p` looks the map up exactly as the surface does; returns the lookup (REFLECTOR_ROUGH's
    // values: 0 sharp, 1 the map's mip chain, 2 the pre-filtered chain), -1 (nothing bound) without a map.
    int bindLookup(const FrameInput& input, int index, const gl::Program& p) const;

    // GPU memory of reflector `index`'s maps (with a bounce's second map) if one made with its current
    // settings exists, else 0.
    std::size_t mapBytes(int index, const Reflector& reflector) const;

    // A reflector's map itself, for tests and tools (null before its first capture).
    const envmap::EnvironmentCapture* map(int index = 0) const;

    void purge() {
        m_warpMeshes.purge();
        m_meshFacts.purge();
    }

private:
    // One reflector's maps and what they hold.
    struct Slot {
        std::optional<envmap::EnvironmentCapture> capture;  // the map as last drawn
        std::optional<envmap::EnvironmentCapture> previous; // a bounce's: the map of the bounce before
        std::uint64_t settingsKey = 0; // of the map last rendered into `capture`; 0: not rendered yet
        std::string reflector;         // the reflector it was rendered for (a deleted one's slot passes on)
        std::uint64_t captures = 0;    // captures so far: the chain knows which one it filtered
        std::uint64_t chainOf = 0;     // the capture the chain holds (0: none)
        std::optional<envmap::GgxPrefilter> prefilter; // built by its first Prefilter pass
        glm::dvec3 centre{0.0};                        // the capture point of the map, world space
        int bounceDrawn = -1; // the bounce its map was last drawn at this frame (-1: not yet)
        bool bounced = false; // `previous` was drawn into this frame
    };
    const Slot* slotOf(int index) const;
    Slot& slot(int index);
    // The texture a map of bounce `bounce` reads of reflector `index`: the bounce before's where its own
    // map of that bounce is already drawn.
    const envmap::EnvironmentCapture* readable(int index, int bounce) const;
    // Makes `s.capture` the target of a later bounce, keeping the map of the bounce before in `previous`.
    base::Status startBounce(Slot& s, const Reflector& reflector);
    // The uniforms every lookup of reflector `r`'s `map` (of slot `s`) needs, seen from `eye`: its type,
    // layout, capture point and parallax proxy.
    void setMapUniforms(const Reflector& r, const glm::dvec3& eye, const Slot& s,
                        const envmap::EnvironmentCapture& map, const gl::Program& p) const;
    // The lookup the reflector's surface takes (reflector_lookup.glsl's REFLECTOR_ROUGH values).
    int lookupOf(const FrameInput& input, int index) const;
    // Binds `map` (its sharp texture, mip chain or slot s's chain, as `lookup` says) for `r`'s lookup.
    void bindMapLookup(const Reflector& r, const glm::dvec3& eye, const Slot& s,
                       const envmap::EnvironmentCapture& map, int lookup, const gl::Program& p) const;
    // Draws reflector env.reflectors[envIndex] (the frame's `index`) into a map of bounce `bounce` with its
    // map of the bounce before, with `program` (m_surface, or m_warpSurface in a direct fill's warp).
    bool drawInMap(const FrameInput& env, int envIndex, int index, int bounce, const ViewSetup& view,
                   const gl::Program& program, MainPassContext& context);

    std::vector<Slot> m_maps;
    std::map<MapKind, gl::SizeFallback> m_fallbacks; // by map layout and fill
    gl::Program m_warp;                              // mesh.vert with ENVMAP_WARP + mesh.frag
    gl::Program m_warpFlat;    // shadow.vert with ENVMAP_WARP + flat.frag: mirror masks in the warp
    gl::Program m_warpMirror;  // mesh.vert with ENVMAP_WARP + mirror.frag: mirror surfaces in the warp
    gl::Program m_surface;     // mesh.vert + reflector.frag
    gl::Program m_warpSurface; // mesh.vert with ENVMAP_WARP + reflector.frag: other reflectors in the warp
    WarpMeshes m_warpMeshes;
    MeshFacts m_meshFacts;
};

} // namespace speculum::render::passes
