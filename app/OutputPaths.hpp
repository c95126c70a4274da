#pragma once

#include "base/Result.hpp"

#include <string>
#include <vector>

namespace speculum::app {

// Checks on where a command writes, made before any work and without throwing (every std::filesystem
// call here takes an error_code: a symlink loop or an over-long name is an error message, not an abort).

// OUT's folder exists and is a folder, and every component of OUT fits the file system's name limit.
base::Status checkOutputFile(const std::string& output);

// OUT is none of `inputs` (the project, the models and textures it reads), by identity of the file, so a
// symlink or a hard link to an input is refused too. `companions` are further names the command writes
// beside OUT (a .gltf's .bin and images), checked the same way: "OUT.bin", and prefixes ending in '_'
// ("OUT_" matches any input whose name starts with it, in OUT's folder).
base::Status checkNotAnInput(const std::string& output, const std::vector<std::string>& inputs,
                             const std::vector<std::string>& companions = {});

// bench --out DIR: not a file, its name fits, and it holds none of `inputs` at any depth (bench replaces
// its own files and sub-folders inside DIR, which must never take an input with them).
base::Status checkOutputFolder(const std::string& folder, const std::vector<std::string>& inputs);

} // namespace speculum::app
