#include "render/passes/ReflectorPass.hpp"

#include "base/Printable.hpp"
#include "render/plan/GpuLimits.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cassert>

namespace speculum::render::passes {

namespace {

envmap::CaptureSettings captureSettings(const Reflector& r) {
    envmap::CaptureSettings s;
    s.type = mapTypeOf(r.map);
    s.resolution = r.resolution;
    s.fill = warpable(r.map) && r.fill == ReflectorFill::Direct ? envmap::FillMethod::Direct
                                                                : envmap::FillMethod::Resampled;
    return s;
}

bool sameSettings(const envmap::CaptureSettings& a, const envmap::CaptureSettings& b) {
    return a.type == b.type && a.resolution == b.resolution && a.cubeResolution == b.cubeResolution &&
           (a.type == envmap::MapType::Cube || a.fill == b.fill) && a.mipmaps == b.mipmaps &&
           a.colorFormat == b.colorFormat;
}

// Pass 1 sees the scene from the capture point: it is the origin of camera-relative space, so model
// matrices are made relative to it in double by the main pass's own drawing, and the eye for specular
// highlights is there too. The reflector is not part of its own environment; the others are.
FrameInput environmentInput(const FrameInput& input, int index, const glm::dvec3& centre) {
    FrameInput env = input;
    env.reflectors.erase(env.reflectors.begin() + index);
    env.camera.position = centre;
    env.camera.target = centre + glm::dvec3(0.0, 0.0, -1.0);
    env.camera.up = glm::dvec3(0.0, 1.0, 0.0);
    return env;
}

MainPassContext withProgram(const gl::Program& program, MainPassContext& base, MeshHandle unitPlane) {
    MainPassContext context{program,          base.meshes,        base.textures,        base.shadows,
                            base.shadowPlans, base.dummyShadow2D, base.dummyShadowCube, std::move(unitPlane)};
    context.coarseItems = base.coarseItems;
    return context;
}

} // namespace

base::Status ReflectorPass::init() {
    auto warp = gl::Program::build("mesh.vert", "mesh.frag", "#define ENVMAP_WARP 1");
    if (!warp)
        return base::Error{warp.error()};
    auto surface = gl::Program::build("mesh.vert", "reflector.frag");
    if (!surface)
        return base::Error{surface.error()};
    auto warpFlat = gl::Program::build("shadow.vert", "flat.frag", "#define ENVMAP_WARP 1");
    if (!warpFlat)
        return base::Error{warpFlat.error()};
    auto warpMirror = gl::Program::build("mesh.vert", "mirror.frag", "#define ENVMAP_WARP 1");
    if (!warpMirror)
        return base::Error{warpMirror.error()};
    auto warpSurface = gl::Program::build("mesh.vert", "reflector.frag", "#define ENVMAP_WARP 1");
    if (!warpSurface)
        return base::Error{warpSurface.error()};
    m_warpSurface = std::move(*warpSurface);
    m_warpFlat = std::move(*warpFlat);
    m_warpMirror = std::move(*warpMirror);
    m_warp = std::move(*warp);
    m_surface = std::move(*surface);
    return base::Done{};
}

const ReflectorPass::Slot* ReflectorPass::slotOf(int index) const {
    return index >= 0 && static_cast<std::size_t>(index) < m_maps.size()
               ? &m_maps[static_cast<std::size_t>(index)]
               : nullptr;
}

ReflectorPass::Slot& ReflectorPass::slot(int index) {
    const auto i = static_cast<std::size_t>(std::max(index, 0));
    if (m_maps.size() <= i)
        m_maps.resize(i + 1);
    return m_maps[i];
}

void ReflectorPass::keepMaps(std::size_t count) {
    if (m_maps.size() > count)
        m_maps.resize(count);
}

void ReflectorPass::beginFrame() {
    for (Slot& s : m_maps) {
        s.bounceDrawn = -1;
        s.bounced = false;
    }
}

void ReflectorPass::endFrame() {
    for (Slot& s : m_maps)
        if (!s.bounced)
            s.previous.reset();
}

bool ReflectorPass::hasMap(int index, const Reflector& reflector) const {
    const Slot* s = slotOf(index);
    return s && s->capture && s->settingsKey == envmapSettingsKey(reflector) &&
           s->reflector == reflector.name;
}

bool ReflectorPass::hasChain(int index, const Reflector& reflector) const {
    const Slot* s = slotOf(index);
    return hasMap(index, reflector) && s->chainOf != 0 && s->chainOf == s->captures;
}

std::size_t ReflectorPass::mapBytes(int index, const Reflector& reflector) const {
    if (!hasMap(index, reflector))
        return 0;
    const Slot& s = *slotOf(index);
    return s.capture->bytes() + (s.previous ? s.previous->bytes() : 0) +
           (s.prefilter ? s.prefilter->bytes() : 0);
}

const envmap::EnvironmentCapture* ReflectorPass::map(int index) const {
    const Slot* s = slotOf(index);
    return s && s->capture ? &*s->capture : nullptr;
}

gl::PlannedAllocation ReflectorPass::allocate(int index, const Reflector& reflector,
                                              std::vector<std::string>& warnings) {
    const envmap::CaptureSettings wanted = captureSettings(reflector);
    Slot& s = slot(index);
    std::string otherError;
    const gl::SizeFallback::Fitted fitted = m_fallbacks[envmapKind(reflector)].fit(
        reflector.resolution, kMinEnvmapResolution, [&](int n) -> base::Status {
            envmap::CaptureSettings settings = wanted;
            settings.resolution = n;
            if (s.capture && sameSettings(s.capture->settings(), settings))
                return base::Done{};
            s.capture.reset(); // the old map's memory first: it may be what the new one needs
            s.previous.reset();
            s.settingsKey = 0;
            bool sizeFailure = false;
            auto created = envmap::EnvironmentCapture::create(settings, &sizeFailure);
            if (!created) {
                if (!sizeFailure) { // a shader: no smaller size helps, and none is remembered as failing
                    otherError = created.error();
                    return base::Done{};
                }
                return base::Error{created.error()};
            }
            s.capture = std::move(*created);
            return base::Done{};
        });
    if (!otherError.empty()) {
        s.capture.reset();
        warnings.push_back("reflector " + base::quoted(reflector.name) + ": " + otherError);
        return gl::PlannedAllocation::Failed;
    }
    if (fitted.size == reflector.resolution)
        return gl::PlannedAllocation::Done;
    // The map of the size that works stays allocated for the next frame; this one's plan is for the other.
    warnings.push_back(envmapFallbackWarning(reflector, reflector.resolution, fitted.reason, fitted.size));
    return gl::PlannedAllocation::FellBack;
}

void ReflectorPass::failedSizes(std::map<MapKind, FailedAllocation>& failed) const {
    for (const auto& [kind, fallback] : m_fallbacks)
        if (fallback.failedAt() != kNoFailedSize)
            failed[kind] = fallback.failed();
}

namespace {

// Where the plan lists the face (or direct-fill component) `index`: its mirror passes name that position.
int positionInPlan(const EnvmapPlan& plan, int index) {
    for (std::size_t i = 0; i < plan.faces.size(); ++i)
        if (plan.faces[i].index == index)
            return static_cast<int>(i);
    assert(false && "ReflectorPass::capture(): a face the plan does not list was drawn");
    return 0;
}

} // namespace

base::Status ReflectorPass::startBounce(Slot& s, const Reflector& reflector) {
    std::swap(s.capture, s.previous);
    if (!s.capture || !sameSettings(s.capture->settings(), s.previous->settings())) {
        s.capture.reset();
        auto created = envmap::EnvironmentCapture::create(s.previous->settings());
        if (!created) {
            std::swap(s.capture, s.previous); // the map drawn stays, and the bounce draws no more of it
            return base::Error{"reflector " + base::quoted(reflector.name) + ": the map of a second bounce " +
                               created.error() + "; its earlier bounce stays"};
        }
        s.capture = std::move(*created);
    }
    s.bounced = true;
    return base::Done{};
}

const envmap::EnvironmentCapture* ReflectorPass::readable(int index, int bounce) const {
    const Slot* s = slotOf(index);
    if (!s)
        return nullptr;
    if (s->bounceDrawn == bounce && s->bounced && s->previous) // drawn over at this bounce, this frame
        return &*s->previous;
    return s->capture ? &*s->capture : nullptr;
}

base::Status ReflectorPass::capture(const FrameInput& input, const EnvmapPlan& plan, MainPassContext& context,
                                    const EnvironmentMirrorPrograms& mirrors,
                                    const RunFacePasses& runFacePasses) {
    const EnvmapCapture& where = plan.capture;
    const int index = plan.reflector;
    const Reflector& reflector = input.reflectors.at(static_cast<std::size_t>(index));
    Slot& s = slot(index);
    const std::uint64_t key = envmapSettingsKey(reflector);
    // allocate() normally made the map already, at a size that fits; a caller that did not gets it made
    // here, still checked.
    if (!s.capture || !sameSettings(s.capture->settings(), captureSettings(reflector))) {
        s.capture.reset();
        s.previous.reset();
        s.settingsKey = 0;
        auto created = envmap::EnvironmentCapture::create(captureSettings(reflector));
        if (!created)
            return base::Error{"reflector " + base::quoted(reflector.name) + ": the environment map " +
                               created.error()};
        s.capture = std::move(*created);
    } else if (plan.bounce > 0 && s.bounceDrawn == plan.bounce - 1 && s.settingsKey == key) {
        // The others of this bounce read this map's bounce before: it is kept, and drawn into the other.
        if (base::Status started = startBounce(s, reflector); !started)
            return started;
    }
    s.settingsKey = 0; // rendered below
    s.centre = where.centre;
    const FrameInput env = environmentInput(input, index, where.centre);
    envmap::CaptureView view;
    view.near = where.near;
    view.far = where.far;
    view.background = input.settings.background;
    view.faces = 0; // the faces the plan lists: all of them, or a time-sliced update's one
    for (const EnvmapFace& planned : plan.faces)
        view.faces |= 1u << planned.index;

    MainPassContext faces = withProgram(context.program, context, context.unitPlane);
    // From bounce 1 on, the other reflectors are drawn with their maps of the bounce before (env holds
    // them without this one: its indices past `index` are one lower than the frame's).
    MainPassContext warped = withProgram(m_warp, context, context.unitPlane);
    if (plan.bounce > 0) {
        auto drawWith = [this, index, bounce = plan.bounce](const gl::Program& program) {
            return [this, index, bounce, &program](const FrameInput& in, int other, const ViewSetup& v,
                                                   MainPassContext& c) {
                return drawInMap(in, other, other < index ? other : other + 1, bounce, v, program, c);
            };
        };
        faces.drawReflector = drawWith(m_surface);
        warped.drawReflector = drawWith(m_warpSurface);
    }
    // The map frame is the world's (CaptureView::mapFromWorld is the identity), so a face's view-projection
    // is its projection times its view.
    EnvironmentTarget face;
    face.near = where.near;
    face.far = where.far;
    face.framebuffer = s.capture->framebuffer();
    face.size = s.capture->targetSize();
    face.meshFacts = &m_meshFacts;
    face.plan = &plan;
    auto drawFace = [&](const glm::dmat4&, int faceIndex) {
        face.faceView = envmap::cubeFaceView(faceIndex);
        face.face = positionInPlan(plan, faceIndex);
        drawEnvironmentTarget(env, face, mirrors, faces, runFacePasses);
    };

    // The direct fill draws copies of the meshes split until no edge spans more than a few degrees seen
    // from the (virtual) capture point: straight edges turn into curves.
    m_warpMeshes.begin();
    auto drawWarped = [&](const envmap::WarpPass& pass) {
        EnvironmentTarget component;
        component.near = where.near;
        component.far = where.far;
        component.framebuffer = s.capture->framebuffer();
        component.size = s.capture->targetSize();
        component.warp = &pass;
        component.warpMeshes = &m_warpMeshes;
        component.warpAngle = warpEdgeAngle(s.capture->layout());
        component.meshFacts = &m_meshFacts;
        component.plan = &plan;
        component.face = positionInPlan(plan, pass.warp.component);
        drawEnvironmentTarget(env, component, {m_warpFlat, m_warpMirror}, warped, runFacePasses);
    };
    s.capture->update(view, drawFace, drawWarped);
    s.settingsKey = key;
    s.reflector = reflector.name;
    s.bounceDrawn = plan.bounce;
    ++s.captures; // the chain, if any, holds an older map now
    return base::Done{};
}

base::Status ReflectorPass::prefilter(int index, const Reflector& reflector, int samples) {
    if (!hasMap(index, reflector))
        return base::Done{}; // nothing captured (the map could not be allocated: warned already)
    Slot& s = slot(index);
    s.chainOf = 0;
    if (!s.prefilter) {
        auto created = envmap::GgxPrefilter::create();
        if (!created)
            return base::Error{"reflector " + base::quoted(reflector.name) + ": the GGX pre-filter " +
                               created.error()};
        s.prefilter = std::move(*created);
    }
    if (base::Status filtered = s.prefilter->filter(*s.capture, samples); !filtered)
        return base::Error{"reflector " + base::quoted(reflector.name) + ": " + filtered.error() +
                           "; drawn with the map's mip chain instead"};
    s.chainOf = s.captures;
    return base::Done{};
}

base::Status ReflectorPass::selectLighting(const std::string& variant, bool drawVariants) {
    for (gl::Program* program : {&m_warp, &m_warpMirror, &m_surface, &m_warpSurface})
        if (base::Status selected = program->select(variant, drawVariants); !selected)
            return selected;
    return base::Done{};
}

void ReflectorPass::setMapUniforms(const Reflector& r, const glm::dvec3& eye, const Slot& s,
                                   const envmap::EnvironmentCapture& map, const gl::Program& p) const {
    p.set("uEnvType", static_cast<int>(map.settings().type));
    p.set("uEnvLayout", map.layout().packed());
    p.set("uEnvCentre", glm::vec3(s.centre - eye));
    const ParallaxParams proxy = r.parallax.value_or(ParallaxParams{});
    p.set("uParallax", !r.parallax ? 0 : proxy.shape == ParallaxShape::Sphere ? 1 : 2);
    p.set("uParallaxRadius", float(proxy.radius));
    p.set("uParallaxMin", glm::vec3(proxy.min));
    p.set("uParallaxMax", glm::vec3(proxy.max));
    p.set("uEnvCube", kEnvCubeUnit);
    p.set("uEnvArray", kEnvArrayUnit);
}

bool ReflectorPass::bindAsProbe(const FrameInput& input, int index, const gl::Program& p) const {
    if (index < 0 || static_cast<std::size_t>(index) >= input.reflectors.size() ||
        !hasMap(index, input.reflectors[static_cast<std::size_t>(index)]))
        return false;
    p.use();
    const Slot& s = *slotOf(index);
    const envmap::EnvironmentCapture& map = *s.capture;
    setMapUniforms(input.reflectors[static_cast<std::size_t>(index)], input.camera.position, s, map, p);
    glActiveTexture(GL_TEXTURE0 + (map.target() == GL_TEXTURE_CUBE_MAP ? kEnvCubeUnit : kEnvArrayUnit));
    glBindTexture(map.target(), map.texture());
    glActiveTexture(GL_TEXTURE0);
    return true;
}

int ReflectorPass::lookupOf(const FrameInput& input, int index) const {
    const Reflector& r = input.reflectors.at(static_cast<std::size_t>(index));
    const double roughness = std::clamp(r.roughness, 0.0, 1.0);
    if (!(roughness > 0.0))
        return 0;
    return input.settings.glossyFilter != GlossyFilter::Mip && hasChain(index, r) ? 2 : 1;
}

void ReflectorPass::bindMapLookup(const Reflector& r, const glm::dvec3& eye, const Slot& s,
                                  const envmap::EnvironmentCapture& map, int lookup,
                                  const gl::Program& p) const {
    const double roughness = std::clamp(r.roughness, 0.0, 1.0);
    const bool chain = lookup == 2;
    p.use();
    setMapUniforms(r, eye, s, map, p);
    p.set("uEnvMapFromWorld", glm::mat3(1.0f));
    // A rough reflector reads one texture at an explicit LOD: the pre-filtered chain (same target and
    // layout as the map) at the roughness that covers the lobe, narrowed by the proxy's distance, and the
    // pixel's footprint (reflector_lookup.glsl's chainLod), or, for Mip (or without a chain), the map's own
    // mip chain at roughness × (its levels − 1), box-filtered levels standing in for the lobe. Roughness 0
    // takes the sharp lookup, as before roughness existed.
    GLuint texture = map.texture();
    float lod = 0.0f;
    if (roughness > 0.0) {
        const int levels = chain ? s.prefilter->levels()
                                 : (map.settings().mipmaps ? envmap::usableMipLevels(map.layout()) : 1);
        texture = chain ? s.prefilter->texture() : texture;
        lod = static_cast<float>(roughness * (levels - 1));
    }
    p.set("uRough", lookup);
    p.set("uRoughnessLod", lod);
    p.set("uRoughness", float(roughness));
    p.set("uGgxAlbedo", kGgxAlbedoUnit);
    glActiveTexture(GL_TEXTURE0 + (map.target() == GL_TEXTURE_CUBE_MAP ? kEnvCubeUnit : kEnvArrayUnit));
    glBindTexture(map.target(), texture);
    glActiveTexture(GL_TEXTURE0);
}

int ReflectorPass::bindLookup(const FrameInput& input, int index, const gl::Program& p) const {
    if (index < 0 || static_cast<std::size_t>(index) >= input.reflectors.size() ||
        !hasMap(index, input.reflectors[static_cast<std::size_t>(index)]))
        return -1;
    const int lookup = lookupOf(input, index);
    const Slot& s = *slotOf(index);
    bindMapLookup(input.reflectors[static_cast<std::size_t>(index)], input.camera.position, s, *s.capture,
                  lookup, p);
    return lookup;
}

bool ReflectorPass::drawSurface(const FrameInput& input, int index, const ViewSetup& view,
                                MainPassContext& context) {
    if (index < 0 || static_cast<std::size_t>(index) >= input.reflectors.size() ||
        !hasMap(index, input.reflectors[static_cast<std::size_t>(index)]))
        return false;
    const Reflector& r = input.reflectors[static_cast<std::size_t>(index)];
    const gl::Program& p = m_surface;
    beginLitView(input, view, p, context);
    // The draw variant without the lookups it does not use (REFLECTOR_ROUGH).
    const int lookup = lookupOf(input, index);
    setMaterial(r.material, p, context, "#define REFLECTOR_ROUGH " + std::to_string(lookup) + "\n");
    p.set("uReflectivity", float(std::clamp(r.reflectivity, 0.0, 1.0)));
    p.set("uFresnel", r.fresnel ? 1 : 0);
    const Slot& s = *slotOf(index);
    bindMapLookup(r, input.camera.position, s, *s.capture, lookup, p);
    drawLitMesh(r.mesh, r.world, input, p, context);
    return true;
}

bool ReflectorPass::drawInMap(const FrameInput& env, int envIndex, int index, int bounce,
                              const ViewSetup& view, const gl::Program& program, MainPassContext& context) {
    const Reflector& r = env.reflectors.at(static_cast<std::size_t>(envIndex));
    const envmap::EnvironmentCapture* map = readable(index, bounce);
    if (!map || !hasMap(index, r))
        return false;
    // A rough one reads its map's mip chain: its pre-filtered chain holds its last bounce, not the one
    // before this. The lookups are relative to the capture point, the env's camera.
    const gl::Program& p = program;
    beginLitView(env, view, p, context);
    if (context.prepareProgram) // a direct fill's warp: its uniforms and its clip at the view's mirror
        context.prepareProgram(p);
    const int lookup = std::clamp(r.roughness, 0.0, 1.0) > 0.0 ? 1 : 0;
    setMaterial(r.material, p, context, "#define REFLECTOR_ROUGH " + std::to_string(lookup) + "\n");
    p.set("uReflectivity", float(std::clamp(r.reflectivity, 0.0, 1.0)));
    p.set("uFresnel", r.fresnel ? 1 : 0);
    bindMapLookup(r, env.camera.position, *slotOf(index), *map, lookup, p);
    drawLitMesh(r.mesh, r.world, env, p, context);
    return true;
}

} // namespace speculum::render::passes
