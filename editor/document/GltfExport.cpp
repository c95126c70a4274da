#include "editor/document/GltfExport.hpp"

#include "editor/document/GltfBuilder.hpp"

#include <QDir>
#include <QFileInfo>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace speculum::document {

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
    fs::path temp;
};

// Writes every file to a temporary sibling, then renames them into place, `files.back()` last (the file
// that refers to the others). On failure nothing new is left behind.
render::Status writeAllOrNothing(std::vector<PendingFile>& files) {
    static int counter = 0;
    auto removeTemps = [&] {
        std::error_code ignored;
        for (const PendingFile& f : files) {
            if (!f.temp.empty()) {
                fs::remove(f.temp, ignored);
            }
        }
    };
    for (PendingFile& f : files) {
        f.temp = f.target.parent_path() / ("." + f.target.filename().string() + ".tmp-" +
                                           std::to_string(::getpid()) + "-" + std::to_string(++counter));
        std::ofstream out(f.temp, std::ios::binary | std::ios::trunc);
        if (out) {
            out.write(reinterpret_cast<const char*>(f.data), static_cast<std::streamsize>(f.size));
            out.close();
        }
        if (!out) {
            const std::string reason = std::strerror(errno);
            removeTemps();
            return render::Error{f.target.string() + ": cannot write the file: " + reason};
        }
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::error_code ec;
        fs::rename(files[i].temp, files[i].target, ec);
        if (ec) {
            removeTemps();
            // Companions already moved would point nowhere without the main file: take them back out.
            std::error_code ignored;
            for (std::size_t j = 0; j < i; ++j) {
                fs::remove(files[j].target, ignored);
            }
            return render::Error{files[i].target.string() +
                                 ": cannot move the finished file into place: " + ec.message()};
        }
        files[i].temp.clear();
    }
    return render::Done{};
}

} // namespace

render::Status exportGltf(const Scene& scene, const QString& path, MeshLibrary& meshes,
                          std::vector<std::string>& warnings) {
    const QFileInfo info(path);
    const QString suffix = info.suffix().toLower();
    if (suffix != QStringLiteral("gltf") && suffix != QStringLiteral("glb")) {
        return render::Error{path.toStdString() + ": expected a .gltf or .glb file name"};
    }
    if (!info.absoluteDir().exists()) {
        return render::Error{path.toStdString() + ": folder " + info.absolutePath().toStdString() +
                             " does not exist"};
    }
    if (info.isDir()) {
        return render::Error{path.toStdString() + ": is a folder"};
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
        files.push_back({target, glb.data(), glb.size(), {}});
    } else {
        if (!asset.bin.empty()) {
            files.push_back({folder / layout.binUri, asset.bin.data(), asset.bin.size(), {}});
        }
        for (const GltfAsset::ImageFile& image : asset.imageFiles) {
            files.push_back(
                {folder / image.fileName, image.image.bytes.data(), image.image.bytes.size(), {}});
        }
        files.push_back({target,
                         reinterpret_cast<const unsigned char*>(asset.json.constData()),
                         static_cast<std::size_t>(asset.json.size()),
                         {}});
    }
    return writeAllOrNothing(files);
}

} // namespace speculum::document
