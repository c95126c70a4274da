#pragma once

#include "accuracy/Results.hpp"
#include "accuracy/Sweep.hpp"
#include "accuracy/run/Measure.hpp"
#include "base/Result.hpp"
#include "render/image/Image.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace speculum::accuracy {

// What a shard run (bench --shard) keeps beside its results so that the merge can compare its frames with
// other shards' (compareFamily): each configuration's frame and each reference, exactly, as floats (an EXR
// is half, a PNG 8-bit, and a tie test on rounded values would not be the one-machine run's). zlib
// compressed, written all or nothing (base::AtomicFile).

// Relative to the shard's output folder: "shard/frame-<id>.bin", "shard/reference-<name>.bin".
inline constexpr const char* kShardFolder = "shard";
std::string shardFrameFile(const std::string& configurationId);
std::string shardReferenceFile(ReferenceKind kind);

base::Status writeShardFrame(const std::string& path, const render::Image& frame);
// Errors: "<path>: cannot read (...)", "<path>: not a frame a bench shard wrote".
base::Result<render::Image> readShardFrame(const std::string& path);

// The reference's exact image, its noise and its mirror and reflector masks: what errors and ties use.
base::Status writeShardReference(const std::string& path, const Reference& reference);
base::Result<Reference> readShardReference(const std::string& path, ReferenceKind kind);

// The merge's part of a sweep (bench --merge): Record::tiedWith and Record::flipToBest of every family
// (compareFamily), from the frames kept in each record's shard folder (`recordFolder`, per record) and the
// references kept in `referenceFolder`'s. One family's frames are in memory at a time.
base::Status compareShardFrames(std::vector<Record>& records,
                                const std::vector<std::filesystem::path>& recordFolder,
                                const std::map<ReferenceKind, std::filesystem::path>& referenceFolder,
                                const std::function<void(const std::string&)>& progress = {});

} // namespace speculum::accuracy
