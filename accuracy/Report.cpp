#include "accuracy/Report.hpp"

#include "accuracy/Analysis.hpp"
#include "accuracy/Plot.hpp"
#include "accuracy/ReportConvergence.hpp"
#include "accuracy/ReportEnergy.hpp"
#include "accuracy/ReportFlip.hpp"
#include "accuracy/ReportShards.hpp"
#include "base/AtomicFile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

namespace speculum::accuracy {

namespace {

const std::vector<Family> kFamilies = {Family::Envmap,          Family::Parallax, Family::MirrorTechnique,
                                       Family::MirrorDepth,     Family::Shadows,  Family::Tessellation,
                                       Family::ReflectedDetail, Family::Glossy,   Family::ScreenSpace,
                                       Family::Bounces,         Family::Update,   Family::Setting};

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string ms(double value) {
    return format(value < 10.0 ? "%.2f ms" : "%.1f ms", value);
}

std::string db(double value) {
    return format("%.2f dB", value);
}

std::string mib(std::size_t bytes) {
    return format("%.2f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
}

std::string familyTitle(Family family) {
    switch (family) {
    case Family::Envmap:
        return "Environment map: type, fill and resolution";
    case Family::Parallax:
        return "Parallax correction of the reflector";
    case Family::MirrorTechnique:
        return "Planar mirror technique";
    case Family::MirrorDepth:
        return "Planar mirror recursion depth";
    case Family::Shadows:
        return "Shadow filtering (PCF kernel)";
    case Family::Tessellation:
        return "Teapot tessellation";
    case Family::ReflectedDetail:
        return "Big meshes in reflections: whole or simplified";
    case Family::Glossy:
        return "Rough reflections: which approximation at which roughness";
    case Family::ScreenSpace:
        return "Screen-space reflections against the planar techniques and the map";
    case Family::Setting:
        return "Other settings";
    case Family::Bounces:
        return "Reflectors seeing each other: bounces";
    case Family::Update:
        return "Maps while the scene moves: redrawn every frame or time-sliced";
    default:
        return "The scene as saved";
    }
}

std::string familyIntro(Family family) {
    switch (family) {
    case Family::Envmap:
        return "Each map type (the cube; the dual paraboloid and the tennis ball, each filled directly "
               "through "
               "the vertex warp or resampled from a cube) at each resolution n, everything else as saved.";
    case Family::Parallax:
        return "The scene's map without and with parallax correction (the scene's own proxy, or a box around "
               "everything the map sees), at each resolution.";
    case Family::MirrorTechnique:
        return "Every planar mirror drawn with the stencil technique, then with the texture technique, then "
               "traced in the camera's image (screen space: what the image does not show reflects the "
               "background). The reference is the scene's own, rough mirrors included (a rough mirror is "
               "drawn with the texture technique unless it is traced in screen space).";
    case Family::MirrorDepth:
        return "settings.mirrorDepth from 1 up; the reference recurses 16 levels, so what a shallower depth "
               "cuts off counts as error.";
    case Family::Shadows:
        return "The PCF kernel of every shadowed light, against exact hard shadows: how close each kernel "
               "comes to the true shadow, aliasing and softening included.";
    case Family::Tessellation:
        return "The built-in teapots' tessellation, against a reference traced with them at tessellation "
               "64: the error of the coarser meshes' facets and silhouettes.";
    case Family::ReflectedDetail:
        return "Meshes of more than 100 000 triangles drawn whole in the mirrors' views and the reflector's "
               "map, then at their simplified level (settings.simplifyReflections), against the exact "
               "reflection of the whole meshes.";
    case Family::Glossy:
        return "Every rough surface at roughness 0.1, 0.3 and 0.6, each against its own traced reference "
               "(the GGX lobe integrated by importance sampling): the cheap filter (one mip level chosen by "
               "the roughness), then the footprint filter (planar mirrors sample the lobe's footprint, "
               "which grows with the distance beyond the mirror; the reflector reads its GGX pre-filtered "
               "map chain) at rising quality. Rows of one roughness compare with each other; the "
               "roughnesses are separate questions.";
    case Family::ScreenSpace:
        return "Every planar mirror traced in the camera's image (screen space), with each setting of the "
               "trace varied from its default (steps through the depth pyramid, the thickness a surface is "
               "taken to have, half resolution, and the background alone as the fallback where the scene "
               "has a reflector), beside the same mirrors drawn with the stencil and the texture technique; "
               "in a scene without mirrors, the reflector's map alone beside it traced in the image first "
               "(a cone when it is rough), at rising steps. The error maps show where tracing fails: what "
               "leaves the image, "
               "what hides behind an object, thin objects, mirrors seen in mirrors.";
    case Family::Setting:
        return "Each setting declared with values to sweep, one series per setting, each value against the "
               "scene's reference, everything else as saved.";
    case Family::Bounces:
        return "settings.reflectorBounces from 0 (each reflector's map shows the others with their plain "
               "material) up: each bounce draws every map again with the others' maps of the bounce "
               "before. The reference follows reflections between reflectors to depth 8, so what fewer "
               "bounces leave out counts as error, on the reflectors' pixels.";
    case Family::Update:
        return "The scene played for " + std::to_string(kPlayedFrames) +
               " frames 1/60 s apart, as the editor plays it, with every reflector's map redrawn every frame "
               "and then time-sliced (one face a frame in turn), against the scene where the frames end: "
               "the error a sliced map shows while something moves, and the time it saves. The time is a "
               "played frame's, the maps kept as their policy keeps them.";
    default:
        return {};
    }
}

// A family's rows with everything the report and the plot need to know about them.
struct FamilyView {
    Family family = Family::Scene;
    std::vector<const Record*> rows;
    Metric metric = Metric::Psnr;
    bool gpu = true;
    std::vector<Point> points;
    std::vector<std::size_t> front;
    std::size_t best = 0;
    std::optional<std::size_t> cheapest;
    std::optional<std::size_t> own;
    std::vector<std::string> series;                  // in order of first appearance
    std::optional<FlipView> flip;                     // none for records without perceptual figures
    const std::vector<FurnaceRow>* furnace = nullptr; // the run's white furnace, for the glossy family
};

FamilyView analyse(Family family, const std::vector<Record>& records) {
    FamilyView v;
    v.family = family;
    for (const Record& r : records)
        if (r.config.family == family)
            v.rows.push_back(&r);
    v.metric = judgedMetric(family, v.rows);
    v.gpu = allGpuTimed(v.rows);
    for (std::size_t i = 0; i < v.rows.size(); ++i) {
        const Record& r = *v.rows[i];
        v.points.push_back({costOf(r, v.gpu), focusValue(r, v.metric)});
        if (r.sceneSetting && !v.own)
            v.own = i;
        if (std::find(v.series.begin(), v.series.end(), r.config.series) == v.series.end())
            v.series.push_back(r.config.series);
        const Point& p = v.points.back();
        const Point& b = v.points[v.best];
        if (p.psnr > b.psnr || (p.psnr == b.psnr && p.cost < b.cost))
            v.best = i;
    }
    v.front = paretoFront(v.points);
    v.cheapest = cheapestWithin(v.points, 1.0);
    v.flip = analyseFlip(v.rows, v.points, v.metric);
    return v;
}

std::string costName(bool gpu) {
    return gpu ? "GPU" : "CPU";
}

PlotSpec plotOf(const FamilyView& v, const RunInfo& run) {
    PlotSpec spec;
    spec.title = familyTitle(v.family) + ": error against frame time";
    spec.subtitle = run.sceneName + " at " + std::to_string(run.width) + "x" + std::to_string(run.height) +
                    ", median of " + std::to_string(run.timedFrames) +
                    " rounds, every map re-rendered each frame";
    spec.xLabel = costName(v.gpu) + " time per frame (ms, lower is better)";
    spec.yLabel = metricAxisLabel(v.metric);
    spec.series = v.series;
    for (std::size_t i = 0; i < v.rows.size(); ++i) {
        const Record& r = *v.rows[i];
        PlotPoint pt;
        pt.x = v.points[i].cost;
        pt.y = v.points[i].psnr;
        pt.label = r.config.label;
        pt.series =
            static_cast<int>(std::find(v.series.begin(), v.series.end(), r.config.series) - v.series.begin());
        pt.sceneSetting = r.sceneSetting;
        spec.points.push_back(pt);
    }
    spec.front = v.front;
    return spec;
}

std::string describe(const FamilyView& v, std::size_t i) {
    const Record& r = *v.rows[i];
    return "**" + displayName(r.config) + "**: " + db(v.points[i].psnr) + " at " + ms(v.points[i].cost) +
           " " + costName(v.gpu) + ", " + mib(r.memory.total()) + " of render targets";
}

// The envmap family's cost of each map type at one error level: the best level every type reaches.
void equalError(std::ostringstream& md, const FamilyView& v) {
    std::vector<std::vector<Point>> series(v.series.size());
    std::vector<std::vector<std::size_t>> rowsOf(v.series.size());
    for (std::size_t i = 0; i < v.rows.size(); ++i) {
        const auto s = static_cast<std::size_t>(
            std::find(v.series.begin(), v.series.end(), v.rows[i]->config.series) - v.series.begin());
        series[s].push_back(v.points[i]);
        rowsOf[s].push_back(i);
    }
    const double target = commonTarget(series);
    md << "**Cost at equal error.** Every map type reaches " << db(target)
       << " on the reflector (the best the weakest type manages). What that error costs with each type "
          "(interpolated linearly in PSNR between the two resolutions around it; \"needs\" is the first "
          "swept "
          "resolution that reaches it):\n\n";
    md << "| map type | " << costName(v.gpu) << " time at " << db(target)
       << " | needs | its time | its memory |\n|---|---|---|---|---|\n";
    std::optional<double> cheapest;
    std::string cheapestName;
    for (std::size_t s = 0; s < series.size(); ++s) {
        const CostAtError at = costAtError(series[s], target);
        md << "| " << v.series[s] << " | ";
        if (!at.firstReaching) {
            md << "not reached | | | |\n";
            continue;
        }
        const std::size_t row = rowsOf[s][*at.firstReaching];
        const Record& r = *v.rows[row];
        md << ms(*at.interpolatedCost) << " | n = " << r.config.label << " | " << ms(v.points[row].cost)
           << " | " << mib(r.memory.total()) << " |\n";
        if (!cheapest || *at.interpolatedCost < *cheapest) {
            cheapest = *at.interpolatedCost;
            cheapestName = v.series[s];
        }
    }
    if (cheapest)
        md << "\nAt this error the cheapest map type is **" << cheapestName << "** (" << ms(*cheapest)
           << ").\n";
    md << "\n";
}

// The glossy family answers one question per roughness (its rows share that roughness's reference): which
// approximation to pick there, and what the cheap one gives up.
std::vector<std::string> glossyLines(const FamilyView& v) {
    std::vector<std::string> lines;
    std::vector<std::string> roughnesses; // "r 0.3", in order
    for (const Record* r : v.rows) {
        const std::string key = r->config.series.substr(0, r->config.series.find(' ', 2));
        if (std::find(roughnesses.begin(), roughnesses.end(), key) == roughnesses.end())
            roughnesses.push_back(key);
    }
    for (const std::string& key : roughnesses) {
        std::optional<std::size_t> best, mip;
        for (std::size_t i = 0; i < v.rows.size(); ++i) {
            if (v.rows[i]->config.series.rfind(key + " ", 0) != 0)
                continue;
            if (!best || v.points[i].psnr > v.points[*best].psnr)
                best = i;
            if (v.rows[i]->config.label == "mip")
                mip = i;
        }
        // The cheapest within 1 dB of the best is the one to pick.
        std::size_t pick = *best;
        for (std::size_t i = 0; i < v.rows.size(); ++i)
            if (v.rows[i]->config.series.rfind(key + " ", 0) == 0 &&
                v.points[i].psnr >= v.points[*best].psnr - 1.0 && v.points[i].cost < v.points[pick].cost)
                pick = i;
        std::string line = "At roughness " + key.substr(2) + ": pick **" + displayName(v.rows[pick]->config) +
                           "** (" + db(v.points[pick].psnr) + ", " + ms(v.points[pick].cost) + ")";
        if (mip && *mip != pick)
            line += "; the mip level scores " + db(v.points[*mip].psnr) + " at " + ms(v.points[*mip].cost);
        if (pick != *best)
            line += "; the best, " + displayName(v.rows[*best]->config) + ", gains only " +
                    db(v.points[*best].psnr - v.points[pick].psnr) + " more";
        if (v.furnace)
            if (std::optional<std::string> energy =
                    energyNote(*v.rows[pick], std::stod(key.substr(2)), *v.furnace))
                line += "; " + *energy;
        lines.push_back(line + ".");
    }
    return lines;
}

// Whether the best screen-space trace comes within 1 dB of the best planar technique, in words; for a
// reflector, what tracing it first gains over its map alone.
std::optional<std::string> screenSpaceAgainstPlanar(const FamilyView& v) {
    std::optional<std::size_t> planar, traced, map;
    for (std::size_t i = 0; i < v.rows.size(); ++i) {
        const std::string& series = v.rows[i]->config.series;
        std::optional<std::size_t>& best = series == "planar"          ? planar
                                           : series == "reflector map" ? map
                                                                       : traced;
        if (!best || v.points[i].psnr > v.points[*best].psnr)
            best = i;
    }
    if (map && traced) {
        const double gain = v.points[*traced].psnr - v.points[*map].psnr;
        return "Traced in screen space first, the reflector " +
               (gain >= 0.0 ? "gains " + db(gain) : "loses " + db(-gain)) + " over its map alone (" +
               displayName(v.rows[*traced]->config) + " " + db(v.points[*traced].psnr) + " at " +
               ms(v.points[*traced].cost) + ", the map alone " + db(v.points[*map].psnr) + " at " +
               ms(v.points[*map].cost) + "): what the image shows has no parallax error.";
    }
    if (!planar || !traced)
        return std::nullopt;
    const double gap = v.points[*planar].psnr - v.points[*traced].psnr;
    const std::string both = displayName(v.rows[*traced]->config) + " scores " + db(v.points[*traced].psnr) +
                             " at " + ms(v.points[*traced].cost) + ", " +
                             displayName(v.rows[*planar]->config) + " " + db(v.points[*planar].psnr) +
                             " at " + ms(v.points[*planar].cost);
    if (gap <= 1.0)
        return "Screen space is good enough here: at its best it comes within 1 dB of the planar technique "
               "(" +
               both + ").";
    return "Screen space is not good enough here: at its best it stays " + db(gap) +
           " below the planar technique (" + both +
           "); its error map shows what the camera's image does not hold.";
}

// Each bounce past the first row, in words: "a second bounce gains X dB on the reflectors for Y ms".
std::vector<std::string> bounceLines(const FamilyView& v) {
    static const char* const ordinal[] = {"first", "second", "third", "fourth", "fifth"};
    std::vector<std::string> lines;
    for (std::size_t i = 1; i < v.rows.size() && i <= 5; ++i) {
        const double gain = v.points[i].psnr - v.points[i - 1].psnr;
        lines.push_back(std::string("A ") + ordinal[i - 1] + " bounce " +
                        (gain >= 0.0 ? "gains " + db(gain) : "loses " + db(-gain)) +
                        " on the reflectors for " + ms(v.points[i].cost - v.points[i - 1].cost) + " (" +
                        describe(v, i) + ").");
    }
    return lines;
}

// What time-slicing the maps costs in error and saves in time, in words.
std::optional<std::string> updateLine(const FamilyView& v) {
    if (v.rows.size() != 2)
        return std::nullopt;
    const double loss = v.points[0].psnr - v.points[1].psnr;
    return "Time-sliced, the maps " + (loss >= 0.0 ? "lose " + db(loss) : "gain " + db(-loss)) +
           " on the reflectors while the scene moves and save " + ms(v.points[0].cost - v.points[1].cost) +
           " a frame (" + describe(v, 0) + "; " + describe(v, 1) + ").";
}

// What a family's sweep found, one sentence (or a few) per line, in Markdown.
std::vector<std::string> findingLines(const FamilyView& v, const std::string& note) {
    if (v.family == Family::Glossy)
        return glossyLines(v);
    std::vector<std::string> lines;
    if (v.family == Family::Bounces)
        lines = bounceLines(v);
    if (v.family == Family::Update)
        if (std::optional<std::string> line = updateLine(v))
            lines.push_back(*line);
    if (v.family == Family::ScreenSpace)
        if (std::optional<std::string> line = screenSpaceAgainstPlanar(v))
            lines.push_back(*line);
    lines.push_back("Best: " + describe(v, v.best) + tiedNote(*v.rows[v.best], v.rows) + ".");
    if (v.cheapest) {
        std::string line = "Cheapest within 1 dB of the best: " + describe(v, *v.cheapest);
        if (*v.cheapest != v.best) {
            const Record& c = *v.rows[*v.cheapest];
            const Record& b = *v.rows[v.best];
            line += " (" + ms(v.points[v.best].cost - v.points[*v.cheapest].cost) + " less";
            if (b.memory.total() > c.memory.total())
                line += ", " + mib(b.memory.total() - c.memory.total()) + " less memory";
            line += " than the best)";
        }
        lines.push_back(line + ".");
    }
    if (v.own)
        lines.push_back("The scene's own setting: " + describe(v, *v.own) + ".");
    if (v.front.size() >= 2) {
        std::string line = "Each step along the Pareto front (cheapest first): ";
        for (std::size_t k = 1; k < v.front.size(); ++k) {
            const std::size_t a = v.front[k - 1], b = v.front[k];
            line += (k > 1 ? "; " : "") + displayName(v.rows[a]->config) + " → " +
                    displayName(v.rows[b]->config) + " costs +" + ms(v.points[b].cost - v.points[a].cost) +
                    " for +" + db(v.points[b].psnr - v.points[a].psnr);
        }
        lines.push_back(line + ".");
    }
    const auto [low, high] = std::minmax_element(
        v.points.begin(), v.points.end(), [](const Point& a, const Point& b) { return a.psnr < b.psnr; });
    if (v.flip)
        for (std::string& line : flipLines(v.rows, *v.flip, {v.front, v.best, v.cheapest, costName(v.gpu)}))
            lines.push_back(std::move(line));
    if (v.rows.size() >= 2 && high->psnr - low->psnr < 1.0)
        lines.push_back(
            "Across this family the error changes by only " + db(high->psnr - low->psnr) +
            ": an error these settings do not touch dominates here (the error maps show where), so "
            "the cheapest setting loses almost nothing.");
    if (!note.empty())
        lines.push_back(note);
    return lines;
}

// "the **scene** reference", or each of a family's references in the order its rows use them.
std::string referenceList(const FamilyView& v) {
    std::vector<ReferenceKind> kinds;
    for (const Record* r : v.rows)
        if (std::find(kinds.begin(), kinds.end(), r->config.reference) == kinds.end())
            kinds.push_back(r->config.reference);
    std::string list;
    for (std::size_t i = 0; i < kinds.size(); ++i)
        list += std::string(i == 0                  ? ""
                            : i + 1 == kinds.size() ? " and "
                                                    : ", ") +
                "**" + referenceName(kinds[i]) + "**";
    return list + (kinds.size() == 1 ? " reference" : " references");
}

void familySection(std::ostringstream& md, const FamilyView& v, const std::string& note) {
    const std::string plot = "plot-" + familyName(v.family) + ".png";
    md << "## " << familyTitle(v.family) << "\n\n"
       << familyIntro(v.family) << " Judged by "
       << metricAxisLabel(v.metric).substr(0, metricAxisLabel(v.metric).find(" (")) << " against the "
       << referenceList(v) << ".\n\n";
    if (v.rows.size() >= 2)
        md << "![" << familyTitle(v.family) << "](" << plot << ")\n\n";
    if (v.rows.size() >= 2 && v.flip)
        md << "![" << familyTitle(v.family) << " by FLIP](plot-" << familyName(v.family) << "-flip.png)\n\n";
    for (const std::string& line : findingLines(v, note))
        md << "- " << line << "\n";
    md << "\n";
    if (v.family == Family::Envmap && v.series.size() >= 2)
        equalError(md, v);
    md << "| setting | " << costName(v.gpu)
       << " ms | CPU ms | memory | PSNR | PSNR 95 % | PSNR mirrors | PSNR reflector | MAE | rel. MSE | SSIM |"
       << " FLIP | FLIP (judged) | HDR-FLIP | error map | FLIP map |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Record* r : v.rows) {
        auto perceptual = [&](const char* pattern, double value) {
            return r->perceptual ? format(pattern, value) : std::string("–");
        };
        const std::optional<double> judged = focusFlip(*r, v.metric);
        md << "| " << displayName(r->config) << (r->sceneSetting ? " (scene)" : "") << " | "
           << format("%.2f", costOf(*r, v.gpu)) << " | " << format("%.2f", r->cpuMs) << " | "
           << mib(r->memory.total()) << " | " << format("%.2f", r->psnr) << " | "
           << (r->perceptual ? format("%.2f", r->psnrLow) + "–" + format("%.2f", r->psnrHigh) : "–") << " | "
           << (r->psnrMirrors ? format("%.2f", *r->psnrMirrors) : "–") << " | "
           << (r->psnrReflector ? format("%.2f", *r->psnrReflector) : "–") << " | "
           << perceptual("%.4f", r->mae) << " | " << perceptual("%.4f", r->relativeMse) << " | "
           << perceptual("%.4f", r->ssim) << " | " << perceptual("%.4f", r->flip) << " | "
           << (judged ? format("%.4f", *judged) : "–") << " | " << perceptual("%.4f", r->hdrFlip)
           << " | [map](" << r->errorMap << ") | "
           << (r->perceptual ? "[FLIP](" + r->flipMap + ")" : std::string("–")) << " |\n";
    }
    md << "\n";
}

// When parallax correction gains more than resolution does, resolution is not what limits the reflector:
// worth saying next to the map sweep, whose flat curves would otherwise puzzle.
std::string parallaxNote(const std::vector<FamilyView>& views) {
    const FamilyView* envmap = nullptr;
    const FamilyView* parallax = nullptr;
    for (const FamilyView& v : views) {
        envmap = v.family == Family::Envmap ? &v : envmap;
        parallax = v.family == Family::Parallax ? &v : parallax;
    }
    if (!envmap || !parallax || !envmap->own || !parallax->own)
        return {};
    const std::string ownSeries = envmap->rows[*envmap->own]->config.series;
    double low = 1e300, high = -1e300;
    for (std::size_t i = 0; i < envmap->rows.size(); ++i)
        if (envmap->rows[i]->config.series == ownSeries) {
            low = std::min(low, envmap->points[i].psnr);
            high = std::max(high, envmap->points[i].psnr);
        }
    const double gain = parallax->points[parallax->best].psnr - parallax->points[*parallax->own].psnr;
    if (gain <= 2.0 * (high - low) || gain < 1.0)
        return {};
    return "Resolution moves the scene's map type (" + ownSeries + ") by only " + db(high - low) +
           " here, while parallax correction gains " + db(gain) +
           " (next section): looking the map up from its centre, not from the surface, is the error that "
           "dominates, so more texels buy little until it is corrected.";
}

std::vector<FamilyView> analyseAll(const std::vector<Record>& records,
                                   const std::vector<FurnaceRow>& furnace) {
    std::vector<FamilyView> views;
    for (Family f : kFamilies)
        if (FamilyView v = analyse(f, records); !v.rows.empty()) {
            v.furnace = furnace.empty() ? nullptr : &furnace;
            views.push_back(std::move(v));
        }
    return views;
}

} // namespace

std::vector<FamilyFindings> findings(const std::vector<Record>& records,
                                     const std::vector<FurnaceRow>& furnace) {
    const std::vector<FamilyView> views = analyseAll(records, furnace);
    std::vector<FamilyFindings> out;
    for (const FamilyView& v : views)
        out.push_back({v.family, familyTitle(v.family),
                       metricAxisLabel(v.metric).substr(0, metricAxisLabel(v.metric).find(" (")),
                       findingLines(v, v.family == Family::Envmap ? parallaxNote(views) : std::string())});
    return out;
}

std::string displayName(const Configuration& c) {
    switch (c.family) {
    case Family::Envmap:
    case Family::Parallax:
        return c.series + " " + c.label;
    case Family::Glossy:
        return c.label == "mip" ? c.series : c.series + " " + c.label;
    case Family::Tessellation:
        return "tessellation " + c.label;
    default:
        return c.label;
    }
}

namespace {

// One plot per family with two points or more (PSNR, and FLIP where measured), and the convergence plot.
base::Status writePlots(const std::filesystem::path& folder, const RunInfo& run,
                        const std::vector<FamilyView>& views) {
    for (const FamilyView& v : views)
        if (v.rows.size() >= 2) {
            const std::string plot = (folder / ("plot-" + familyName(v.family) + ".png")).string();
            const PlotSpec spec = plotOf(v, run);
            if (base::Status s = writePlot(plot, spec); !s)
                return s;
            const std::string flip = (folder / ("plot-" + familyName(v.family) + "-flip.png")).string();
            if (v.flip)
                if (base::Status s = writePlot(flip, flipPlot(spec, *v.flip, v.metric)); !s)
                    return s;
        }

    if (run.convergence && !run.convergence->points.empty())
        if (base::Status s =
                writePlot((folder / "plot-convergence.png").string(), convergencePlot(*run.convergence, run));
            !s)
            return s;

    return base::Done{};
}

// The heading and what the figures are.
void introduction(std::ostringstream& md, const RunInfo& run) {
    md << "# speculum bench: " << run.sceneName << "\n\n";
    md << "Frame " << run.width << "x" << run.height << " of `" << run.scene << "` on " << run.renderer
       << ". " << (run.quick ? "Quick sweep. " : "") << "Times are medians over " << run.timedFrames
       << " rounds; each round renders every distinct configuration once, after one untimed frame that "
          "absorbs the switch, so load from other processes spreads over all configurations alike (still, "
          "compare times within one run, not across runs on a busy machine). Every frame renders all of its "
          "shadow and environment maps again, so the times are what the settings cost an animated scene (a "
          "static one reuses them). "
          "GPU time is the sum of the passes' timer queries, CPU time the renderer's own clock for the "
          "frame. "
          "Memory counts the render targets the frame uses (colour and depth buffers, reflection textures, "
          "shadow maps, the environment map with its mip chain), from their sizes and formats. Errors are "
          "measured on sRGB values, as a viewer sees them; PSNR has a peak of 1. Beside PSNR: MAE (mean "
          "absolute "
          "error of the sRGB values), relative MSE (on linear values, (test − exact)² / (exact² + 0.01)), "
          "SSIM "
          "(1 for identical images), and FLIP (0 to 1: what a viewer flipping between the two images would "
          "notice, LDR-FLIP on the displayed values and HDR-FLIP on the linear ones, seen at 67 pixels per "
          "degree). One just-noticeable difference (JND) is a FLIP of "
       << format("%.3f", flipJnd())
       << ", what a uniform colour difference of ΔE*ab 2.3 scores. The exact images of rough surfaces are "
          "averages of random paths, so they carry noise: PSNR 95 % is the interval that noise leaves on the "
          "PSNR, and two settings whose difference is smaller than the noise can tell apart are called tied, "
          "not ranked.\n\n";
}

// The references and the tracer's time against the rasterizer's.
void referencesSection(std::ostringstream& md, const RunInfo& run, const std::vector<Record>& records) {
    const Record* scene = nullptr;
    for (const Record& r : records)
        if (r.config.family == Family::Scene)
            scene = &r;
    md << "## References\n\nEvery configuration is compared with an exact ray-traced image of the same "
          "frame, "
          "traced once per run at the same size with one sample per pixel (so edges alias alike in both). "
          "The "
          "tracer does not depend on map type, resolution, fill, parallax or mirror technique, so those "
          "share the scene's reference; the settings it does depend on get their own:\n\n";
    md << "| reference | what it is | traced in | image |\n|---|---|---|---|\n";
    for (const ReferenceInfo& ref : run.references)
        md << "| " << referenceName(ref.kind) << " | " << referenceDescription(ref.kind) << " | "
           << ms(ref.traceMs) << " (" << ref.threads << " threads) | [" << ref.image << "](" << ref.image
           << ") |\n";
    md << "\n";
    for (const ReferenceInfo& ref : run.references)
        if (ref.kind == ReferenceKind::Scene && scene) {
            const bool gpu = scene->gpuMs >= 0.0;
            const double raster = gpu ? scene->gpuMs : scene->cpuMs;
            const double ratio = ref.traceMs / std::max(raster, 1e-3);
            md << "**The tracer's time for the same frame:** " << ms(ref.traceMs) << " on " << ref.threads
               << " CPU threads, " << format(ratio < 10.0 ? "%.1f" : "%.0f", ratio)
               << " times the rasterizer's " << ms(raster) << " (" << costName(gpu)
               << ") with the scene's own settings, which come within " << db(scene->psnr)
               << " PSNR of it over the whole frame";
            if (scene->psnrReflector)
                md << " (" << db(*scene->psnrReflector) << " on the reflector)";
            if (scene->psnrMirrors)
                md << " (" << db(*scene->psnrMirrors) << " on the mirrors)";
            md << ".\n\n";
        }
}

// One row per family: its judge, the scene's setting, the best and the cheap picks.
void summarySection(std::ostringstream& md, const std::vector<FamilyView>& views) {
    md << "## Summary\n\n| family | judged by | scene's own setting | best | cheapest within 1 dB of the "
          "best | cheapest within one JND (FLIP) |\n"
          "|---|---|---|---|---|---|\n";
    for (const FamilyView& v : views) {
        auto cell = [&](std::optional<std::size_t> i) {
            if (!i)
                return std::string("–");
            return displayName(v.rows[*i]->config) + ": " + db(v.points[*i].psnr) + ", " +
                   ms(v.points[*i].cost);
        };
        std::string jnd = "–";
        if (v.flip && v.flip->cheapest)
            jnd = displayName(v.rows[*v.flip->cheapest]->config) + ": FLIP " +
                  format("%.4f", -v.flip->points[*v.flip->cheapest].psnr) + ", " +
                  ms(v.flip->points[*v.flip->cheapest].cost);
        md << "| " << familyName(v.family) << " | " << metricField(v.metric) << " | " << cell(v.own) << " | "
           << cell(v.best) << " | " << cell(v.cheapest) << " | " << jnd << " |\n";
    }
    if (views.empty())
        md << "| – | | | | | |\n\nThe scene has nothing to sweep: no curved reflector, no planar mirror, no "
              "shadowed light and no built-in teapot.\n";
    md << "\n";
}

} // namespace

base::Status writeReport(const std::filesystem::path& folder, const RunInfo& run,
                         const std::vector<Record>& records) {
    const std::vector<FamilyView> views = analyseAll(records, run.furnace);
    if (base::Status plotted = writePlots(folder, run, views); !plotted)
        return plotted;

    std::ostringstream md;
    introduction(md, run);
    referencesSection(md, run, records);
    summarySection(md, views);
    for (const FamilyView& v : views)
        familySection(md, v, v.family == Family::Envmap ? parallaxNote(views) : std::string());

    furnaceSection(md, run.furnace);
    if (run.convergence)
        convergenceSection(md, *run.convergence);
    shardsSection(md, run, records);
    md << "## Files\n\n`results.csv` and `results.json` hold one record per configuration (the same fields); "
          "`render.png` is the frame with the scene's own settings; `reference*.png` the exact images; "
          "`errors/<id>.png` the error map of each configuration (per-pixel error on a fixed scale: black "
          "none, pale yellow a quarter of the sRGB range or more); `flip/<id>.png` its FLIP map (magma: "
          "black "
          "none, pale yellow 1); `plot-<family>-flip.png` each family's FLIP against frame time.\n";

    const std::filesystem::path path = folder / "report.md";
    // Staged and checked (base::AtomicFile): a full disk is an error, never a truncated report.
    return base::writeFileAtomically(path.string(), md.str());
}

} // namespace speculum::accuracy
