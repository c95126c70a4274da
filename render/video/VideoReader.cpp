#include "base/Printable.hpp"
#include "render/video/VideoWriter.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libswscale/swscale.h>
}

#include <array>

namespace speculum::render::video {

namespace {

// FFmpeg's objects for reading one clip, freed together.
struct Reading {
    AVFormatContext* format = nullptr;
    AVCodecContext* context = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    SwsContext* scale = nullptr;
    int stream = -1;

    ~Reading() {
        sws_freeContext(scale);
        av_frame_free(&frame);
        av_packet_free(&packet);
        avcodec_free_context(&context);
        avformat_close_input(&format);
    }
};

std::string avError(int code) {
    std::array<char, AV_ERROR_MAX_STRING_SIZE> text{};
    av_strerror(code, text.data(), text.size());
    return text.data();
}

base::Status openDecoder(Reading& r, DecodedVideo& video) {
    r.stream = av_find_best_stream(r.format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (r.stream < 0)
        return base::Error{"no video stream"};
    const AVStream* stream = r.format->streams[r.stream];
    const AVCodec* decoder = avcodec_find_decoder(stream->codecpar->codec_id);
    if (!decoder)
        return base::Error{"no decoder for its codec"};
    r.context = avcodec_alloc_context3(decoder);
    r.frame = av_frame_alloc();
    r.packet = av_packet_alloc();
    if (!r.context || !r.frame || !r.packet)
        return base::Error{"out of memory"};
    if (int code = avcodec_parameters_to_context(r.context, stream->codecpar); code < 0)
        return base::Error{avError(code)};
    if (int code = avcodec_open2(r.context, decoder, nullptr); code < 0)
        return base::Error{avError(code)};
    video.width = r.context->width;
    video.height = r.context->height;
    video.codec = decoder->name;
    const AVRational rate = stream->avg_frame_rate.num ? stream->avg_frame_rate : stream->r_frame_rate;
    video.fps = rate.den ? av_q2d(rate) : 0.0;
    const AVDictionaryEntry* entry = nullptr;
    while ((entry = av_dict_get(r.format->metadata, "", entry, AV_DICT_IGNORE_SUFFIX)))
        video.metadata[entry->key] = entry->value;
    return base::Done{};
}

// Converts the decoded frame to 8-bit RGB, reading YUV as BT.709 in the studio range (as written).
base::Status keepFrame(Reading& r, DecodedVideo& video) {
    const AVFrame& f = *r.frame;
    r.scale = sws_getCachedContext(r.scale, f.width, f.height, static_cast<AVPixelFormat>(f.format), f.width,
                                   f.height, AV_PIX_FMT_RGB24, SWS_BICUBIC | SWS_ACCURATE_RND, nullptr,
                                   nullptr, nullptr);
    if (!r.scale)
        return base::Error{"cannot convert its frames to RGB"};
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(r.scale, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(f.width) * f.height * 3);
    std::uint8_t* target[1] = {rgb.data()};
    const int stride[1] = {f.width * 3};
    sws_scale(r.scale, f.data, f.linesize, 0, f.height, target, stride);
    video.frames.push_back(std::move(rgb));
    return base::Done{};
}

base::Status drain(Reading& r, DecodedVideo& video) {
    int code = 0;
    while ((code = avcodec_receive_frame(r.context, r.frame)) >= 0) {
        if (base::Status kept = keepFrame(r, video); !kept)
            return kept;
        av_frame_unref(r.frame);
    }
    if (code != AVERROR(EAGAIN) && code != AVERROR_EOF)
        return base::Error{avError(code)};
    return base::Done{};
}

} // namespace

base::Result<DecodedVideo> decodeVideo(const std::string& path) {
    quietenFfmpeg();
    Reading r;
    DecodedVideo video;
    const auto fail = [&](const std::string& why) {
        return base::Error{base::printable(path, 400) + ": cannot decode: " + why};
    };
    if (int code = avformat_open_input(&r.format, ("file:" + path).c_str(), nullptr, nullptr); code < 0)
        return fail(avError(code));
    if (int code = avformat_find_stream_info(r.format, nullptr); code < 0)
        return fail(avError(code));
    if (base::Status opened = openDecoder(r, video); !opened)
        return fail(opened.error());
    int read = 0;
    while ((read = av_read_frame(r.format, r.packet)) >= 0) {
        const bool ours = r.packet->stream_index == r.stream;
        const int code = ours ? avcodec_send_packet(r.context, r.packet) : 0;
        av_packet_unref(r.packet);
        if (code < 0)
            return fail(avError(code));
        if (base::Status drained = drain(r, video); !drained)
            return fail(drained.error());
    }
    if (read != AVERROR_EOF) // a damaged clip is an error, not a shorter one
        return fail(avError(read));
    avcodec_send_packet(r.context, nullptr);
    if (base::Status drained = drain(r, video); !drained)
        return fail(drained.error());
    return video;
}

} // namespace speculum::render::video
