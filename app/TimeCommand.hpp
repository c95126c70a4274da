#pragma once

#include "app/CliOptions.hpp"

namespace speculum::app {

// `time PROJECT [--size WxH] [--frames N] [--animated] [--json]`: what the scene costs per frame, as a
// window would show it. Returns the exit status (0, or 1 with one line on stderr).
int runTime(const CliOptions& options);

} // namespace speculum::app
