#pragma once

#include "accuracy/Results.hpp"
#include "accuracy/Sweep.hpp"
#include "accuracy/run/Measure.hpp"
#include "base/Result.hpp"
#include "render/renderer/Renderer.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace speculum::accuracy {

// The frame sizes the bench measures at: 480x270 quick, 1280x720 otherwise.
struct SweepSize {
    int width = 0;
    int height = 0;
};
SweepSize defaultSweepSize(bool quick);

// Timing runs in rounds: each round renders every distinct configuration once (after one untimed frame
// that absorbs the switch: new map textures, shader variants). Contention from other processes then
// spreads over all configurations alike instead of spoiling whichever one it happened to meet, and the
// median over rounds drops the rounds it hit.
struct SweepTiming {
    int warmUp; // untimed frames before a configuration's image is taken
    int rounds;
};
SweepTiming sweepTiming(bool quick); // 2 and 7 quick, 2 and 9 otherwise

// What a sweep measures: one frame of a scene, and how to swap its built-in teapots.
struct SweepInput {
    std::string sceneName; // for progress lines and RunInfo::sceneName: "chrome.speculum.json"
    render::FrameInput scene;
    std::optional<int> teapotTessellation; // of the (first) built-in teapot; none: the scene has none
    TessellateTeapot tessellate;           // called on the sweep's thread
    // The scene at its time and kPlayedFrames − 1 frames 1/60 s after it (animations evaluated), for the
    // update family; empty where nothing moves, or the caller plays none.
    std::vector<render::FrameInput> playedFrames;
    int width = 0; // 0: defaultSweepSize(quick)
    int height = 0;
    bool quick = false;
    // Measure only this share of the configurations (base::shardItems of sweepPlan's list): bench --shard.
    std::optional<base::Shard> shard;
};

// The configurations the sweep measures, in its order (planSweep on the scene's traits): a shard run's
// share is base::shardItems of this list.
std::vector<Configuration> sweepPlan(const SweepInput& input);

// What a running sweep tells its caller. Every callback is called on the thread running the sweep, and
// each may be empty.
struct SweepObserver {
    std::function<void(const std::string& line)> progress; // "tracing the scene reference: 25%"
    // Asked between frames and between the tracer's tiles: true stops the sweep within one frame.
    std::function<bool()> stop;
    // A reference was traced (before any configuration is rendered). An error ends the sweep with it.
    std::function<base::Status(const Reference& reference, const ReferenceInfo& info)> referenceTraced;
    // Configuration `index` of `total` was rendered and compared with its reference. Its times are of the
    // one frame rendered so far (the timing rounds come later); `cost.image` is that frame. An error ends
    // the sweep with it.
    std::function<base::Status(std::size_t index, std::size_t total, const Record& record,
                               const FrameCost& cost, const ErrorFigures& errors)>
        measured;
    // Timing round `round` of `rounds` ended: every record, its times the medians of the rounds so far.
    std::function<void(int round, int rounds, const std::vector<Record>& records)> timed;
};

// A finished sweep: the run's description (scene name, size, frames, references; the caller adds the
// project path and the renderer) and one record per configuration, in the order of planSweep. A shard's
// (SweepInput::shard) has the records of its share only, RunInfo::shard says which (the caller adds the
// project's digest and the host), and its records have no tiedWith nor flipToBest: those compare frames of
// other shards, and the merge finds them (compareFamily).
struct SweepOutcome {
    RunInfo run;
    std::vector<Record> records;
};

// What a stopped sweep returns as its error.
inline constexpr const char* kSweepStopped = "stopped";

// The bench's sweep: plans the configurations the scene calls for (planSweep), traces each reference they
// need, renders and compares every configuration once, then times all distinct configurations in rounds.
// A shard does the same for its share; the white furnace runs in the shard that measures the first glossy
// configuration.
// Needs `renderer`'s GL context current on the calling thread. Errors: a reference or a frame that fails,
// an observer's error, or kSweepStopped.
base::Result<SweepOutcome> runSweep(render::Renderer& renderer, const SweepInput& input,
                                    const SweepObserver& observer = {});

// One line for a log: "[3/40] envmap: cube 128: PSNR 31.20 dB, reflector 27.01 dB, 3.1 MiB".
std::string summaryLine(const std::string& step, const Record& record);

} // namespace speculum::accuracy
