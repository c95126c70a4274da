#include "scene/import/ModelPrecheck.hpp"

#include "base/FileKind.hpp"
#include "scene/import/ModelPrecheckFormats.hpp"

#include <QByteArray>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

// The dispatch by content, and the nesting checks of text formats and binary FBX; the other format
// families' checks are in ModelPrecheckGraph.cpp and ModelPrecheckCounts.cpp.
namespace speculum::scene::detail {
namespace {

using base::Error;
using precheck::depthError;
using precheck::readU32;
using precheck::readU64;

// ---------------------------------------------------------------------------------------------------
// Text formats nested with braces, brackets or parentheses (ASCII FBX, text .x, OpenGEX, ASE, MD5,
// IFC/STEP, ...): their parsers recurse once per level. A NUL byte means a binary file: not checked.
base::Status checkTextNesting(const char* bytes, std::size_t size) {
    int depth = 0;
    bool quoted = false;
    for (std::size_t i = 0; i < size; ++i) {
        const char c = bytes[i];
        switch (c) {
        case '\0':
            return base::Done{};
        case '\n':
            quoted = false; // an unterminated string does not hide the rest of the file
            break;
        case '"':
            quoted = !quoted;
            break;
        case '{':
        case '[':
        case '(':
            if (!quoted && ++depth > kMaxNesting) {
                return Error{depthError("braces, brackets or parentheses")};
            }
            break;
        case '}':
        case ']':
        case ')':
            if (!quoted && depth > 0) {
                --depth;
            }
            break;
        default:
            break;
        }
    }
    return base::Done{};
}

// Binary FBX: records (end offset, property count and length, name) holding nested records up to their
// end offset. Walked with a stack of open end offsets; a corrupt record stops the walk (Assimp refuses it).
base::Status checkFbxBinary(const char* bytes, std::size_t size) {
    if (size < 27) {
        return base::Done{};
    }
    const bool wide = readU32(bytes + 23) >= 7500; // 64-bit offsets from FBX 7.5
    const std::size_t header = wide ? 25 : 13;
    std::vector<std::uint64_t> ends;
    std::uint64_t pos = 27;
    while (true) {
        while (!ends.empty() && pos >= ends.back()) {
            pos = ends.back();
            ends.pop_back();
        }
        if (pos + header > size) {
            return base::Done{};
        }
        const char* p = bytes + pos;
        const std::uint64_t end = wide ? readU64(p) : readU32(p);
        const std::uint64_t propertyBytes = wide ? readU64(p + 16) : readU32(p + 8);
        const auto nameLength = static_cast<unsigned char>(p[header - 1]);
        if (end == 0) { // the null record that closes a list
            if (ends.empty()) {
                return base::Done{};
            }
            pos += header;
            continue;
        }
        if (end <= pos || end > size || (!ends.empty() && end > ends.back()) || propertyBytes > size) {
            return base::Done{};
        }
        const std::uint64_t childStart = pos + header + nameLength + propertyBytes;
        if (childStart < end) {
            ends.push_back(end);
            if (ends.size() > static_cast<std::size_t>(kMaxNesting)) {
                return Error{depthError("FBX records")};
            }
            pos = childStart;
        } else {
            pos = end;
        }
    }
}

bool startsWith(const char* bytes, std::size_t size, const char* prefix) {
    const std::size_t n = std::strlen(prefix);
    return size >= n && std::memcmp(bytes, prefix, n) == 0;
}

} // namespace

using precheck::checkGlb;
using precheck::checkGltfJson;
using precheck::checkOff;
using precheck::checkPly;
using precheck::checkXml;
using precheck::firstWord;
using precheck::offKeywordLength;

ModelContent identifyModelContent(const char* bytes, std::size_t size) {
    if (startsWith(bytes, size, "glTF")) {
        return ModelContent::Glb;
    }
    if (startsWith(bytes, size, "Kaydara FBX Binary")) {
        return ModelContent::FbxBinary;
    }
    if (startsWith(bytes, size, "ply")) {
        return ModelContent::Ply;
    }
    std::size_t i = startsWith(bytes, size, "\xEF\xBB\xBF") ? 3 : 0;
    while (i < size && i < 4096 && std::isspace(static_cast<unsigned char>(bytes[i]))) {
        ++i;
    }
    if (i < size && bytes[i] == '{') {
        return ModelContent::GltfJson;
    }
    if (i < size && bytes[i] == '<') {
        return ModelContent::Xml;
    }
    if (offKeywordLength(firstWord(bytes, size)) > 0) {
        return ModelContent::Off;
    }
    if (std::memchr(bytes, '\0', std::min<std::size_t>(size, 65536)) == nullptr) {
        return ModelContent::Text;
    }
    return ModelContent::Unknown;
}

base::Status precheckModelBytes(const char* bytes, std::size_t size) {
    switch (identifyModelContent(bytes, size)) {
    case ModelContent::Glb:
        return checkGlb(bytes, size);
    case ModelContent::GltfJson: {
        // A JSON file is glTF for Assimp; anything else starting with '{' is checked as nested text.
        const base::Status nesting = checkTextNesting(bytes, size);
        if (!nesting) {
            return nesting;
        }
        return checkGltfJson(QByteArray::fromRawData(bytes, static_cast<qsizetype>(size)));
    }
    case ModelContent::Xml:
        return checkXml(bytes, size);
    case ModelContent::FbxBinary:
        return checkFbxBinary(bytes, size);
    case ModelContent::Ply:
        return checkPly(bytes, size);
    case ModelContent::Off:
        return checkOff(bytes, size);
    case ModelContent::Text:
        return checkTextNesting(bytes, size);
    case ModelContent::Unknown:
        break;
    }
    return base::Done{};
}

base::Status precheckModel(const std::filesystem::path& file) {
    // O_NONBLOCK and fstat on the opened descriptor: a FIFO swapped in after the caller's check still
    // cannot block here.
    const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        return base::requireRegularFile(file);
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        return Error{"it is not a regular file"};
    }
    const auto size = static_cast<std::size_t>(info.st_size);
    if (size == 0) {
        return base::Done{};
    }
    // Mapped, not read: a large binary model costs no copy, and the whole-file scans read it once.
    void* mapped = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    if (mapped == MAP_FAILED) {
        return Error{std::string("cannot map the file: ") + std::strerror(errno)};
    }
    const base::Status status = precheckModelBytes(static_cast<const char*>(mapped), size);
    ::munmap(mapped, size);
    return status;
}

} // namespace speculum::scene::detail
