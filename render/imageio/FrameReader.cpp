#include "render/imageio/FrameReader.hpp"

#include "base/Printable.hpp"
#include "render/image/ColorSpace.hpp"

#include <OpenImageIO/imageio.h>

namespace speculum::render {

namespace {

namespace oiio = OIIO;

base::Result<SequenceFrame> readFrame(const std::string& path, bool pixels) {
    const auto fail = [&](const std::string& why) {
        return base::Error{base::printable(path, 400) + ": " + why};
    };
    auto input = oiio::ImageInput::open(path);
    if (!input)
        return fail("cannot read it as an image (" + base::printable(oiio::geterror(), 200) + ")");
    const oiio::ImageSpec& spec = input->spec();
    SequenceFrame frame;
    frame.width = spec.width;
    frame.height = spec.height;
    for (const oiio::ParamValue& p : spec.extra_attribs)
        frame.attributes[p.name().string()] = p.get_string();
    if (!pixels)
        return frame;
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels < 1 ||
        static_cast<long long>(spec.width) * spec.height > (1ll << 28))
        return fail("an image of " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                    " pixels cannot be a frame");
    const bool linear =
        spec.format.basetype == oiio::TypeDesc::FLOAT || spec.format.basetype == oiio::TypeDesc::HALF;
    const int channels = std::min(spec.nchannels, 4);
    const std::size_t pixelsCount = static_cast<std::size_t>(spec.width) * spec.height;
    std::vector<float> values(linear ? pixelsCount * static_cast<std::size_t>(channels) : 0);
    std::vector<std::uint8_t> bytes(linear ? 0 : pixelsCount * static_cast<std::size_t>(channels));
    const bool read = linear ? input->read_image(0, 0, 0, channels, oiio::TypeDesc::FLOAT, values.data())
                             : input->read_image(0, 0, 0, channels, oiio::TypeDesc::UINT8, bytes.data());
    if (!read)
        return fail("cannot read its pixels (" + base::printable(input->geterror(), 200) + ")");
    frame.rgba8.assign(pixelsCount * 4, 255);
    for (std::size_t i = 0; i < pixelsCount; ++i)
        for (int c = 0; c < 3; ++c) {
            const std::size_t from =
                i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(channels >= 3 ? c : 0);
            frame.rgba8[i * 4 + static_cast<std::size_t>(c)] =
                linear ? linearToSrgb8(values[from]) : bytes[from];
        }
    return frame;
}

} // namespace

base::Result<SequenceFrame> readSequenceFrameHeader(const std::string& path) {
    return readFrame(path, false);
}

base::Result<SequenceFrame> readSequenceFrame(const std::string& path) {
    return readFrame(path, true);
}

} // namespace speculum::render
