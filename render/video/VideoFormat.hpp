#pragma once

#include "base/Result.hpp"

#include <optional>
#include <string>
#include <vector>

struct AVCodec; // FFmpeg's (libavcodec/codec.h); declared here so that this header needs none of it

namespace speculum::render::video {

// The clips speculum writes, by the output's extension (case-insensitive): H.264 in MP4, VP9 in WebM, and
// animated GIF, all encoded by FFmpeg's libraries (libavcodec, libavformat, libswscale).
enum class VideoFormat { Mp4, WebM, Gif };

// The format `path` names by its extension, or none when the extension is no video's.
std::optional<VideoFormat> videoFormatOf(const std::string& path);

// ".mp4 (H.264), .webm (VP9), .gif", for messages.
std::string videoFormatList();

// "H.264" and the like, for messages.
std::string codecName(VideoFormat format);

// The formats whose encoder this machine's FFmpeg has.
std::vector<VideoFormat> availableVideoFormats();

// Everything the encoder can check before there are pixels: that the installed FFmpeg has the format's
// encoder (naming the formats it does have when not), and a size the codec takes (H.264 and VP9 in 4:2:0
// need an even width and height; GIF at most 65535 pixels a side). `available` stands in for the
// installed FFmpeg's list of encoders, so the message for a missing one can be tested.
base::Status checkVideoTarget(VideoFormat format, int width, int height, int fps);
base::Status checkVideoTarget(VideoFormat format, int width, int height, int fps,
                              const std::vector<VideoFormat>& available);

// FFmpeg's encoder for the format (libx264, libvpx-vp9, its own GIF encoder), or null when this machine's
// FFmpeg lacks it. Only render/video's own files call it: they are the ones that link FFmpeg.
const AVCodec* findEncoder(VideoFormat format);

// Turns FFmpeg's own logging off (once): every failure is reported through the callers' messages.
void quietenFfmpeg();

inline constexpr int kMinFps = 1;
inline constexpr int kMaxFps = 240;

} // namespace speculum::render::video
