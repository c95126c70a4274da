#include "render/passes/MainPass.hpp"

#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/passes/EnvironmentFaces.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

namespace speculum::render::passes {

namespace {

std::string indexed(const char* name, int i) {
    return std::string(name) + "[" + std::to_string(i) + "]";
}

// A double vector as a float uniform that is never Inf or NaN: values no reader accepts (an intensity of
// 1e39 overflows a float) are clamped to ±1e30, NaN becomes 0. Accepted values (SceneLimits.hpp) pass as
// they are.
glm::vec3 finiteUniform(const glm::dvec3& v) {
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = std::isnan(v[i]) ? 0.0f : float(std::clamp(v[i], -1e30, 1e30));
    return out;
}

// The inverse transpose of a model matrix, scaled so its largest column is unit length. The shader
// normalizes the normal anyway, and a scale of 1e-20 or 1e20 would otherwise make it overflow or vanish
// in float (a scale of 1e-9 gives 1e9 per normal, 1e-9 per tangent plane: far from both limits, but the
// division costs nothing).
glm::mat3 normalMatrix(const glm::dmat4& model) {
    glm::dmat3 n = glm::inverseTranspose(glm::dmat3(model));
    const double largest = std::max({glm::length(n[0]), glm::length(n[1]), glm::length(n[2])});
    if (largest > 0.0 && std::isfinite(largest))
        n /= largest;
    else
        n = glm::dmat3(1.0); // a singular or non-finite transform: no triangle of it is drawn anyway
    return glm::mat3(n);
}

void setLights(const FrameInput& input, const glm::dmat4& toCameraRelative, const gl::Program& p,
               const MainPassContext& ctx) {
    const int count = std::min<int>(static_cast<int>(input.lights.size()), kMaxLights);
    p.set("uLightCount", count);
    for (int i = 0; i < count; ++i) {
        const Light& light = input.lights[static_cast<std::size_t>(i)];
        const int type = light.type == LightType::Point ? 0 : light.type == LightType::Directional ? 1 : 2;
        p.set(indexed("uLightType", i), type);
        p.set(indexed("uLightPosition", i),
              finiteUniform(glm::dvec3(toCameraRelative * glm::dvec4(light.position, 1.0))));
        const double dirLength = glm::length(light.direction);
        const glm::dvec3 dir =
            dirLength > 0.0 && std::isfinite(dirLength) ? light.direction / dirLength : glm::dvec3(0, -1, 0);
        p.set(indexed("uLightDirection", i), glm::vec3(dir));
        p.set(indexed("uLightRadiance", i), finiteUniform(light.color * light.intensity));
        const double outer = glm::radians(std::clamp(light.spotAngle, 0.1, 179.0));
        const double inner = outer * (1.0 - std::clamp(light.spotBlend, 0.0, 1.0));
        p.set(indexed("uLightSpotCos", i), glm::vec2(std::cos(outer), std::cos(inner)));
        p.set(indexed("uLightShadowSlot", i), -1);
    }

    // Every sampler gets a texture of its own type, used or not, so no unit is left incomplete.
    for (int slot = 0; slot < kMaxShadowedLights; ++slot) {
        glActiveTexture(GL_TEXTURE0 + kShadow2DUnit + slot);
        glBindTexture(GL_TEXTURE_2D, ctx.dummyShadow2D);
        glActiveTexture(GL_TEXTURE0 + kShadowCubeUnit + slot);
        glBindTexture(GL_TEXTURE_CUBE_MAP, ctx.dummyShadowCube);
        p.set(indexed("uShadowMaps", slot), kShadow2DUnit + slot);
        p.set(indexed("uShadowCubes", slot), kShadowCubeUnit + slot);
        p.set(indexed("uShadowIsCube", slot), 0);
    }
    const glm::dmat4 fromCameraRelative = glm::inverse(toCameraRelative);
    for (int slot = 0; slot < static_cast<int>(ctx.shadowPlans.size()); ++slot) {
        const ShadowPlan& shadow = ctx.shadowPlans[static_cast<std::size_t>(slot)];
        const int lightIndex = shadow.light;
        const ShadowMap* map = ctx.shadows.find(lightIndex);
        if (!map || lightIndex >= count)
            continue;
        p.set(indexed("uLightShadowSlot", lightIndex), slot);
        if (map->cube) {
            glActiveTexture(GL_TEXTURE0 + kShadowCubeUnit + slot);
            glBindTexture(GL_TEXTURE_CUBE_MAP, map->depth.id());
        } else {
            glActiveTexture(GL_TEXTURE0 + kShadow2DUnit + slot);
            glBindTexture(GL_TEXTURE_2D, map->depth.id());
        }
        p.set(indexed("uShadowIsCube", slot), map->cube ? 1 : 0);
        p.set(indexed("uShadowPerspective", slot), shadow.frustum.perspective ? 1 : 0);
        // World → light clip composed with camera-relative → world, in double, then rounded once.
        p.set(indexed("uShadowMatrix", slot),
              glm::mat4(shadow.frustum.viewProjection[0] * fromCameraRelative));
        p.set(indexed("uShadowNearFar", slot), glm::vec2(shadow.frustum.near, shadow.frustum.far));
        p.set(indexed("uShadowTexelSize", slot), float(shadow.frustum.texelSize));
        p.set(indexed("uShadowMapSize", slot), map->size);
        p.set(indexed("uShadowPcf", slot), shadow.pcf);
        // Camera-relative, as the positions the shader tests against it; empty: min above max.
        const math::Box bounds = ctx.shadows.lookupBounds(*map);
        const glm::dvec3 offset = glm::dvec3(toCameraRelative[3]);
        p.set(indexed("uShadowCasterMin", slot),
              bounds.empty() ? glm::vec3(1e30f) : finiteUniform(bounds.min + offset));
        p.set(indexed("uShadowCasterMax", slot),
              bounds.empty() ? glm::vec3(-1e30f) : finiteUniform(bounds.max + offset));
    }
    glActiveTexture(GL_TEXTURE0);
}

} // namespace

void setMaterial(const Material& m, const gl::Program& p, const MainPassContext& ctx,
                 const std::string& drawDefines) {
    const bool texture = !m.texture.empty();
    const bool emissionTexture = !m.emissionTexture.empty();
    const bool normalTexture = !m.normalTexture.empty();
    const bool mask = m.alphaMode != AlphaMode::Opaque;
    std::string defines = drawDefines;
    defines += ctx.pathLengthInAlpha ? "#define PATH_LENGTH_ALPHA 1\n" : "#define PATH_LENGTH_ALPHA 0\n";
    if (!texture)
        defines += "#define MATERIAL_TEXTURE 0\n";
    if (!emissionTexture)
        defines += "#define MATERIAL_EMISSION_TEXTURE 0\n";
    if (!normalTexture)
        defines += "#define MATERIAL_NORMAL_TEXTURE 0\n";
    if (!mask)
        defines += "#define MATERIAL_ALPHA_MASK 0\n";
    ctx.materialDefines = defines;
    ctx.materialNormalMap = normalTexture;
    p.useWith(defines + "#define MATERIAL_VERTEX_COLOR 0\n");
    p.set("uColor", glm::vec3(m.color));
    p.set("uAmbient", float(m.ambient));
    p.set("uDiffuse", float(m.diffuse));
    p.set("uSpecular", float(m.specular));
    p.set("uSpecularColor", glm::vec3(m.specularColor));
    p.set("uShininess", float(std::max(m.shininess, 1e-3)));
    p.set("uEmission", glm::vec3(m.emission));
    p.set("uOpacity", float(m.opacity));
    p.set("uAlphaMask", mask ? 1 : 0);
    p.set("uAlphaCutoff", float(alphaCutoff(m)));
    p.set("uNormalScale", float(m.normalScale));
    p.set("uHasTexture", texture ? 1 : 0);
    p.set("uHasEmissionTexture", emissionTexture ? 1 : 0);
    p.set("uHasNormalTexture", normalTexture ? 1 : 0);
    if (texture)
        ctx.textures.bind(m.texture, m.wrap, TextureUse::Color, kMaterialTextureUnit);
    if (emissionTexture)
        ctx.textures.bind(m.emissionTexture, m.wrap, TextureUse::Color, kEmissionTextureUnit);
    if (normalTexture)
        ctx.textures.bind(m.normalTexture, m.wrap, TextureUse::Data, kNormalTextureUnit);
    glActiveTexture(GL_TEXTURE0);
}

double alphaCutoff(const Material& m) {
    return effectiveAlphaCutoff(m);
}

void beginLitView(const FrameInput& input, const ViewSetup& view, const gl::Program& p,
                  MainPassContext& ctx) {
    ctx.mirroredView = view.clockwise;
    ctx.pathLengthInAlpha = view.pathLengthInAlpha;
    const glm::dmat4 toCameraRelative = math::cameraRelative(input.camera);
    const glm::dmat4 fromCameraRelative = glm::inverse(toCameraRelative);
    p.use();
    p.set("uViewProjection", glm::mat4(view.viewProjection));
    // The reflection acts on camera-relative coordinates: composed in double, rounded once.
    p.set("uReflection", glm::mat4(toCameraRelative * view.reflection * fromCameraRelative));
    p.set("uEye", glm::vec3(view.eye - input.camera.position));
    p.set("uPathLengthAlpha", view.pathLengthInAlpha ? 1 : 0);
    p.set("uViewWeight", glm::vec3(view.weight));
    p.set("uSceneAmbient", float(input.settings.ambient));
    p.set("uTexture", kMaterialTextureUnit);
    p.set("uEmissionTexture", kEmissionTextureUnit);
    p.set("uNormalTexture", kNormalTextureUnit);
    setLights(input, toCameraRelative, p, ctx);
}

void drawLitMesh(const MeshHandle& mesh, const glm::dmat4& world, const FrameInput& input,
                 const gl::Program& p, const MainPassContext& ctx, gl::Detail detail) {
    const glm::dmat4 model = math::cameraRelative(input.camera) * world;
    // Counter-clockwise stays front-facing unless the object's own transform or the view's reflection
    // (but not both) mirrors it: negative scales and mirror views both flip the winding.
    const bool mirrored = (glm::determinant(glm::dmat3(world)) < 0.0) != ctx.mirroredView;
    glFrontFace(mirrored ? GL_CW : GL_CCW);
    const gl::GpuMesh& gpu = ctx.meshes.get(mesh);
    // setMaterial bound the variant for a mesh without colours; one with them needs the multiply.
    if (gpu.hasColors)
        p.useWith(ctx.materialDefines);
    if (ctx.materialNormalMap)
        p.set("uHasTangents", gpu.hasTangents ? 1 : 0);
    p.set("uModel", glm::mat4(model));
    p.set("uNormalMatrix", normalMatrix(model));
    gpu.draw(detail);
}

glm::dmat4 mirrorRectangle(const Mirror& mirror) {
    return mirror.world *
           glm::scale(glm::dmat4(1.0), glm::dvec3(mirror.size.x * 0.5, 1.0, mirror.size.y * 0.5));
}

namespace {

// The mirror's rectangle as drawn in `view`: only the part in view when the rest is huge (see
// math::visibleMirrorRectangle: a 1e12 mirror's float corners would move its plane by kilometres).
glm::dmat4 drawnMirrorRectangle(const FrameInput& input, const Mirror& mirror, const ViewSetup& view) {
    const glm::dmat4 rectangle = mirrorRectangle(mirror);
    const glm::dmat4 toClip = view.viewProjection * math::cameraRelative(input.camera) * view.reflection;
    return math::visibleMirrorRectangle(rectangle, toClip * rectangle);
}

} // namespace

glm::dmat4 drawnMirrorWorld(const FrameInput& input, std::size_t mirror, const ViewSetup& view,
                            const MainPassContext& context) {
    // A split mesh follows the warp, whose clip space no part of the rectangle can be cut to.
    return context.mirrorMesh(mirror) == context.unitPlane
               ? drawnMirrorRectangle(input, input.mirrors[mirror], view)
               : mirrorRectangle(input.mirrors[mirror]);
}

glm::mat4 mirrorRectangleClip(const FrameInput& input, std::size_t mirror, const ViewSetup& view,
                              const MainPassContext& context) {
    const glm::dmat4 toCameraRelative = math::cameraRelative(input.camera);
    return glm::mat4(view.viewProjection * toCameraRelative * view.reflection *
                     drawnMirrorWorld(input, mirror, view, context));
}

namespace {

// The depth of the view's stencil mirrors goes first: whatever lies behind a mirror (the wall it hangs
// on) then fails the depth test before it is shaded, so a mirror's pixels are not paid for twice. The
// mask pass later finds exactly these depths (same program, same matrix) where nothing stands in front.
void drawStencilMirrorDepths(const FrameInput& input, const ViewSetup& view, const MainPassContext& ctx) {
    if (!ctx.depthOnlyProgram)
        return;
    bool any = false;
    for (std::size_t i = 0; i < view.stencilMirror.size(); ++i) {
        if (!view.stencilMirror[i])
            continue;
        if (!any) {
            ctx.depthOnlyProgram->use();
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            any = true;
        }
        ctx.depthOnlyProgram->set("uModelLightClip", mirrorRectangleClip(input, i, view, ctx));
        ctx.meshes.get(ctx.mirrorMesh(i)).draw();
    }
    if (any)
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// Object (local) coordinates to the view's clip space.
glm::dmat4 toClipOf(const glm::dmat4& world, const FrameInput& input, const ViewSetup& view) {
    return view.viewProjection * math::cameraRelative(input.camera) * view.reflection * world;
}

glm::dvec3 boundsCorner(const Bounds& b, int corner) {
    return {(corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
            (corner & 4) ? b.max.z : b.min.z};
}

// True when no part of the box can show in the view: its eight corners all lie outside one side of the
// view's clip volume (narrowed to its pixels). Each side is a half-space in clip coordinates, so the test
// holds for corners behind the eye too; a box that straddles a corner of the frustum is kept.
bool outsideView(const Bounds& local, const glm::dmat4& world, const FrameInput& input,
                 const ViewSetup& view) {
    if (!view.cullOutside)
        return false;
    const glm::dmat4 toClip = toClipOf(world, input, view);
    const glm::dvec4& r = view.ndcBounds;
    int outside[6] = {0, 0, 0, 0, 0, 0};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec4 c = toClip * glm::dvec4(boundsCorner(local, corner), 1.0);
        outside[0] += c.x < r.x * c.w;
        outside[1] += c.x > r.z * c.w;
        outside[2] += c.y < r.y * c.w;
        outside[3] += c.y > r.w * c.w;
        outside[4] += c.z < -c.w; // the near plane (oblique in a mirror's view: the mirror's plane)
        outside[5] += c.z > c.w;
    }
    return std::any_of(std::begin(outside), std::end(outside), [](int n) { return n == 8; });
}

// The facts of the item's mesh where the view may cull or reorder its back faces: a closed, outward-wound
// mesh of an opaque material (with context.meshFacts set); null otherwise.
const MeshFacts::Facts* closedOpaqueFacts(const DrawItem& item, const MainPassContext& ctx) {
    if (!ctx.meshFacts || item.material.alphaMode != AlphaMode::Opaque)
        return nullptr;
    const MeshFacts::Facts& facts = ctx.meshFacts->get(item.mesh);
    return facts.closed ? &facts : nullptr;
}

// The deepest cut, as a share of the mesh's bounding box diagonal, through which drawing the back faces
// after the front faces still pays: an object resting on a mirror, whose reflection's clip
// (kMirrorClipOffset) takes off a sliver. Deeper (a camera standing in the mesh), the back faces show
// over much of it and the second draw only repeats the vertex work.
constexpr double kThinCut = 0.01;
// Above this, a second draw's vertex work costs more than the shading it saves on a software rasterizer.
constexpr GLsizei kMaxIndicesDrawnTwice = 3 * 65536;

} // namespace

// Wholly beyond the near plane, the eye is outside the mesh too. The far and side planes only take away
// what lies behind its front.
bool hidesBackFaces(const DrawItem& item, const FrameInput& input, const ViewSetup& view,
                    const MainPassContext& ctx) {
    const MeshFacts::Facts* facts = closedOpaqueFacts(item, ctx);
    if (!facts)
        return false;
    const glm::dmat4 toClip = toClipOf(item.world, input, view);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec4 c = toClip * glm::dvec4(boundsCorner(facts->bounds, corner), 1.0);
        // With a margin for the GPU's single precision. An object resting on a mirror is not culled in
        // its reflection: the reflection keeps only what lies kMirrorClipOffset beyond the plane, so its
        // bottom is cut open.
        if (!(c.w > 0.0) || !(c.z + c.w > 1e-4 * c.w))
            return false;
    }
    return true;
}

bool drawsBackFacesLast(const DrawItem& item, const FrameInput& input, const ViewSetup& view,
                        const MainPassContext& ctx) {
    const MeshFacts::Facts* facts = closedOpaqueFacts(item, ctx);
    if (!facts || ctx.meshes.get(item.mesh).indexCount > kMaxIndicesDrawnTwice)
        return false;
    // The near plane (z + w >= 0 in clip space) in the mesh's own coordinates.
    const glm::dmat4 toClip = toClipOf(item.world, input, view);
    const glm::dvec4 near = glm::row(toClip, 2) + glm::row(toClip, 3);
    const double scale = glm::length(glm::dvec3(near));
    const double diagonal = glm::length(facts->bounds.max - facts->bounds.min);
    if (!(scale > 0.0) || !(diagonal > 0.0))
        return false;
    double deepest = 0.0;
    for (int corner = 0; corner < 8; ++corner)
        deepest = std::min(
            deepest, (glm::dot(glm::dvec3(near), boundsCorner(facts->bounds, corner)) + near.w) / scale);
    // A corner behind the near plane: hidesBackFaces is false, so the faces are not culled either.
    return deepest < 0.0 && deepest >= -kThinCut * diagonal;
}

namespace {

// A mirror with no pass of its own in the view: one whose paths end here (the depth limit or the view
// budget) shows its surface's share alone in front (mesh.frag's MIRROR_CUT), one without a plane its
// material, as the tracer draws them.
void drawMirrorWithoutReflection(const FrameInput& input, std::size_t i, const ViewSetup& view,
                                 MainPassContext& ctx) {
    const Mirror& mirror = input.mirrors[i];
    const gl::Program& p = ctx.program;
    const bool cut = math::mirrorPlane(mirror.world).ok();
    setMaterial(mirror.material, p, ctx, cut ? "#define MIRROR_CUT 1\n" : "");
    if (cut) {
        p.set("uMirrorReflectivity", float(std::clamp(mirror.reflectivity, 0.0, 1.0)));
        p.set("uMirrorFresnel", mirror.fresnel ? 1 : 0);
    }
    drawLitMesh(ctx.mirrorMesh(i), drawnMirrorWorld(input, i, view, ctx), input, p, ctx);
}

} // namespace

void drawMainPass(const FrameInput& input, const ViewSetup& view, MainPassContext& ctx) {
    drawStencilMirrorDepths(input, view, ctx);
    const gl::Program& p = ctx.program;
    beginLitView(input, view, p, ctx);
    for (std::size_t i = 0; i < input.items.size(); ++i) {
        const DrawItem& item = input.items[i];
        if (!item.mesh || outsideView(ctx.meshes.get(item.mesh).bounds, item.world, input, view))
            continue;
        const bool cull =
            (i < ctx.cullBackFaces.size() && ctx.cullBackFaces[i]) || hidesBackFaces(item, input, view, ctx);
        // Opaque faces are depth-tested, so their order changes no pixel (but a depth tie); back faces
        // drawn after the front faces fail that test but where a cut opens the mesh, and are not shaded.
        const bool backLast = !cull && drawsBackFacesLast(item, input, view, ctx);
        (cull || backLast ? glEnable : glDisable)(GL_CULL_FACE);
        setMaterial(item.material, p, ctx);
        const bool coarse = view.coarseDetail && i < ctx.coarseItems.size() && ctx.coarseItems[i];
        const gl::Detail detail = coarse ? gl::Detail::Coarse : gl::Detail::Full;
        drawLitMesh(item.mesh, item.world, input, p, ctx, detail);
        if (backLast) {
            glCullFace(GL_FRONT);
            drawLitMesh(item.mesh, item.world, input, p, ctx, detail);
            glCullFace(GL_BACK);
        }
    }
    glDisable(GL_CULL_FACE);
    for (std::size_t i = 0; i < input.mirrors.size(); ++i) {
        if ((i < view.skipMirror.size() && view.skipMirror[i]) ||
            outsideView(ctx.meshes.get(ctx.unitPlane).bounds, mirrorRectangle(input.mirrors[i]), input, view))
            continue;
        drawMirrorWithoutReflection(input, i, view, ctx);
    }
    for (std::size_t i = 0; i < input.reflectors.size(); ++i) {
        const Reflector& reflector = input.reflectors[i];
        if (!reflector.mesh ||
            outsideView(ctx.meshes.get(reflector.mesh).bounds, reflector.world, input, view) ||
            (ctx.drawReflector && ctx.drawReflector(input, static_cast<int>(i), view, ctx)))
            continue;
        setMaterial(reflector.material, p, ctx);
        drawLitMesh(reflector.mesh, reflector.world, input, p, ctx);
    }
}

} // namespace speculum::render::passes
