#include "app/PixelCommand.hpp"

#include "app/ProjectInput.hpp"
#include "base/Printable.hpp"
#include "render/image/ColorSpace.hpp"
#include "render/inspect/PixelExplanation.hpp"
#include "render/reference/Tracer.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cstdio>
#include <iostream>

namespace speculum::app {

namespace {

using render::inspect::PixelExplanation;
using render::reference::HitKind;
using render::reference::PathVertex;
using render::reference::PixelId;
using render::reference::TracedPath;

QString hitKindText(HitKind kind) {
    const std::string_view text = render::reference::toString(kind);
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

std::string hitName(const render::FrameInput& input, const PixelId& id) {
    return render::inspect::nodeName(input, id);
}

QJsonArray vec(const glm::dvec3& v) {
    return QJsonArray{v.x, v.y, v.z};
}

QString text(const std::string& s) {
    return QString::fromStdString(s);
}

QJsonObject shadingJson(const render::FrameInput& input, const render::reference::ShadingTerms& s) {
    QJsonArray lights;
    for (const render::reference::LightTerm& t : s.lights)
        lights.append(QJsonObject{{"light", text(input.lights[std::size_t(t.light)].name)},
                                  {"nDotL", t.nDotL},
                                  {"cone", t.cone},
                                  {"shadowed", t.shadowed},
                                  {"visibility", t.visibility},
                                  {"diffuse", vec(t.diffuse)},
                                  {"specular", vec(t.specular)}});
    return QJsonObject{{"base", vec(s.base)},
                       {"emitted", vec(s.emitted)},
                       {"ambient", vec(s.ambient)},
                       {"lights", lights},
                       {"total", vec(s.total)}};
}

QJsonArray pathJson(const render::FrameInput& input, const TracedPath& path) {
    QJsonArray vertices;
    for (const PathVertex& v : path.vertices) {
        QJsonObject o{{"event", text(std::string(toString(v.kind)))},
                      {"hit", hitKindText(v.hit.kind)},
                      {"target", text(hitName(input, v.hit))},
                      {"from", vec(v.from)},
                      {"position", vec(v.position)},
                      {"normal", vec(v.normal)},
                      {"incoming", vec(v.incoming)},
                      {"distance", v.distance},
                      {"mirrorLevel", v.mirrorLevel},
                      {"reflectorLevel", v.reflectorLevel},
                      {"colour", vec(v.colour)},
                      {"weight", vec(v.weight)}};
        if (v.kind == render::reference::PathEventKind::Mirror ||
            v.kind == render::reference::PathEventKind::Reflector ||
            v.kind == render::reference::PathEventKind::LostBelow ||
            v.kind == render::reference::PathEventKind::DepthLimit) {
            o["reflectivity"] = v.reflectivity;
            o["fresnel"] = v.fresnel;
            o["tint"] = vec(v.tint);
            o["roughness"] = v.roughness;
            o["lobeWeight"] = v.lobeWeight;
            o["outgoing"] = vec(v.outgoing);
            o["mirrored"] = vec(v.mirrored);
        }
        o["shading"] = v.shaded ? QJsonValue(shadingJson(input, v.shading)) : QJsonValue();
        vertices.append(o);
    }
    return vertices;
}

QJsonValue lookupJson(const PixelExplanation& e) {
    if (!e.lookup)
        return QJsonValue();
    const render::inspect::MapLookup& l = *e.lookup;
    return QJsonObject{{"reflector", text(l.reflector)},
                       {"layout", text(l.layout)},
                       {"resolution", l.resolution},
                       {"component", l.component},
                       {"componentLabel", text(l.componentLabel)},
                       {"texel", QJsonArray{l.texelX, l.texelY}},
                       {"mipLevel", l.mipLevel},
                       {"filter", text(l.filter)},
                       {"position", vec(l.position)},
                       {"normal", vec(l.normal)},
                       {"reflected", vec(l.reflected)},
                       {"lookup", vec(l.lookup)},
                       {"texelCentre", vec(l.texelCentre)},
                       {"centre", vec(l.centre)},
                       {"parallax", l.parallax},
                       {"texelSolidAngle", l.texelSolidAngle},
                       {"cubeTexelSolidAngle", l.cubeTexelSolidAngle}};
}

QJsonArray recipeJson(const PixelExplanation& e) {
    QJsonArray steps;
    for (const render::inspect::RecipeStep& s : e.recipe)
        steps.append(QJsonObject{{"pass", text(s.pass)},
                                 {"target", text(s.target)},
                                 {"what", text(s.what)},
                                 {"reason", text(s.why)},
                                 {"buffer", text(s.buffer)},
                                 {"wrote", s.wrote},
                                 {"feeds", s.feeds},
                                 {"colour", s.readable ? QJsonValue(vec(s.colour)) : QJsonValue()},
                                 {"stencil", s.stencil},
                                 {"mirrorLevel", s.mirrorLevel}});
    return steps;
}

void printJson(const CliOptions& options, const render::FrameInput& input, const PixelExplanation& e,
               const std::string& renderer) {
    QJsonArray samples, causes, notes;
    for (const TracedPath& p : e.exact.samples)
        samples.append(QJsonObject{{"colour", vec(p.colour)}, {"path", pathJson(input, p)}});
    for (const render::inspect::Cause& c : e.causes)
        causes.append(QJsonObject{{"code", text(c.code)}, {"text", text(c.text)}});
    for (const std::string& n : e.notes)
        notes.append(text(n));
    const QJsonObject exact{{"colour", vec(e.exactColour)},
                            {"standardError", e.exactStandardError},
                            {"glossy", e.exact.glossy},
                            {"lobeSpreadDegrees", e.lobeSpreadDegrees},
                            {"hit", hitKindText(e.exact.id.kind)},
                            {"target", text(hitName(input, e.exact.id))},
                            {"path", pathJson(input, e.exact.centre)},
                            {"samples", samples}};
    const QJsonObject difference{
        {"error", vec(e.error)},
        {"errorRms", e.errorRms},
        {"windowRadius", e.windowRadius},
        {"window", QJsonArray{e.exact.windowX, e.exact.windowY, e.exact.windowWidth, e.exact.windowHeight}},
        {"windowRmse", e.windowRmse},
        {"windowPsnr", e.windowPsnr}};
    const QJsonObject root{
        {"pixel", QJsonArray{e.x, e.y}},
        {"size", text(std::to_string(e.width) + "x" + std::to_string(e.height))},
        {"time", options.time},
        {"raster", QJsonObject{{"colour", vec(e.rasterColour)}, {"steps", recipeJson(e)}}},
        {"exact", exact},
        {"lookup", lookupJson(e)},
        {"difference", difference},
        {"screenSpace",
         e.screenSpaceHit < 0.0
             ? QJsonValue()
             : QJsonValue(QJsonObject{{"hit", e.screenSpaceHit}, {"fallback", text(e.screenSpaceFallback)}})},
        {"causes", causes},
        {"notes", notes},
        {"renderer", text(renderer)}};
    std::cout << QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
}

std::string triple(const glm::dvec3& v, int decimals = 3) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "(%.*f, %.*f, %.*f)", decimals, v.x, decimals, v.y, decimals, v.z);
    return buffer;
}

std::string shadingText(const render::FrameInput& input, const render::reference::ShadingTerms& s) {
    std::string out = "ambient " + triple(s.ambient);
    if (s.emitted != glm::dvec3(0.0))
        out += ", emitted " + triple(s.emitted);
    for (const render::reference::LightTerm& t : s.lights) {
        out += "; light " + base::quoted(input.lights[std::size_t(t.light)].name) + ": ";
        if (t.nDotL <= 0.0 || t.cone <= 0.0) {
            out += "behind or outside its cone";
            continue;
        }
        out += "diffuse " + triple(t.diffuse) + ", specular " + triple(t.specular);
        if (t.shadowed)
            out += t.visibility >= 1.0   ? ", shadow ray lit"
                   : t.visibility <= 0.0 ? ", shadow ray blocked"
                                         : ", partly lit";
    }
    return out;
}

void printVertex(const render::FrameInput& input, int n, const PathVertex& v) {
    const std::string name =
        v.hit.kind == HitKind::Background ? "the background" : base::quoted(hitName(input, v.hit));
    std::printf("  %d. %-11s %s", n, std::string(toString(v.kind)).c_str(), name.c_str());
    if (v.hit.kind != HitKind::Background)
        std::printf(" at %s, %.3f m", triple(v.position).c_str(), v.distance);
    std::printf(" -> colour %s", triple(v.colour).c_str());
    if (n > 1)
        std::printf(", weighted by %s", triple(v.weight).c_str());
    std::printf("\n");
    if (v.kind == render::reference::PathEventKind::Mirror ||
        v.kind == render::reference::PathEventKind::Reflector ||
        v.kind == render::reference::PathEventKind::LostBelow)
        std::printf(
            "       R %.3f%s%s, reflected towards %s%s\n", v.reflectivity, v.fresnel ? " (Fresnel)" : "",
            v.tint != glm::dvec3(1.0) ? (", tint " + triple(v.tint)).c_str() : "", triple(v.outgoing).c_str(),
            v.roughness > 0.0 ? (" (rough " + std::to_string(v.roughness).substr(0, 4) + ", lobe weight " +
                                 std::to_string(v.lobeWeight).substr(0, 5) + ")")
                                    .c_str()
                              : "");
    if (v.shaded)
        std::printf("       %s = %s\n", shadingText(input, v.shading).c_str(),
                    triple(v.shading.total).c_str());
}

void printRecipe(const PixelExplanation& e) {
    std::printf("\nRaster recipe (the passes that wrote this pixel, or drew a map it reads), in order:\n");
    int n = 0;
    for (const render::inspect::RecipeStep& s : e.recipe) {
        std::printf("  %d. %-14s %-12s %s\n", ++n, s.pass.c_str(),
                    s.target.empty() ? "-" : base::printable(s.target).c_str(), oneLine(s.what).c_str());
        if (s.readable)
            std::printf("       %s: colour %s%s\n", s.buffer.c_str(), triple(s.colour).c_str(),
                        s.stencil >= 0 ? (", stencil " + std::to_string(s.stencil)).c_str() : "");
    }
    if (const auto& l = e.lookup)
        std::printf(
            "  map lookup: the %s map of %s, %d², %s, texel (%d, %d), %s%s; reflected %s, looked up %s\n",
            l->layout.c_str(), base::quoted(l->reflector).c_str(), l->resolution, l->componentLabel.c_str(),
            l->texelX, l->texelY, l->filter.c_str(),
            l->filter == "sharp" ? "" : (", level " + std::to_string(l->mipLevel).substr(0, 4)).c_str(),
            triple(l->reflected).c_str(), triple(l->lookup).c_str());
}

void printText(const CliOptions& options, const render::FrameInput& input, const PixelExplanation& e,
               const std::string& renderer) {
    std::printf("Pixel %d,%d of %dx%d at t = %g s on %s\n\n", e.x, e.y, e.width, e.height, options.time,
                renderer.c_str());
    std::printf("  raster %s\n  exact  %s", triple(e.rasterColour, 4).c_str(),
                triple(e.exactColour, 4).c_str());
    if (e.exact.glossy)
        std::printf(" ± %.4f (standard error)", e.exactStandardError);
    std::printf("\n  error  %s in sRGB (RMS %.4f); %dx%d window: RMSE %.4f, PSNR %.2f dB\n",
                triple(e.error, 4).c_str(), e.errorRms, e.exact.windowWidth, e.exact.windowHeight,
                e.windowRmse, e.windowPsnr);
    std::printf("\nExact path (the ray through the pixel's centre):\n");
    int n = 0;
    for (const PathVertex& v : e.exact.centre.vertices)
        printVertex(input, ++n, v);
    if (!e.exact.samples.empty()) {
        std::printf("  %zu more sampled paths of the rough lobe bring:", e.exact.samples.size());
        for (const TracedPath& p : e.exact.samples)
            std::printf(" %s", triple(p.colour).c_str());
        std::printf("\n");
    }
    printRecipe(e);
    std::printf("\nWhy they differ:\n");
    if (e.causes.empty())
        std::printf("  (no cause the recipe knows)\n");
    for (const render::inspect::Cause& c : e.causes)
        std::printf("  %s: %s\n", c.code.c_str(), oneLine(c.text).c_str());
    for (const std::string& note : e.notes)
        std::printf("  note: %s\n", note.c_str());
}

} // namespace

int printPixelExplanation(const CliOptions& options, const render::FrameInput& input,
                          const render::StillResult& still,
                          const std::optional<glm::dvec3>& screenSpaceSource, const std::string& renderer) {
    auto tracer = render::reference::Tracer::create(input);
    if (!tracer) {
        printError("explain: " + tracer.error());
        return 1;
    }
    render::reference::TraceSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    auto paths = tracer->explainPixel(settings, options.pixel->x, options.pixel->y);
    if (!paths) {
        printError("explain: " + paths.error());
        return 1;
    }
    auto explained = render::inspect::explainPixel(input, still.firstSample, still.image, *paths, *tracer,
                                                   screenSpaceSource);
    if (!explained) {
        printError("explain: " + explained.error());
        return 1;
    }
    if (options.json)
        printJson(options, input, *explained, renderer);
    else
        printText(options, input, *explained, renderer);
    return 0;
}

} // namespace speculum::app
