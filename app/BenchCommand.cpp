#include "app/BenchCommand.hpp"

#include "accuracy/Report.hpp"
#include "accuracy/Results.hpp"
#include "accuracy/ShardMerge.hpp"
#include "accuracy/StagedOutput.hpp"
#include "accuracy/run/Convergence.hpp"
#include "accuracy/run/ShardFiles.hpp"
#include "accuracy/run/SweepRun.hpp"
#include "app/Interrupt.hpp"
#include "app/OutputPaths.hpp"
#include "app/Progress.hpp"
#include "app/ProjectInput.hpp"
#include "base/Printable.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/Flip.hpp"
#include "render/renderer/Renderer.hpp"
#include "scene/evaluate/Snapshot.hpp"

#include <QCryptographicHash>
#include <QFile>
#include <QGuiApplication>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <unistd.h>

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
//
// A shard also keeps each reference and each frame exactly (accuracy/run/ShardFiles.hpp), for the merge to
// find the ties and the distances to each family's best, which compare frames of different shards.
accuracy::SweepObserver sweepObserver(const fs::path& staging, std::set<std::string>& warned, bool shard) {
    accuracy::SweepObserver observer;
    observer.progress = progress;
    observer.stop = [] { return StopOnSignal::requested(); };
    observer.referenceTraced = [staging, shard](const accuracy::Reference& reference,
                                                const accuracy::ReferenceInfo& info) -> base::Status {
        printWarnings(reference.traced.warnings);
        if (shard)
            if (base::Status s = accuracy::writeShardReference(
                    (staging / accuracy::shardReferenceFile(info.kind)).string(), reference);
                !s)
                return s;
        return render::writeImage((staging / info.image).string(), reference.traced.image);
    };
    observer.measured = [staging, &warned, shard](std::size_t, std::size_t, const accuracy::Record& record,
                                                  const accuracy::FrameCost& cost,
                                                  const accuracy::ErrorFigures& errors) -> base::Status {
        for (const std::string& w : cost.warnings)
            if (warned.insert(w).second)
                printWarnings({w});
        if (shard)
            if (base::Status s = accuracy::writeShardFrame(
                    (staging / accuracy::shardFrameFile(record.config.id)).string(), cost.image);
                !s)
                return s;
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

// results.csv, results.json, report.md and its plots, into the staging folder; a shard's share gets no
// report (its findings would be of a part of each family). A failed write is told as the user sees it
// (outputMessage).
base::Status writeResults(const StagedOutput& output, const accuracy::RunInfo& run,
                          const std::vector<accuracy::Record>& records) {
    const fs::path staging = output.staging();
    if (base::Status s = accuracy::writeCsv((staging / "results.csv").string(), records); !s)
        return base::Error{outputMessage(s.error(), output)};
    if (base::Status s = accuracy::writeJson((staging / "results.json").string(), run, records); !s)
        return base::Error{outputMessage(s.error(), output)};
    if (run.shard)
        return base::Done{};
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

// Plots and references of an earlier run in the same folder would mix two runs: the commit removes them
// (and a shard, which writes no report, an earlier run's report.md and render.png).
bool isEarlierOutput(const std::string& name) {
    const bool png = name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0;
    return png && (name.rfind("plot-", 0) == 0 || name.rfind("reference", 0) == 0);
}

bool isEarlierShardOutput(const std::string& name) {
    return isEarlierOutput(name) || name == "report.md" || name == "render.png";
}

// The machine a shard ran on, as its results name it.
std::string hostName() {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0')
        return "unknown host";
    return name;
}

// SHA-256 of the project file, hex: the shards and the merge check they read the same project.
base::Result<std::string> projectDigest(const std::string& project) {
    QFile file(QString::fromStdString(project));
    if (!file.open(QIODevice::ReadOnly))
        return base::Error{base::quoted(project) + ": cannot read (" + file.errorString().toStdString() +
                           ")"};
    QCryptographicHash hash(QCryptographicHash::Sha256);
    if (!hash.addData(&file))
        return base::Error{base::quoted(project) + ": cannot read"};
    return hash.result().toHex().toStdString();
}

// The folders the staging folder needs before the sweep writes into it.
base::Status makeSubfolders(const fs::path& staging, bool shard) {
    std::error_code ec;
    for (const char* sub : {"errors", "flip", accuracy::kShardFolder}) {
        if (!shard && std::string(sub) == accuracy::kShardFolder)
            continue;
        fs::create_directory(staging / sub, ec);
        if (ec)
            return base::Error{(staging / sub).string() + ": " + ec.message()};
    }
    return base::Done{};
}

// What a shard adds to its run's description for the merge: the project's digest, the convergence study
// asked for, the host.
base::Status describeShard(accuracy::RunInfo& run, const Options& options) {
    auto digest = projectDigest(options.project);
    if (!digest)
        return base::Error{digest.error()};
    run.shard->projectDigest = *digest;
    run.shard->convergence = options.convergence;
    run.shard->host = hostName();
    return base::Done{};
}

// The sweep (a shard's share of it with --shard) and, with --convergence, the study of the reference (in
// shard 0 alone: the merge judges it against every shard's errors). Errors as the user sees them.
base::Result<accuracy::SweepOutcome> measure(const Options& options, const accuracy::SweepInput& input,
                                             const StagedOutput& output, std::string& renderer) {
    auto context = render::gl::HeadlessContext::create();
    if (!context)
        return base::Error{"no OpenGL: " + context.error()};
    auto gl = render::Renderer::create();
    if (!gl)
        return base::Error{gl.error()};
    std::set<std::string> warned;
    const accuracy::SweepObserver observer =
        sweepObserver(output.staging(), warned, options.shard.has_value());
    auto swept = accuracy::runSweep(**gl, input, observer);
    if (!swept)
        return base::Error{outputMessage(swept.error(), output)};
    if (options.convergence && (!options.shard || options.shard->index == 0)) {
        auto study = accuracy::studyConvergence(input, swept->run.width, swept->run.height,
                                                smallestError(swept->records), progress,
                                                [] { return StopOnSignal::requested(); });
        if (!study)
            return base::Error{outputMessage(study.error(), output)};
        swept->run.convergence = std::move(*study);
    }
    renderer = (*context)->description();
    return swept;
}

// Copies `relative` from a shard's folder into the staging folder (a hard link where the file system
// allows: the shards' files are replaced by renames, never written in place, so the link stays theirs).
base::Status copyFromShard(const fs::path& shard, const std::string& relative, const fs::path& staging) {
    std::error_code ec;
    const fs::path from = shard / relative, to = staging / relative;
    fs::create_hard_link(from, to, ec);
    if (ec) {
        ec.clear();
        fs::copy_file(from, to, ec);
    }
    if (ec)
        return base::Error{base::quoted(from.string()) + ": cannot copy (" + ec.message() + ")"};
    return base::Done{};
}

// The images a one-machine run writes, from the shards that made them: references, error and FLIP maps,
// the scene's own frame.
base::Status copyImages(const accuracy::MergedShards& merged, const fs::path& staging) {
    for (const accuracy::ReferenceInfo& ref : merged.run.references)
        if (base::Status s = copyFromShard(merged.referenceFolder.at(ref.kind), ref.image, staging); !s)
            return s;
    for (std::size_t i = 0; i < merged.records.size(); ++i) {
        const accuracy::Record& r = merged.records[i];
        for (const std::string& image : {r.errorMap, r.flipMap})
            if (base::Status s = copyFromShard(merged.recordFolder[i], image, staging); !s)
                return s;
        if (r.config.family == accuracy::Family::Scene)
            if (base::Status s = copyFromShard(merged.recordFolder[i], "render.png", staging); !s)
                return s;
    }
    return base::Done{};
}

// --out is neither one of the merged folders nor inside one (a merge leaves its inputs as they are), nor
// a folder that holds one (the commit replaces what it writes there).
base::Status checkMergeFolders(const Options& options) {
    std::vector<std::string> inputs{options.project};
    std::error_code ec;
    const fs::path out = fs::weakly_canonical(options.outDir, ec);
    for (const std::string& dir : options.mergeDirs) {
        inputs.push_back((fs::path(dir) / "results.json").string());
        fs::path in = fs::weakly_canonical(dir, ec);
        if (in.filename().empty()) // "shard0/": its last element is empty
            in = in.parent_path();
        const auto [inEnd, outAt] = std::mismatch(in.begin(), in.end(), out.begin(), out.end());
        if (!ec && inEnd == in.end())
            return base::Error{"--out: " + base::quoted(options.outDir) + " is, or is inside, " +
                               base::quoted(dir) +
                               ", a folder it merges, which a merge leaves as it is: choose another folder"};
    }
    return checkOutputFolder(options.outDir, inputs);
}

// The images and records of a merge, their ties and distances to each family's best, the convergence
// study judged against every shard's errors: ready to write.
base::Status joinShards(accuracy::MergedShards& merged, const Options& options, const StagedOutput& output) {
    if (base::Status s = makeSubfolders(output.staging(), false); !s)
        return s;
    progress("copying the shards' images");
    if (base::Status s = copyImages(merged, output.staging()); !s)
        return base::Error{outputMessage(s.error(), output)};
    if (base::Status s = accuracy::compareShardFrames(merged.records, merged.recordFolder,
                                                      merged.referenceFolder, progress);
        !s)
        return s;
    if (merged.run.convergence)
        accuracy::judgeConvergence(*merged.run.convergence, smallestError(merged.records));
    merged.run.scene = options.project;
    return base::Done{};
}

// `bench --merge DIR... --out DIR`: the shards' results joined into what one machine's run writes.
int merge(const Options& options) {
    const auto start = Clock::now();
    const StopOnSignal stop;
    if (base::Status folders = checkMergeFolders(options); !folders)
        return fail(folders.error());
    auto digest = projectDigest(options.project);
    if (!digest)
        return fail(digest.error());
    progress("reading " + std::to_string(options.mergeDirs.size()) + " shard folders");
    auto merged = accuracy::mergeShards({options.mergeDirs.begin(), options.mergeDirs.end()});
    if (!merged)
        return fail(merged.error());
    if (merged->projectDigest != *digest)
        return fail(base::quoted(options.project) +
                    ": not the project the shards measured (the file's contents differ)");
    auto output = StagedOutput::begin(options.outDir);
    if (!output)
        return fail(output.error());
    if (base::Status joined = joinShards(*merged, options, *output); !joined)
        return fail(joined.error());
    if (stop.requested())
        return interrupted();
    progress("writing results, plots and the report");
    if (base::Status s = writeResults(*output, merged->run, merged->records); !s)
        return fail(s.error());
    if (base::Status s = output->commit(isEarlierOutput); !s)
        return fail(s.error());
    const fs::path report = output->folder() / "report.md";
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    progress("merged in " + std::to_string(static_cast<int>(seconds + 0.5)) + " s: " + report.string());
    std::cout << report.string() << "\n";
    return 0;
}

// `bench PROJECT --out DIR` and, with --shard K/N, its share.
int sweep(const Options& options) {
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
    if (base::Status s = makeSubfolders(output->staging(), options.shard.has_value()); !s)
        return fail(s.error());

    accuracy::SweepInput input = sweepInput(options, *project);
    input.shard = options.shard;
    std::string renderer;
    auto swept = measure(options, input, *output, renderer);
    if (stop.requested())
        return interrupted();
    if (!swept)
        return fail(swept.error());
    accuracy::RunInfo run = std::move(swept->run);
    run.scene = options.project;
    run.renderer = renderer;
    if (run.shard)
        if (base::Status s = describeShard(run, options); !s)
            return fail(s.error());

    progress(run.shard ? "writing the shard's results" : "writing results, plots and the report");
    if (base::Status s = writeResults(*output, run, swept->records); !s)
        return fail(s.error());
    if (base::Status s = output->commit(run.shard ? isEarlierShardOutput : isEarlierOutput); !s)
        return fail(s.error());
    const fs::path written = output->folder() / (run.shard ? "results.json" : "report.md");
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    progress("done in " + std::to_string(static_cast<int>(seconds + 0.5)) + " s: " + written.string());
    std::cout << written.string() << "\n";
    return 0;
}

} // namespace

int run(const Options& options) {
    if (options.shard && !options.mergeDirs.empty())
        return fail("--merge: not with --shard (merge the shards' folders once every shard is measured)");
    return options.mergeDirs.empty() ? sweep(options) : merge(options);
}

} // namespace speculum::app::bench
