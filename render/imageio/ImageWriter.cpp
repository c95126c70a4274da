#include "render/imageio/ImageWriter.hpp"

#include "base/AtomicFile.hpp"
#include "base/Printable.hpp"
#include "render/image/ColorSpace.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cassert>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace speculum::render {

namespace fs = std::filesystem;

namespace {

enum class StoredAs { Srgb8, LinearHalf };

struct Format {
    StoredAs encoding;
    bool keepsAlpha;
    bool keepsCustomKeys; // PNG (tEXt) and EXR store any string attribute; TIFF and JPEG drop unknown ones
    // Encoded in memory and written by AtomicFile. OIIO 2.4.7's TIFF writer through an IOProxy produces a
    // file without its ImageLength field once there is metadata, so TIFF is written by name to a staged
    // temporary instead (libtiff checks its own writes) and read back in full before it is committed.
    bool inMemory;
};

struct Extension {
    const char* name;
    Format format;
};

constexpr Extension kExtensions[] = {
    {".png", {StoredAs::Srgb8, true, true, true}},    {".jpg", {StoredAs::Srgb8, false, false, true}},
    {".jpeg", {StoredAs::Srgb8, false, false, true}}, {".tif", {StoredAs::Srgb8, true, false, false}},
    {".tiff", {StoredAs::Srgb8, true, false, false}}, {".exr", {StoredAs::LinearHalf, true, true, true}},
};

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// Half floats end at 65504: OIIO would turn anything larger into Inf, and a NaN stays NaN, so one hot
// pixel of the tracer (a caustic, a light seen in a mirror) would put Inf into the EXR and poison every
// tool that filters or averages it. speculum's EXRs are half, always (a float EXR for the odd pixel
// would double every file's size): values beyond +-65504, Inf included, are clamped to +-65504 and NaN
// becomes 0, so a written EXR never holds a non-finite value.
float halfRepresentable(float value) {
    constexpr float kHalfMax = 65504.0f;
    if (std::isnan(value)) {
        return 0.0f;
    }
    return std::clamp(value, -kHalfMax, kHalfMax);
}

// Every other extension OpenImageIO has a writer for, by its own lists ("extension_list",
// "output_format_list"), mapped to the writer's format name: ".webp" → "webp", ".ppm" → "pnm". Writers that
// make no image file of the frame are left out: "null" and "term" (nothing written, a terminal) and "zfile"
// (depth only).
const std::map<std::string, std::string>& otherWritableExtensions() {
    static const std::map<std::string, std::string> writable = [] {
        std::map<std::string, std::string> out;
        std::string outputs;
        std::string extensions;
        OIIO::getattribute("output_format_list", outputs);
        OIIO::getattribute("extension_list", extensions);
        std::set<std::string> writers;
        for (std::size_t at = 0; at <= outputs.size();) {
            const std::size_t end = std::min(outputs.find(',', at), outputs.size());
            writers.insert(outputs.substr(at, end - at));
            at = end + 1;
        }
        for (const char* excluded : {"null", "term", "zfile"}) {
            writers.erase(excluded);
        }
        // "openexr:exr,sxr,mxr;tiff:tif,tiff,tx,...;..."
        for (std::size_t at = 0; at < extensions.size();) {
            const std::size_t end = std::min(extensions.find(';', at), extensions.size());
            const std::string entry = extensions.substr(at, end - at);
            at = end + 1;
            const std::size_t colon = entry.find(':');
            if (colon == std::string::npos || !writers.count(entry.substr(0, colon))) {
                continue;
            }
            const std::string format = entry.substr(0, colon);
            for (std::size_t e = colon + 1; e <= entry.size();) {
                const std::size_t comma = std::min(entry.find(',', e), entry.size());
                out.emplace("." + entry.substr(e, comma - e), format);
                e = comma + 1;
            }
        }
        return out;
    }();
    return writable;
}

std::optional<Format> formatFor(const std::string& path) {
    const std::string ext = lowerExtension(path);
    for (const Extension& e : kExtensions) {
        if (ext == e.name) {
            return e.format;
        }
    }
    const auto& others = otherWritableExtensions();
    if (const auto it = others.find(ext); it != others.end() && !ext.empty()) {
        // High dynamic range formats keep linear light (Radiance RGBE, the float PFM, OpenEXR's other
        // names); every other format is 8-bit sRGB, with alpha where the writer stores it.
        // The writer is asked by the file's own name: OIIO 2.4 lists .pfm under pnm, whose writer refuses it.
        const std::unique_ptr<OIIO::ImageOutput> writer = OIIO::ImageOutput::create("x" + ext);
        if (!writer) {
            return std::nullopt;
        }
        const bool hdr = it->second == "hdr" || it->second == "openexr" || ext == ".pfm";
        return Format{hdr ? StoredAs::LinearHalf : StoredAs::Srgb8, writer->supports("alpha") != 0, false,
                      true};
    }
    return std::nullopt;
}

base::Error failure(const std::string& path, const std::string& reason) {
    return base::Error{"cannot write " + base::quoted(path, 200) + ": " + reason};
}

// OIIO messages may span lines or end in a newline; the CLI wants one line.
std::string oneLine(std::string message) {
    std::replace(message.begin(), message.end(), '\n', ' ');
    while (!message.empty() && message.back() == ' ') {
        message.pop_back();
    }
    return message.empty() ? std::string("unknown OpenImageIO error") : message;
}

} // namespace

base::Status checkImageTarget(const std::string& path, int width, int height) {
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
        return failure(path, "folder " + base::quoted(folder.string()) + " does not exist");
    }
    if (!fs::is_directory(folderStatus)) {
        return failure(path, base::quoted(folder.string()) + " is not a folder");
    }
    if (::access(folder.c_str(), W_OK | X_OK) != 0) {
        return failure(path, "folder " + base::quoted(folder.string()) + " is not writable");
    }
    if (fs::is_directory(fs::status(target, ec))) {
        return failure(path, "a folder of that name exists");
    }
    return base::Done{};
}

namespace {

// A file written by name is only trusted once it reads back whole: some codecs do not report a write that
// failed (libpng ignores a failed fwrite; libtiff's final directory write is unchecked by TIFFClose).
// Empty when the file holds a complete image of this size. Only the reader of the format written is
// asked: ImageInput::open would, on a half-written file, try every other plugin OIIO has (FFmpeg,
// OpenVDB, DICOM among them), which is slow and runs libraries that have no business with the file.
std::string readBackError(const std::string& file, int width, int height) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create(file, /*do_open=*/false);
    OIIO::ImageSpec opened;
    if (!in || !in->open(file, opened)) {
        const std::string why = in ? in->geterror() : OIIO::geterror();
        return "the written file does not read back (" + oneLine(why) + ")";
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width != width || spec.height != height) {
        return "the written file does not read back at its size";
    }
    std::vector<unsigned char> pixels(spec.image_bytes());
    if (!in->read_image(0, 0, 0, spec.nchannels, spec.format, pixels.data()) || in->has_error()) {
        return "the written file is incomplete (" + oneLine(in->geterror()) + ")";
    }
    return {};
}

// The single place that talks to OIIO for output. `pixels` are interleaved, `channels` per pixel, of
// type `memoryType`; OIIO converts them to the file type the format calls for (uint8 or half).
//
// The file is encoded into memory first and written by AtomicFile: OIIO's own file output does not
// notice a full disk (libpng ignores a failed fwrite, so a truncated PNG was renamed into place with
// success; libjpeg's write error ends in its error_exit, which printed the codec's message and left the
// temporary behind). In memory no codec ever sees a write fail, and AtomicFile checks every byte, the
// fsync and the close before the rename.
base::Status writeAtomically(const std::string& path, int width, int height, int channels,
                             OIIO::TypeDesc memoryType, const void* pixels, const Format& format,
                             const ImageMetadata& metadata) {
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) {
        return failure(path, oneLine(OIIO::geterror()));
    }
    // Into memory where the writer can (OIIO refuses to create one with a proxy it does not support).
    if (format.inMemory && out->supports("ioproxy")) {
        out = OIIO::ImageOutput::create(path, &memory);
        if (!out) {
            return failure(path, oneLine(OIIO::geterror()));
        }
    }
    // A writer that cannot (or must not, see Format::inMemory) write into memory writes a file by name:
    // it gets a staged temporary path, its errors are checked after close(), and the file is read back.
    std::optional<base::StagedPath> staged;
    if (!format.inMemory || !out->supports("ioproxy")) {
        base::Result<base::StagedPath> created = base::StagedPath::create(path);
        if (!created) {
            return base::Error{created.error()};
        }
        staged.emplace(std::move(created).value());
        out = OIIO::ImageOutput::create(staged->path());
        if (!out) {
            return staged->failure(oneLine(OIIO::geterror()));
        }
    }
    const std::string openName = staged ? staged->path() : path;

    const bool srgb = format.encoding == StoredAs::Srgb8;
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

    // OIIO reports some failures only in its error state, and some (a full disk) only at close().
    std::string writerError;
    if (!out->open(openName, spec)) {
        writerError = oneLine(out->geterror());
    } else {
        const bool written = out->write_image(memoryType, pixels);
        const bool closed = out->close();
        if (!written || !closed || out->has_error()) {
            writerError = oneLine(out->geterror());
        }
    }
    out.reset();
    if (staged) {
        if (writerError.empty()) {
            writerError = readBackError(staged->path(), width, height);
        }
        return staged->commit(writerError);
    }
    if (!writerError.empty()) {
        return failure(path, writerError);
    }
    if (encoded.empty()) {
        return failure(path, "OpenImageIO produced no bytes");
    }
    return base::writeFileAtomically(path, encoded.data(), encoded.size());
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
    std::string others;
    for (const auto& entry : otherWritableExtensions()) {
        // A named copy, not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
        const std::string& ext = entry.first;
        const bool tuned = std::any_of(std::begin(kExtensions), std::end(kExtensions),
                                       [&](const Extension& e) { return ext == e.name; });
        if (!tuned && formatFor("x" + ext)) {
            others += others.empty() ? "" : ", ";
            others += ext;
        }
    }
    if (!others.empty()) {
        list += "; and through OpenImageIO: " + others;
    }
    return list;
}

base::Status writeImage(const std::string& path, const Image& linear, const ImageMetadata& metadata) {
    if (base::Status ok = checkImageTarget(path, linear.width, linear.height); !ok) {
        return ok;
    }
    assert(linear.rgba.size() == static_cast<std::size_t>(linear.width) * linear.height * 4 &&
           "writeImage(): rgba size does not match width * height * 4");
    const Format format = *formatFor(path);
    const std::size_t pixels = static_cast<std::size_t>(linear.width) * linear.height;

    if (format.encoding == StoredAs::LinearHalf) {
        std::vector<float> premultiplied(linear.rgba);
        for (std::size_t i = 0; i < pixels; ++i) {
            const float alpha = halfRepresentable(premultiplied[i * 4 + 3]);
            premultiplied[i * 4 + 3] = alpha;
            for (int c = 0; c < 3; ++c) {
                premultiplied[i * 4 + c] = halfRepresentable(premultiplied[i * 4 + c] * alpha);
            }
        }
        if (!format.keepsAlpha) { // RGBE and PFM hold colour only: alpha is dropped, colour kept as drawn
            std::vector<float> rgb(pixels * 3);
            for (std::size_t i = 0; i < pixels; ++i) {
                for (int c = 0; c < 3; ++c) {
                    // RGBE has no sign: a negative value (never radiance) would come back as garbage.
                    rgb[i * 3 + c] = std::max(0.0f, halfRepresentable(linear.rgba[i * 4 + c]));
                }
            }
            return writeAtomically(path, linear.width, linear.height, 3, OIIO::TypeDesc::FLOAT, rgb.data(),
                                   format, metadata);
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

base::Status writeImage(const std::string& path, const TextureImage& srgb, const ImageMetadata& metadata) {
    if (base::Status ok = checkImageTarget(path, srgb.width, srgb.height); !ok) {
        return ok;
    }
    assert(srgb.rgba8.size() == static_cast<std::size_t>(srgb.width) * srgb.height * 4 &&
           "writeImage(): rgba8 size does not match width * height * 4");
    const Format format = *formatFor(path);
    const std::size_t pixels = static_cast<std::size_t>(srgb.width) * srgb.height;

    if (format.encoding == StoredAs::LinearHalf) {
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
