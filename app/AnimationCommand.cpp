#include "app/AnimationCommand.hpp"

#include "app/Interrupt.hpp"
#include "app/OutputPaths.hpp"
#include "app/Progress.hpp"
#include "app/ProjectInput.hpp"
#include "base/Printable.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/imageio/FrameReader.hpp"
#include "render/video/VideoWriter.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/export/AnimationExport.hpp"
#include "scene/model/SceneAnimation.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace speculum::app {

namespace {

scene::AnimationSettings animationSettings(const CliOptions& options) {
    scene::AnimationSettings settings;
    settings.still.width = options.width;
    settings.still.height = options.height;
    settings.still.ssaa = options.ssaa;
    settings.still.reference = options.reference;
    settings.still.samples = options.samples;
    settings.still.screenSpaceSources = options.screenSpaceSources;
    settings.frames = {options.frameRange->first, options.frameRange->second};
    settings.fps = options.fps;
    settings.turntableSeconds = options.turntable;
    if (options.shard)
        settings.shard = *options.shard;
    return settings;
}

// The output checked before the project is read: its kind, its folder, and that it is not the project.
// A sequence's folder is made when missing (the shards of a cluster each find it or make it).
base::Result<scene::AnimationOutput> checkAnimationOutput(const CliOptions& options) {
    auto output = scene::parseAnimationOutput(options.output);
    if (!output)
        return base::Error{"render: " + output.error()};
    const std::string first =
        output->video ? output->path : scene::sequenceFramePath(output->path, options.frameRange->first);
    const std::filesystem::path folder = std::filesystem::path(first).parent_path();
    std::error_code ec;
    if (!output->video && !folder.empty() && !std::filesystem::exists(folder, ec))
        std::filesystem::create_directories(folder, ec);
    if (base::Status where = checkOutputFile(first); !where)
        return base::Error{"render: " + where.error()};
    if (base::Status distinct = checkNotAnInput(first, {options.project}); !distinct)
        return base::Error{"render: " + distinct.error()};
    if (base::Status valid = scene::validateAnimationExport(animationSettings(options), *output); !valid)
        return base::Error{"render: " + valid.error()};
    return output;
}

// "the scene's animation loops every 2 s, not in the turntable's 3 s: the clip's last frame will not
// lead into its first" when a turntable's loop would jump.
void warnOfTurntableSeam(const CliOptions& options, const scene::Scene& scene) {
    if (!options.turntable || !scene::sceneHasAnimation(scene))
        return;
    const double loop = scene::animationLoopSeconds(scene);
    const double turns = *options.turntable / loop;
    if (std::abs(turns - std::round(turns)) > 1e-6) {
        std::ostringstream text;
        text << "the scene's animation repeats every " << loop << " s, not within the turntable's "
             << *options.turntable << " s: the loop will jump where the clip starts again";
        printWarnings(std::vector<std::string>{text.str()});
    }
}

std::string rangeText(const std::vector<int>& frames) {
    if (frames.empty())
        return "none";
    return frames.size() == 1 ? std::to_string(frames.front())
                              : std::to_string(frames.front()) + ".." + std::to_string(frames.back());
}

void printProgress(Progress& progress, const scene::AnimationProgress& p) {
    std::ostringstream stage;
    stage << "frame " << p.frame << ", " << p.done << " of " << p.total << " done";
    if (p.remainingSeconds >= 0.0)
        stage << ", about " << static_cast<long long>(std::ceil(p.remainingSeconds)) << " s left";
    progress.update(p.fraction, stage.str());
}

int reportResult(const CliOptions& options, const scene::AnimationOutput& output,
                 const scene::AnimationResult& result) {
    printWarnings(result.warnings);
    // A signal that came as the work was done does not undo it: only a stopped export is interrupted.
    if (result.cancelled || (!result.status && StopOnSignal::requested()))
        return interrupted("render",
                           output.video ? std::string("the partial clip was removed") : result.outcome);
    if (!result.status) {
        printError("render: " + result.status.error());
        return 1;
    }
    if (!Progress::quiet())
        std::cerr << "speculum: " << (options.reference ? "traced " : "rendered ") << result.written.size()
                  << (result.written.size() == 1 ? " frame" : " frames") << " (" << rangeText(result.written)
                  << (result.replayed > 0
                          ? ", " + std::to_string(result.replayed) + " more drawn for the maps"
                          : std::string())
                  << ") in " << static_cast<long long>(result.totalMs + 0.5) << " ms\n";
    if (output.video)
        std::cout << base::printable(output.path, 4096) << "\n";
    else
        for (const std::string& file : result.files)
            std::cout << base::printable(file, 4096) << "\n";
    return 0;
}

} // namespace

int runAnimation(const CliOptions& options) {
    auto output = checkAnimationOutput(options);
    if (!output) {
        printError(output.error());
        return 1;
    }
    auto project = loadProjectFrame(options.project, 0.0,
                                    options.keepGoing ? MissingFiles::KeepGoing : MissingFiles::Fail);
    if (!project) {
        printError("render: " + project.error());
        return 1;
    }
    const std::string first =
        output->video ? output->path : scene::sequenceFramePath(output->path, options.frameRange->first);
    if (base::Status distinct = checkNotAnInput(first, project->inputs); !distinct) {
        printError("render: " + distinct.error());
        return 1;
    }
    warnOfTurntableSeam(options, *project->scene);
    std::unique_ptr<render::gl::HeadlessContext> context;
    std::unique_ptr<render::Renderer> renderer;
    std::string description;
    if (!options.reference) {
        auto made = render::gl::HeadlessContext::create();
        if (!made) {
            printError("no OpenGL: " + made.error());
            return 1;
        }
        context = std::move(*made);
        description = context->description();
        auto createdRenderer = render::Renderer::create();
        if (!createdRenderer) {
            printError(createdRenderer.error());
            return 1;
        }
        renderer = std::move(*createdRenderer);
    }
    const scene::FrameSource source = [&](double time) {
        std::vector<scene::Warning> repeated; // said when the project was loaded
        render::FrameInput input = scene::snapshot(*project->scene, time, *project->meshes, repeated);
        useCheckedTextures(input, project->textures);
        return input;
    };
    Progress progress(options.reference ? "tracing" : "rendering");
    const auto report = [&](const scene::AnimationProgress& p) {
        printProgress(progress, p);
        return !StopOnSignal::requested();
    };
    std::error_code ec;
    const std::string projectPath = std::filesystem::weakly_canonical(options.project, ec).string();
    const scene::AnimationResult result = scene::exportAnimation(
        renderer.get(), source, projectPath, animationSettings(options), *output, report, description);
    progress.finish();
    return reportResult(options, *output, result);
}

} // namespace speculum::app
