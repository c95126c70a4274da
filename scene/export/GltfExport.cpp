#include "scene/export/GltfExport.hpp"

#include "base/AtomicFile.hpp"
#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "scene/export/GltfBuilder.hpp"

#include <QDir>
#include <QFileInfo>
#include <cctype>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tiny_gltf.h>
#include <utility>

namespace speculum::scene {

namespace fs = std::filesystem;

namespace {

// A previous .gltf is read only for the names of its companions; one larger than this is not ours.
constexpr std::size_t kMaxPreviousGltfBytes = std::size_t(256) << 20;

// The .glb whole (header, JSON chunk, BIN chunk) or the .gltf's JSON, compact, as tinygltf writes them.
std::string serialize(const tinygltf::Model& model, bool binary) {
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/false, /*writeBinary=*/binary) || !out) {
        throw std::runtime_error("tinygltf could not write it");
    }
    return std::move(out).str();
}

// tinygltf writes a .gltf's buffers into its JSON as base64 data URIs; its file writer, the one that refers
// to a .bin instead, writes the files itself, in place and without checking them. So the buffers go
// through it empty, and their entries get their length and their file's URI afterwards.
std::string gltfJson(tinygltf::Model& model) {
    std::vector<std::vector<unsigned char>> data;
    for (tinygltf::Buffer& buffer : model.buffers) {
        data.push_back(std::exchange(buffer.data, {}));
    }
    const std::string text = serialize(model, false);
    nlohmann::json doc = nlohmann::json::parse(text);
    for (std::size_t i = 0; i < model.buffers.size(); ++i) {
        model.buffers[i].data = std::move(data[i]);
        doc["buffers"][i]["byteLength"] = model.buffers[i].data.size();
        doc["buffers"][i]["uri"] = model.buffers[i].uri;
    }
    return doc.dump();
}

base::Result<std::string> document(tinygltf::Model& model, bool binary) {
    try {
        return binary ? serialize(model, true) : gltfJson(model);
    } catch (const std::exception& e) { // the JSON library's, or out of memory
        return base::Error{std::string("cannot write the glTF document: ") + e.what()};
    }
}

struct PendingFile {
    fs::path target;
    const unsigned char* data;
    std::size_t size;
};

// Writes every file to its own staged temporary (base::AtomicFile), then replaces the previous set as one
// (base::commitTogether), `files.back()` (the file that refers to the others) last: a full disk, a failed
// rename or any other failure leaves every previous file as it was, and no temporary behind.
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
        staged.push_back(std::move(file).value());
    }
    return base::commitTogether(staged);
}

// The file names a previous .gltf at `target` refers to (its buffers' and images' relative URIs): the
// companions an earlier export wrote, which this one may replace. Empty for no file, a .glb or a file that
// does not parse (nothing beside it is then known to be the export's).
std::set<std::string> previousCompanions(const fs::path& target) {
    std::set<std::string> names;
    base::Result<std::string> text = base::readRegularFile(target.string(), kMaxPreviousGltfBytes);
    if (!text) {
        return names;
    }
    const nlohmann::json doc = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object()) {
        return names;
    }
    for (const char* list : {"buffers", "images"}) {
        const auto entries = doc.find(list);
        if (entries == doc.end() || !entries->is_array()) {
            continue;
        }
        for (const nlohmann::json& entry : *entries) {
            const auto uri = entry.is_object() ? entry.find("uri") : entry.end();
            if (entry.is_object() && uri != entry.end() && uri->is_string()) {
                names.insert(fs::path(uri->get<std::string>()).filename().string());
            }
        }
    }
    return names;
}

// Files beside the target this export would replace that the previous export did not write.
std::vector<std::string> unrelatedFiles(const std::vector<PendingFile>& files) {
    const fs::path& target = files.back().target;
    const std::set<std::string> ours = previousCompanions(target);
    std::vector<std::string> unrelated;
    for (std::size_t i = 0; i + 1 < files.size(); ++i) {
        std::error_code error;
        if (fs::exists(files[i].target, error) && !ours.count(files[i].target.filename().string())) {
            unrelated.push_back(files[i].target.string());
        }
    }
    return unrelated;
}

} // namespace

base::Status exportGltf(const Scene& scene, const QString& path, MeshLibrary& meshes,
                        std::vector<std::string>& warnings, const ReplaceUnrelatedFiles& mayReplace) {
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
    GltfAsset asset = buildGltf(scene, meshes, layout, warnings);
    const base::Result<std::string> written = document(asset.model, layout.binary);
    if (!written) {
        return base::Error{base::printable(path.toStdString(), 200) + ": " + written.error()};
    }

    std::vector<PendingFile> files;
    if (!layout.binary) {
        if (!asset.model.buffers.empty()) { // the scene's one buffer, when it has binary data
            const std::vector<unsigned char>& bin = asset.model.buffers[0].data;
            files.push_back({folder / layout.binUri, bin.data(), bin.size()});
        }
        for (const GltfAsset::ImageFile& image : asset.imageFiles) {
            files.push_back({folder / image.fileName, image.image.bytes.data(), image.image.bytes.size()});
        }
    }
    files.push_back({target, reinterpret_cast<const unsigned char*>(written->data()), written->size()});
    if (const std::vector<std::string> unrelated = unrelatedFiles(files);
        !unrelated.empty() && !(mayReplace && mayReplace(unrelated))) {
        return base::Error{base::printable(unrelated.front(), 200) +
                           " exists and is not part of an earlier " + "export to " +
                           base::printable(target.filename().string(), 200) +
                           (unrelated.size() > 1 ? " (nor " + std::to_string(unrelated.size() - 1) + " more)"
                                                 : std::string()) +
                           "; move it or export under another name; nothing was written"};
    }
    return writeAllOrNothing(files);
}

} // namespace speculum::scene
