#pragma once

#include <assimp/DefaultIOSystem.h>
#include <string>

namespace speculum::scene::detail {

// The file access Assimp gets while reading a model: the model itself and every file it references
// (glTF buffers and images, OBJ mtllib, ...). Only regular files open: a FIFO, a device, /dev/stdin or a
// symlink to one would block the reader for good (or, for /dev/zero, feed it without end). The file is
// opened without blocking and checked on the descriptor, so nothing swapped in after a check can block
// either. The first refusal is remembered so that the import error names the referenced file rather
// than Assimp's generic "cannot open".
class ModelIoSystem : public Assimp::DefaultIOSystem {
public:
    // `modelPath`: referenced files are named relative to its folder in refusals.
    explicit ModelIoSystem(std::string modelPath);

    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;
    // DefaultIOSystem's Exists() opens the file with fopen, which blocks on a FIFO; this only stats it
    // (a FIFO exists, and Open() then refuses it with a message).
    bool Exists(const char* file) const override;

    // "referenced file 'data.bin': it is a FIFO (named pipe), not a regular file", or "" when nothing
    // was refused.
    const std::string& refusal() const { return m_refusal; }

private:
    std::string m_modelPath;
    std::string m_refusal;
};

} // namespace speculum::scene::detail
