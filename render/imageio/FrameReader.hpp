#pragma once

#include "base/Result.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace speculum::render {

// One frame of an image sequence read back for encoding (`speculum join`): 8-bit sRGB RGBA, row 0 at the
// top, and the file's attributes by name. 8-bit files keep their stored values; float files (EXR, HDR)
// hold linear values and are encoded to sRGB as writeImage() encodes PNG frames.
struct SequenceFrame {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba8;
    std::map<std::string, std::string> attributes;
};

// The frame's size and attributes only, without its pixels.
base::Result<SequenceFrame> readSequenceFrameHeader(const std::string& path);
base::Result<SequenceFrame> readSequenceFrame(const std::string& path);

} // namespace speculum::render
