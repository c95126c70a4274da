#include "app/bench/Bench.hpp"

#include "app/OutputPaths.hpp"
#include "app/ProjectInput.hpp"
#include "app/bench/Measure.hpp"
#include "app/bench/Report.hpp"
#include "app/bench/Results.hpp"
#include "app/bench/StagedOutput.hpp"
#include "app/bench/Sweep.hpp"
#include "editor/document/SceneData.hpp"
#include "render/Renderer.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/image/ImageWriter.hpp"

#include <QGuiApplication>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <thread>

namespace speculum::app::bench {

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

int fail(const std::string& message) {
    printError("bench: " + message);
    return 1;
}

// A write into the staging folder that failed (render::AtomicFile's "<staging>/results.csv: the disk is
// full (...); nothing was written") is told as the user sees it: the file in the output folder, whose
// previous run is left as it was (the staging folder is discarded, nothing is committed).
std::string outputMessage(std::string message, const StagedOutput& output) {
    const std::string staging = output.staging().string();
    if (!staging.empty()) {
        for (std::size_t at = message.find(staging); at != std::string::npos; at = message.find(staging, at))
            message.replace(at, staging.size(), output.folder().string());
    }
    const std::string fresh = "; nothing was written";
    if (const std::size_t at = message.find(fresh); at != std::string::npos)
        message.replace(at, fresh.size(), "; the previous output is unchanged");
    return message;
}

void progress(const std::string& line) {
    std::cerr << "speculum: bench: " << line << std::endl;
}

volatile std::sig_atomic_t g_stopSignal = 0;

extern "C" void requestStop(int signal) {
    g_stopSignal = signal;
}

// Ctrl-C (SIGINT) or a polite kill (SIGTERM) during a run: the run stops at its next step and, like any
// failed run, leaves the output folder as it found it. The previous handlers return when the run ends.
class StopOnSignal {
public:
    StopOnSignal() {
        g_stopSignal = 0;
        struct sigaction action {};
        action.sa_handler = requestStop;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &m_previousInt);
        sigaction(SIGTERM, &action, &m_previousTerm);
    }
    ~StopOnSignal() {
        sigaction(SIGINT, &m_previousInt, nullptr);
        sigaction(SIGTERM, &m_previousTerm, nullptr);
    }
    StopOnSignal(const StopOnSignal&) = delete;
    StopOnSignal& operator=(const StopOnSignal&) = delete;

    static bool requested() { return g_stopSignal != 0; }

private:
    struct sigaction m_previousInt {};
    struct sigaction m_previousTerm {};
};

// The exit status of a shell's command killed by SIGINT, which is what the user asked for.
int interrupted() {
    std::cerr << "speculum: bench: interrupted; nothing was written\n";
    return 130;
}

std::string key(const Settings& settings) {
    std::string k;
    for (const auto& [name, value] : settings)
        k += name + "=" + value + ";";
    return k;
}

std::string referenceFile(ReferenceKind kind) {
    return kind == ReferenceKind::Scene ? "reference.png" : "reference-" + referenceName(kind) + ".png";
}

// Timing runs in rounds: each round renders every distinct configuration once (after one untimed frame
// that absorbs the switch: new map textures, shader variants). Contention from other processes then
// spreads over all configurations alike instead of spoiling whichever one it happened to meet, and the
// median over rounds drops the rounds it hit.
struct Timing {
    int warmUp; // untimed frames before a configuration's image is taken
    int rounds;
};

// What the sweep needs beyond the frame: the teapot swap, the traits, the references.
struct Context {
    const render::FrameInput& scene;
    SceneTraits traits;
    std::optional<int> teapot;
    TessellateTeapot tessellate;
    int width = 0;
    int height = 0;
};

// Traces each reference the configurations need, writing its image into the staging folder.
render::Result<std::map<ReferenceKind, Reference>> traceReferences(const Context& ctx,
                                                                   const std::vector<Configuration>& configs,
                                                                   const fs::path& staging, RunInfo& run) {
    std::vector<ReferenceKind> kinds;
    for (const Configuration& c : configs)
        if (std::find(kinds.begin(), kinds.end(), c.reference) == kinds.end())
            kinds.push_back(c.reference);
    std::map<ReferenceKind, Reference> references;
    const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    for (ReferenceKind kind : kinds) {
        const std::string name = referenceName(kind);
        progress("tracing the " + name + " reference on " + std::to_string(threads) + " threads");
        int lastQuarter = 0;
        auto traced = traceReference(
            referenceInput(ctx.scene, kind, ctx.tessellate), kind, ctx.width, ctx.height, [&](double f) {
                const int quarter = static_cast<int>(f * 4.0);
                if (quarter > lastQuarter && quarter < 4)
                    progress("tracing the " + name + " reference: " + std::to_string(quarter * 25) + "%");
                lastQuarter = std::max(lastQuarter, quarter);
                return !StopOnSignal::requested();
            });
        if (!traced)
            return render::Error{traced.error()};
        printWarnings(traced->traced.warnings);
        progress("traced the " + name + " reference in " +
                 std::to_string(static_cast<int>(traced->traced.totalMs + 0.5)) + " ms");
        const std::string file = referenceFile(kind);
        if (render::Status s = render::writeImage((staging / file).string(), traced->traced.image); !s)
            return render::Error{s.error()};
        run.references.push_back({kind, traced->traced.totalMs, threads, file});
        references.emplace(kind, std::move(*traced));
    }
    return references;
}

std::string summaryLine(const std::string& step, const Record& r) {
    char text[200];
    std::snprintf(text, sizeof text, "%s: PSNR %.2f dB", step.c_str(), r.psnr);
    std::string line = text;
    if (r.psnrReflector) {
        std::snprintf(text, sizeof text, ", reflector %.2f dB", *r.psnrReflector);
        line += text;
    }
    if (r.psnrMirrors) {
        std::snprintf(text, sizeof text, ", mirrors %.2f dB", *r.psnrMirrors);
        line += text;
    }
    std::snprintf(text, sizeof text, ", %.1f MiB", static_cast<double>(r.memory.total()) / (1024.0 * 1024.0));
    return line + text;
}

// Writes the report and the plots; QPainter needs a QGuiApplication, the offscreen platform will do.
render::Status writeReportWithGui(const fs::path& staging, const RunInfo& run,
                                  const std::vector<Record>& records) {
    int argc = 3;
    char arg0[] = "speculum", arg1[] = "-platform", arg2[] = "offscreen";
    char* argv[] = {arg0, arg1, arg2, nullptr};
    std::optional<QGuiApplication> app;
    // Qt's own chatter (no XDG_RUNTIME_DIR on a server) is not the user's business here.
    const QtMessageHandler previous =
        qInstallMessageHandler([](QtMsgType type, const QMessageLogContext&, const QString& message) {
            if (type == QtCriticalMsg || type == QtFatalMsg)
                std::cerr << "speculum: bench: " << message.toStdString() << "\n";
        });
    if (!QCoreApplication::instance())
        app.emplace(argc, argv);
    render::Status written = writeReport(staging, run, records);
    app.reset();
    qInstallMessageHandler(previous);
    return written;
}

} // namespace

int run(const Options& options) {
    const auto start = Clock::now();
    const StopOnSignal stop; // before the output folder exists: a stop always finds it to clean up
    const int width = options.width > 0 ? options.width : options.quick ? 480 : 1280;
    const int height = options.height > 0 ? options.height : options.quick ? 270 : 720;
    const Timing timing = options.quick ? Timing{2, 7} : Timing{2, 9};

    // Nothing an input is may be replaced: DIR holds neither the project nor a file it reads.
    if (render::Status folder = checkOutputFolder(options.outDir, {options.project}); !folder)
        return fail(folder.error());
    auto project = loadProjectFrame(options.project, 0.0,
                                    options.keepGoing ? MissingFiles::KeepGoing : MissingFiles::Fail);
    if (!project)
        return fail(project.error());
    if (render::Status folder = checkOutputFolder(options.outDir, project->inputs); !folder)
        return fail(folder.error());
    // The folder is checked (and made) before the long work, so a bad --out costs nothing.
    auto output = StagedOutput::begin(options.outDir);
    if (!output)
        return fail(output.error());
    const fs::path staging = output->staging();
    auto context = render::gl::HeadlessContext::create();
    if (!context)
        return fail("no OpenGL: " + context.error());
    auto renderer = render::Renderer::create();
    if (!renderer)
        return fail(renderer.error());

    std::optional<int> teapot;
    if (!project->teapotTessellations.empty())
        teapot = *project->teapotTessellations.begin();
    // Built-in teapots are the mesh library's, one shared mesh per tessellation: swap them by identity.
    std::set<const render::MeshData*> teapotMeshes;
    for (int t : project->teapotTessellations)
        teapotMeshes.insert(project->meshes->builtin(document::BuiltinMesh::Teapot, t).get());
    const TessellateTeapot tessellate = [&](const render::MeshHandle& mesh, int tessellation) {
        return teapotMeshes.count(mesh.get())
                   ? project->meshes->builtin(document::BuiltinMesh::Teapot, tessellation)
                   : mesh;
    };
    const Context ctx{project->input, sceneTraits(project->input, teapot), teapot, tessellate, width, height};
    const std::vector<Configuration> configs = planSweep(ctx.scene, ctx.traits, {options.quick});

    RunInfo run;
    run.scene = options.project;
    run.sceneName = fs::path(options.project).filename().string();
    run.width = width;
    run.height = height;
    run.quick = options.quick;
    run.warmUpFrames = timing.warmUp;
    run.timedFrames = timing.rounds;
    run.renderer = (*context)->description();
    progress(std::to_string(configs.size()) + " configurations of " + run.sceneName + " at " +
             std::to_string(width) + "x" + std::to_string(height) + (options.quick ? " (quick)" : ""));

    auto references = traceReferences(ctx, configs, staging, run);
    if (stop.requested())
        return interrupted();
    if (!references)
        return fail(outputMessage(references.error(), *output));

    // Warm the whole pipeline up once (shader variants, textures, meshes), so that the first configuration
    // measured is not the one that pays for it.
    progress("warming up");
    if (auto warm = measureFrames(**renderer, ctx.scene, width, height, 2, 0); !warm)
        return fail(warm.error());
    std::error_code ec;
    fs::create_directory(staging / "errors", ec);
    if (ec)
        return fail((staging / "errors").string() + ": " + ec.message());

    // Images, memory and errors, one configuration at a time. Configurations with the same settings (the
    // scene's own recur in every family) are rendered once and timed once.
    std::vector<Record> records;
    std::vector<std::string> keys;                      // per record
    std::map<std::string, render::FrameInput> distinct; // the frame of each distinct setting
    std::map<std::string, FrameCost> costs;
    std::set<std::string> warned;
    const std::string sceneKey = key(effectiveSettings(ctx.scene, ctx.traits, teapot));
    for (std::size_t i = 0; i < configs.size(); ++i) {
        if (stop.requested())
            return interrupted();
        const Configuration& config = configs[i];
        const std::string step = "[" + std::to_string(i + 1) + "/" + std::to_string(configs.size()) + "] " +
                                 familyName(config.family) + ": " + displayName(config);
        render::FrameInput applied = applyVariation(ctx.scene, ctx.traits, config.variation, tessellate);
        Record record;
        record.config = config;
        record.settings = effectiveSettings(
            applied, ctx.traits, config.variation.tessellation ? config.variation.tessellation : teapot);
        const std::string k = key(record.settings);
        record.sceneSetting = k == sceneKey;
        if (!costs.count(k)) {
            progress(step + ": rendering");
            auto cost = measureFrames(**renderer, applied, width, height, timing.warmUp, 1);
            if (!cost)
                return fail(displayName(config) + ": " + cost.error());
            costs.emplace(k, std::move(*cost));
            distinct.emplace(k, std::move(applied));
        }
        const FrameCost& cost = costs.at(k);
        for (const std::string& w : cost.warnings)
            if (warned.insert(w).second)
                printWarnings({w});
        auto errors = compareWithReference(cost.image, references->at(config.reference));
        if (!errors)
            return fail(displayName(config) + ": " + errors.error());
        record.memory = cost.memory;
        record.rmse = errors->overall.rmse;
        record.psnr = errors->overall.psnr;
        if (errors->mirrors)
            record.psnrMirrors = errors->mirrors->psnr;
        if (errors->reflector)
            record.psnrReflector = errors->reflector->psnr;
        record.errorMap = "errors/" + config.id + ".png";
        if (render::Status s =
                render::metrics::writeErrorMap((staging / record.errorMap).string(), errors->difference);
            !s)
            return fail(outputMessage(s.error(), *output));
        if (config.family == Family::Scene)
            if (render::Status s = render::writeImage((staging / "render.png").string(), cost.image); !s)
                return fail(outputMessage(s.error(), *output));
        progress(summaryLine(step, record));
        records.push_back(std::move(record));
        keys.push_back(k);
    }
    costs.clear(); // the images are compared and written: free them before the timing rounds

    std::map<std::string, std::vector<double>> gpu, cpu;
    for (int round = 1; round <= timing.rounds; ++round) {
        progress("timing round " + std::to_string(round) + "/" + std::to_string(timing.rounds) + ": " +
                 std::to_string(distinct.size()) + " distinct configurations");
        for (const auto& [k, input] : distinct) {
            if (stop.requested())
                return interrupted();
            auto cost = measureFrames(**renderer, input, width, height, 1, 1);
            if (!cost)
                return fail(cost.error());
            gpu[k].push_back(cost->gpuMs);
            cpu[k].push_back(cost->cpuMs);
        }
    }
    for (std::size_t i = 0; i < records.size(); ++i) {
        const std::vector<double>& g = gpu[keys[i]];
        records[i].gpuMs =
            std::all_of(g.begin(), g.end(), [](double ms) { return ms >= 0.0; }) ? median(g) : -1.0;
        records[i].cpuMs = median(cpu[keys[i]]);
    }
    // The GL work is done: free it before the plots.
    renderer->reset();
    context->reset();

    if (stop.requested())
        return interrupted();
    progress("writing results, plots and the report");
    if (render::Status s = writeCsv((staging / "results.csv").string(), records); !s)
        return fail(outputMessage(s.error(), *output));
    if (render::Status s = writeJson((staging / "results.json").string(), run, records); !s)
        return fail(outputMessage(s.error(), *output));
    if (render::Status s = writeReportWithGui(staging, run, records); !s)
        return fail(outputMessage(s.error(), *output));
    // Plots and references of an earlier run in the same folder would mix two runs: they go too.
    auto earlierOutput = [](const std::string& name) {
        const bool png = name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0;
        return png && (name.rfind("plot-", 0) == 0 || name.rfind("reference", 0) == 0);
    };
    if (render::Status s = output->commit(earlierOutput); !s)
        return fail(s.error());
    const fs::path report = output->folder() / "report.md";
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    progress("done in " + std::to_string(static_cast<int>(seconds + 0.5)) + " s: " + report.string());
    std::cout << report.string() << "\n";
    return 0;
}

} // namespace speculum::app::bench
