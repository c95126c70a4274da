#include "app/BenchCommand.hpp"

#include "accuracy/Report.hpp"
#include "accuracy/Results.hpp"
#include "accuracy/StagedOutput.hpp"
#include "accuracy/run/Convergence.hpp"
#include "accuracy/run/SweepRun.hpp"
#include "app/Interrupt.hpp"
#include "app/OutputPaths.hpp"
#include "app/Progress.hpp"
#include "app/ProjectInput.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/Flip.hpp"
#include "render/renderer/Renderer.hpp"
#include "scene/evaluate/Snapshot.hpp"

#include <QGuiApplication>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

namespace speculum::app::bench {

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;
using accuracy::StagedOutput;

int fail(const std::string& message) {
    printError("bench: " + message);
    return 1;
}

// A write into the staging folder that failed (base::AtomicFile's "<staging>/results.csv: the disk is
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
    static Progress steps("bench");
    steps.step(line);
}

int interrupted() {
    return app::interrupted("bench");
}

// Writes the report and the plots; QPainter needs a QGuiApplication, the offscreen platform will do.
base::Status writeReportWithGui(const fs::path& staging, const accuracy::RunInfo& run,
                                const std::vector<accuracy::Record>& records) {
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
    base::Status written = accuracy::writeReport(staging, run, records);
    app.reset();
    qInstallMessageHandler(previous);
    return written;
}

// The scene played forward from its time for the update family: kPlayedFrames frames 1/60 s apart, as the
// editor plays it (the sweep leaves the family out where nothing in them moves).
std::vector<render::FrameInput> playedFrames(const ProjectFrame& project) {
    std::vector<render::FrameInput> frames{project.input};
    if (!project.scene || project.input.reflectors.empty())
        return {};
    for (int k = 1; k < accuracy::kPlayedFrames; ++k) {
        std::vector<scene::Warning> repeated; // the first frame's warnings were reported already
        frames.push_back(scene::snapshot(*project.scene, project.input.time + k * kAnimationFrameStep,
                                         *project.meshes, repeated));
        useCheckedTextures(frames.back(), project.textures);
    }
    return frames;
}

// The sweep's input: the project's frame and, for the tessellation family, a way to put other
// tessellations of the built-in teapots in place. `project` must outlive it (its mesh library).
accuracy::SweepInput sweepInput(const Options& options, const ProjectFrame& project) {
    accuracy::SweepInput input;
    input.sceneName = fs::path(options.project).filename().string();
    input.scene = project.input;
    input.quick = options.quick;
    input.width = options.width;
    input.height = options.height;
    if (!project.teapotTessellations.empty())
        input.teapotTessellation = *project.teapotTessellations.begin();
    // Built-in teapots are the mesh library's, one shared mesh per tessellation: swap them by identity.
    std::set<const render::MeshData*> teapotMeshes;
    for (int t : project.teapotTessellations)
        teapotMeshes.insert(project.meshes->builtin(scene::BuiltinMesh::Teapot, t).get());
    scene::MeshLibrary* meshes = project.meshes.get();
    input.tessellate = [teapotMeshes = std::move(teapotMeshes), meshes](const render::MeshHandle& mesh,
                                                                        int tessellation) {
        return teapotMeshes.count(mesh.get()) ? meshes->builtin(scene::BuiltinMesh::Teapot, tessellation)
                                              : mesh;
    };
    input.playedFrames = playedFrames(project);
    return input;
}

// What the sweep reports as it goes: progress on stderr, a stop on Ctrl-C, and every image (each
// reference, each configuration's error map, the scene's own frame) written into the staging folder as
// soon as it exists, so that none is held until the end. A frame warning is printed once, however many
// configurations repeat it (`warned` remembers them).
accuracy::SweepObserver sweepObserver(const fs::path& staging, std::set<std::string>& warned) {
    accuracy::SweepObserver observer;
    observer.progress = progress;
    observer.stop = [] { return StopOnSignal::requested(); };
    observer.referenceTraced = [staging](const accuracy::Reference& reference,
                                         const accuracy::ReferenceInfo& info) {
        printWarnings(reference.traced.warnings);
        return render::writeImage((staging / info.image).string(), reference.traced.image);
    };
    observer.measured = [staging, &warned](std::size_t, std::size_t, const accuracy::Record& record,
                                           const accuracy::FrameCost& cost,
                                           const accuracy::ErrorFigures& errors) -> base::Status {
        for (const std::string& w : cost.warnings)
            if (warned.insert(w).second)
                printWarnings({w});
        if (base::Status s =
                render::metrics::writeErrorMap((staging / record.errorMap).string(), errors.difference);
            !s)
            return s;
        if (base::Status s = render::metrics::writeFlipMap((staging / record.flipMap).string(), errors.flip);
            !s)
            return s;
        if (record.config.family == accuracy::Family::Scene)
            return render::writeImage((staging / "render.png").string(), cost.image);
        return base::Done{};
    };
    return observer;
}

// results.csv, results.json, report.md and its plots, into the staging folder. A failed write is told as
// the user sees it (outputMessage).
base::Status writeResults(const StagedOutput& output, const accuracy::RunInfo& run,
                          const std::vector<accuracy::Record>& records) {
    const fs::path staging = output.staging();
    if (base::Status s = accuracy::writeCsv((staging / "results.csv").string(), records); !s)
        return base::Error{outputMessage(s.error(), output)};
    if (base::Status s = accuracy::writeJson((staging / "results.json").string(), run, records); !s)
        return base::Error{outputMessage(s.error(), output)};
    if (base::Status s = writeReportWithGui(staging, run, records); !s)
        return base::Error{outputMessage(s.error(), output)};
    return base::Done{};
}

// The smallest error the run's configurations scored against the scene's reference (whole-frame RMSE,
// sRGB), the one the convergence study traces: what its noise must stay well below to judge.
double smallestError(const std::vector<accuracy::Record>& records) {
    double smallest = 0.0;
    for (const accuracy::Record& r : records)
        if (r.config.reference == accuracy::ReferenceKind::Scene && r.rmse > 0.0 &&
            (smallest == 0.0 || r.rmse < smallest))
            smallest = r.rmse;
    return smallest;
}

// Plots and references of an earlier run in the same folder would mix two runs: the commit removes them.
bool isEarlierOutput(const std::string& name) {
    const bool png = name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0;
    return png && (name.rfind("plot-", 0) == 0 || name.rfind("reference", 0) == 0);
}

} // namespace

int run(const Options& options) {
    const auto start = Clock::now();
    const StopOnSignal stop; // before the output folder exists: a stop always finds it to clean up

    // Nothing an input is may be replaced: DIR holds neither the project nor a file it reads.
    if (base::Status folder = checkOutputFolder(options.outDir, {options.project}); !folder)
        return fail(folder.error());
    auto project = loadProjectFrame(options.project, 0.0,
                                    options.keepGoing ? MissingFiles::KeepGoing : MissingFiles::Fail);
    if (!project)
        return fail(project.error());
    if (base::Status folder = checkOutputFolder(options.outDir, project->inputs); !folder)
        return fail(folder.error());
    // The folder is checked (and made) before the long work, so a bad --out costs nothing.
    auto output = StagedOutput::begin(options.outDir);
    if (!output)
        return fail(output.error());
    const fs::path staging = output->staging();
    std::error_code ec;
    for (const char* maps : {"errors", "flip"}) {
        fs::create_directory(staging / maps, ec);
        if (ec)
            return fail((staging / maps).string() + ": " + ec.message());
    }
    auto context = render::gl::HeadlessContext::create();
    if (!context)
        return fail("no OpenGL: " + context.error());
    auto renderer = render::Renderer::create();
    if (!renderer)
        return fail(renderer.error());

    const accuracy::SweepInput input = sweepInput(options, *project);
    std::set<std::string> warned;
    const accuracy::SweepObserver observer = sweepObserver(staging, warned);
    auto swept = accuracy::runSweep(**renderer, input, observer);
    if (stop.requested())
        return interrupted();
    if (!swept)
        return fail(outputMessage(swept.error(), *output));
    if (options.convergence) {
        auto study = accuracy::studyConvergence(input, swept->run.width, swept->run.height,
                                                smallestError(swept->records), progress,
                                                [] { return StopOnSignal::requested(); });
        if (stop.requested())
            return interrupted();
        if (!study)
            return fail(outputMessage(study.error(), *output));
        swept->run.convergence = std::move(*study);
    }
    // The GL work is done: free it before the plots.
    renderer->reset();
    accuracy::RunInfo run = std::move(swept->run);
    run.scene = options.project;
    run.renderer = (*context)->description();
    context->reset();

    progress("writing results, plots and the report");
    if (base::Status s = writeResults(*output, run, swept->records); !s)
        return fail(s.error());
    if (base::Status s = output->commit(isEarlierOutput); !s)
        return fail(s.error());
    const fs::path report = output->folder() / "report.md";
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    progress("done in " + std::to_string(static_cast<int>(seconds + 0.5)) + " s: " + report.string());
    std::cout << report.string() << "\n";
    return 0;
}

} // namespace speculum::app::bench
