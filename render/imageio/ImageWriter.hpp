#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"

#include <string>

namespace speculum::render {

// Writes a linear frame to PNG, JPEG, TIFF or OpenEXR, chosen by the extension (case-insensitive).
// PNG/JPEG/TIFF get 8-bit sRGB-encoded values (clamped to 0..1, rounded, alpha straight; JPEG drops
// alpha). EXR gets linear half floats with alpha premultiplied, as the OpenEXR convention expects;
// values beyond the half range (+-65504, Inf included) are clamped to it and NaN becomes 0, so an EXR
// never holds Inf or NaN.
// Metadata attributes are stored as strings (PNG tEXt, EXR header, TIFF/JPEG tags); TIFF and JPEG cannot
// hold custom keys, so "speculum:*" entries are appended to their ImageDescription as "key=value" lines.
// "Software" defaults to "speculum <version>".
//
// Atomic: the image is encoded in memory and written through base::AtomicFile (a temporary sibling,
// every write, the fsync and the close checked, then renamed over `path`), so a failure (a full disk
// included) is an error with one line, never leaves a partial file or a temporary, and never touches an
// existing file: "out.png: the disk is full (No space left on device); the previous file is unchanged".
base::Status writeImage(const std::string& path, const Image& linear, const ImageMetadata& metadata = {});

// Writes 8-bit sRGB-encoded RGBA bytes as they are (no second encoding) to PNG, JPEG or TIFF; EXR
// gets the decoded linear values. Same atomicity and errors as above.
base::Status writeImage(const std::string& path, const TextureImage& srgb,
                        const ImageMetadata& metadata = {});

// Everything writeImage() can check before there are pixels: the format, whether it can hold an image
// of this size (JPEG: at most 65500 pixels per side), the folder. Callers check first, so a bad target
// costs no rendering.
base::Status checkImageTarget(const std::string& path, int width, int height);

// True when `path` ends in an extension writeImage() supports, so callers can reject a bad output name
// before doing any expensive work.
bool isSupportedImagePath(const std::string& path);

// The supported extensions for messages: ".png, .jpg, .jpeg, .tif, .tiff, .exr; and through OpenImageIO:
// .bmp, ...": the first six tuned here, then every other format OpenImageIO writes (8-bit sRGB, or linear
// float for .hdr and .pfm).
std::string supportedImageFormats();

} // namespace speculum::render
