#pragma once

#include "app/CliOptions.hpp"

namespace speculum::app {

// `render PROJECT --frames A..B|--turntable SECONDS -o OUT`: an image sequence or a clip
// (scene::exportAnimation), raster on an EGL context or exact with --reference; --shard K/N draws one
// share of the frames. Prints each file written (a clip: its path; a sequence: its pattern and range).
// Returns 0, 1 after one line (a sequence says which frames it kept and where to resume), or 130.
int runAnimation(const CliOptions& options);

// `join SEQUENCE -o CLIP [--frames A..B] [--fps N]`: encodes a finished sequence, refusing one with a
// missing frame or frames of another size or another clip's settings before anything is written.
int runJoin(const CliOptions& options);

} // namespace speculum::app
