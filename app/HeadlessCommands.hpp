#pragma once

#include "app/CliOptions.hpp"

namespace speculum::app {

// The commands that need no display. Each returns the process exit status: 0 success, 1 failure
// (one line on stderr naming what is wrong; no output file is left behind).
int runRender(const CliOptions& options);
int runExplain(const CliOptions& options);
int runBench(const CliOptions& options);
// `export PROJECT -o OUT.glb|OUT.gltf`: the scene as glTF 2.0 (scene::exportGltf); prints OUT.
int runExport(const CliOptions& options);

} // namespace speculum::app
