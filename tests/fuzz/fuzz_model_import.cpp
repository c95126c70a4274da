// libFuzzer target for model import: any bytes, written to a file named after the format they
// look like, must import or be refused with a one-line message naming the file — never crash, hang,
// overflow the stack or exhaust memory (run with -rss_limit_mb and -timeout, see scripts/fuzz). For a
// glTF input the buffers and images it names are written next to it (a triangle's floats, a 1x1 PNG) so
// the fuzzer gets past "file not found" into the readers; an OBJ's mtllib gets a small material library.
// The read runs in a child process (ModelImportProcess): a crash or hang inside Assimp is a refusal, not
// a finding, and the CPU limit is set low so that a hang ends well inside libFuzzer's -timeout.
#include "scene/import/ModelImport.hpp"
#include "scene/import/ModelPrecheck.hpp"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using speculum::scene::detail::ModelContent;

const fs::path& folder() {
    static const fs::path dir = [] {
        std::string pattern = (fs::temp_directory_path() / "speculum-fuzz-model-XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) {
            std::abort();
        }
        return fs::path(pattern);
    }();
    return dir;
}

// Only a plain file name inside the fuzz folder: "../x", "/etc/passwd" or "a/b" are not written.
bool plainName(const std::string& name) {
    if (name.empty() || name.size() > 64 || name == "." || name == "..") {
        return false;
    }
    for (char c : name) {
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) {
            return false;
        }
    }
    return true;
}

void writeFile(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

std::string triangleBytes(std::size_t size) {
    const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::string one(reinterpret_cast<const char*>(p), sizeof p);
    std::string out;
    out.reserve(size);
    while (out.size() < size) {
        out += one.substr(0, size - out.size());
    }
    return out;
}

// A 1x1 RGB PNG.
const unsigned char kPngBytes[] = {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d,
                                   0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01,
                                   0x08, 0x02, 0x00, 0x00, 0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00,
                                   0x0c, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xdf, 0xc0, 0x00,
                                   0x00, 0x04, 0x01, 0x01, 0x80, 0xc5, 0x2a, 0x18, 0x5d, 0x00, 0x00, 0x00,
                                   0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
const std::string kPng(reinterpret_cast<const char*>(kPngBytes), sizeof kPngBytes);

// The files a glTF names, written next to it; returns their paths for removal.
std::vector<fs::path> writeGltfReferences(const QByteArray& json) {
    std::vector<fs::path> written;
    const QJsonObject top = QJsonDocument::fromJson(json).object();
    for (const char* key : {"buffers", "images"}) {
        for (const QJsonValue& entry : top.value(QLatin1String(key)).toArray()) {
            const std::string uri = entry.toObject().value(QStringLiteral("uri")).toString().toStdString();
            if (!plainName(uri)) {
                continue;
            }
            const double length = entry.toObject().value(QStringLiteral("byteLength")).toDouble(64);
            const fs::path path = folder() / uri;
            writeFile(path, std::string(key) == "images"
                                ? kPng
                                : triangleBytes(static_cast<std::size_t>(std::clamp(length, 0.0, 1e6))));
            written.push_back(path);
        }
    }
    return written;
}

std::vector<fs::path> writeObjReferences(const std::string& text) {
    std::vector<fs::path> written;
    std::istringstream lines(text.substr(0, 65536));
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string keyword, name;
        if (words >> keyword >> name && keyword == "mtllib" && plainName(name)) {
            const fs::path path = folder() / name;
            writeFile(path, "newmtl m\nKd 0.8 0.2 0.2\nmap_Kd t.png\n");
            writeFile(folder() / "t.png", kPng);
            written.push_back(path);
        }
    }
    return written;
}

const char* extensionFor(ModelContent content) {
    switch (content) {
    case ModelContent::GltfJson:
        return ".gltf";
    case ModelContent::Glb:
        return ".glb";
    case ModelContent::Xml:
        return ".dae";
    case ModelContent::Off:
        return ".off";
    case ModelContent::Ply:
        return ".ply";
    case ModelContent::FbxBinary:
        return ".fbx";
    case ModelContent::Text:
        return ".obj";
    case ModelContent::Unknown:
        break;
    }
    return ".bin";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace speculum::scene;
    speculum::scene::setModelImportCpuLimit(5);
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const ModelContent content = speculum::scene::detail::identifyModelContent(bytes.data(), bytes.size());
    const fs::path model = folder() / (std::string("model") + extensionFor(content));
    writeFile(model, bytes);
    std::vector<fs::path> references;
    if (content == ModelContent::GltfJson) {
        references = writeGltfReferences(QByteArray::fromRawData(bytes.data(), qsizetype(bytes.size())));
    } else if (content == ModelContent::Text) {
        references = writeObjReferences(bytes);
    }
    std::vector<std::string> warnings;
    const auto imported = speculum::scene::importModelFile(model.string(), warnings);
    if (imported.ok()) {
        (void)speculum::scene::flattenModel(*imported);
        (void)speculum::scene::modelNodeTree(*imported, model.string(), "model", &warnings);
    } else {
        // Every refusal names the file, in one line.
        const std::string& message = imported.error();
        if (message.rfind(model.filename().string() + ": ", 0) != 0 ||
            message.find('\n') != std::string::npos) {
            std::abort();
        }
    }
    std::error_code ec;
    fs::remove(model, ec);
    for (const fs::path& path : references) {
        fs::remove(path, ec);
    }
    return 0;
}
