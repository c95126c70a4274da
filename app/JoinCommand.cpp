#include "app/AnimationCommand.hpp"
#include "app/Interrupt.hpp"
#include "app/OutputPaths.hpp"
#include "app/Progress.hpp"
#include "app/ProjectInput.hpp"
#include "base/Printable.hpp"
#include "render/imageio/FrameReader.hpp"
#include "render/video/VideoWriter.hpp"
#include "scene/export/AnimationExport.hpp"

#include <algorithm>
#include <iostream>

namespace speculum::app {

namespace {

// "5, 9 and 12" (the first few, and how many more).
std::string frameList(const std::vector<int>& frames) {
    std::string text;
    const std::size_t shown = std::min<std::size_t>(frames.size(), 5);
    for (std::size_t i = 0; i < shown; ++i)
        text += (i == 0                                     ? ""
                 : i + 1 == shown && frames.size() == shown ? " and "
                                                            : ", ") +
                std::to_string(frames[i]);
    if (frames.size() > shown)
        text += " and " + std::to_string(frames.size() - shown) + " more";
    return text;
}

struct Sequence {
    std::string pattern;
    std::vector<int> frames; // the frames to encode, in order
    int width = 0;
    int height = 0;
    int fps = 24;
};

// The frames the clip takes, all present and alike: the range given, or the frames on disk from the
// lowest to the highest, none missing; every frame the size of the first and, when the first records the
// clip it belongs to (speculum:clip), of that clip.
base::Result<Sequence> checkSequence(const CliOptions& options) {
    auto output = scene::parseAnimationOutput(options.project);
    if (!output || output->video)
        return base::Error{"join: " + (output ? base::quoted(options.project) +
                                                    ": SEQUENCE is an image sequence's name with its frame "
                                                    "number, such as frames/shot_%04d.png"
                                              : output.error())};
    Sequence sequence{output->path, {}, 0, 0, options.fps};
    if (base::Status shards = scene::checkShardRecordsAgree(sequence.pattern); !shards)
        return base::Error{"join: " + base::quoted(sequence.pattern) + ": " + shards.error()};
    const std::vector<int> onDisk = scene::framesOnDisk(sequence.pattern);
    if (onDisk.empty() && !options.frameRange)
        return base::Error{"join: no frame of " + base::quoted(sequence.pattern) + " exists"};
    const int first = options.frameRange ? options.frameRange->first : onDisk.front();
    const int last = options.frameRange ? options.frameRange->second : onDisk.back();
    std::vector<int> missing;
    for (int f = first; f <= last; ++f)
        (std::binary_search(onDisk.begin(), onDisk.end(), f) ? sequence.frames : missing).push_back(f);
    if (!missing.empty())
        return base::Error{"join: " + base::quoted(sequence.pattern) + " lacks " +
                           (missing.size() == 1 ? "frame " : "frames ") + frameList(missing) + " of " +
                           std::to_string(first) + ".." + std::to_string(last) +
                           " (render them first, e.g. " +
                           base::quoted(scene::sequenceFramePath(sequence.pattern, missing.front())) + ")"};
    std::optional<render::SequenceFrame> reference;
    for (int f : sequence.frames) {
        const std::string path = scene::sequenceFramePath(sequence.pattern, f);
        auto header = render::readSequenceFrameHeader(path);
        if (!header)
            return base::Error{"join: " + header.error()};
        if (!reference) {
            reference = std::move(*header);
            continue;
        }
        if (header->width != reference->width || header->height != reference->height)
            return base::Error{"join: frame " + std::to_string(f) + " is " + std::to_string(header->width) +
                               "x" + std::to_string(header->height) + ", frame " + std::to_string(first) +
                               " is " + std::to_string(reference->width) + "x" +
                               std::to_string(reference->height)};
        const auto clipOf = [](const render::SequenceFrame& frame) {
            const auto it = frame.attributes.find("speculum:clip");
            return it == frame.attributes.end() ? std::string() : it->second;
        };
        if (clipOf(*reference) != clipOf(*header))
            return base::Error{"join: frame " + std::to_string(f) + " belongs to another clip (" +
                               base::quoted(clipOf(*header)) + "; frame " + std::to_string(first) + ": " +
                               base::quoted(clipOf(*reference)) + ")"};
    }
    sequence.width = reference->width;
    sequence.height = reference->height;
    if (!options.fpsGiven)
        if (const auto it = reference->attributes.find("speculum:fps"); it != reference->attributes.end())
            sequence.fps =
                std::clamp(std::atoi(it->second.c_str()), render::video::kMinFps, render::video::kMaxFps);
    return sequence;
}

} // namespace

int runJoin(const CliOptions& options) {
    const auto format = render::video::videoFormatOf(options.output);
    if (!format) {
        printError("join: " + base::quoted(options.output) + ": a clip is " +
                   render::video::videoFormatList());
        return 1;
    }
    if (base::Status where = checkOutputFile(options.output); !where) {
        printError("join: " + where.error());
        return 1;
    }
    auto sequence = checkSequence(options);
    if (!sequence) {
        printError(sequence.error());
        return 1;
    }
    std::vector<std::string> inputs;
    for (int f : sequence->frames)
        inputs.push_back(scene::sequenceFramePath(sequence->pattern, f));
    if (base::Status distinct = checkNotAnInput(options.output, inputs); !distinct) {
        printError("join: " + distinct.error());
        return 1;
    }
    auto writer = render::video::VideoWriter::open(
        options.output, *format,
        {sequence->width, sequence->height, sequence->fps, {{"comment", "speculum " SPECULUM_VERSION}}});
    if (!writer) {
        printError("join: " + writer.error());
        return 1;
    }
    Progress progress("encoding");
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (StopOnSignal::requested())
            return interrupted("join", "no clip was written");
        auto frame = render::readSequenceFrame(inputs[i]);
        base::Status written =
            frame ? (*writer)->write(frame->rgba8) : base::Status(base::Error{frame.error()});
        if (!written) {
            printError("join: " + written.error());
            return 1;
        }
        progress.update(static_cast<double>(i + 1) / static_cast<double>(inputs.size()));
    }
    progress.finish();
    if (base::Status finished = (*writer)->finish(); !finished) {
        printError("join: " + finished.error());
        return 1;
    }
    std::cout << base::printable(options.output, 4096) << "\n";
    return 0;
}

} // namespace speculum::app
