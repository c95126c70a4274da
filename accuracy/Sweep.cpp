#include "accuracy/Sweep.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/frame/SceneNames.hpp"
#include "render/math/Projection.hpp"
#include "render/mesh/Simplify.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <tuple>
#include <utility>

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

// The map methods the envmap family compares: the cube, each warpable map with each fill, and the
// octahedral map (always resampled).
struct MapMethod {
    ReflectorMap map;
    ReflectorFill fill;
};
const std::vector<MapMethod> kMethods = {{ReflectorMap::Cube, ReflectorFill::Resampled},
                                         {ReflectorMap::DualParaboloid, ReflectorFill::Direct},
                                         {ReflectorMap::DualParaboloid, ReflectorFill::Resampled},
                                         {ReflectorMap::TennisBall, ReflectorFill::Direct},
                                         {ReflectorMap::TennisBall, ReflectorFill::Resampled},
                                         {ReflectorMap::Octahedral, ReflectorFill::Resampled}};

std::string methodName(const MapMethod& m) {
    return !render::warpable(m.map) ? mapName(m.map) : mapName(m.map) + " " + fillName(m.fill);
}

std::string methodId(const MapMethod& m) {
    return !render::warpable(m.map) ? mapName(m.map) : mapName(m.map) + "-" + fillName(m.fill);
}

int firstShadowPcf(const render::FrameInput& scene) {
    for (const render::Light& light : scene.lights)
        if (light.shadows.has_value())
            return light.shadows->pcf;
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
    case Family::ScreenSpace:
        return "screen-space";
    case Family::Setting:
        return "setting";
    case Family::Bounces:
        return "bounces";
    case Family::Update:
        return "update";
    }
    return "scene";
}

std::optional<Family> familyFromName(const std::string& name) {
    for (Family f : {Family::Scene, Family::Envmap, Family::Parallax, Family::MirrorTechnique,
                     Family::MirrorDepth, Family::Shadows, Family::Tessellation, Family::ReflectedDetail,
                     Family::Glossy, Family::ScreenSpace, Family::Setting, Family::Bounces, Family::Update})
        if (familyName(f) == name)
            return f;
    return std::nullopt;
}

std::optional<ReferenceKind> referenceFromName(const std::string& name) {
    for (ReferenceKind k : {ReferenceKind::Scene, ReferenceKind::HardShadows, ReferenceKind::DeepMirrors,
                            ReferenceKind::FineMesh, ReferenceKind::RoughLow, ReferenceKind::RoughMid,
                            ReferenceKind::RoughHigh, ReferenceKind::Played})
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
    case ReferenceKind::Played:
        return "played";
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
    case ReferenceKind::Played:
        return "the scene " + std::to_string(kPlayedFrames - 1) +
               "/60 s after its time, where the update family's played frames end, traced exactly";
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
        t.shadowedLights += light.shadows.has_value() ? 1 : 0;
    t.teapotTessellation = teapotTessellation;
    for (const render::Mirror& m : scene.mirrors)
        t.roughMirrors += m.roughness > 0.0 ? 1 : 0;
    t.roughReflector = std::any_of(scene.reflectors.begin(), scene.reflectors.end(),
                                   [](const render::Reflector& r) { return r.mesh && r.roughness > 0.0; });
    const int first = render::probeReflector(scene); // the first reflector with a mesh
    t.reflectors =
        static_cast<std::size_t>(std::count_if(scene.reflectors.begin(), scene.reflectors.end(),
                                               [](const render::Reflector& r) { return r.mesh != nullptr; }));
    if (!scene.mirrors.empty() || first >= 0)
        for (const render::DrawItem& item : scene.items)
            t.simplifiableMeshes += item.mesh && render::wantsCoarseLevel(*item.mesh) ? 1 : 0;
    if (first < 0)
        return t;
    const render::Reflector& reflector = scene.reflectors[static_cast<std::size_t>(first)];
    t.reflector = true;
    t.ownProxy = reflector.parallax.has_value();
    t.proxy = t.ownProxy ? reflector.parallax : sceneProxy(scene, first);
    t.proxyMakesSense = t.proxy.has_value();
    return t;
}

namespace {

using Configurations = std::vector<Configuration>;

Configuration configuration(Family family, std::string id, std::string label, std::string series,
                            Variation variation, ReferenceKind reference = ReferenceKind::Scene) {
    return {family, std::move(id), std::move(label), std::move(series), std::move(variation), reference};
}

// Each map method at each resolution; parallax off and on where a proxy makes sense.
void planEnvmap(Configurations& out, const render::FrameInput& scene, const SceneTraits& traits,
                const SweepOptions& options) {
    if (!traits.reflector)
        return;
    const int own = scene.reflectors[static_cast<std::size_t>(render::probeReflector(scene))].resolution;
    const std::vector<int> resolutions = withSceneValue(
        options.quick ? std::vector<int>{64, 128, 256} : std::vector<int>{64, 128, 256, 512}, own);
    for (const MapMethod& method : kMethods)
        for (int n : resolutions) {
            Variation v;
            v.set(Part::Reflector, "map", int(method.map))
                .set(Part::Reflector, "fill", int(method.fill))
                .set(Part::Reflector, "resolution", n);
            out.push_back(configuration(Family::Envmap,
                                        "envmap-" + methodId(method) + "-" + std::to_string(n),
                                        std::to_string(n), methodName(method), v));
        }
    if (!traits.proxyMakesSense)
        return;
    // Quick: the scene's resolution only; full: how the benefit changes with resolution.
    for (bool on : {false, true})
        for (int n : options.quick ? std::vector<int>{own} : resolutions) {
            Variation v;
            v.parallax = on;
            v.set(Part::Reflector, "resolution", n);
            out.push_back(configuration(
                Family::Parallax, std::string("parallax-") + (on ? "on" : "off") + "-" + std::to_string(n),
                std::to_string(n), on ? "parallax on" : "parallax off", v));
        }
}

// Every mirror with each technique, and the mirror depth from 1 to a little beyond the scene's own.
void planMirrors(Configurations& out, const render::FrameInput& scene, const SceneTraits& traits,
                 const SweepOptions& options) {
    if (traits.mirrors == 0)
        return;
    for (MirrorTechnique t :
         {MirrorTechnique::Stencil, MirrorTechnique::Texture, MirrorTechnique::ScreenSpace}) {
        Variation v;
        v.set(Part::Mirrors, "technique", int(t));
        out.push_back(configuration(Family::MirrorTechnique, "mirror-technique-" + techniqueName(t),
                                    techniqueName(t), "technique", v));
    }
    const int own = scene.settings.mirrorDepth;
    const int cap = options.quick ? std::min(std::max(own, 1), 4) : std::min(std::max(own, 1) + 2, 8);
    std::vector<int> depths;
    for (int d = 1; d <= cap; ++d)
        depths.push_back(d);
    for (int d : withSceneValue(depths, own)) {
        Variation v;
        v.set(Part::Settings, "mirrorDepth", d);
        out.push_back(configuration(Family::MirrorDepth, "mirror-depth-" + std::to_string(d),
                                    "depth " + std::to_string(d), "mirror depth", v,
                                    ReferenceKind::DeepMirrors));
    }
}

// The reflector in a scene without mirrors: its map alone, then traced in screen space first at rising
// steps, a cone for a rough one (judged on its own pixels; with mirrors the family judges the mirrors'
// pixels, and the reflector is left as the scene has it).
void planReflectorScreenSpace(Configurations& out, const SceneTraits& traits, const SweepOptions& options) {
    if (!traits.reflector)
        return;
    Variation map;
    map.set(Part::Reflector, "technique", int(render::ReflectorTechnique::Map));
    out.push_back(configuration(Family::ScreenSpace, "screen-space-reflector-map", "reflector map alone",
                                "reflector map", map));
    for (int n : options.quick ? std::vector<int>{64} : std::vector<int>{16, 64, 256}) {
        Variation v;
        v.set(Part::Reflector, "technique", int(render::ReflectorTechnique::ScreenSpace))
            .set(Part::Settings, "screenSteps", n);
        out.push_back(configuration(Family::ScreenSpace, "screen-space-reflector-steps-" + std::to_string(n),
                                    "reflector traced " + std::to_string(n) + " steps", "reflector traced",
                                    v));
    }
}

// Every mirror traced in screen space, each setting of the trace varied from the defaults, beside the two
// planar techniques, so that one plot and one Pareto front hold them all: how many steps, how thick a
// surface is taken to be, half resolution, and (with a reflector) the background alone as the fallback.
void planScreenSpace(Configurations& out, const SceneTraits& traits, const SweepOptions& options) {
    if (traits.mirrors == 0) {
        planReflectorScreenSpace(out, traits, options);
        return;
    }
    for (MirrorTechnique t : {MirrorTechnique::Stencil, MirrorTechnique::Texture}) {
        Variation v;
        v.set(Part::Mirrors, "technique", int(t));
        out.push_back(configuration(Family::ScreenSpace, "screen-space-planar-" + techniqueName(t),
                                    "planar " + techniqueName(t), "planar", v));
    }
    auto traced = [&](const std::string& id, const std::string& label, const std::string& series) {
        Variation v;
        v.set(Part::Mirrors, "technique", int(MirrorTechnique::ScreenSpace));
        out.push_back(configuration(Family::ScreenSpace, "screen-space-" + id, label, series, v));
        return &out.back().variation;
    };
    const std::vector<int> steps =
        options.quick ? std::vector<int>{16, 64} : std::vector<int>{16, 32, 64, 128, 256};
    for (int n : steps)
        traced("steps-" + std::to_string(n), "traced " + std::to_string(n) + " steps", "steps")
            ->set(Part::Settings, "screenSteps", n);
    struct Thickness {
        double value;
        const char* text;
        const char* id; // ids are kebab-case, without a decimal point
    };
    const Thickness thicknesses[] = {{0.01, "0.01", "0-01"}, {0.1, "0.1", "0-1"}, {0.3, "0.3", "0-3"}};
    for (const Thickness& t : thicknesses)
        traced(std::string("thickness-") + t.id, std::string("traced thickness ") + t.text, "thickness")
            ->set(Part::Settings, "screenThickness", t.value);
    for (int n : options.quick ? std::vector<int>{64} : std::vector<int>{16, 64})
        traced("half-" + std::to_string(n), "traced at half resolution, " + std::to_string(n) + " steps",
               "half resolution")
            ->set(Part::Settings, "screenSteps", n)
            .set(Part::Settings, "screenResolution", int(render::ScreenResolution::Half));
    if (traits.reflector)
        traced("fallback-background", "traced, the background as fallback", "fallback")
            ->set(Part::Settings, "screenFallback", int(render::ScreenFallback::Background));
}

// PCF kernels against exact hard shadows; teapot tessellations against the finest.
void planShadowsAndMeshes(Configurations& out, const render::FrameInput& scene, const SceneTraits& traits,
                          const SweepOptions& options) {
    if (traits.shadowedLights > 0)
        for (int k : withSceneValue({1, 3, 5, 7}, firstShadowPcf(scene))) {
            Variation v;
            v.set(Part::Shadows, "pcf", k);
            out.push_back(configuration(Family::Shadows, "pcf-" + std::to_string(k),
                                        "pcf " + std::to_string(k), "PCF kernel", v,
                                        ReferenceKind::HardShadows));
        }
    if (traits.teapotTessellation) {
        const std::vector<int> levels =
            withSceneValue(options.quick ? std::vector<int>{2, 4, 8, 16} : std::vector<int>{2, 4, 8, 16, 32},
                           *traits.teapotTessellation);
        for (int n : levels) {
            Variation v;
            v.tessellation = n;
            out.push_back(configuration(Family::Tessellation, "tessellation-" + std::to_string(n),
                                        std::to_string(n), "teapot tessellation", v,
                                        ReferenceKind::FineMesh));
        }
    }
    if (traits.simplifiableMeshes > 0)
        // Against the scene's reference, which traces every mesh whole: what drawing reflections from the
        // simplified level costs in accuracy, and what it saves in time.
        for (bool simplified : {false, true}) {
            Variation v;
            v.set(Part::Settings, "simplifyReflections", simplified);
            const std::string name = simplified ? "simplified" : "full";
            out.push_back(configuration(Family::ReflectedDetail, "reflected-detail-" + name, name,
                                        "reflected detail", v));
        }
}

// At three roughnesses, each against its own traced reference: the cheap mip level, the convolved chain,
// then the footprint (planar lobe taps, the reflector's pre-filtered chain) at rising quality.
void planGlossy(Configurations& out, const SceneTraits& traits, const SweepOptions& options) {
    if (traits.roughMirrors == 0 && !traits.roughReflector)
        return;
    const std::vector<GlossyQuality> qualities =
        options.quick ? std::vector<GlossyQuality>{{4, 16}, {16, 64}}
                      : std::vector<GlossyQuality>{{4, 16}, {16, 64}, {64, 256}};
    for (ReferenceKind kind : {ReferenceKind::RoughLow, ReferenceKind::RoughMid, ReferenceKind::RoughHigh}) {
        const double roughness = *referenceRoughness(kind);
        const std::string r = roughnessText(roughness);
        Variation mip;
        mip.roughness = roughness;
        mip.set(Part::Settings, "glossyFilter", int(render::GlossyFilter::Mip));
        out.push_back(
            configuration(Family::Glossy, "glossy-r" + r + "-mip", "mip", "r " + r + " mip", mip, kind));
        // The convolved chain: one point (its cost does not grow with taps); the reflector's chain at the
        // default samples.
        Variation chain;
        chain.roughness = roughness;
        chain.set(Part::Settings, "glossyFilter", int(render::GlossyFilter::Chain))
            .set(Part::Settings, "prefilterSamples", 64);
        out.push_back(configuration(Family::Glossy, "glossy-r" + r + "-chain",
                                    traits.roughReflector ? "chain 64 samples" : "chain", "r " + r + " chain",
                                    chain, kind));
        for (const GlossyQuality& q : qualities) {
            Variation v;
            v.roughness = roughness;
            v.set(Part::Settings, "glossyFilter", int(render::GlossyFilter::Footprint))
                .set(Part::Settings, "glossyTaps", q.taps)
                .set(Part::Settings, "prefilterSamples", q.samples);
            out.push_back(configuration(Family::Glossy,
                                        "glossy-r" + r + "-footprint-" + std::to_string(q.taps) + "-" +
                                            std::to_string(q.samples),
                                        qualityLabel(q, traits), "r " + r + " footprint", v, kind));
        }
    }
}

// Every declared field with sweep values of its own, on a scene that has a component of its part: each
// value against the scene's reference (the scene's own value is the scene's configuration).
void planDeclared(Configurations& out, const SceneTraits& traits) {
    for (const auto& [part, spec] : declaredSweeps()) {
        const bool present = part == Part::Settings || (part == Part::Mirrors && traits.mirrors > 0) ||
                             (part == Part::Reflector && traits.reflector) ||
                             (part == Part::Shadows && traits.shadowedLights > 0);
        if (!present)
            continue;
        for (double x : spec->sweep) {
            const render::FieldValue value = spec->type == render::FieldType::Number
                                                 ? render::FieldValue(x)
                                                 : render::FieldValue(static_cast<int>(x));
            const std::string text = render::fieldValueText(*spec, value);
            Variation v;
            v.set(part, spec->name, value);
            out.push_back(configuration(Family::Setting,
                                        "setting-" + std::string(partName(part)) + "-" +
                                            std::string(spec->name) + "-" + text,
                                        std::string(spec->name) + " " + text, std::string(spec->label), v));
        }
    }
}

// Reflectors seeing each other: the maps drawn with the other reflectors plain, then bounce by bounce,
// against the scene's reference (the tracer follows reflections between reflectors to its depth).
void planBounces(Configurations& out, const SceneTraits& traits, const SweepOptions& options) {
    if (traits.reflectors < 2)
        return;
    for (int b = 0; b <= (options.quick ? 2 : 3); ++b) {
        Variation v;
        v.set(Part::Settings, "reflectorBounces", b);
        out.push_back(configuration(Family::Bounces, "bounces-" + std::to_string(b),
                                    std::to_string(b) + (b == 1 ? " bounce" : " bounces"), "bounces", v));
    }
}

// Maps while the scene moves: every reflector's map redrawn every frame, then one face a frame in turn,
// each the last of kPlayedFrames frames played as the editor plays them (the maps kept between frames as
// their policy keeps them), against the scene where the frames end.
void planUpdate(Configurations& out, const SceneTraits& traits) {
    if (!traits.reflector || !traits.moves)
        return;
    for (const auto& [update, id, label] :
         {std::tuple{render::ReflectorUpdate::Always, "update-always", "every frame"},
          std::tuple{render::ReflectorUpdate::TimeSliced, "update-time-sliced", "time-sliced"}}) {
        Variation v;
        v.set(Part::Reflector, "update", int(update));
        out.push_back(configuration(Family::Update, id, label, "update", v, ReferenceKind::Played));
    }
}

} // namespace

std::vector<Configuration> planSweep(const render::FrameInput& scene, const SceneTraits& traits,
                                     const SweepOptions& options) {
    Configurations out;
    out.push_back(configuration(Family::Scene, "scene", "scene", "scene", {}));
    planEnvmap(out, scene, traits, options);
    planMirrors(out, scene, traits, options);
    planShadowsAndMeshes(out, scene, traits, options);
    planGlossy(out, traits, options);
    planScreenSpace(out, traits, options);
    planDeclared(out, traits);
    planBounces(out, traits, options);
    planUpdate(out, traits);
    return out;
}

render::FrameInput referenceInput(const render::FrameInput& scene, ReferenceKind kind,
                                  const TessellateTeapot& tessellate) {
    Variation v;
    if (kind == ReferenceKind::DeepMirrors)
        v.set(Part::Settings, "mirrorDepth", kReferenceMirrorDepth);
    if (kind == ReferenceKind::FineMesh)
        v.tessellation = kReferenceTessellation;
    v.roughness = referenceRoughness(kind);
    return applyVariation(scene, v, std::nullopt, tessellate);
}

} // namespace speculum::accuracy
