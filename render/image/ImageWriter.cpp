#include "render/image/ImageWriter.hpp"

#include "render/image/ColorSpace.hpp"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <atomic>
#include <cassert>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace speculum::render {

namespace fs = std::filesystem;

namespace {

enum class Encoding { Srgb8, LinearHalf };

struct Format {
    Encoding encoding;
    bool keepsAlpha;
    bool keepsCustomKeys; // PNG (tEXt) and EXR store any string attribute; TIFF and JPEG drop unknown ones
};

struct Extension {
    const char* name;
    Format format;
};

constexpr Extension kExtensions[] = {
    {".png", {Encoding::Srgb8, true, true}},    {".jpg", {Encoding::Srgb8, false, false}},
    {".jpeg", {Encoding::Srgb8, false, false}}, {".tif", {Encoding::Srgb8, true, false}},
    {".tiff", {Encoding::Srgb8, true, false}},  {".exr", {Encoding::LinearHalf, true, true}},
};

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::optional<Format> formatFor(const std::string& path) {
    const std::string ext = lowerExtension(path);
    for (const Extension& e : kExtensions) {
        if (ext == e.name) {
            return e.format;
        }
    }
    return std::nullopt;
}

Error failure(const std::string& path, const std::string& reason) {
    return Error{"cannot write '" + path + "': " + reason};
}

// OIIO messages may span lines or end in a newline; the CLI wants one line.
std::string oneLine(std::string message) {
    std::replace(message.begin(), message.end(), '\n', ' ');
    while (!message.empty() && message.back() == ' ') {
        message.pop_back();
    }
    return message.empty() ? std::string("unknown OpenImageIO error") : message;
}

// A hidden sibling that keeps the real extension last, so OIIO picks the same format for it.
std::optional<fs::path> temporarySibling(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    std::random_device entropy;
    const fs::path folder = target.parent_path();
    for (int attempt = 0; attempt < 64; ++attempt) {
        char tag[32];
        std::snprintf(tag, sizeof tag, "%x%x%x", static_cast<unsigned>(::getpid()), entropy(),
                      counter.fetch_add(1));
        const fs::path candidate =
            folder / ("." + target.filename().string() + ".tmp-" + tag + target.extension().string());
        std::error_code ec;
        if (!fs::exists(candidate, ec) && !ec) {
            return candidate;
        }
    }
    return std::nullopt;
}

// Removes the temporary file on every early return; release() once it has been renamed.
class TemporaryFile {
public:
    explicit TemporaryFile(fs::path path)
        : m_path(std::move(path)) {}
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    ~TemporaryFile() {
        if (!m_path.empty()) {
            std::error_code ignored;
            fs::remove(m_path, ignored);
        }
    }
    const fs::path& path() const { return m_path; }
    void release() { m_path.clear(); }

private:
    fs::path m_path;
};

} // namespace

Status checkImageTarget(const std::string& path, int width, int height) {
    if (!formatFor(path)) {
        const std::string ext = fs::path(path).extension().string();
        const std::string what =
            ext.empty() ? std::string("no file extension") : "unsupported format '" + ext + "'";
        return failure(path, what + " (supported: " + supportedImageFormats() + ")");
    }
    if (width <= 0 || height <= 0) {
        return failure(path,
                       "the image is empty (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    }
    // libjpeg's limit; OIIO 2.4's JPEG writer reports it by exiting the process, so it must be caught here.
    constexpr int kMaxJpegSide = 65500;
    const std::string ext = lowerExtension(path);
    if ((ext == ".jpg" || ext == ".jpeg") && (width > kMaxJpegSide || height > kMaxJpegSide)) {
        return failure(path, "JPEG cannot hold images larger than " + std::to_string(kMaxJpegSide) +
                                 " pixels per side");
    }
    const fs::path target(path);
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code ec;
    const fs::file_status folderStatus = fs::status(folder, ec);
    if (!fs::exists(folderStatus)) {
        return failure(path, "folder '" + folder.string() + "' does not exist");
    }
    if (!fs::is_directory(folderStatus)) {
        return failure(path, "'" + folder.string() + "' is not a folder");
    }
    if (::access(folder.c_str(), W_OK | X_OK) != 0) {
        return failure(path, "folder '" + folder.string() + "' is not writable");
    }
    if (fs::is_directory(fs::status(target, ec))) {
        return failure(path, "a folder of that name exists");
    }
    return Done{};
}

namespace {

// The single place that talks to OIIO for output. `pixels` are interleaved, `channels` per pixel, of
// type `memoryType`; OIIO converts them to the file type the format calls for (uint8 or half).
Status writeAtomically(const std::string& path, int width, int height, int channels,
                       OIIO::TypeDesc memoryType, const void* pixels, const Format& format,
                       const ImageMetadata& metadata) {
    const fs::path target(path);
    const std::optional<fs::path> tempPath = temporarySibling(target);
    if (!tempPath) {
        return failure(path, "could not choose a temporary file name");
    }
    TemporaryFile temp(*tempPath);

    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(temp.path().string());
    if (!out) {
        return failure(path, oneLine(OIIO::geterror()));
    }

    const bool srgb = format.encoding == Encoding::Srgb8;
    OIIO::ImageSpec spec(width, height, channels, srgb ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::HALF);
    if (channels == 4) {
        spec.alpha_channel = 3;
    }
    spec.attribute("oiio:ColorSpace", srgb ? "sRGB" : "Linear");
    if (srgb && channels == 4) {
        // Our alpha is straight; without this OIIO would "un-premultiply" PNG colours on write.
        spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    if (lowerExtension(path) == ".jpg" || lowerExtension(path) == ".jpeg") {
        spec.attribute("CompressionQuality", 95);
    }
    bool hasSoftware = false;
    std::string description;
    std::string foldedKeys;
    for (const auto& [key, value] : metadata.attributes) {
        hasSoftware = hasSoftware || key == "Software";
        if (key == "ImageDescription") {
            description = value;
        } else if (!format.keepsCustomKeys && key.rfind("speculum:", 0) == 0) {
            // TIFF and JPEG would silently drop these; keep them readable in the description instead.
            foldedKeys += "\n" + key + "=" + value;
        } else {
            spec.attribute(key, value);
        }
    }
    if (!description.empty() || !foldedKeys.empty()) {
        spec.attribute("ImageDescription",
                       description.empty() ? foldedKeys.substr(1) : description + foldedKeys);
    }
    if (!hasSoftware) {
        spec.attribute("Software", "speculum " SPECULUM_VERSION);
    }

    if (!out->open(temp.path().string(), spec)) {
        return failure(path, oneLine(out->geterror()));
    }
    if (!out->write_image(memoryType, pixels)) {
        const std::string message = oneLine(out->geterror());
        out->close();
        return failure(path, message);
    }
    if (!out->close()) {
        return failure(path, oneLine(out->geterror()));
    }
    out.reset();

    std::error_code ec;
    fs::rename(temp.path(), target, ec);
    if (ec) {
        return failure(path, "could not move the finished file into place: " + ec.message());
    }
    temp.release();
    return Done{};
}

} // namespace

bool isSupportedImagePath(const std::string& path) {
    return formatFor(path).has_value();
}

std::string supportedImageFormats() {
    std::string list;
    for (const Extension& e : kExtensions) {
        list += list.empty() ? "" : ", ";
        list += e.name;
    }
    return list;
}

Status writeImage(const std::string& path, const Image& linear, const ImageMetadata& metadata) {
    if (Status ok = checkImageTarget(path, linear.width, linear.height); !ok) {
        return ok;
    }
    assert(linear.rgba.size() == static_cast<std::size_t>(linear.width) * linear.height * 4 &&
           "writeImage(): rgba size does not match width * height * 4");
    const Format format = *formatFor(path);
    const std::size_t pixels = static_cast<std::size_t>(linear.width) * linear.height;

    if (format.encoding == Encoding::LinearHalf) {
        std::vector<float> premultiplied(linear.rgba);
        for (std::size_t i = 0; i < pixels; ++i) {
            const float alpha = premultiplied[i * 4 + 3];
            for (int c = 0; c < 3; ++c) {
                premultiplied[i * 4 + c] *= alpha;
            }
        }
        return writeAtomically(path, linear.width, linear.height, 4, OIIO::TypeDesc::FLOAT,
                               premultiplied.data(), format, metadata);
    }

    const int channels = format.keepsAlpha ? 4 : 3;
    std::vector<std::uint8_t> bytes(pixels * channels);
    for (std::size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) {
            bytes[i * channels + c] = linearToSrgb8(linear.rgba[i * 4 + c]);
        }
        if (channels == 4) {
            bytes[i * 4 + 3] = toUnorm8(linear.rgba[i * 4 + 3]);
        }
    }
    return writeAtomically(path, linear.width, linear.height, channels, OIIO::TypeDesc::UINT8, bytes.data(),
                           format, metadata);
}

Status writeImage(const std::string& path, const TextureImage& srgb, const ImageMetadata& metadata) {
    if (Status ok = checkImageTarget(path, srgb.width, srgb.height); !ok) {
        return ok;
    }
    assert(srgb.rgba8.size() == static_cast<std::size_t>(srgb.width) * srgb.height * 4 &&
           "writeImage(): rgba8 size does not match width * height * 4");
    const Format format = *formatFor(path);
    const std::size_t pixels = static_cast<std::size_t>(srgb.width) * srgb.height;

    if (format.encoding == Encoding::LinearHalf) {
        Image linear{srgb.width, srgb.height, std::vector<float>(pixels * 4)};
        for (std::size_t i = 0; i < pixels * 4; ++i) {
            linear.rgba[i] = (i % 4 == 3) ? srgb.rgba8[i] / 255.0f : srgb8ToLinear(srgb.rgba8[i]);
        }
        return writeImage(path, linear, metadata);
    }
    if (format.keepsAlpha) {
        return writeAtomically(path, srgb.width, srgb.height, 4, OIIO::TypeDesc::UINT8, srgb.rgba8.data(),
                               format, metadata);
    }
    std::vector<std::uint8_t> rgb(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i) {
        std::copy_n(&srgb.rgba8[i * 4], 3, &rgb[i * 3]);
    }
    return writeAtomically(path, srgb.width, srgb.height, 3, OIIO::TypeDesc::UINT8, rgb.data(), format,
                           metadata);
}

} // namespace speculum::render
