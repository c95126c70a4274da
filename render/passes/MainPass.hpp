#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/gl/GpuMesh.hpp"
#include "render/gl/Program.hpp"
#include "render/gl/TextureCache.hpp"
#include "render/passes/ShadowMaps.hpp"

#include <functional>
#include <glm/mat4x4.hpp>
#include <string>
#include <vector>

namespace speculum::render::passes {

// Texture units the main pass uses: 0 for the material texture, then the shadow slots.
inline constexpr int kMaterialTextureUnit = 0;
inline constexpr int kShadow2DUnit = 1;   // 1..4
inline constexpr int kShadowCubeUnit = 5; // 5..8
inline constexpr int kReflectionTextureUnit = 9;
inline constexpr int kEnvCubeUnit = 10;  // the reflector's cube map
inline constexpr int kEnvArrayUnit = 11; // the reflector's dual-paraboloid or tennis-ball map
inline constexpr int kEmissionTextureUnit = 12;
inline constexpr int kNormalTextureUnit = 13;
inline constexpr int kGgxAlbedoUnit = 14; // math::ggxAlbedoTable, bound for the whole frame (runPasses)

struct MainPassContext;
struct ViewSetup;
class MeshFacts;
// Draws curved reflector `index` (into FrameInput::reflectors) in a view instead of the main pass's plain
// material; returns false (having changed nothing) when it cannot, and the main pass draws the material.
using DrawReflector = std::function<bool(const FrameInput&, int index, const ViewSetup&, MainPassContext&)>;

// Everything the main pass needs besides the scene: resources owned by the renderer.
struct MainPassContext {
    const gl::Program& program;
    gl::MeshCache& meshes;
    gl::TextureCache& textures;
    const ShadowMaps& shadows;
    // The frame's shadow maps, by slot (FramePlan::shadows): which light, where its map looks from, how
    // its lookups filter.
    const std::vector<ShadowPlan>& shadowPlans;
    GLuint dummyShadow2D;
    GLuint dummyShadowCube;
    MeshHandle unitPlane;           // the mirror rectangle: [-1,1]² in XZ
    bool mirroredView = false;      // set by beginLitView from ViewSetup::clockwise
    bool pathLengthInAlpha = false; // set by beginLitView from ViewSetup::pathLengthInAlpha
    DrawReflector drawReflector;    // empty: the reflectors are drawn with their material
    // Per mirror (by index), a mesh drawn instead of unitPlane where set: the environment's direct fill
    // splits each rectangle for the capture point it is seen from.
    std::vector<MeshHandle> mirrorMeshes;
    // Sets on another program what the view being drawn gave its own (a direct-fill warp's uniforms and clip
    // plane), so that a DrawReflector with a program of its own draws into the same view; empty: nothing.
    std::function<void(const gl::Program&)> prepareProgram;
    // Per item (by index), true where the view can never see the item's back faces (a closed mesh seen from
    // outside): drawn with them culled. The environment pass sets it; empty draws every face.
    std::vector<bool> cullBackFaces;
    // Where set, each view also culls the back faces of items it can never see them on (closed meshes of
    // opaque materials wholly beyond its near plane); null: only cullBackFaces.
    MeshFacts* meshFacts = nullptr;
    // Per item (by index), true where a view with ViewSetup::coarseDetail draws the item's simplified level
    // (FramePlan::coarseItems).
    std::vector<bool> coarseItems;

    const MeshHandle& mirrorMesh(std::size_t mirror) const {
        return mirror < mirrorMeshes.size() && mirrorMeshes[mirror] ? mirrorMeshes[mirror] : unitPlane;
    }
    // Draws a mirror rectangle's depth (uModelLightClip); null: stencil mirrors lay no depth first.
    const gl::Program* depthOnlyProgram = nullptr;

    // What setMaterial chose for the draws that follow: its draw-variant defines (which assume a mesh
    // without vertex colours; drawLitMesh switches for one that has them) and whether it has a normal map.
    mutable std::string materialDefines;
    mutable bool materialNormalMap = false;
};

// How one view sees the scene: the camera's own, or the scene reflected in a mirror.
struct ViewSetup {
    glm::dmat4 viewProjection{1.0};  // camera-relative world → clip (with an oblique near plane in mirrors)
    glm::dmat4 reflection{1.0};      // world → reflected world (identity for the camera's view)
    glm::dvec3 eye{0.0};             // world position of the (virtual) eye: lighting and specular use it
    std::vector<bool> skipMirror;    // mirrors drawn by passes of their own in this view (by mirror index)
    std::vector<bool> stencilMirror; // of those, the ones drawn through the stencil (their depth goes first)
    // Front faces wind clockwise in this view: the plan's PassWrites::clockwise (an odd number of
    // reflections), flipped once more where a warped environment component mirrors the image.
    bool clockwise = false;
    // The part of clip space the view can draw into (x0, y0, x1, y1 in normalized device coordinates):
    // a mirror's view only shows through its mirror's pixels. Objects wholly outside are not drawn.
    glm::dvec4 ndcBounds{-1.0, -1.0, 1.0, 1.0};
    bool cullOutside = false; // off for warped views, whose clip space is not a frustum
    // A reflected view or one of the environment map's: draws MainPassContext::coarseItems simplified.
    bool coarseDetail = false;
    // The view draws into a mirror's reflection texture: shaders store each point's path length in alpha
    // (material.glsl's outputAlpha), which a rough mirror's blur reads.
    bool pathLengthInAlpha = false;
    // What the camera's buffer keeps of this view's scene (MirrorView::weight): lit shaders multiply their
    // colour by it (uViewWeight).
    glm::dvec3 weight{1.0};
    // Stencil mirrors seen in this view draw pre-weighted (FramePlan::preWeighted): their surfaces are
    // added over reflections already weighted, instead of blended onto them.
    bool preWeightedStencil = false;
};

// Binds the lit-material program and sets everything that is the same for every object of the view:
// camera, lights, shadow maps.
void beginLitView(const FrameInput& input, const ViewSetup& view, const gl::Program& program,
                  MainPassContext& context);

// True when `view` can never see the item's back faces, so drawMainPass culls them (with
// context.meshFacts set): a closed, outward-wound mesh (isClosed) of an opaque material lying wholly
// beyond the view's near plane (the mirror's plane in a mirror's view), so no clip opens it.
bool hidesBackFaces(const DrawItem& item, const FrameInput& input, const ViewSetup& view,
                    const MainPassContext& context);

// True when drawMainPass draws the item's front faces first and then its back faces (with
// context.meshFacts set): a closed, outward-wound mesh of an opaque material (at most 65 536 triangles)
// that the view's near plane cuts only thinly (at most 1% of its bounds' diagonal), as a mirror's clip
// cuts an object resting on it. Its back faces show only through the cut; drawn last, they are not
// shaded where the front faces hide them, and the image is the same but for a rare depth tie.
bool drawsBackFacesLast(const DrawItem& item, const FrameInput& input, const ViewSetup& view,
                        const MainPassContext& context);

// Draws every object with Blinn-Phong lighting and filtered shadows into the bound framebuffer, and the
// mirrors that got no pass of their own: their paths end there, so their front shows only their surface's
// share (1 − reflectivity) and their back their material.
void drawMainPass(const FrameInput& input, const ViewSetup& view, MainPassContext& context);

// Sets a material's uniforms (and binds its textures) on the lit program, and binds the program's draw
// variant that compiles out what the material does not use (no texture, emission or normal map, no mask).
// `drawDefines` specialise the variant further for every draw that follows (a mirror's technique).
void setMaterial(const Material& material, const gl::Program& program, const MainPassContext& context,
                 const std::string& drawDefines = {});

// The alpha below which a masked material is cut away: its cutoff, or one half for Blend (drawn as Mask).
double alphaCutoff(const Material& material);

// Draws one mesh with a world matrix, in the view set by beginLitView.
void drawLitMesh(const MeshHandle& mesh, const glm::dmat4& world, const FrameInput& input,
                 const gl::Program& program, const MainPassContext& context,
                 gl::Detail detail = gl::Detail::Full);

// The world matrix of a mirror's rectangle drawn with the unit plane mesh.
glm::dmat4 mirrorRectangle(const Mirror& mirror);

// The world matrix a mirror's mesh (MainPassContext::mirrorMesh) is drawn with in a view: the unit
// plane's rectangle, only the part in view when the rest is huge; a split mesh's whole rectangle.
glm::dmat4 drawnMirrorWorld(const FrameInput& input, std::size_t mirror, const ViewSetup& view,
                            const MainPassContext& context);

// Object → clip of a mirror's mesh drawn in a view, composed in double. The depth-first pass and the
// stencil mask both use it with the same program, so their depths agree exactly. In a direct-fill
// component, whose views have no projection (an identity viewProjection), it ends in the reflected
// capture-relative coordinates the warp takes.
glm::mat4 mirrorRectangleClip(const FrameInput& input, std::size_t mirror, const ViewSetup& view,
                              const MainPassContext& context);

} // namespace speculum::render::passes
