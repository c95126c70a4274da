#pragma once

#include "base/Result.hpp"

#include <cstdint>
#include <filesystem>

namespace speculum::scene::detail {

// Deeper node hierarchies than this are treated as broken: no real model needs them, and every reader
// (Assimp's and ours) walks them recursively.
constexpr int kMaxNodeDepth = 1024;
// How many nodes a file may unfold into. Each aiNode costs over 1 KB (name, matrix, metadata) and each
// becomes a scene node in the editor; 100 000 is far beyond any real model (the largest in Assimp's test
// set has a few thousand) and still a few hundred MB at worst.
constexpr double kMaxNodeInstances = 100000;
// Deeper nesting than this of braces, brackets, XML elements or binary FBX records is refused: readers
// parse nesting recursively, and 1024 levels is far beyond what any exporter writes.
constexpr int kMaxNesting = 1024;

// What the file is, judged by its content (Assimp too picks its reader by content, whatever the name).
enum class ModelContent { Unknown, GltfJson, Glb, Xml, Off, Ply, FbxBinary, Text };
ModelContent identifyModelContent(const char* bytes, std::size_t size);

// Checks a model file before Assimp reads it, for what would exhaust memory, time or the stack inside
// Assimp: a glTF or Collada node graph that is a DAG unfolding into billions of nodes, a cycle, a node
// chain or nesting deeper than the limits above, OFF/PLY headers that declare more elements than the
// file has bytes. Identifies the format by content. The error is one line naming the cause ("the node
// graph unfolds into more than 100000 node instances (nodes[3] is reached 2^40 ways)"), without the
// file name. Opens the file without blocking and only if it is a regular file.
base::Status precheckModel(const std::filesystem::path& file);

// The same on bytes in memory (the fuzz target and tests use it directly).
base::Status precheckModelBytes(const char* bytes, std::size_t size);

} // namespace speculum::scene::detail
