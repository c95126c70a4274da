#include "render/video/VideoFormat.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavutil/log.h>
}

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace speculum::render::video {

namespace {

constexpr VideoFormat kFormats[] = {VideoFormat::Mp4, VideoFormat::WebM, VideoFormat::Gif};

std::string extensionOf(VideoFormat format) {
    switch (format) {
    case VideoFormat::Mp4:
        return ".mp4";
    case VideoFormat::WebM:
        return ".webm";
    case VideoFormat::Gif:
        return ".gif";
    }
    return {};
}

} // namespace

// The encoders FFmpeg names for the formats: the library ones Debian's FFmpeg links (libx264, libvpx).
const AVCodec* findEncoder(VideoFormat format) {
    switch (format) {
    case VideoFormat::Mp4:
        return avcodec_find_encoder_by_name("libx264");
    case VideoFormat::WebM:
        return avcodec_find_encoder_by_name("libvpx-vp9");
    case VideoFormat::Gif:
        return avcodec_find_encoder(AV_CODEC_ID_GIF);
    }
    return nullptr;
}

namespace {

std::string withCodec(VideoFormat format) {
    return extensionOf(format) + (format == VideoFormat::Gif ? "" : " (" + codecName(format) + ")");
}

} // namespace

std::optional<VideoFormat> videoFormatOf(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (VideoFormat format : kFormats)
        if (extension == extensionOf(format))
            return format;
    return std::nullopt;
}

std::string videoFormatList() {
    std::string list;
    for (VideoFormat format : kFormats)
        list += (list.empty() ? "" : ", ") + withCodec(format);
    return list;
}

std::string codecName(VideoFormat format) {
    switch (format) {
    case VideoFormat::Mp4:
        return "H.264";
    case VideoFormat::WebM:
        return "VP9";
    case VideoFormat::Gif:
        return "GIF";
    }
    return {};
}

void quietenFfmpeg() {
    // Errors come back as codes and are said in one line of ours; FFmpeg's own log (the encoder's
    // settings, statistics) would only clutter the terminal.
    static const bool quiet = [] {
        av_log_set_level(AV_LOG_QUIET);
        return true;
    }();
    (void)quiet;
}

std::vector<VideoFormat> availableVideoFormats() {
    quietenFfmpeg();
    std::vector<VideoFormat> available;
    for (VideoFormat format : kFormats)
        if (findEncoder(format))
            available.push_back(format);
    return available;
}

base::Status checkVideoTarget(VideoFormat format, int width, int height, int fps) {
    return checkVideoTarget(format, width, height, fps, availableVideoFormats());
}

base::Status checkVideoTarget(VideoFormat format, int width, int height, int fps,
                              const std::vector<VideoFormat>& available) {
    if (std::find(available.begin(), available.end(), format) == available.end()) {
        std::string others;
        for (VideoFormat f : available)
            others += (others.empty() ? "" : ", ") + withCodec(f);
        return base::Error{"this FFmpeg has no " + codecName(format) + " encoder for " + extensionOf(format) +
                           (others.empty() ? "; it can encode no clip, write an image sequence instead"
                                           : "; it can write " + others + ", or an image sequence")};
    }
    if (fps < kMinFps || fps > kMaxFps)
        return base::Error{"--fps " + std::to_string(fps) + " is out of range (" + std::to_string(kMinFps) +
                           ".." + std::to_string(kMaxFps) + ")"};
    if (format == VideoFormat::Gif) {
        // A GIF counts each frame's delay in hundredths of a second; players stretch delays under 2.
        if (fps > 50)
            return base::Error{"a GIF plays at most 50 frames a second (its frame delays are hundredths of "
                               "a second), not " +
                               std::to_string(fps) + "; use .mp4 or .webm"};
        if (width > 65535 || height > 65535)
            return base::Error{"a GIF is at most 65535 pixels a side, not " + std::to_string(width) + "x" +
                               std::to_string(height)};
        return base::Done{};
    }
    if (width % 2 != 0 || height % 2 != 0)
        return base::Error{codecName(format) + " needs an even width and height (4:2:0 colour), not " +
                           std::to_string(width) + "x" + std::to_string(height)};
    if (format == VideoFormat::Mp4 && (width > 16384 || height > 16384))
        return base::Error{"H.264 is at most 16384 pixels a side, not " + std::to_string(width) + "x" +
                           std::to_string(height)};
    return base::Done{};
}

} // namespace speculum::render::video
