#pragma once

// A decompression bomb as small as a PNG gets: the signature, a header that declares 16384×16384 texels of
// 16-bit RGBA (2 GiB once decoded), a few bytes of a deflate stream of zeros cut short, and the end
// chunk; 69 bytes in all. A reader that trusts the header allocates gigabytes before it finds the data
// missing.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <zlib.h>

namespace speculum::test {

inline constexpr int kBombSide = 16384;

namespace detail {

inline void appendBigEndian(std::string& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out += static_cast<char>((value >> shift) & 0xFF);
}

// One PNG chunk: length, type, data and the CRC-32 of type and data.
inline void appendChunk(std::string& out, const std::string& type, const std::string& data) {
    appendBigEndian(out, static_cast<std::uint32_t>(data.size()));
    const std::string checked = type + data;
    out += checked;
    appendBigEndian(out, static_cast<std::uint32_t>(
                             crc32(0L, reinterpret_cast<const Bytef*>(checked.data()), checked.size())));
}

} // namespace detail

inline std::string bombPng() {
    std::string header;
    detail::appendBigEndian(header, kBombSide);
    detail::appendBigEndian(header, kBombSide);
    header += std::string{16, 6, 0, 0, 0}; // 16 bits, RGBA, deflate, adaptive filters, not interlaced
    // The start of the zlib stream of the image's zero rows: enough to begin decoding, far from all.
    std::vector<Bytef> zeros(1 << 16, 0);
    std::vector<Bytef> deflated(compressBound(zeros.size()));
    uLongf size = deflated.size();
    compress2(deflated.data(), &size, zeros.data(), zeros.size(), Z_BEST_COMPRESSION);
    const std::string cut(reinterpret_cast<const char*>(deflated.data()), 12);
    std::string png("\x89PNG\r\n\x1a\n", 8);
    detail::appendChunk(png, "IHDR", header);
    detail::appendChunk(png, "IDAT", cut);
    detail::appendChunk(png, "IEND", "");
    return png;
}

inline void writeBombPng(const std::filesystem::path& path) {
    const std::string bytes = bombPng();
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

} // namespace speculum::test
