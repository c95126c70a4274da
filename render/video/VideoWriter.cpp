#include "render/video/VideoWriter.hpp"

#include "base/Printable.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/error.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <array>
#include <cmath>

namespace speculum::render::video {

namespace {

std::string avError(int code) {
    std::array<char, AV_ERROR_MAX_STRING_SIZE> text{};
    av_strerror(code, text.data(), text.size());
    return text.data();
}

const char* muxerName(VideoFormat format) {
    switch (format) {
    case VideoFormat::Mp4:
        return "mp4";
    case VideoFormat::WebM:
        return "webm";
    case VideoFormat::Gif:
        return "gif";
    }
    return "";
}

// The GIF palette: 6 levels of red, 7 of green, 6 of blue (252 colours), and a 4x4 Bayer matrix for the
// ordered dither that spreads each pixel's rounding over its neighbours.
constexpr int kRedLevels = 6, kGreenLevels = 7, kBlueLevels = 6;
constexpr std::array<std::array<int, 4>, 4> kBayer = {
    {{{0, 8, 2, 10}}, {{12, 4, 14, 6}}, {{3, 11, 1, 9}}, {{15, 7, 13, 5}}}};

int ditheredLevel(std::uint8_t value, int levels, int threshold) {
    const double v = value / 255.0 * (levels - 1) + (threshold + 0.5) / 16.0 - 0.5;
    return std::clamp(static_cast<int>(std::lround(v)), 0, levels - 1);
}

std::uint32_t paletteEntry(int index) {
    const auto level = [](int i, int levels) {
        return static_cast<std::uint32_t>(std::lround(i * 255.0 / (levels - 1)));
    };
    const int r = index / (kGreenLevels * kBlueLevels), g = index / kBlueLevels % kGreenLevels,
              b = index % kBlueLevels;
    return 0xFF000000u | level(r, kRedLevels) << 16 | level(g, kGreenLevels) << 8 | level(b, kBlueLevels);
}

void quantizeToPalette(const std::vector<std::uint8_t>& rgba8, int width, int height, AVFrame& frame) {
    auto* palette = reinterpret_cast<std::uint32_t*>(frame.data[1]);
    for (int i = 0; i < 256; ++i)
        palette[i] = i < kRedLevels * kGreenLevels * kBlueLevels ? paletteEntry(i) : 0xFF000000u;
    for (int y = 0; y < height; ++y) {
        std::uint8_t* row = frame.data[0] + static_cast<std::ptrdiff_t>(y) * frame.linesize[0];
        for (int x = 0; x < width; ++x) {
            const std::uint8_t* p = &rgba8[(static_cast<std::size_t>(y) * width + x) * 4];
            const int t = kBayer[static_cast<std::size_t>(y % 4)][static_cast<std::size_t>(x % 4)];
            row[x] = static_cast<std::uint8_t>(
                ditheredLevel(p[0], kRedLevels, t) * kGreenLevels * kBlueLevels +
                ditheredLevel(p[1], kGreenLevels, t) * kBlueLevels + ditheredLevel(p[2], kBlueLevels, t));
        }
    }
}

// BT.709 coefficients in the studio range, which players assume for HD video; the decoder below reads
// them back the same way.
void useBt709(SwsContext* scale, bool toYuv) {
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(scale, bt709, toYuv ? 1 : 0, bt709, toYuv ? 0 : 1, 0, 1 << 16, 1 << 16);
}

// The encoder's quality settings: constant quality, the speed a desktop's export can afford.
AVDictionary* encoderOptions(VideoFormat format) {
    AVDictionary* options = nullptr;
    if (format == VideoFormat::Mp4) {
        av_dict_set(&options, "crf", "18", 0);
        av_dict_set(&options, "preset", "medium", 0);
    } else if (format == VideoFormat::WebM) {
        av_dict_set(&options, "crf", "24", 0);
        av_dict_set(&options, "b", "0", 0);
        av_dict_set(&options, "deadline", "good", 0);
        av_dict_set(&options, "cpu-used", "4", 0);
        av_dict_set(&options, "row-mt", "1", 0);
    }
    return options;
}

// The frames' size, rate and colour: 4:2:0 BT.709 in the studio range for H.264 and VP9, palette for GIF.
void describeFrames(AVCodecContext& ctx, VideoFormat format, const VideoWriter::Settings& settings) {
    ctx.width = settings.width;
    ctx.height = settings.height;
    ctx.time_base = AVRational{1, settings.fps};
    ctx.framerate = AVRational{settings.fps, 1};
    ctx.pix_fmt = format == VideoFormat::Gif ? AV_PIX_FMT_PAL8 : AV_PIX_FMT_YUV420P;
    if (format == VideoFormat::Gif)
        return;
    ctx.color_range = AVCOL_RANGE_MPEG;
    ctx.colorspace = AVCOL_SPC_BT709;
    ctx.color_primaries = AVCOL_PRI_BT709;
    ctx.color_trc = AVCOL_TRC_IEC61966_2_1; // the frames are sRGB-encoded
}

} // namespace

struct VideoWriter::Codec {
    AVFormatContext* format = nullptr;
    AVCodecContext* context = nullptr;
    AVStream* stream = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    SwsContext* scale = nullptr;
    bool ioOpen = false;

    ~Codec() {
        sws_freeContext(scale);
        av_frame_free(&frame);
        av_packet_free(&packet);
        avcodec_free_context(&context);
        if (format) {
            if (ioOpen)
                avio_closep(&format->pb);
            avformat_free_context(format);
        }
    }
};

VideoWriter::VideoWriter(std::string path, VideoFormat format, Settings settings)
    : m_path(std::move(path))
    , m_format(format)
    , m_settings(std::move(settings))
    , m_codec(std::make_unique<Codec>()) {}

VideoWriter::~VideoWriter() = default; // the codec first (declared last), then the AtomicFile

base::Result<std::unique_ptr<VideoWriter>> VideoWriter::open(const std::string& path, VideoFormat format,
                                                             const Settings& settings) {
    if (base::Status ok = checkVideoTarget(format, settings.width, settings.height, settings.fps); !ok)
        return base::Error{base::printable(path, 400) + ": " + ok.error()};
    std::unique_ptr<VideoWriter> writer(new VideoWriter(path, format, settings));
    auto file = base::AtomicFile::create(path);
    if (!file)
        return base::Error{file.error()};
    writer->m_file.emplace(std::move(*file));
    if (base::Status started = writer->start(); !started)
        return base::Error{started.error()};
    return writer;
}

base::Status VideoWriter::failure(const std::string& what, int code) {
    m_failed = true;
    if (code == AVERROR(ENOSPC) || code == AVERROR(EDQUOT) || code == AVERROR(EFBIG) || code == AVERROR(EIO))
        return base::Error{base::printable(m_path, 400) + ": " + base::describeWriteError(AVUNERROR(code)) +
                           "; " + what + "; no clip was written"};
    return base::Error{base::printable(m_path, 400) + ": " + what + ": " + avError(code) +
                       "; no clip was written"};
}

base::Status VideoWriter::start() {
    quietenFfmpeg();
    Codec& c = *m_codec;
    const std::string& temp = m_file->temporaryPath();
    int code = avformat_alloc_output_context2(&c.format, nullptr, muxerName(m_format), temp.c_str());
    if (code < 0)
        return failure("cannot start the " + std::string(muxerName(m_format)) + " container", code);
    const AVCodec* encoder = findEncoder(m_format);
    c.stream = avformat_new_stream(c.format, nullptr);
    c.context = avcodec_alloc_context3(encoder);
    c.packet = av_packet_alloc();
    c.frame = av_frame_alloc();
    if (!c.stream || !c.context || !c.packet || !c.frame)
        return failure("out of memory", AVERROR(ENOMEM));
    AVCodecContext& ctx = *c.context;
    describeFrames(ctx, m_format, m_settings);
    if (c.format->oformat->flags & AVFMT_GLOBALHEADER)
        ctx.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* options = encoderOptions(m_format);
    code = avcodec_open2(c.context, encoder, &options);
    av_dict_free(&options);
    if (code < 0)
        return failure("cannot open the " + codecName(m_format) + " encoder", code);
    if ((code = avcodec_parameters_from_context(c.stream->codecpar, c.context)) < 0)
        return failure("cannot set up the stream", code);
    c.stream->time_base = ctx.time_base;
    c.stream->avg_frame_rate = ctx.framerate;
    for (const auto& [key, value] : m_settings.metadata)
        av_dict_set(&c.format->metadata, key.c_str(), value.c_str(), 0);
    if ((code = avio_open(&c.format->pb, ("file:" + temp).c_str(), AVIO_FLAG_WRITE)) < 0)
        return failure("cannot open the file", code);
    c.ioOpen = true;
    if ((code = avformat_write_header(c.format, nullptr)) < 0)
        return failure("cannot write the container's header", code);
    c.frame->format = ctx.pix_fmt;
    c.frame->width = ctx.width;
    c.frame->height = ctx.height;
    if ((code = av_frame_get_buffer(c.frame, 0)) < 0)
        return failure("out of memory", code);
    if (m_format != VideoFormat::Gif) {
        c.scale =
            sws_getContext(ctx.width, ctx.height, AV_PIX_FMT_RGBA, ctx.width, ctx.height, AV_PIX_FMT_YUV420P,
                           SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
        if (!c.scale)
            return failure("cannot convert to YUV", AVERROR(EINVAL));
        useBt709(c.scale, true);
    }
    return base::Done{};
}

// Sends the frame (or, to flush, none) and writes every packet the encoder returns.
base::Status VideoWriter::encode(bool flush) {
    Codec& c = *m_codec;
    int code = avcodec_send_frame(c.context, flush ? nullptr : c.frame);
    if (code < 0)
        return failure("the " + codecName(m_format) + " encoder failed", code);
    while ((code = avcodec_receive_packet(c.context, c.packet)) >= 0) {
        if (c.packet->duration == 0)
            c.packet->duration = 1; // one frame: without it the last frame has no length in MP4
        av_packet_rescale_ts(c.packet, c.context->time_base, c.stream->time_base);
        c.packet->stream_index = c.stream->index;
        code = av_interleaved_write_frame(c.format, c.packet); // takes the packet's data
        if (code < 0)
            return failure("writing frame " + std::to_string(m_frames), code);
        if (c.format->pb->error < 0)
            return failure("writing frame " + std::to_string(m_frames), c.format->pb->error);
    }
    if (code != AVERROR(EAGAIN) && code != AVERROR_EOF)
        return failure("the " + codecName(m_format) + " encoder failed", code);
    return base::Done{};
}

base::Status VideoWriter::write(const std::vector<std::uint8_t>& rgba8) {
    if (m_failed)
        return base::Error{base::printable(m_path, 400) + ": the clip failed earlier"};
    Codec& c = *m_codec;
    const int w = m_settings.width, h = m_settings.height;
    if (rgba8.size() != static_cast<std::size_t>(w) * h * 4)
        return base::Error{base::printable(m_path, 400) + ": a frame of the wrong size"};
    if (int code = av_frame_make_writable(c.frame); code < 0)
        return failure("out of memory", code);
    if (m_format == VideoFormat::Gif) {
        quantizeToPalette(rgba8, w, h, *c.frame);
    } else {
        const std::uint8_t* source[1] = {rgba8.data()};
        const int stride[1] = {w * 4};
        sws_scale(c.scale, source, stride, 0, h, c.frame->data, c.frame->linesize);
    }
    c.frame->pts = m_frames;
    if (base::Status sent = encode(false); !sent)
        return sent;
    ++m_frames;
    return base::Done{};
}

base::Status VideoWriter::finish() {
    if (m_failed)
        return base::Error{base::printable(m_path, 400) + ": the clip failed earlier"};
    Codec& c = *m_codec;
    if (base::Status flushed = encode(true); !flushed)
        return flushed;
    if (int code = av_write_trailer(c.format); code < 0)
        return failure("cannot finish the container", code);
    c.ioOpen = false;
    if (int code = avio_closep(&c.format->pb); code < 0)
        return failure("cannot close the file", code);
    return m_file->commit();
}

} // namespace speculum::render::video
