#include "render/inspect/PixelExplanation.hpp"

#include "render/envmap/Layout.hpp"
#include "render/envmap/Mapping.hpp"
#include "render/envmap/SolidAngle.hpp"
#include "render/image/ColorSpace.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <map>

namespace speculum::render::inspect {

namespace {

using reference::HitKind;
using reference::PathEventKind;
using reference::PathVertex;
using reference::PixelId;
using reference::TracedPath;

std::string quoted(const std::string& name) {
    return "'" + name + "'";
}

std::string number(double value, int decimals = 2) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string bufferName(const PassWrites& writes) {
    switch (writes.target) {
    case PassTarget::OwnMap:
        return "map";
    case PassTarget::Linear:
        return "camera";
    case PassTarget::Reflection:
        return "reflection texture " + std::to_string(writes.slot);
    case PassTarget::Output:
        return "output";
    }
    return "map";
}

std::string mirrorTechnique(const MirrorView& view) {
    if (view.screenSpace)
        return "screen-space";
    return view.ownTarget ? "texture" : "stencil";
}

std::string glossyText(const Mirror& mirror, const MirrorView& view, const ReasonDetails& details) {
    if (!(mirror.roughness > 0.0))
        return "";
    const std::string filter(names::kGlossyFilters[std::size_t(view.glossyFilter)].file);
    const double alpha = mirror.roughness * mirror.roughness;
    // The GGX lobe is about 2.6 α wide at half its peak (the half-vector's density halves at tan θ = 0.64 α,
    // and the reflection turns by twice the half-vector's angle).
    std::string text = "; rough " + number(mirror.roughness) + " (a lobe about " +
                       number(2.6 * alpha * 180.0 / M_PI, 1) + "° wide at half its peak): " + filter +
                       " filter";
    if (details.glossyTaps > 0)
        text += ", " + std::to_string(details.glossyTaps) + " taps a pixel over the lobe's footprint";
    return text;
}

std::string mirrorPassText(const FrameInput& input, const FramePlan& plan, const PlannedPass& pass) {
    if (pass.view < 0 || std::size_t(pass.view) >= plan.views.size())
        return "";
    const MirrorView& view = plan.views[std::size_t(pass.view)];
    const Mirror& mirror = input.mirrors[std::size_t(view.mirror)];
    const std::string name = quoted(mirror.name);
    const std::string level = "level " + std::to_string(view.depth);
    switch (pass.kind) {
    case PassKind::MirrorMask:
        return "marks the pixels of " + name + " (" + level + ") with stencil " +
               std::to_string(view.stencilLevel);
    case PassKind::Mirror:
        if (view.screenSpace)
            return "traces the reflection in " + name + " through the camera's image (" + level + ")";
        if (view.ownTarget)
            return "draws the scene reflected in " + name + " (" + level + ") into reflection texture " +
                   std::to_string(view.textureSlot);
        return "draws the scene reflected in " + name + " (" + level + ") where the stencil is " +
               std::to_string(view.stencilLevel);
    default:
        return "blends the surface of " + name + " with its reflection (" + mirrorTechnique(view) +
               " technique, reflectivity " + number(mirror.reflectivity) +
               (mirror.fresnel ? ", Fresnel" : "") + ")" + glossyText(mirror, view, pass.details);
    }
}

std::string reflectorText(const FrameInput& input, const FramePlan& plan, const PlannedPass& pass) {
    if (pass.reflector < 0 || std::size_t(pass.reflector) >= input.reflectors.size())
        return "";
    const Reflector& r = input.reflectors[std::size_t(pass.reflector)];
    const std::string map(names::kReflectorMaps[std::size_t(r.map)].file);
    const int n = plan.reflectorResolution(pass.reflector);
    if (pass.kind == PassKind::Prefilter)
        return "filters the map of " + quoted(r.name) + " into its GGX chain (roughness " +
               number(r.roughness) + ")";
    if (pass.kind == PassKind::ReflectorTrace)
        return "traces the reflection of " + quoted(r.name) +
               " through the camera's image, its map where it finds nothing";
    if (pass.kind == PassKind::ScreenColour)
        return "keeps the camera's image for the screen-space traces";
    const int bounce = pass.details.bounce;
    return "draws the " + map + " map of " + quoted(r.name) + ", " + std::to_string(n) + "² texels" +
           (bounce > 0 ? ", bounce " + std::to_string(bounce) : "");
}

std::string passText(const FrameInput& input, const FramePlan& plan, const PlannedPass& pass) {
    switch (pass.kind) {
    case PassKind::Shadow: {
        const ShadowPlan* shadow = plan.shadowOf(pass.lightIndex);
        const std::string name = pass.lightIndex >= 0 && std::size_t(pass.lightIndex) < input.lights.size()
                                     ? quoted(input.lights[std::size_t(pass.lightIndex)].name)
                                     : std::string("a light");
        return "draws the shadow map of " + name +
               (shadow ? " (" + std::to_string(shadow->mapSize) + "², PCF " + std::to_string(shadow->pcf) +
                             "×" + std::to_string(shadow->pcf) + ")"
                       : std::string());
    }
    case PassKind::MirrorMask:
    case PassKind::Mirror:
    case PassKind::MirrorSurface:
        return mirrorPassText(input, plan, pass);
    case PassKind::Envmap:
    case PassKind::Prefilter:
    case PassKind::ReflectorTrace:
    case PassKind::ScreenColour:
        return reflectorText(input, plan, pass);
    case PassKind::Main:
        return "draws the scene seen from the camera, lit and shadowed, the reflectors with their maps";
    case PassKind::Guides:
        return "draws the editor's guides";
    case PassKind::Composite:
        return "resolves the camera's buffer into the output";
    case PassKind::ScreenDepth:
        return "keeps the camera's depth for the screen-space traces";
    }
    return "";
}

bool differs(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::any(glm::greaterThan(glm::abs(a - b), glm::dvec3(1e-6)));
}

} // namespace

std::string nodeName(const FrameInput& input, const PixelId& id) {
    switch (id.kind) {
    case HitKind::Background:
        return {};
    case HitKind::Object:
        return input.items[std::size_t(id.index)].name;
    case HitKind::Mirror:
    case HitKind::MirrorBack:
        return input.mirrors[std::size_t(id.index)].name;
    case HitKind::Reflector:
        return input.reflectors[std::size_t(id.index)].name;
    }
    return {};
}

std::vector<RecipeStep> rasterRecipe(const FrameInput& input, const FrameReport& report) {
    std::vector<RecipeStep> steps;
    struct Last {
        glm::dvec3 colour;
        int stencil;
    };
    std::map<std::string, Last> last; // per buffer: what it held after the pass before
    for (const PixelProbe& probe : report.probes) {
        if (probe.run < 0 || std::size_t(probe.run) >= report.ran.size())
            continue;
        const PassRun& run = report.ran[std::size_t(probe.run)];
        const PlannedPass& pass = report.planned(run);
        RecipeStep step;
        step.run = probe.run;
        step.pass = std::string(toString(pass.kind));
        step.target = pass.target;
        step.what = passText(input, report.plan, pass);
        step.why = report.reason(run);
        step.buffer = bufferName(pass.writes);
        step.readable = probe.readable;
        step.colour = glm::dvec3(probe.colour);
        step.stencil = probe.stencil;
        if (pass.view >= 0 && std::size_t(pass.view) < report.plan.views.size())
            step.mirrorLevel = report.plan.views[std::size_t(pass.view)].depth;
        if (probe.readable) {
            // A pass that clears its rectangle and draws there wrote the pixel even where it drew the
            // value that was there before.
            const auto& rect = pass.writes.scissor;
            step.cleared =
                pass.writes.clear &&
                (pass.writes.clearWhole || !rect ||
                 (probe.x >= rect->x0 && probe.x < rect->x1 && probe.y >= rect->y0 && probe.y < rect->y1));
            const auto before = last.find(step.buffer);
            // Depth is not compared: mirror passes reset it where they draw, a change no one sees.
            step.wrote = step.cleared || before == last.end() ||
                         differs(before->second.colour, step.colour) ||
                         before->second.stencil != step.stencil;
            last[step.buffer] = {step.colour, step.stencil};
        }
        steps.push_back(std::move(step));
    }
    return steps;
}

namespace {

// shaders/parallax.glsl's parallaxHit: where the ray from p (relative to the capture point) along unit r
// leaves the proxy, relative to the capture point (xyz), and how far along the ray that is (w); r itself
// and 0 where it never meets it.
glm::dvec4 parallaxHit(const ParallaxParams& proxy, const glm::dvec3& p, const glm::dvec3& r) {
    if (proxy.shape == ParallaxShape::Sphere) {
        const double b = glm::dot(p, r);
        const double c = glm::dot(p, p) - proxy.radius * proxy.radius;
        const double disc = b * b - c;
        const double t = -b + std::sqrt(std::max(disc, 0.0));
        return disc >= 0.0 && t > 0.0 ? glm::dvec4(p + t * r, t) : glm::dvec4(r, 0.0);
    }
    double t = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        const double safe = std::abs(r[k]) > 1e-20 ? r[k] : 1e-20;
        t = std::min(t, std::max((proxy.min[k] - p[k]) / safe, (proxy.max[k] - p[k]) / safe));
    }
    return t > 0.0 ? glm::dvec4(p + t * r, t) : glm::dvec4(r, 0.0);
}

std::string componentLabel(envmap::MapType type, int component) {
    static const char* const faces[] = {"+X face", "-X face", "+Y face", "-Y face", "+Z face", "-Z face"};
    switch (type) {
    case envmap::MapType::Cube:
        return faces[std::clamp(component, 0, 5)];
    case envmap::MapType::DualParaboloid:
        return component == 0 ? "-Z half" : "+Z half";
    case envmap::MapType::TennisBall:
        return "part " + std::to_string(component + 1);
    case envmap::MapType::Octahedral:
        return "square";
    }
    return "";
}

// The texel of `layout` that direction `d` falls in, and its component.
glm::ivec3 texelOf(const envmap::MapLayout& layout, const glm::dvec3& d) {
    const envmap::MapCoord coord = envmap::toMap(layout.type, d);
    const glm::dvec2 uv = layout.toTexture(coord.uv);
    const int x = std::clamp(int(std::floor(uv.x * layout.width)), 0, layout.width - 1);
    const int y = std::clamp(int(std::floor(uv.y * layout.height)), 0, layout.height - 1);
    return {x, y, coord.component};
}

// Texels from the lookup's nominal uv to its component's edge (the rim, for a paraboloid).
double seamDistance(const envmap::MapLayout& layout, const glm::dvec3& d) {
    const envmap::MapCoord coord = envmap::toMap(layout.type, d);
    const glm::dvec2 texels(layout.width * layout.scale.x, layout.height * layout.scale.y); // nominal square
    if (layout.type == envmap::MapType::DualParaboloid)
        return (1.0 - glm::length(coord.uv * 2.0 - 1.0)) * 0.5 * texels.x;
    const glm::dvec2 edge = glm::min(coord.uv, 1.0 - coord.uv) * texels;
    return std::min(edge.x, edge.y);
}

// The level reflector_lookup.glsl reads for the lobe alone: the GGX chain at the roughness whose lobe
// covers it (narrowed by the proxy's distance: `narrowing`, hit.w / |hit.xyz|), or the mip chain at
// roughness × (levels − 1). The pixel's footprint can only raise it. (Where the chain could not be made,
// the frame warns and reads the mip chain.)
void lookupFilter(const FrameInput& input, const Reflector& r, const envmap::MapLayout& layout,
                  double narrowing, MapLookup& out) {
    const double roughness = std::clamp(r.roughness, 0.0, 1.0);
    if (!(roughness > 0.0)) {
        out.filter = "sharp";
        return;
    }
    const bool chain = input.settings.glossyFilter != GlossyFilter::Mip;
    out.filter = chain ? "GGX chain" : "mip chain";
    const int levels = chain ? envmap::prefilterLevels(layout) : envmap::usableMipLevels(layout);
    const double alpha = roughness * roughness * std::clamp(narrowing, 0.0, 1.0);
    out.mipLevel = (chain ? std::sqrt(alpha) : roughness) * (levels - 1);
}

} // namespace

std::optional<MapLookup> mapLookup(const FrameInput& input, const FramePlan& plan, const TracedPath& path) {
    const auto at = std::find_if(path.vertices.begin(), path.vertices.end(), [](const PathVertex& v) {
        return v.kind == PathEventKind::Reflector || v.kind == PathEventKind::LostBelow;
    });
    if (at == path.vertices.end() || at->hit.kind != HitKind::Reflector)
        return std::nullopt;
    const int index = at->hit.index;
    const Reflector& r = input.reflectors[std::size_t(index)];
    MapLookup out;
    out.reflector = r.name;
    out.reflectorIndex = index;
    out.resolution = plan.reflectorResolution(index);
    if (out.resolution <= 0)
        return std::nullopt; // no map this frame
    const auto type = static_cast<envmap::MapType>(int(r.map));
    out.layout = std::string(envmap::mapTypeName(type));
    out.centre = envmapCapture(input, index).centre;
    out.position = at->position;
    out.normal = at->normal;
    const glm::dvec3 e = -at->incoming;
    out.reflected = glm::normalize(2.0 * std::max(glm::dot(out.normal, e), 0.0) * out.normal - e);
    out.parallax = r.parallax.has_value();
    const glm::dvec4 hit = out.parallax ? parallaxHit(*r.parallax, out.position - out.centre, out.reflected)
                                        : glm::dvec4(out.reflected, 0.0);
    out.lookup = glm::normalize(glm::dvec3(hit));
    const double narrowing = hit.w > 0.0 ? hit.w / std::max(glm::length(glm::dvec3(hit)), 1e-6) : 1.0;
    const envmap::MapLayout layout = envmap::makeLayout(type, out.resolution);
    const glm::ivec3 texel = texelOf(layout, out.lookup);
    out.texelX = texel.x;
    out.texelY = texel.y;
    out.component = texel.z;
    out.componentLabel = componentLabel(type, texel.z);
    out.texelCentre = envmap::fromMap(type, texel.z, layout.texelCentre(texel.x, texel.y));
    out.texelSolidAngle = envmap::texelSolidAngle(layout, texel.x, texel.y);
    const envmap::MapLayout cube = envmap::makeLayout(envmap::MapType::Cube, out.resolution);
    const glm::ivec3 cubeTexel = texelOf(cube, out.lookup);
    out.cubeTexelSolidAngle = envmap::texelSolidAngle(cube, cubeTexel.x, cubeTexel.y);
    out.seamTexels = seamDistance(layout, out.lookup);
    out.guard = layout.guard;
    lookupFilter(input, r, layout, narrowing, out);
    return out;
}

namespace {

std::string nameOf(const FrameInput& input, const PixelId& id) {
    return id.kind == HitKind::Background ? std::string("the background") : quoted(nodeName(input, id));
}

std::string metres(double d) {
    return std::isfinite(d) ? number(d) + " m" : std::string("far away");
}

// What the map shows along the lookup (seen from the capture point, or the proxy's point) against what the
// exact reflected ray meets.
std::optional<Cause> captureCause(const FrameInput& input, const MapLookup& lookup, const TracedPath& path,
                                  const reference::Tracer& tracer) {
    const auto at = std::find_if(path.vertices.begin(), path.vertices.end(), [&](const PathVertex& v) {
        return v.kind == PathEventKind::Reflector && v.hit.index == lookup.reflectorIndex;
    });
    if (at == path.vertices.end())
        return std::nullopt;
    // What the mirror direction from the point meets (on a rough reflector, the lobe's axis, which is what
    // the map is looked up along), against what the map shows along the lookup from its capture point.
    const reference::RayHit seen = tracer.firstHit(at->position, lookup.reflected, lookup.reflectorIndex);
    const reference::RayHit mapped = tracer.firstHit(lookup.centre, lookup.lookup, lookup.reflectorIndex);
    const double offset = glm::length(lookup.position - lookup.centre);
    const std::string exactName = nameOf(input, seen.id);
    const double exactDistance = seen.id.kind == HitKind::Background ? INFINITY : seen.distance;
    const double mapDistance = glm::length(mapped.position - lookup.centre);
    std::string text = "the map is captured from the centre of " + quoted(lookup.reflector) + ", " +
                       metres(offset) + " from this point";
    if (lookup.parallax)
        text += " (with a parallax proxy)";
    if (!(mapped.id == seen.id)) {
        text += ": the reflected ray meets " + exactName +
                (std::isfinite(exactDistance) ? " " + metres(exactDistance) + " away" : "") +
                ", but along the lookup direction the map shows " + nameOf(input, mapped.id) +
                (mapped.id.kind == HitKind::Background ? "" : " " + metres(mapDistance) + " from the centre");
        return Cause{"capture-point", text};
    }
    if (seen.id.kind == HitKind::Background)
        return Cause{"capture-point",
                     text + ": both see the background, which is infinitely far: no parallax error"};
    const double gap = mapDistance - exactDistance;
    text += ": the reflected " + exactName + " is " + metres(std::abs(gap)) +
            (gap > 0 ? " closer" : " farther") + " than the map assumes (" + metres(exactDistance) +
            " from the point, " + metres(mapDistance) + " from the centre)";
    return Cause{"capture-point", text};
}

Cause texelCause(const MapLookup& lookup) {
    const double across = std::sqrt(lookup.texelSolidAngle) * 180.0 / M_PI;
    const std::string size = std::to_string(lookup.resolution) + "²";
    if (lookup.layout == "cube")
        return {"texel-size", "this texel of the " + size + " cube map (" + lookup.componentLabel +
                                  ") spans " + number(across, 3) + "° across"};
    const double ratio = lookup.texelSolidAngle / std::max(lookup.cubeTexelSolidAngle, 1e-300);
    return {"texel-size", "this texel of the " + lookup.layout + " map spans " + number(ratio) +
                              "× the solid angle of the cube's at " + size + " (" + number(across, 3) +
                              "° across)"};
}

std::optional<Cause> seamCause(const MapLookup& lookup) {
    if (!(lookup.seamTexels < 2.0))
        return std::nullopt;
    const std::string where = number(std::max(lookup.seamTexels, 0.0)) + " texels from the edge of the " +
                              lookup.componentLabel + " of the " + lookup.layout + " map: ";
    if (lookup.layout == "cube")
        return Cause{"seam", where + "GL's seamless cube filtering blends it with the neighbouring face"};
    return Cause{"seam",
                 where + "the " + std::to_string(lookup.guard) +
                     "-texel guard band holds the mapping's continuation there, so filtering reads the "
                     "environment, not a clamped edge"};
}

// Whether the pixel's neighbours show something else than it does (an edge or a silhouette).
std::optional<Cause> edgeCause(const FrameInput& input, const reference::PixelPaths& exact) {
    std::vector<PixelId> others;
    for (int j = 0; j < exact.windowHeight; ++j)
        for (int i = 0; i < exact.windowWidth; ++i) {
            const int dx = exact.windowX + i - exact.x, dy = exact.windowY + j - exact.y;
            const PixelId& id = exact.windowIds[std::size_t(j * exact.windowWidth + i)];
            if (std::abs(dx) <= 1 && std::abs(dy) <= 1 && !(id == exact.id) &&
                std::find(others.begin(), others.end(), id) == others.end())
                others.push_back(id);
        }
    if (others.empty())
        return std::nullopt;
    std::string names;
    for (const PixelId& id : others)
        names += (names.empty() ? "" : ", ") + nameOf(input, id);
    return Cause{"edge",
                 "this pixel is on an edge: " + nameOf(input, exact.id) + " here, " + names +
                     " beside it; a rasterizer covers a pixel by its centre and the two renderers place "
                     "an edge a fraction of a pixel apart, so edge pixels dominate the window's error"};
}

void pathCauses(const FrameInput& input, const PixelExplanation& e, std::vector<Cause>& causes) {
    const TracedPath& path = e.exact.centre;
    int reflectorBounces = 0;
    for (const PathVertex& v : path.vertices) {
        if (v.kind == PathEventKind::Reflector)
            ++reflectorBounces;
        if (v.kind == PathEventKind::DepthLimit)
            causes.push_back(
                {"depth-limit", "depth " + std::to_string(v.mirrorLevel) + " reached: the reflection in " +
                                    nameOf(input, v.hit) + " at level " + std::to_string(v.mirrorLevel + 1) +
                                    " is not followed, so it shows its own surface only, in both"});
        if (v.kind == PathEventKind::Surface && v.hit.kind == HitKind::Reflector)
            causes.push_back({"reflector-surface",
                              "the ray meets " + nameOf(input, v.hit) +
                                  " where its reflection is not followed (its own map leaves it "
                                  "out, or the reflector depth is reached): its plain material, in both"});
        if (v.kind == PathEventKind::LostBelow)
            causes.push_back({"lobe-below", "this lobe sample leaves below the surface of " +
                                                nameOf(input, v.hit) + ": it carries nothing"});
    }
    if (!path.vertices.empty() && path.vertices.front().kind == PathEventKind::Background)
        causes.push_back({"background", "the camera ray meets nothing: both show the background"});
    const int drawn = input.reflectors.size() > 1 ? input.settings.reflectorBounces : 0;
    if (reflectorBounces > drawn + 1)
        causes.push_back({"reflector-bounces", "the exact path bounces between reflectors " +
                                                   std::to_string(reflectorBounces) +
                                                   " times; the maps draw " + std::to_string(drawn) +
                                                   " bounce" + (drawn == 1 ? "" : "s") +
                                                   " between them, so the deeper ones show plain material"});
}

void shadowCauses(const FrameInput& input, const FramePlan& plan, const TracedPath& path,
                  const reference::Tracer& tracer, std::vector<Cause>& causes) {
    const auto last = std::find_if(path.vertices.rbegin(), path.vertices.rend(),
                                   [](const PathVertex& v) { return v.shaded; });
    if (last == path.vertices.rend())
        return;
    for (const reference::LightTerm& t : last->shading.lights) {
        if (!t.shadowed || t.nDotL <= 0.0 || t.cone <= 0.0)
            continue;
        const ShadowPlan* shadow = plan.shadowOf(t.light);
        const double filtered = tracer.footprintVisibility(t.light, last->position, last->shading.normal);
        const std::string answer = t.visibility >= 1.0   ? "reaches the light"
                                   : t.visibility <= 0.0 ? "is blocked"
                                                         : "is partly blocked";
        std::string text = "light " + quoted(input.lights[std::size_t(t.light)].name) + " at " +
                           nameOf(input, last->hit) + ": the exact shadow ray " + answer;
        if (shadow)
            text += "; the raster filters its " + std::to_string(shadow->mapSize) + "² shadow map " +
                    std::to_string(shadow->pcf) + "×" + std::to_string(shadow->pcf) +
                    ", whose footprint here is " + number(filtered * 100.0, 0) + " % lit";
        const bool edge = shadow && std::abs(filtered - t.visibility) > 0.05;
        if (edge)
            text += ": a shadow's edge, where the filtered map and the exact ray disagree";
        causes.push_back({edge ? "shadow-edge" : "shadow", text});
    }
}

const Material* materialOf(const FrameInput& input, const PixelId& id) {
    switch (id.kind) {
    case HitKind::Object:
        return &input.items[std::size_t(id.index)].material;
    case HitKind::Mirror:
    case HitKind::MirrorBack:
        return &input.mirrors[std::size_t(id.index)].material;
    case HitKind::Reflector:
        return &input.reflectors[std::size_t(id.index)].material;
    case HitKind::Background:
        return nullptr;
    }
    return nullptr;
}

// A textured surface: the two renderers filter its texture differently.
void textureCause(const FrameInput& input, const TracedPath& path, std::vector<Cause>& causes) {
    for (const PathVertex& v : path.vertices) {
        const Material* m = v.shaded ? materialOf(input, v.hit) : nullptr;
        if (!m || (m->texture.empty() && m->normalTexture.empty() && m->emissionTexture.empty()))
            continue;
        causes.push_back(
            {"texture-filter", nameOf(input, v.hit) +
                                   " is textured: the raster filters the mip level of the pixel's "
                                   "footprint, the tracer samples the full-resolution image at the "
                                   "pixel's centre (no mip maps), so a texture seen from afar differs "
                                   "pixel by pixel; supersample both to compare"});
        return;
    }
}

double meanSpreadDegrees(const reference::PixelPaths& exact) {
    double sum = 0.0;
    int count = 0;
    auto add = [&](const TracedPath& p) {
        for (const PathVertex& v : p.vertices)
            if (v.roughness > 0.0 && v.lobeWeight > 0.0) {
                sum += metrics::angleBetween(v.outgoing, v.mirrored) * 180.0 / M_PI;
                ++count;
                return;
            }
    };
    add(exact.centre);
    for (const TracedPath& p : exact.samples)
        add(p);
    return count > 0 ? sum / count : 0.0;
}

void glossyCause(const PixelExplanation& e, std::vector<Cause>& causes) {
    if (!e.exact.glossy)
        return;
    const glm::dvec3 gap = glm::abs(e.rasterColour - e.exactColour);
    const double difference = (gap.r + gap.g + gap.b) / 3.0;
    const double errors = e.exactStandardError > 0.0 ? difference / e.exactStandardError : 0.0;
    std::string text = "the exact colour averages sampled paths of a rough lobe (mean " +
                       number(e.lobeSpreadDegrees, 1) +
                       "° from the mirror direction over the paths listed); its standard error is " +
                       number(e.exactStandardError, 4) + " (linear) and the raster differs by " +
                       number(difference, 4) + ", " + number(errors, 1) + " standard errors: ";
    text += errors < 2.0 ? "within the reference's noise, not measurable at this sample count"
                         : "more than its noise explains, so the raster's filter is off here";
    causes.push_back({"glossy-noise", text});
}

// The mirrors the raster drew the pixel through (the views that hold it, by level) against
// those the exact path meets before any reflector: where they differ, the two show different things.
void mirrorChainCause(const FrameInput& input, const PixelExplanation& e, std::vector<Cause>& causes) {
    std::vector<std::string> raster;
    // A stencil view holds the pixel where its mask marked it; a texture view where its pass cleared it.
    for (const RecipeStep& s : e.recipe) {
        const bool holds = (s.pass == "mirror-mask" && s.wrote) || (s.pass == "mirror" && s.cleared);
        if (!holds || s.mirrorLevel < 1)
            continue;
        raster.resize(std::max(raster.size(), std::size_t(s.mirrorLevel)));
        raster[std::size_t(s.mirrorLevel - 1)] = s.target;
    }
    std::vector<std::string> exact;
    std::string after = "the background";
    for (const PathVertex& v : e.exact.centre.vertices) {
        if (v.kind != PathEventKind::Mirror) {
            after = nameOf(input, v.hit);
            break;
        }
        if (v.roughness > 0.0)
            return; // the path listed is one lobe sample, not the mirror direction the raster's view follows
        exact.push_back(v.hit.kind == HitKind::Mirror ? input.mirrors[std::size_t(v.hit.index)].name : "");
    }
    if (raster.empty() || raster == exact)
        return;
    auto chain = [](const std::vector<std::string>& names) {
        std::string text;
        for (const std::string& n : names)
            text += (text.empty() ? "" : " → ") + quoted(n);
        return text.empty() ? std::string("no mirror") : text;
    };
    causes.push_back(
        {"mirror-chain", "the raster draws this pixel through " + chain(raster) +
                             ", the exact path goes through " + chain(exact) + " to " + after +
                             ": near an edge of what a reflection shows, or a rough mirror's filter "
                             "reading past it, the two see different things"});
}

glm::dvec3 encoded(const glm::dvec3& c) {
    glm::dvec3 out;
    for (int k = 0; k < 3; ++k)
        out[k] = linearToSrgb(float(std::clamp(std::isfinite(c[k]) ? c[k] : 0.0, 0.0, 1.0)));
    return out;
}

glm::dvec3 pixelOf(const Image& image, int x, int y) {
    const std::size_t p = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4;
    return {image.rgba[p], image.rgba[p + 1], image.rgba[p + 2]};
}

void windowError(const Image& raster, PixelExplanation& e) {
    const reference::PixelPaths& x = e.exact;
    Image test, exact;
    test.width = exact.width = x.windowWidth;
    test.height = exact.height = x.windowHeight;
    for (int j = 0; j < x.windowHeight; ++j)
        for (int i = 0; i < x.windowWidth; ++i) {
            const glm::dvec3 r = pixelOf(raster, x.windowX + i, x.windowY + j);
            const glm::dvec3& t = x.window[std::size_t(j * x.windowWidth + i)];
            for (int k = 0; k < 3; ++k) {
                test.rgba.push_back(float(r[k]));
                exact.rgba.push_back(float(t[k]));
            }
            test.rgba.push_back(1.0f);
            exact.rgba.push_back(1.0f);
        }
    if (auto stats = metrics::compare(test, exact)) {
        e.windowRmse = stats->rmse;
        e.windowPsnr = stats->psnr;
    }
}

// Whether the pixel's first surface draws its reflection by a screen-space trace.
bool tracedInTheImage(const FrameInput& input, const reference::PixelPaths& exact) {
    if (exact.id.kind == HitKind::Mirror)
        return input.mirrors[std::size_t(exact.id.index)].technique == MirrorTechnique::ScreenSpace;
    if (exact.id.kind == HitKind::Reflector)
        return input.reflectors[std::size_t(exact.id.index)].technique == ReflectorTechnique::ScreenSpace;
    return false;
}

// The sources view's colour is mix(fallback, green, confidence), the fallback blue (the map) or red (the
// background).
void screenSpaceCause(const glm::dvec3& source, PixelExplanation& e) {
    const double fallback = std::max(source.r, source.b);
    const double total = source.g + fallback;
    if (!(total > 1e-6))
        return;
    e.screenSpaceHit = source.g / total;
    e.screenSpaceFallback = source.b >= source.r ? "the reflector's map" : "the background";
    const int percent = int(std::lround(e.screenSpaceHit * 100.0));
    e.causes.push_back(
        {"screen-space", "the screen-space trace met this pixel's reflection in the camera's image for " +
                             std::to_string(percent) + " % of it, the rest from " + e.screenSpaceFallback +
                             (percent < 100 ? ": what the image does not hold (off screen, hidden, "
                                              "behind the mirror) is not where the exact ray finds it"
                                            : "")});
}

// A reflection texture is shared by the views of one nesting level, one after the other: of the writes to
// its pixel, those since the last clear before a mirror surface reads it reach the image (a mirror pass
// clears and draws its view; the surfaces of mirrors inside it blend over that), and the others do not.
std::vector<RecipeStep> readReflectionWrites(const FrameReport& report, std::vector<RecipeStep> steps) {
    std::vector<bool> keep(steps.size(), true);
    std::map<int, std::vector<std::size_t>> pending; // slot → the writes since its last clear, not yet read
    auto drop = [&](std::vector<std::size_t>& writes) {
        for (std::size_t i : writes)
            keep[i] = false;
        writes.clear();
    };
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const PassWrites& writes = report.planned(report.ran[std::size_t(steps[i].run)]).writes;
        if (writes.readSlot >= 0)
            pending.erase(writes.readSlot); // read: they reach the image
        if (writes.target != PassTarget::Reflection || !steps[i].wrote)
            continue;
        std::vector<std::size_t>& slot = pending[writes.slot];
        if (steps[i].cleared)
            drop(slot); // cleared here: what was written before never reaches the image
        slot.push_back(i);
    }
    for (auto& [slot, unread] : pending)
        drop(unread);
    std::vector<RecipeStep> out;
    for (std::size_t i = 0; i < steps.size(); ++i)
        if (keep[i])
            out.push_back(std::move(steps[i]));
    return out;
}

// Which recipe steps matter to the pixel: those that wrote it, and the maps its path reads.
void keepStepsOfThePixel(const FrameInput& input, const FrameReport& report, PixelExplanation& e) {
    std::vector<bool> reflectorSeen(input.reflectors.size(), false), lightShaded(input.lights.size(), false);
    auto mark = [&](const TracedPath& p) {
        for (const PathVertex& v : p.vertices) {
            if (v.hit.kind == HitKind::Reflector && std::size_t(v.hit.index) < reflectorSeen.size())
                reflectorSeen[std::size_t(v.hit.index)] = true;
            for (const reference::LightTerm& t : v.shading.lights)
                if (t.shadowed && t.nDotL > 0.0 && std::size_t(t.light) < lightShaded.size())
                    lightShaded[std::size_t(t.light)] = true;
        }
    };
    mark(e.exact.centre);
    std::vector<RecipeStep> kept;
    for (RecipeStep& step : e.recipe) {
        const PlannedPass& pass = report.planned(report.ran[std::size_t(step.run)]);
        if (pass.kind == PassKind::Shadow)
            step.feeds = pass.lightIndex >= 0 && std::size_t(pass.lightIndex) < lightShaded.size() &&
                         lightShaded[std::size_t(pass.lightIndex)];
        if (pass.kind == PassKind::Envmap || pass.kind == PassKind::Prefilter)
            step.feeds = pass.reflector >= 0 && std::size_t(pass.reflector) < reflectorSeen.size() &&
                         reflectorSeen[std::size_t(pass.reflector)];
        if (step.wrote || step.feeds)
            kept.push_back(std::move(step));
    }
    e.recipe = readReflectionWrites(report, std::move(kept));
}

} // namespace

base::Result<PixelExplanation> explainPixel(const FrameInput& input, const FrameReport& report,
                                            const Image& raster, const reference::PixelPaths& exact,
                                            const reference::Tracer& tracer,
                                            const std::optional<glm::dvec3>& screenSpaceSource) {
    if (exact.x < 0 || exact.y < 0 || exact.x >= raster.width || exact.y >= raster.height)
        return base::Error{"pixel " + std::to_string(exact.x) + "," + std::to_string(exact.y) +
                           " is outside the " + std::to_string(raster.width) + "x" +
                           std::to_string(raster.height) + " image"};
    PixelExplanation e;
    e.x = exact.x;
    e.y = exact.y;
    e.width = raster.width;
    e.height = raster.height;
    e.exact = exact;
    e.rasterColour = pixelOf(raster, e.x, e.y);
    e.exactColour = exact.colour;
    e.error = glm::abs(encoded(e.rasterColour) - encoded(e.exactColour));
    e.errorRms = std::sqrt(glm::dot(e.error, e.error) / 3.0);
    e.windowRadius = std::max(exact.x - exact.windowX, exact.windowX + exact.windowWidth - 1 - exact.x);
    windowError(raster, e);
    const glm::dvec3 noise = glm::max(exact.noise, glm::dvec3(0.0));
    e.exactStandardError = (std::sqrt(noise.r) + std::sqrt(noise.g) + std::sqrt(noise.b)) / 3.0;
    e.lobeSpreadDegrees = meanSpreadDegrees(exact);
    e.recipe = rasterRecipe(input, report);
    if (report.probes.empty())
        e.notes.push_back("the raster recipe was not recorded: the still was drawn in tiles");
    keepStepsOfThePixel(input, report, e);
    e.lookup = mapLookup(input, report.plan, exact.centre);
    if (e.lookup) {
        if (auto cause = captureCause(input, *e.lookup, exact.centre, tracer))
            e.causes.push_back(*cause);
        e.causes.push_back(texelCause(*e.lookup));
        if (auto seam = seamCause(*e.lookup))
            e.causes.push_back(*seam);
    }
    if (auto edge = edgeCause(input, exact))
        e.causes.push_back(*edge);
    if (screenSpaceSource && tracedInTheImage(input, exact))
        screenSpaceCause(*screenSpaceSource, e);
    pathCauses(input, e, e.causes);
    mirrorChainCause(input, e, e.causes);
    shadowCauses(input, report.plan, exact.centre, tracer, e.causes);
    textureCause(input, exact.centre, e.causes);
    glossyCause(e, e.causes);
    return e;
}

} // namespace speculum::render::inspect
