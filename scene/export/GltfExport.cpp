#include "scene/export/GltfExport.hpp"

#include "base/AtomicFile.hpp"
#include "base/Printable.hpp"
#include "scene/export/GltfBuilder.hpp"

#include <QDir>
#include <QFileInfo>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace speculum::scene {

namespace fs = std::filesystem;

namespace {

void append32(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) {
        out.push_back(static_cast<unsigned char>(v >> (8 * i))); // GLB is little-endian
    }
}

// The GLB container (glTF 2.0, section 4.4): a 12-byte header, the JSON chunk padded with spaces to 4
// bytes, then the BIN chunk padded with zeros (left out when there is no binary data).
std::vector<unsigned char> glbContainer(const QByteArray& json, const std::vector<unsigned char>& bin) {
    const std::uint32_t jsonLength = (static_cast<std::uint32_t>(json.size()) + 3u) & ~3u;
    const std::uint32_t binLength = (static_cast<std::uint32_t>(bin.size()) + 3u) & ~3u;
    const std::uint32_t total = 12 + 8 + jsonLength + (bin.empty() ? 0 : 8 + binLength);
    std::vector<unsigned char> out;
    out.reserve(total);
    append32(out, 0x46546C67); // "glTF"
    append32(out, 2);
    append32(out, total);
    append32(out, jsonLength);
    append32(out, 0x4E4F534A); // "JSON"
    out.insert(out.end(), json.begin(), json.end());
    out.resize(20 + jsonLength, ' ');
    if (!bin.empty()) {
        append32(out, binLength);
        append32(out, 0x004E4942); // "BIN\0"
        out.insert(out.end(), bin.begin(), bin.end());
        out.resize(total, 0);
    }
    return out;
}

struct PendingFile {
    fs::path target;
    const unsigned char* data;
    std::size_t size;
};

// Writes every file to its own staged temporary (base::AtomicFile) and finishes them all (fsync, close)
// before any is renamed into place, `files.back()` last (the file that refers to the others). A full disk
// or any other failed write stops the export while every previous file is still untouched, and no
// temporary stays behind (AtomicFile removes its own).
base::Status writeAllOrNothing(const std::vector<PendingFile>& files) {
    std::vector<base::AtomicFile> staged;
    staged.reserve(files.size());
    for (const PendingFile& f : files) {
        base::Result<base::AtomicFile> file = base::AtomicFile::create(f.target.string());
        if (!file) {
            return base::Error{file.error()};
        }
        if (base::Status s = file->write(f.data, f.size); !s) {
            return s;
        }
        if (base::Status s = file->finish(); !s) {
            return s;
        }
        staged.push_back(std::move(file).value());
    }
    for (base::AtomicFile& file : staged) {
        // Only a rename can fail here (in the same folder, after every byte is on disk): rare, and the
        // companions renamed so far are complete files of this export.
        if (base::Status s = file.commit(); !s) {
            return s;
        }
    }
    return base::Done{};
}

} // namespace

base::Status exportGltf(const Scene& scene, const QString& path, MeshLibrary& meshes,
                        std::vector<std::string>& warnings) {
    const QFileInfo info(path);
    const QString suffix = info.suffix().toLower();
    if (suffix != QStringLiteral("gltf") && suffix != QStringLiteral("glb")) {
        return base::Error{base::printable(path.toStdString(), 200) + ": expected a .gltf or .glb file name"};
    }
    if (!info.absoluteDir().exists()) {
        return base::Error{base::printable(path.toStdString(), 200) + ": folder " +
                           base::printable(info.absolutePath().toStdString(), 200) + " does not exist"};
    }
    if (info.isDir()) {
        return base::Error{base::printable(path.toStdString(), 200) + ": is a folder"};
    }
    const fs::path target = fs::absolute(fs::path(path.toStdString()));
    const fs::path folder = target.parent_path();
    // Companion names keep to letters, digits, '.', '-' and '_': their URIs then need no percent-encoding,
    // which some readers (Assimp 5.2) do not decode.
    std::string stem = target.stem().string();
    for (char& c : stem) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') {
            c = '_';
        }
    }

    GltfLayout layout;
    layout.binary = suffix == QStringLiteral("glb");
    layout.binUri = stem + ".bin";
    layout.imageStem = stem;
    const GltfAsset asset = buildGltf(scene, meshes, layout, warnings);

    std::vector<PendingFile> files;
    std::vector<unsigned char> glb;
    if (layout.binary) {
        glb = glbContainer(asset.json, asset.bin);
        files.push_back({target, glb.data(), glb.size()});
    } else {
        if (!asset.bin.empty()) {
            files.push_back({folder / layout.binUri, asset.bin.data(), asset.bin.size()});
        }
        for (const GltfAsset::ImageFile& image : asset.imageFiles) {
            files.push_back({folder / image.fileName, image.image.bytes.data(), image.image.bytes.size()});
        }
        files.push_back({target, reinterpret_cast<const unsigned char*>(asset.json.constData()),
                         static_cast<std::size_t>(asset.json.size())});
    }
    return writeAllOrNothing(files);
}

} // namespace speculum::scene
