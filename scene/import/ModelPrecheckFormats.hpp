#pragma once

// The prechecks of ModelPrecheck by format family, for its dispatch by content (ModelPrecheck.cpp, which
// also checks the nesting of text formats and binary FBX): the node graphs Assimp unfolds, of glTF and XML
// (ModelPrecheckGraph.cpp), and the element counts OFF and PLY headers declare (ModelPrecheckCounts.cpp).
// Internal to the import library.
#include "base/Result.hpp"
#include "scene/import/ModelPrecheck.hpp"

#include <QByteArray>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace speculum::scene::detail::precheck {

inline std::string depthError(const char* what) {
    return std::string(what) + " nested deeper than " + std::to_string(kMaxNesting) + " levels";
}

inline std::uint32_t readU32(const char* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4); // little-endian on every platform speculum builds for
    return v;
}

inline std::uint64_t readU64(const char* p) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    return v;
}

// glTF 1 and 2 (JSON; .glb holds the same JSON in its first chunk): the node graph, and no key twice in
// one object.
base::Status checkGltfJson(const QByteArray& json);
base::Status checkGlb(const char* bytes, std::size_t size);
// XML (Collada, X3D, AMF, XGL, Ogre XML, Irrlicht, ...): element depth, and Collada/X3D node instances.
base::Status checkXml(const char* bytes, std::size_t size);

// The length of the [ST][C][N][4][n]OFF keyword the word starts with, 0 for none.
std::size_t offKeywordLength(std::string word);
// The first word of the file, '#' comments skipped.
std::string firstWord(const char* bytes, std::size_t size);
// A header that declares more elements than the file has bytes is refused.
base::Status checkPly(const char* bytes, std::size_t size);
base::Status checkOff(const char* bytes, std::size_t size);

} // namespace speculum::scene::detail::precheck
