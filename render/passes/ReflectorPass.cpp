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
// highlights is there too. The reflector is not part of its own environment.
FrameInput environmentInput(const FrameInput& input, const glm::dvec3& centre) {
    FrameInput env = input;
    env.reflector.reset();
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
    m_warpFlat = std::move(*warpFlat);
    m_warpMirror = std::move(*warpMirror);
    m_warp = std::move(*warp);
    m_surface = std::move(*surface);
    return base::Done{};
}

bool ReflectorPass::hasMap(const Reflector& reflector) const {
    return m_capture && m_settingsKey == envmapSettingsKey(reflector);
}

gl::PlannedAllocation ReflectorPass::allocate(const Reflector& reflector,
                                              std::vector<std::string>& warnings) {
    const envmap::CaptureSettings wanted = captureSettings(reflector);
    std::string otherError;
    const gl::SizeFallback::Fitted fitted = m_fallbacks[envmapKind(reflector)].fit(
        reflector.resolution, kMinEnvmapResolution, [&](int n) -> base::Status {
            envmap::CaptureSettings settings = wanted;
            settings.resolution = n;
            if (m_capture && sameSettings(m_capture->settings(), settings))
                return base::Done{};
            m_capture.reset(); // the old map's memory first: it may be what the new one needs
            m_settingsKey = 0;
            bool sizeFailure = false;
            auto created = envmap::EnvironmentCapture::create(settings, &sizeFailure);
            if (!created) {
                if (!sizeFailure) { // a shader: no smaller size helps, and none is remembered as failing
                    otherError = created.error();
                    return base::Done{};
                }
                return base::Error{created.error()};
            }
            m_capture = std::move(*created);
            return base::Done{};
        });
    if (!otherError.empty()) {
        m_capture.reset();
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

base::Status ReflectorPass::capture(const FrameInput& input, const EnvmapPlan& plan, MainPassContext& context,
                                    const EnvironmentMirrorPrograms& mirrors,
                                    const RunFacePasses& runFacePasses) {
    const EnvmapCapture& where = plan.capture;
    const Reflector& reflector = *input.reflector;
    const std::uint64_t key = envmapSettingsKey(reflector);
    // allocate() normally made the map already, at a size that fits; a caller that did not gets it made
    // here, still checked.
    if (!m_capture || !sameSettings(m_capture->settings(), captureSettings(reflector))) {
        m_capture.reset();
        m_settingsKey = 0;
        auto created = envmap::EnvironmentCapture::create(captureSettings(reflector));
        if (!created)
            return base::Error{"reflector " + base::quoted(reflector.name) + ": the environment map " +
                               created.error()};
        m_capture = std::move(*created);
    }
    m_settingsKey = 0; // rendered below
    m_centre = where.centre;
    const FrameInput env = environmentInput(input, where.centre);
    envmap::CaptureView view;
    view.near = where.near;
    view.far = where.far;
    view.background = input.settings.background;
    view.faces = 0; // the faces the plan lists: all of them, or a time-sliced update's one
    for (const EnvmapFace& planned : plan.faces)
        view.faces |= 1u << planned.index;

    MainPassContext faces = withProgram(context.program, context, context.unitPlane);
    // The map frame is the world's (CaptureView::mapFromWorld is the identity), so a face's view-projection
    // is its projection times its view.
    EnvironmentTarget face;
    face.near = where.near;
    face.far = where.far;
    face.framebuffer = m_capture->framebuffer();
    face.size = m_capture->targetSize();
    face.meshFacts = &m_meshFacts;
    face.plan = &plan;
    auto drawFace = [&](const glm::dmat4&, int index) {
        face.faceView = envmap::cubeFaceView(index);
        face.face = positionInPlan(plan, index);
        drawEnvironmentTarget(env, face, mirrors, faces, runFacePasses);
    };

    // The direct fill draws copies of the meshes split until no edge spans more than a few degrees seen
    // from the (virtual) capture point: straight edges turn into curves.
    MainPassContext warped = withProgram(m_warp, context, context.unitPlane);
    m_warpMeshes.begin();
    auto drawWarped = [&](const envmap::WarpPass& pass) {
        EnvironmentTarget component;
        component.near = where.near;
        component.far = where.far;
        component.framebuffer = m_capture->framebuffer();
        component.size = m_capture->targetSize();
        component.warp = &pass;
        component.warpMeshes = &m_warpMeshes;
        component.warpAngle = warpEdgeAngle(m_capture->layout());
        component.meshFacts = &m_meshFacts;
        component.plan = &plan;
        component.face = positionInPlan(plan, pass.warp.component);
        drawEnvironmentTarget(env, component, {m_warpFlat, m_warpMirror}, warped, runFacePasses);
    };
    m_capture->update(view, drawFace, drawWarped);
    m_settingsKey = key;
    ++m_captures; // the chain, if any, holds an older map now
    return base::Done{};
}

base::Status ReflectorPass::prefilter(const Reflector& reflector, int samples) {
    if (!hasMap(reflector))
        return base::Done{}; // nothing captured (the map could not be allocated: warned already)
    m_chainOf = 0;
    if (!m_prefilter) {
        auto created = envmap::GgxPrefilter::create();
        if (!created)
            return base::Error{"reflector " + base::quoted(reflector.name) + ": the GGX pre-filter " +
                               created.error()};
        m_prefilter = std::move(*created);
    }
    if (base::Status filtered = m_prefilter->filter(*m_capture, samples); !filtered)
        return base::Error{"reflector " + base::quoted(reflector.name) + ": " + filtered.error() +
                           "; drawn with the map's mip chain instead"};
    m_chainOf = m_captures;
    return base::Done{};
}

base::Status ReflectorPass::selectLighting(const std::string& variant, bool drawVariants) {
    for (gl::Program* program : {&m_warp, &m_warpMirror, &m_surface})
        if (base::Status selected = program->select(variant, drawVariants); !selected)
            return selected;
    return base::Done{};
}

void ReflectorPass::setMapUniforms(const FrameInput& input, const gl::Program& p) const {
    const Reflector& r = *input.reflector;
    const envmap::EnvironmentCapture& map = *m_capture;
    p.set("uEnvType", static_cast<int>(map.settings().type));
    p.set("uEnvLayout", map.layout().packed());
    p.set("uEnvCentre", glm::vec3(m_centre - input.camera.position));
    const ParallaxParams proxy = r.parallax.value_or(ParallaxParams{});
    p.set("uParallax", !r.parallax ? 0 : proxy.shape == ParallaxShape::Sphere ? 1 : 2);
    p.set("uParallaxRadius", float(proxy.radius));
    p.set("uParallaxMin", glm::vec3(proxy.min));
    p.set("uParallaxMax", glm::vec3(proxy.max));
    p.set("uEnvCube", kEnvCubeUnit);
    p.set("uEnvArray", kEnvArrayUnit);
}

bool ReflectorPass::bindAsProbe(const FrameInput& input, const gl::Program& p) const {
    if (!input.reflector || !hasMap(*input.reflector))
        return false;
    p.use();
    setMapUniforms(input, p);
    const envmap::EnvironmentCapture& map = *m_capture;
    glActiveTexture(GL_TEXTURE0 + (map.target() == GL_TEXTURE_CUBE_MAP ? kEnvCubeUnit : kEnvArrayUnit));
    glBindTexture(map.target(), map.texture());
    glActiveTexture(GL_TEXTURE0);
    return true;
}

int ReflectorPass::lookupOf(const FrameInput& input) const {
    const double roughness = std::clamp(input.reflector->roughness, 0.0, 1.0);
    if (!(roughness > 0.0))
        return 0;
    return input.settings.glossyFilter != GlossyFilter::Mip && hasChain(*input.reflector) ? 2 : 1;
}

int ReflectorPass::bindLookup(const FrameInput& input, const gl::Program& p) const {
    if (!input.reflector || !hasMap(*input.reflector))
        return -1;
    const double roughness = std::clamp(input.reflector->roughness, 0.0, 1.0);
    const int lookup = lookupOf(input);
    const bool chain = lookup == 2;
    p.use();
    setMapUniforms(input, p);
    p.set("uEnvMapFromWorld", glm::mat3(1.0f));
    // A rough reflector reads one texture at an explicit LOD: the pre-filtered chain (same target and
    // layout as the map) at the roughness that covers the lobe, narrowed by the proxy's distance, and the
    // pixel's footprint (reflector_lookup.glsl's chainLod), or, for Mip (or without a chain), the map's own
    // mip chain at roughness × (its levels − 1), box-filtered levels standing in for the lobe. Roughness 0
    // takes the sharp lookup, as before roughness existed.
    const envmap::EnvironmentCapture& map = *m_capture;
    GLuint texture = map.texture();
    float lod = 0.0f;
    if (roughness > 0.0) {
        const int levels = chain ? m_prefilter->levels()
                                 : (map.settings().mipmaps ? envmap::usableMipLevels(map.layout()) : 1);
        texture = chain ? m_prefilter->texture() : texture;
        lod = static_cast<float>(roughness * (levels - 1));
    }
    p.set("uRough", lookup);
    p.set("uRoughnessLod", lod);
    p.set("uRoughness", float(roughness));
    p.set("uGgxAlbedo", kGgxAlbedoUnit);
    glActiveTexture(GL_TEXTURE0 + (map.target() == GL_TEXTURE_CUBE_MAP ? kEnvCubeUnit : kEnvArrayUnit));
    glBindTexture(map.target(), texture);
    glActiveTexture(GL_TEXTURE0);
    return lookup;
}

bool ReflectorPass::drawSurface(const FrameInput& input, const ViewSetup& view, MainPassContext& context) {
    if (!input.reflector || !hasMap(*input.reflector))
        return false;
    const Reflector& r = *input.reflector;
    const gl::Program& p = m_surface;
    beginLitView(input, view, p, context);
    // The draw variant without the lookups it does not use (REFLECTOR_ROUGH).
    setMaterial(r.material, p, context, "#define REFLECTOR_ROUGH " + std::to_string(lookupOf(input)) + "\n");
    p.set("uReflectivity", float(std::clamp(r.reflectivity, 0.0, 1.0)));
    p.set("uFresnel", r.fresnel ? 1 : 0);
    bindLookup(input, p);
    drawLitMesh(r.mesh, r.world, input, p, context);
    return true;
}

} // namespace speculum::render::passes
