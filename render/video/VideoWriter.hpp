#pragma once

#include "base/AtomicFile.hpp"
#include "base/Result.hpp"
#include "render/video/VideoFormat.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace speculum::render::video {

// A clip being encoded: frames go in one at a time as 8-bit sRGB RGBA rows (row 0 at the top), and only
// finish() puts the file in place. Until then the encoder writes a temporary beside it (base::AtomicFile),
// so a failure half-way (a full disk, a cancel, a signal) leaves no half-written clip, and an existing
// file of that name stays as it was; destroying the writer without finish() removes the temporary.
//
// H.264 is encoded by libx264 at constant quality (CRF 18: visually lossless for these images), VP9 by
// libvpx at CRF 24, both in 4:2:0; a GIF's frames are each mapped to a fixed 252-colour palette with
// ordered dithering (no palette is computed from the clip, so a frame's colours never depend on others).
class VideoWriter {
public:
    struct Settings {
        int width = 0;
        int height = 0;
        int fps = 24;
        // Stored in the container (MP4 and WebM: title, comment; GIF has no place for them).
        std::map<std::string, std::string> metadata;
    };

    static base::Result<std::unique_ptr<VideoWriter>> open(const std::string& path, VideoFormat format,
                                                           const Settings& settings);
    ~VideoWriter();
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    // The next frame: width * height * 4 bytes of sRGB RGBA (alpha ignored).
    base::Status write(const std::vector<std::uint8_t>& rgba8);
    // Flushes the encoder, writes the container's index and renames the clip into place.
    base::Status finish();

    int framesWritten() const { return m_frames; }

private:
    struct Codec;
    VideoWriter(std::string path, VideoFormat format, Settings settings);
    base::Status start();
    base::Status encode(bool flush);
    base::Status failure(const std::string& what, int code);

    std::string m_path;
    VideoFormat m_format;
    Settings m_settings;
    // The file first: members go in reverse order, so the encoder closes its handle on the temporary
    // before the AtomicFile removes an uncommitted one.
    std::optional<base::AtomicFile> m_file;
    std::unique_ptr<Codec> m_codec;
    int m_frames = 0;
    bool m_failed = false;
};

// A clip read back through libavformat and libavcodec: every frame converted to 8-bit RGB (3 bytes a
// pixel, row 0 at the top). What the tests and `speculum join`'s checks decode with.
struct DecodedVideo {
    int width = 0;
    int height = 0;
    double fps = 0.0;
    std::string codec; // FFmpeg's name for it ("h264", "vp9", "gif")
    std::map<std::string, std::string> metadata;
    std::vector<std::vector<std::uint8_t>> frames;
};

base::Result<DecodedVideo> decodeVideo(const std::string& path);

} // namespace speculum::render::video
