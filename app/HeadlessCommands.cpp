#include "app/HeadlessCommands.hpp"

#include "app/AnimationCommand.hpp"
#include "app/BenchCommand.hpp"
#include "app/Interrupt.hpp"
#include "app/OutputPaths.hpp"
#include "app/PixelCommand.hpp"
#include "app/Progress.hpp"
#include "app/ProjectInput.hpp"
#include "base/Printable.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/plan/FrameReport.hpp"
#include "render/plan/Planner.hpp"
#include "render/reference/Tracer.hpp"
#include "render/renderer/Renderer.hpp"
#include "render/renderer/StillRenderer.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/export/GltfExport.hpp"
#include "scene/export/StillExport.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

namespace speculum::app {

namespace {

using Clock = std::chrono::steady_clock;

void fail(const std::string& message) {
    printError(message);
}

MissingFiles policyOf(const CliOptions& options) {
    if (options.command == Command::Explain)
        return MissingFiles::Report; // explain lists what the frame lacks; it is how one finds out
    return options.keepGoing ? MissingFiles::KeepGoing : MissingFiles::Fail;
}

std::string commandName(const CliOptions& options) {
    return commandWord(options.command);
}

// Skips that drop something the scene asks for are warnings (render::dropsWhatTheSceneAsks); the frame
// working as meant, or the scene's own settings, are not. Lights past kMaxLights are said once by
// lightDrops.
bool expectedSkip(render::PlanReason code) {
    return !render::dropsWhatTheSceneAsks(code) || code == render::PlanReason::LightLimit;
}

// What kind of node a plan's target names, for "mirror 'M': skipped: ...".
std::string targetLabel(const render::FrameInput& input, const std::string& target) {
    for (const render::Mirror& m : input.mirrors)
        if (m.name == target)
            return "mirror " + base::quoted(target);
    for (const render::Light& l : input.lights)
        if (l.name == target)
            return "light " + base::quoted(target);
    for (const render::Reflector& r : input.reflectors)
        if (r.name == target)
            return "reflector " + base::quoted(target);
    return base::quoted(target);
}

// Lights past the ones drawn: the rasterizer and the tracer both light with the first kMaxLights.
std::vector<std::string> lightDrops(const render::FrameInput& input) {
    std::vector<std::string> drops;
    for (std::size_t i = render::kMaxLights; i < input.lights.size(); ++i) {
        const std::string& name = input.lights[i].name;
        drops.push_back("light " + (name.empty() ? "#" + std::to_string(i + 1) : base::quoted(name)) +
                        " ignored: at most " + std::to_string(render::kMaxLights) + " lights are drawn");
    }
    return drops;
}

// Every drop a rendered frame made, as warnings: lights beyond the limit and each unexpected skip, the
// plan's and those found while running it.
std::vector<std::string> frameDrops(const render::FrameInput& input, const render::FrameReport& report) {
    std::vector<std::string> drops = lightDrops(input);
    for (const render::SkippedEffect& s : report.skipped) {
        if (expectedSkip(s.code))
            continue;
        drops.push_back((s.target.empty() ? std::string("frame") : targetLabel(input, s.target)) +
                        ": skipped: " + base::printable(s.reason(), 400));
    }
    return drops;
}

std::string absoluteText(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    return ec ? path : absolute.string();
}

// Everything a headless command needs: the scene snapshot and a renderer on an EGL context.
struct HeadlessFrame {
    std::unique_ptr<render::gl::HeadlessContext> context;
    std::unique_ptr<render::Renderer> renderer;
    render::FrameInput input;
    std::string glDescription;
    // The project itself, for `explain --animated`, which evaluates it at each frame's time.
    std::unique_ptr<ProjectFrame> project;
};

// Loads the project and evaluates it at options.time; no GL needed. A missing model or texture is an
// error unless --keep-going (explain: reported by the frame). For a command that writes, the output is
// then checked against every file the project reads, before any rendering.
base::Result<ProjectFrame> loadProject(const CliOptions& options) {
    auto frame = loadProjectFrame(options.project, options.time, policyOf(options));
    if (!frame)
        return base::Error{commandName(options) + ": " + frame.error()};
    if (!options.output.empty())
        if (base::Status distinct = checkNotAnInput(options.output, frame->inputs); !distinct)
            return base::Error{commandName(options) + ": " + distinct.error()};
    return frame;
}

base::Result<render::FrameInput> loadFrameInput(const CliOptions& options) {
    auto project = loadProject(options);
    if (!project)
        return base::Error{project.error()};
    return std::move(project->input);
}

base::Result<HeadlessFrame> prepare(const CliOptions& options) {
    auto project = loadProject(options);
    if (!project)
        return base::Error{project.error()};
    HeadlessFrame frame;
    frame.input = std::move(project->input);
    if (options.animated)
        frame.project = std::make_unique<ProjectFrame>(std::move(*project));
    auto context = render::gl::HeadlessContext::create();
    if (!context)
        return base::Error{"no OpenGL: " + context.error()};
    frame.context = std::move(*context);
    frame.glDescription = frame.context->description();
    auto renderer = render::Renderer::create();
    if (!renderer)
        return base::Error{renderer.error()};
    frame.renderer = std::move(*renderer);
    warnAsPlanned(*frame.renderer);
    return frame;
}

std::string sizeText(int w, int h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

// What the Monte Carlo part of a reference render left: the noise of its rough reflections, in linear
// radiance (the root mean square of the pixels' standard errors).
std::string noiseLine(const render::Image& image, const scene::TraceFigures& trace) {
    std::ostringstream line;
    line << "reference: " << image.width << "\u00d7" << image.height << ", " << trace.paths
         << (trace.paths == 1 ? " path" : " paths") << " per glossy pixel (" << trace.glossyPixels
         << (trace.glossyPixels == 1 ? " pixel), " : " pixels), ");
    if (trace.glossyPixels == 0)
        line << "exact (no rough reflections)";
    else if (std::isnan(trace.noiseRms))
        line << "noise not estimated (one path has no spread)";
    else
        line << "noise " << std::setprecision(2) << trace.noiseRms << " RMS standard error";
    return line.str();
}

// Checks the output before any work: an unsupported format, a missing folder, the project itself or a
// size the format cannot hold cost nothing.
base::Status checkRenderOutput(const CliOptions& options) {
    if (!render::isSupportedImagePath(options.output))
        return base::Error{base::quoted(options.output) +
                           ": unsupported image format (supported: " + render::supportedImageFormats() + ")"};
    if (base::Status where = checkOutputFile(options.output); !where)
        return base::Error{"render: " + where.error()};
    // The project itself before it is read; the models and textures it names once it is loaded.
    if (base::Status distinct = checkNotAnInput(options.output, {options.project}); !distinct)
        return base::Error{"render: " + distinct.error()};
    return render::checkImageTarget(options.output, options.width, options.height);
}

scene::StillExportSettings stillSettings(const CliOptions& options) {
    scene::StillExportSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.ssaa = options.ssaa;
    settings.time = options.time;
    settings.reference = options.reference;
    settings.samples = options.samples;
    settings.screenSpaceSources = options.screenSpaceSources;
    return settings;
}

// ---- explain: the frame, then its passes as JSON (--json) or as a table ----

// The scene time of the explained frame: --time, or with --animated the Nth frame's, 1/60 s apart.
double explainedTime(const CliOptions& options) {
    return options.animated ? options.time + (options.frame - 1) * kAnimationFrameStep : options.time;
}

// Renders the frame `explain` describes, offscreen at the requested size. The frames before it (--frame N
// explains the Nth) warm the renderer's caches exactly as a live viewport would; with --animated each is
// the scene at its own time, as the playing editor draws it.
base::Result<render::StillResult> renderExplainedFrame(HeadlessFrame& frame, const CliOptions& options) {
    // In one piece whenever the GPU can: a tile's plan holds only the passes that draw in that tile.
    render::StillSettings settings{options.width, options.height, 1, render::maxStillSize()};
    settings.preview = options.preview;
    const auto untilStopped = [](double, const std::string&) { return !StopOnSignal::requested(); };
    for (int number = 1; number <= options.frame; ++number) {
        if (frame.project && number > 1) {
            std::vector<scene::Warning> repeated; // the first frame's warnings were reported already
            frame.input =
                scene::snapshot(*frame.project->scene, options.time + (number - 1) * kAnimationFrameStep,
                                *frame.project->meshes, repeated);
            useCheckedTextures(frame.input, frame.project->textures);
        }
        // Only the explained frame reads its pixel back after each pass.
        settings.probePixel = number == options.frame ? options.pixel : std::nullopt;
        auto drawn = render::renderStill(*frame.renderer, frame.input, settings, untilStopped);
        if (!drawn || number == options.frame)
            return drawn;
    }
    return base::Error{"explain: no frame to explain"}; // --frame is at least 1
}

QString jsonText(std::string_view name) {
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

QString kindText(render::PassKind kind) {
    return jsonText(render::toString(kind));
}

// The reason's code as explain's JSON names it ("mirror-outside-view").
QString codeText(render::PlanReason code) {
    return jsonText(render::toString(code));
}

QJsonArray passesJson(const render::FrameReport& report) {
    QJsonArray passes;
    for (const render::PassRun& run : report.ran) {
        const render::PlannedPass& p = report.planned(run);
        QJsonObject o;
        o["kind"] = kindText(p.kind);
        o["target"] = QString::fromStdString(p.target);
        o["reason"] = QString::fromStdString(report.reason(run));
        o["code"] = codeText(p.code);
        if (p.kind == render::PassKind::Envmap)
            o["bounce"] = p.details.bounce;
        o["gpuMs"] = run.gpuMs;
        o["cpuMs"] = run.cpuMs;
        passes.append(o);
    }
    return passes;
}

QJsonArray skippedJson(const std::vector<render::SkippedEffect>& skipped) {
    QJsonArray array;
    for (const render::SkippedEffect& s : skipped)
        array.append(QJsonObject{{"target", QString::fromStdString(s.target)},
                                 {"reason", QString::fromStdString(s.reason())},
                                 {"code", codeText(s.code)}});
    return array;
}

// What the environment pass drew inside the map: the mirror views of each face, with reasons.
QJsonObject envmapJson(const render::EnvmapPlan& map) {
    auto faceLabel = [&](int face) {
        return face >= 0 ? QString::fromStdString(map.faces[static_cast<std::size_t>(face)].label)
                         : QString("every face");
    };
    QJsonArray faces, mapPasses, mapSkipped;
    for (const render::EnvmapFace& f : map.faces)
        faces.append(QString::fromStdString(f.label));
    for (const render::PlannedPass& p : map.passes) {
        const render::MirrorView& view = map.views[static_cast<std::size_t>(p.view)];
        mapPasses.append(QJsonObject{{"kind", kindText(p.kind)},
                                     {"target", QString::fromStdString(p.target)},
                                     {"reason", QString::fromStdString(p.reason())},
                                     {"code", codeText(p.code)},
                                     {"face", faceLabel(view.face)},
                                     {"depth", view.depth}});
    }
    for (const render::SkippedEffect& s : map.skipped)
        mapSkipped.append(QJsonObject{{"target", QString::fromStdString(s.target)},
                                      {"reason", QString::fromStdString(s.reason())},
                                      {"code", codeText(s.code)},
                                      {"face", faceLabel(s.face)}});
    return QJsonObject{{"target", QString::fromStdString(map.target)},
                       {"bounce", map.bounce},
                       {"faces", faces},
                       {"passes", mapPasses},
                       {"skipped", mapSkipped}};
}

// `drawnEnvmaps`: the plans of the environment maps whose passes ran this frame, in their order.
// "envmapMirrors" holds the first (null when none ran), "envmaps" all of them.
void printExplanationJson(const CliOptions& options, const HeadlessFrame& frame,
                          const render::StillResult& still,
                          const std::vector<const render::EnvmapPlan*>& drawnEnvmaps) {
    const render::FrameReport& report = still.firstSample;
    QJsonArray warnings;
    for (const std::string& w : report.warnings)
        warnings.append(QString::fromStdString(w));
    QJsonValue envmap; // null when no map was drawn this frame
    QJsonArray envmaps;
    for (const render::EnvmapPlan* map : drawnEnvmaps)
        envmaps.append(envmapJson(*map));
    if (!drawnEnvmaps.empty())
        envmap = envmaps.first();
    QJsonValue preview; // null for a frame at rest
    if (options.preview.active())
        preview = QJsonObject{
            {"scale", options.preview.scale},
            {"mirrorDepthCut", options.preview.mirrorDepthCut},
            {"drag", options.preview.redrawsShadows},
            {"drawnSize", QString::fromStdString(sizeText(report.drawnWidth, report.drawnHeight))}};
    QJsonObject root{{"passes", passesJson(report)},
                     {"envmapMirrors", envmap},
                     {"envmaps", envmaps},
                     {"skipped", skippedJson(report.skipped)},
                     {"warnings", warnings},
                     {"size", QString::fromStdString(sizeText(options.width, options.height))},
                     {"time", options.time},
                     {"frame", options.frame},
                     {"animated", options.animated},
                     {"frameTime", explainedTime(options)},
                     {"preview", preview},
                     {"tiles", still.tiles},
                     {"frameGpuMs", report.gpuMs},
                     {"frameCpuMs", report.cpuMs},
                     {"renderer", QString::fromStdString(frame.glDescription)}};
    std::cout << QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
}

// The passes the environment pass drew inside the map, and what it skipped there; nothing when it drew
// and skipped nothing.
void printEnvmapPasses(const render::EnvmapPlan& map) {
    if (map.passes.empty() && map.skipped.empty())
        return;
    std::printf("\nInside the environment map of %s (drawn by its envmap pass%s):\n",
                base::printable(map.target).c_str(),
                map.bounce > 0 ? (", bounce " + std::to_string(map.bounce)).c_str() : "");
    for (const render::PlannedPass& p : map.passes) {
        const std::string kind(render::toString(p.kind));
        std::printf("  %-11s %-14s %s\n", kind.c_str(), base::printable(p.target).c_str(),
                    oneLine(p.reason()).c_str());
    }
    for (const render::SkippedEffect& s : map.skipped)
        std::printf("  %-11s %-14s %s\n", "skipped", base::printable(s.target).c_str(),
                    oneLine(s.reason()).c_str());
}

void printExplanationText(const CliOptions& options, const HeadlessFrame& frame,
                          const render::StillResult& still,
                          const std::vector<const render::EnvmapPlan*>& drawnEnvmaps) {
    const render::FrameReport& report = still.firstSample;
    std::printf("Frame %s at t = %g s on %s\n\n", sizeText(options.width, options.height).c_str(),
                explainedTime(options), frame.glDescription.c_str());
    if (options.animated && options.frame > 1)
        std::printf("The last of %d frames played 1/60 s apart from t = %g s.\n\n", options.frame,
                    options.time);
    if (still.tiles > 1)
        std::printf("Larger than this GPU renders in one piece: the passes of the first of %d tiles.\n\n",
                    still.tiles);
    else if (options.preview.active())
        std::printf(
            "A preview%s, drawn at %s: what it gives up is skipped, with reasons starting \"preview:\".\n\n",
            options.preview.redrawsShadows ? " while a handle is dragged" : " while the view moves",
            sizeText(report.drawnWidth, report.drawnHeight).c_str());
    std::printf("Passes (in order):\n");
    for (const render::PassRun& run : report.ran) {
        const render::PlannedPass& p = report.planned(run);
        const std::string kind(render::toString(p.kind));
        std::printf("  %-11s %-14s gpu %7.2f ms  cpu %7.2f ms  %s\n", kind.c_str(),
                    p.target.empty() ? "-" : base::printable(p.target).c_str(), run.gpuMs, run.cpuMs,
                    oneLine(report.reason(run)).c_str());
    }
    for (const render::EnvmapPlan* map : drawnEnvmaps)
        printEnvmapPasses(*map);
    std::printf("\nSkipped:\n");
    if (report.skipped.empty())
        std::printf("  (nothing)\n");
    for (const render::SkippedEffect& s : report.skipped)
        std::printf("  %-14s %s\n", s.target.empty() ? "-" : base::printable(s.target).c_str(),
                    oneLine(s.reason()).c_str());
    // What the frame could not do as the scene asks (a map larger than the GPU holds, a missing texture).
    if (!report.warnings.empty()) {
        std::printf("\nWarnings:\n");
        for (const std::string& w : report.warnings)
            std::printf("  %s\n", oneLine(w).c_str());
    }
    std::printf("\nTotal: gpu %.2f ms, cpu %.2f ms\n", report.gpuMs, report.cpuMs);
}

} // namespace

// The still through scene::writeStill, the path the editor's Export Still takes too: rasterized on an EGL
// context, or traced by the exact tracer on the CPU (no GL) with --reference.
int runRender(const CliOptions& options) {
    if (options.frameRange)
        return runAnimation(options);
    const auto start = Clock::now();
    if (base::Status output = checkRenderOutput(options); !output) {
        fail(output.error());
        return 1;
    }
    std::optional<HeadlessFrame> frame;
    render::FrameInput input;
    if (options.reference) {
        auto loaded = loadFrameInput(options);
        if (!loaded) {
            fail(loaded.error());
            return 1;
        }
        input = std::move(*loaded);
    } else {
        auto prepared = prepare(options);
        if (!prepared) {
            fail(prepared.error());
            return 1;
        }
        frame = std::move(*prepared);
        input = frame->input;
    }
    // Progress on stderr for renders that take a while: every sample when supersampling.
    const int samples = options.ssaa * options.ssaa;
    Progress progress(options.reference ? "tracing" : "rendering");
    const auto report = [&](double fraction, const std::string& stage) {
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        if (seconds > (options.reference ? 0.5 : 1.0) || (!options.reference && samples > 1))
            progress.update(fraction, options.reference ? std::string() : stage);
        return !StopOnSignal::requested(); // a stop ends the render here, before anything is written
    };
    auto still = scene::writeStill(frame ? frame->renderer.get() : nullptr, input,
                                   absoluteText(options.project), stillSettings(options), options.output,
                                   report, frame ? frame->glDescription : std::string());
    progress.finish();
    if (!still && StopOnSignal::requested())
        return interrupted("render");
    if (!still) {
        fail("render: " + still.error());
        return 1;
    }
    printWarnings(options.reference ? lightDrops(input) : frameDrops(input, still->still.firstSample));
    printWarnings(still->warnings);
    if (!Progress::quiet())
        std::cerr << "speculum: " << (options.reference ? "traced " : "rendered ")
                  << sizeText(options.width, options.height) << " with " << still->still.samples
                  << (still->still.samples == 1 ? " sample" : " samples") << " per pixel in "
                  << static_cast<int>(still->still.totalMs + 0.5) << " ms\n";
    std::cout << base::printable(options.output, 4096) << "\n";
    if (still->trace)
        std::cout << noiseLine(still->still.image, *still->trace) << "\n";
    return 0;
}

int runExplain(const CliOptions& options) {
    auto frame = prepare(options);
    if (!frame) {
        fail(frame.error());
        return 1;
    }
    // Explain what a frame at this size really does: render it offscreen and report its timings.
    auto still = renderExplainedFrame(*frame, options);
    if (StopOnSignal::requested())
        return interrupted("explain", "nothing was printed");
    if (!still) {
        fail("explain: " + still.error());
        return 1;
    }
    if (options.pixel) {
        const render::StillSettings size{options.width, options.height, 1, render::maxStillSize()};
        const auto source = render::screenSpaceSourceAt(*frame->renderer, frame->input, size, *options.pixel);
        if (!source) {
            fail("explain: " + source.error());
            return 1;
        }
        return printPixelExplanation(options, frame->input, *still, *source, frame->glDescription);
    }
    const render::FrameReport& report = still->firstSample;
    // A map's mirrors are those its envmap pass drew: none when the pass did not run (no map could be
    // allocated), though the plan still holds them.
    std::vector<const render::EnvmapPlan*> drawnEnvmaps;
    for (const render::PassRun& run : report.ran) {
        const render::PlannedPass& p = report.planned(run);
        if (p.kind == render::PassKind::Envmap && p.envmap >= 0 &&
            static_cast<std::size_t>(p.envmap) < report.plan.envmaps.size())
            drawnEnvmaps.push_back(&report.plan.envmaps[static_cast<std::size_t>(p.envmap)]);
    }
    if (options.json)
        printExplanationJson(options, *frame, *still, drawnEnvmaps);
    else
        printExplanationText(options, *frame, *still, drawnEnvmaps);
    return 0;
}

int runExport(const CliOptions& options) {
    // The output name and folder first: a bad target costs no loading.
    const std::filesystem::path out(options.output);
    std::string extension = out.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".glb" && extension != ".gltf") {
        fail(base::quoted(options.output) + ": unsupported export format (supported: .glb, .gltf)");
        return 1;
    }
    if (base::Status where = checkOutputFile(options.output); !where) {
        fail("export: " + where.error());
        return 1;
    }
    // A .gltf writes its buffer and images beside it: "OUT.bin", "OUT_0.png", ...
    std::vector<std::string> companions;
    if (extension == ".gltf") {
        const std::filesystem::path stem = out.parent_path() / out.stem();
        companions = {stem.string() + ".bin", stem.string() + "_"};
    }
    if (base::Status distinct = checkNotAnInput(options.output, {options.project}, companions); !distinct) {
        fail("export: " + distinct.error());
        return 1;
    }
    scene::Scene scene;
    if (base::Status opened = loadProjectScene(options.project, scene); !opened) {
        fail(opened.error());
        return 1;
    }
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> modelWarnings;
    const ProjectFiles files = checkProjectFiles(options.project, scene, meshes, modelWarnings);
    if (base::Status missing = applyMissingFiles(files, policyOf(options)); !missing) {
        fail("export: " + missing.error());
        return 1;
    }
    if (base::Status distinct = checkNotAnInput(options.output, files.inputs, companions); !distinct) {
        fail("export: " + distinct.error());
        return 1;
    }
    if (StopOnSignal::requested()) // the last moment before files are written
        return interrupted("export");
    std::vector<std::string> warnings;
    const base::Status exported =
        scene::exportGltf(scene, QString::fromStdString(options.output), meshes, warnings);
    if (!exported) {
        fail("export: " + exported.error()); // alone: a failure is one line
        return 1;
    }
    printWarnings(modelWarnings);
    printWarnings(warnings);
    std::cout << base::printable(options.output, 4096) << "\n";
    return 0;
}

int runBench(const CliOptions& options) {
    bench::Options b;
    b.project = options.project;
    b.outDir = options.outDir;
    b.quick = options.quick;
    b.convergence = options.convergence;
    b.keepGoing = options.keepGoing;
    b.shard = options.shard;
    b.mergeDirs = options.mergeDirs;
    if (options.sizeGiven) {
        b.width = options.width;
        b.height = options.height;
    }
    return bench::run(b);
}

} // namespace speculum::app
