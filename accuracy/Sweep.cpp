#include "accuracy/Sweep.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/frame/SceneNames.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cstdio>
#include <set>

namespace speculum::accuracy {

namespace {

using render::MirrorTechnique;
using render::ReflectorFill;
using render::ReflectorMap;

// The deepest mirror recursion and finest tessellation the project file allows: the references stand in
// for "infinitely deep" and "the smooth surface".
constexpr int kReferenceMirrorDepth = render::kMaxMirrorDepth;
constexpr int kReferenceTessellation = render::kMaxTessellation;

// The values swept, with the scene's own value added (sorted, no duplicates).
std::vector<int> withSceneValue(std::vector<int> values, int own) {
    values.push_back(own);
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    return values;
}

std::string techniqueName(MirrorTechnique t) {
    return std::string(render::names::fileName(render::names::kMirrorTechniques, t));
}

// The map methods the envmap family compares: the cube, and each non-linear map with each fill.
struct MapMethod {
    ReflectorMap map;
    ReflectorFill fill;
};
const std::vector<MapMethod> kMethods = {{ReflectorMap::Cube, ReflectorFill::Resampled},
                                         {ReflectorMap::DualParaboloid, ReflectorFill::Direct},
                                         {ReflectorMap::DualParaboloid, ReflectorFill::Resampled},
                                         {ReflectorMap::TennisBall, ReflectorFill::Direct},
                                         {ReflectorMap::TennisBall, ReflectorFill::Resampled}};

std::string methodName(const MapMethod& m) {
    return m.map == ReflectorMap::Cube ? mapName(m.map) : mapName(m.map) + " " + fillName(m.fill);
}

std::string methodId(const MapMethod& m) {
    return m.map == ReflectorMap::Cube ? mapName(m.map) : mapName(m.map) + "-" + fillName(m.fill);
}

int firstShadowPcf(const render::FrameInput& scene) {
    for (const render::Light& light : scene.lights)
        if (light.shadows.enabled)
            return light.shadows.pcf;
    return 1;
}

std::string roughnessText(double roughness) {
    char text[16];
    std::snprintf(text, sizeof text, "%.1f", roughness);
    return text;
}

// The quality steps of the footprint approximation: planar taps per pixel, pre-filter samples per texel.
struct GlossyQuality {
    int taps;
    int samples;
};

std::string qualityLabel(const GlossyQuality& q, const SceneTraits& traits) {
    std::string label;
    if (traits.roughMirrors > 0)
        label = std::to_string(q.taps) + " taps";
    if (traits.roughReflector)
        label += (label.empty() ? "" : " / ") + std::to_string(q.samples) + " samples";
    return label;
}

} // namespace

std::optional<double> referenceRoughness(ReferenceKind kind) {
    switch (kind) {
    case ReferenceKind::RoughLow:
        return kGlossyRoughness[0];
    case ReferenceKind::RoughMid:
        return kGlossyRoughness[1];
    case ReferenceKind::RoughHigh:
        return kGlossyRoughness[2];
    default:
        return std::nullopt;
    }
}

std::string familyName(Family family) {
    switch (family) {
    case Family::Scene:
        return "scene";
    case Family::Envmap:
        return "envmap";
    case Family::Parallax:
        return "parallax";
    case Family::MirrorTechnique:
        return "mirror-technique";
    case Family::MirrorDepth:
        return "mirror-depth";
    case Family::Shadows:
        return "shadows";
    case Family::Tessellation:
        return "tessellation";
    case Family::ReflectedDetail:
        return "reflected-detail";
    case Family::Glossy:
        return "glossy";
    }
    return "scene";
}

std::optional<Family> familyFromName(const std::string& name) {
    for (Family f :
         {Family::Scene, Family::Envmap, Family::Parallax, Family::MirrorTechnique, Family::MirrorDepth,
          Family::Shadows, Family::Tessellation, Family::ReflectedDetail, Family::Glossy})
        if (familyName(f) == name)
            return f;
    return std::nullopt;
}

std::optional<ReferenceKind> referenceFromName(const std::string& name) {
    for (ReferenceKind k : {ReferenceKind::Scene, ReferenceKind::HardShadows, ReferenceKind::DeepMirrors,
                            ReferenceKind::FineMesh, ReferenceKind::RoughLow, ReferenceKind::RoughMid,
                            ReferenceKind::RoughHigh})
        if (referenceName(k) == name)
            return k;
    return std::nullopt;
}

std::string referenceName(ReferenceKind kind) {
    switch (kind) {
    case ReferenceKind::Scene:
        return "scene";
    case ReferenceKind::HardShadows:
        return "hard-shadows";
    case ReferenceKind::DeepMirrors:
        return "deep-mirrors";
    case ReferenceKind::FineMesh:
        return "fine-mesh";
    case ReferenceKind::RoughLow:
    case ReferenceKind::RoughMid:
    case ReferenceKind::RoughHigh:
        return "rough-" + roughnessText(*referenceRoughness(kind));
    }
    return "scene";
}

std::string referenceDescription(ReferenceKind kind) {
    switch (kind) {
    case ReferenceKind::Scene:
        return "the scene as saved, traced exactly; each light's shadow uses the footprint of its own PCF "
               "kernel, so the error measured is that of the reflections, not of the chosen shadow softness";
    case ReferenceKind::HardShadows:
        return "the scene with exact hard shadows (one shadow ray per point): the true shadow every PCF "
               "kernel approximates";
    case ReferenceKind::DeepMirrors:
        return "the scene with planar mirrors recursing " + std::to_string(kReferenceMirrorDepth) +
               " levels deep (the file format's maximum), standing in for endless recursion";
    case ReferenceKind::FineMesh:
        return "the scene with its built-in teapots at tessellation " +
               std::to_string(kReferenceTessellation) +
               " (the file format's maximum), standing in for the smooth Bezier surface";
    case ReferenceKind::RoughLow:
    case ReferenceKind::RoughMid:
    case ReferenceKind::RoughHigh:
        return "the scene with every rough surface at roughness " + roughnessText(*referenceRoughness(kind)) +
               ", its glossy reflections integrated over the GGX lobe by the tracer's importance sampling";
    }
    return {};
}

std::string mapName(ReflectorMap map) {
    return std::string(render::names::fileName(render::names::kReflectorMaps, map));
}

std::string fillName(ReflectorFill fill) {
    return std::string(render::names::fileName(render::names::kReflectorFills, fill));
}

SceneTraits sceneTraits(const render::FrameInput& scene, const std::optional<int>& teapotTessellation) {
    SceneTraits t;
    t.mirrors = scene.mirrors.size();
    for (const render::Light& light : scene.lights)
        t.shadowedLights += light.shadows.enabled ? 1 : 0;
    t.teapotTessellation = teapotTessellation;
    for (const render::Mirror& m : scene.mirrors)
        t.roughMirrors += m.roughness > 0.0 ? 1 : 0;
    t.roughReflector = scene.reflector && scene.reflector->mesh && scene.reflector->roughness > 0.0;
    if (!scene.mirrors.empty() || (scene.reflector && scene.reflector->mesh))
        for (const render::DrawItem& item : scene.items)
            t.simplifiableMeshes += item.mesh && !item.mesh->coarse.indices.empty() ? 1 : 0;
    if (!scene.reflector || !scene.reflector->mesh)
        return t;
    t.reflector = true;
    if (scene.reflector->parallax.shape != render::ParallaxProxy::Shape::None) {
        t.ownProxy = true;
        t.proxy = scene.reflector->parallax;
        t.proxyMakesSense = true;
        return t;
    }
    // No proxy of its own: a box around what the map sees, if that box encloses the reflector (a reflector
    // outside the scene's bounds has nothing around it for a box to stand for).
    render::FrameInput environment = scene;
    environment.reflector.reset();
    const render::math::Box around = render::math::sceneBounds(environment);
    const render::math::Box own =
        render::math::worldBounds(render::computeBounds(*scene.reflector->mesh), scene.reflector->world);
    if (around.empty() || own.empty())
        return t;
    const double tolerance = 1e-6 * std::max(1.0, glm::length(around.max - around.min));
    const bool encloses = glm::all(glm::lessThanEqual(around.min, own.min + tolerance)) &&
                          glm::all(glm::greaterThanEqual(around.max, own.max - tolerance));
    if (!encloses)
        return t;
    const glm::dvec3 centre = render::envmapCapture(scene).centre;
    t.proxy.shape = render::ParallaxProxy::Shape::Box;
    t.proxy.min = around.min - centre;
    t.proxy.max = around.max - centre;
    t.proxyMakesSense = true;
    return t;
}

std::vector<Configuration> planSweep(const render::FrameInput& scene, const SceneTraits& traits,
                                     const SweepOptions& options) {
    std::vector<Configuration> out;
    out.push_back({Family::Scene, "scene", "scene", "scene", {}, ReferenceKind::Scene});

    if (traits.reflector) {
        const render::Reflector& r = *scene.reflector;
        const std::vector<int> resolutions = withSceneValue(
            options.quick ? std::vector<int>{64, 128, 256} : std::vector<int>{64, 128, 256, 512},
            r.resolution);
        for (const MapMethod& method : kMethods)
            for (int n : resolutions) {
                Configuration c{Family::Envmap,
                                "envmap-" + methodId(method) + "-" + std::to_string(n),
                                std::to_string(n),
                                methodName(method),
                                {},
                                ReferenceKind::Scene};
                c.variation.map = method.map;
                c.variation.fill = method.fill;
                c.variation.resolution = n;
                out.push_back(std::move(c));
            }
        if (traits.proxyMakesSense) {
            // Quick: the scene's resolution only; full: how the benefit changes with resolution.
            const std::vector<int> parallaxResolutions =
                options.quick ? std::vector<int>{r.resolution} : resolutions;
            for (bool on : {false, true})
                for (int n : parallaxResolutions) {
                    Configuration c{Family::Parallax,
                                    std::string("parallax-") + (on ? "on" : "off") + "-" + std::to_string(n),
                                    std::to_string(n),
                                    on ? "parallax on" : "parallax off",
                                    {},
                                    ReferenceKind::Scene};
                    c.variation.parallax = on;
                    c.variation.resolution = n;
                    out.push_back(std::move(c));
                }
        }
    }

    if (traits.mirrors > 0) {
        for (MirrorTechnique t : {MirrorTechnique::Stencil, MirrorTechnique::Texture}) {
            Configuration c{Family::MirrorTechnique,
                            "mirror-technique-" + techniqueName(t),
                            techniqueName(t),
                            "technique",
                            {},
                            ReferenceKind::Scene};
            c.variation.technique = t;
            out.push_back(std::move(c));
        }
        const int own = scene.settings.mirrorDepth;
        const int cap = options.quick ? std::min(std::max(own, 1), 4) : std::min(std::max(own, 1) + 2, 8);
        std::vector<int> depths;
        for (int d = 1; d <= cap; ++d)
            depths.push_back(d);
        for (int d : withSceneValue(depths, own)) {
            Configuration c{Family::MirrorDepth,
                            "mirror-depth-" + std::to_string(d),
                            "depth " + std::to_string(d),
                            "mirror depth",
                            {},
                            ReferenceKind::DeepMirrors};
            c.variation.mirrorDepth = d;
            out.push_back(std::move(c));
        }
    }

    if (traits.shadowedLights > 0) {
        for (int k : withSceneValue({1, 3, 5, 7}, firstShadowPcf(scene))) {
            Configuration c{Family::Shadows,
                            "pcf-" + std::to_string(k),
                            "pcf " + std::to_string(k),
                            "PCF kernel",
                            {},
                            ReferenceKind::HardShadows};
            c.variation.pcf = k;
            out.push_back(std::move(c));
        }
    }

    if (traits.teapotTessellation) {
        const std::vector<int> levels =
            withSceneValue(options.quick ? std::vector<int>{2, 4, 8, 16} : std::vector<int>{2, 4, 8, 16, 32},
                           *traits.teapotTessellation);
        for (int n : levels) {
            Configuration c{Family::Tessellation,
                            "tessellation-" + std::to_string(n),
                            std::to_string(n),
                            "teapot tessellation",
                            {},
                            ReferenceKind::FineMesh};
            c.variation.tessellation = n;
            out.push_back(std::move(c));
        }
    }

    if (traits.simplifiableMeshes > 0) {
        // Against the scene's reference, which traces every mesh whole: what drawing reflections from the
        // simplified level costs in accuracy, and what it saves in time.
        for (bool simplified : {false, true}) {
            Configuration c{Family::ReflectedDetail,
                            std::string("reflected-detail-") + (simplified ? "simplified" : "full"),
                            simplified ? "simplified" : "full",
                            "reflected detail",
                            {},
                            ReferenceKind::Scene};
            c.variation.simplifyReflections = simplified;
            out.push_back(std::move(c));
        }
    }

    if (traits.roughMirrors > 0 || traits.roughReflector) {
        // At three roughnesses, each against its own traced reference: the cheap mip level, then the
        // footprint (planar lobe taps, the reflector's pre-filtered chain) at rising quality.
        const std::vector<GlossyQuality> qualities =
            options.quick ? std::vector<GlossyQuality>{{4, 16}, {16, 64}}
                          : std::vector<GlossyQuality>{{4, 16}, {16, 64}, {64, 256}};
        const ReferenceKind kinds[3] = {ReferenceKind::RoughLow, ReferenceKind::RoughMid,
                                        ReferenceKind::RoughHigh};
        for (ReferenceKind kind : kinds) {
            const double roughness = *referenceRoughness(kind);
            const std::string r = roughnessText(roughness);
            Configuration mip{Family::Glossy, "glossy-r" + r + "-mip", "mip", "r " + r + " mip", {}, kind};
            mip.variation.roughness = roughness;
            mip.variation.glossyFilter = render::GlossyFilter::Mip;
            out.push_back(std::move(mip));
            for (const GlossyQuality& q : qualities) {
                Configuration c{Family::Glossy,
                                "glossy-r" + r + "-footprint-" + std::to_string(q.taps) + "-" +
                                    std::to_string(q.samples),
                                qualityLabel(q, traits),
                                "r " + r + " footprint",
                                {},
                                kind};
                c.variation.roughness = roughness;
                c.variation.glossyFilter = render::GlossyFilter::Footprint;
                c.variation.glossyTaps = q.taps;
                c.variation.prefilterSamples = q.samples;
                out.push_back(std::move(c));
            }
        }
    }
    return out;
}

render::FrameInput applyVariation(const render::FrameInput& scene, const SceneTraits& traits,
                                  const Variation& v, const TessellateTeapot& tessellate) {
    render::FrameInput out = scene;
    if (out.reflector) {
        render::Reflector& r = *out.reflector;
        r.map = v.map.value_or(r.map);
        r.resolution = v.resolution.value_or(r.resolution);
        r.fill = v.fill.value_or(r.fill);
        if (v.parallax)
            r.parallax = *v.parallax ? traits.proxy : render::ParallaxProxy{};
    }
    if (v.technique)
        for (render::Mirror& m : out.mirrors)
            m.technique = *v.technique;
    out.settings.mirrorDepth = v.mirrorDepth.value_or(out.settings.mirrorDepth);
    if (v.pcf)
        for (render::Light& light : out.lights)
            if (light.shadows.enabled)
                light.shadows.pcf = *v.pcf;
    out.settings.simplifyReflections = v.simplifyReflections.value_or(out.settings.simplifyReflections);
    if (v.roughness) {
        for (render::Mirror& m : out.mirrors)
            if (m.roughness > 0.0)
                m.roughness = *v.roughness;
        if (out.reflector && out.reflector->roughness > 0.0)
            out.reflector->roughness = *v.roughness;
    }
    out.settings.glossyFilter = v.glossyFilter.value_or(out.settings.glossyFilter);
    out.settings.glossyTaps = v.glossyTaps.value_or(out.settings.glossyTaps);
    out.settings.prefilterSamples = v.prefilterSamples.value_or(out.settings.prefilterSamples);
    if (v.tessellation && tessellate) {
        for (render::DrawItem& item : out.items)
            item.mesh = tessellate(item.mesh, *v.tessellation);
        if (out.reflector)
            out.reflector->mesh = tessellate(out.reflector->mesh, *v.tessellation);
    }
    return out;
}

render::FrameInput referenceInput(const render::FrameInput& scene, ReferenceKind kind,
                                  const TessellateTeapot& tessellate) {
    Variation v;
    if (kind == ReferenceKind::DeepMirrors)
        v.mirrorDepth = kReferenceMirrorDepth;
    if (kind == ReferenceKind::FineMesh)
        v.tessellation = kReferenceTessellation;
    v.roughness = referenceRoughness(kind);
    return applyVariation(scene, SceneTraits{}, v, tessellate);
}

Settings effectiveSettings(const render::FrameInput& applied, const SceneTraits& traits,
                           const std::optional<int>& teapotTessellation) {
    Settings s;
    if (applied.reflector && traits.reflector) {
        const render::Reflector& r = *applied.reflector;
        s.emplace_back("map", mapName(r.map));
        s.emplace_back("resolution", std::to_string(r.resolution));
        if (r.map != ReflectorMap::Cube) // the cube is always drawn directly: it has no fill to choose
            s.emplace_back("fill", fillName(r.fill));
        s.emplace_back("parallax", r.parallax.shape == render::ParallaxProxy::Shape::None ? "off" : "on");
    }
    if (!applied.mirrors.empty()) {
        const MirrorTechnique first = applied.mirrors.front().technique;
        const bool mixed = std::any_of(applied.mirrors.begin(), applied.mirrors.end(),
                                       [&](const render::Mirror& m) { return m.technique != first; });
        s.emplace_back("technique", mixed ? "mixed" : techniqueName(first));
        s.emplace_back("mirrorDepth", std::to_string(applied.settings.mirrorDepth));
    }
    std::set<int> kernels;
    for (const render::Light& light : applied.lights)
        if (light.shadows.enabled)
            kernels.insert(light.shadows.pcf);
    if (!kernels.empty()) {
        std::string pcf; // lights with different kernels: "3/5"
        for (int k : kernels)
            pcf += (pcf.empty() ? "" : "/") + std::to_string(k);
        s.emplace_back("pcf", pcf);
    }
    if (teapotTessellation)
        s.emplace_back("tessellation", std::to_string(*teapotTessellation));
    if (traits.simplifiableMeshes > 0)
        s.emplace_back("reflectedDetail", applied.settings.simplifyReflections ? "simplified" : "full");
    if (traits.roughMirrors > 0 || traits.roughReflector) {
        double roughness = applied.reflector && traits.roughReflector ? applied.reflector->roughness : 0.0;
        for (const render::Mirror& m : applied.mirrors)
            roughness = std::max(roughness, m.roughness);
        s.emplace_back("roughness", roughnessText(roughness));
        const render::Settings& g = applied.settings;
        s.emplace_back("glossy",
                       g.glossyFilter == render::GlossyFilter::Mip
                           ? std::string("mip")
                           : "footprint " + qualityLabel({g.glossyTaps, g.prefilterSamples}, traits));
    }
    return s;
}

} // namespace speculum::accuracy
