#pragma once

#include "base/Result.hpp"
#include "base/Shard.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/renderer/Renderer.hpp"
#include "render/video/VideoFormat.hpp"
#include "scene/export/StillExport.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace speculum::scene {

// Animations out: `speculum render --frames A..B` and the editor's Export Animation share this, so the
// two write the same frames. Frame N shows the scene at N / fps seconds; the frames are drawn in order
// by one renderer, so its shadow and environment maps follow the scene's update policies exactly as the
// playing editor's do (a time-sliced map redraws one face a frame, a map drawn once stays).

struct FrameRange {
    int first = 0;
    int last = 0;
    int count() const { return last - first + 1; }
};

inline constexpr int kMaxFrameNumber = 9999999;

// Where the frames go: an image sequence (a name with one printf-style frame number, "shot_%04d.png",
// in any format writeImage() writes) or a clip (.mp4, .webm, .gif).
struct AnimationOutput {
    std::string path;
    std::optional<render::video::VideoFormat> video; // none: an image sequence
};

// Reads OUT: a clip by its extension, else a sequence pattern. Errors name what is wrong: a sequence
// name without a frame number (or with two), an extension that is neither a clip's nor an image's.
base::Result<AnimationOutput> parseAnimationOutput(const std::string& out);

// The file of frame N of a sequence pattern ("shot_%04d.png", 7 → "shot_0007.png").
std::string sequenceFramePath(const std::string& pattern, int frame);

// The frame numbers a sequence pattern's files on disk hold, ascending (`speculum join`).
std::vector<int> framesOnDisk(const std::string& pattern);

// The shards of one sequence must split one range the same way, or their frames overlap (a frame drawn
// twice, by shards that disagree on which is whose) or leave gaps. Each shard leaves a record beside the
// frames, ".NAME.shard-K-of-N", holding the range and the layout; a shard whose range or layout differs
// from a record there is refused before it draws, and `join` refuses a sequence whose records disagree.
// A whole render of the range replaces the records (it draws every frame itself).
base::Status checkShardRecords(const std::string& pattern, const FrameRange& frames,
                               const base::Shard& shard);
base::Status recordShard(const std::string& pattern, const FrameRange& frames, const base::Shard& shard);
void clearShardRecords(const std::string& pattern, const FrameRange& frames);
// The records `join` checks: all alike, or an error naming two that differ.
base::Status checkShardRecordsAgree(const std::string& pattern);

struct AnimationSettings {
    StillExportSettings still; // size, supersampling, exact or raster, camera; `time` is each frame's
    FrameRange frames;
    int fps = 24;
    // Orbit the camera about its target once in this many seconds (a turntable): the frame after the last
    // of a clip of seconds × fps frames is the first again, so the clip loops without a seam.
    std::optional<double> turntableSeconds;
    base::Shard shard; // this machine's share of the frames (image sequences only)
};

// The scene time of frame N.
double frameTime(const AnimationSettings& settings, int frame);

// The camera orbited about its target, about its own up axis, by the turn `time` makes of a turn that
// lasts `turnSeconds`.
render::Camera turntableCamera(const render::Camera& camera, double turnSeconds, double time);

// Everything checked before any frame is drawn: the settings, the output (folder, format, codec, size),
// a shard only for sequences.
base::Status validateAnimationExport(const AnimationSettings& settings, const AnimationOutput& output);

struct AnimationProgress {
    int done = 0;          // frames finished
    int total = 0;         // frames this export writes
    int frame = 0;         // the frame being drawn
    double fraction = 0.0; // of the whole export, the frame being drawn included
    double elapsedSeconds = 0.0;
    double remainingSeconds = -1.0; // estimated from the frames so far; negative until there is one
};
// Returning false cancels the export at the next step.
using AnimationProgressCallback = std::function<bool(const AnimationProgress&)>;

// The scene at a time (the editor's document, the command line's project with its checked textures).
using FrameSource = std::function<render::FrameInput(double time)>;

struct AnimationResult {
    base::Status status = base::Done{};
    bool cancelled = false;
    std::vector<int> written;      // frames written to the sequence, or encoded into the clip
    std::optional<int> resumeFrom; // a sequence that stopped: the first frame it lacks
    // What a stop left and how to finish ("frames 0..37 are kept; resume with --frames 38..239", "no
    // clip was written"); the status's error ends with it.
    std::string outcome;
    int replayed = 0;                  // frames drawn only to bring the maps to where the clip has them
    std::vector<std::string> warnings; // each once, the first frame's
    double totalMs = 0.0;
    std::string renderer;           // what drew the frames
    std::vector<std::string> files; // what was written: the sequence's frames, or the clip
};

// Draws the frames of settings.shard and writes them. A sequence keeps every frame it finished when it
// stops (a failure, a cancel) and says which frame to resume from; a clip is written whole or not at all.
// `renderer` (its context current) draws raster frames; exact frames need none.
AnimationResult exportAnimation(render::Renderer* renderer, const FrameSource& source,
                                const std::string& projectPath, const AnimationSettings& settings,
                                const AnimationOutput& output, const AnimationProgressCallback& progress = {},
                                const std::string& rendererDescription = {});

} // namespace speculum::scene
