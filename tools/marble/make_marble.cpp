// speculum-make-marble OUT.png [--size N] [--seed S]
// Writes the procedural marble texture; resources/scenes/textures/marble.png is made with
//   speculum-make-marble resources/scenes/textures/marble.png --size 512 --seed 7
#include "render/imageio/ImageWriter.hpp"
#include "tools/marble/Marble.hpp"

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace {

constexpr const char* kUsage = "usage: speculum-make-marble OUT.png [--size N] [--seed S]";

template <typename T>
bool parseNumber(std::string_view text, T& value) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size();
}

} // namespace

int main(int argc, char** argv) {
    std::string out;
    int size = 512;
    std::uint32_t seed = 7;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "-h" || arg == "--help") {
            std::puts(kUsage);
            return 0;
        }
        if (arg == "--size" || arg == "--seed") {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "speculum-make-marble: %s needs a value\n%s\n", argv[i], kUsage);
                return 2;
            }
            const std::string_view value = argv[++i];
            const bool ok = arg == "--size" ? parseNumber(value, size) && size > 0 && size <= 16384
                                            : parseNumber(value, seed);
            if (!ok) {
                std::fprintf(stderr, "speculum-make-marble: bad value '%s' for %s\n", argv[i], arg.data());
                return 2;
            }
        } else if (!arg.empty() && arg[0] == '-') {
            std::fprintf(stderr, "speculum-make-marble: unknown option '%s'\n%s\n", argv[i], kUsage);
            return 2;
        } else if (out.empty()) {
            out = arg;
        } else {
            std::fprintf(stderr, "speculum-make-marble: more than one output file\n%s\n", kUsage);
            return 2;
        }
    }
    if (out.empty()) {
        std::fprintf(stderr, "%s\n", kUsage);
        return 2;
    }
    if (!speculum::render::isSupportedImagePath(out)) {
        std::fprintf(stderr, "speculum-make-marble: '%s': unsupported format (supported: %s)\n", out.c_str(),
                     speculum::render::supportedImageFormats().c_str());
        return 2;
    }

    const speculum::render::TextureImage marble = speculum::render::generateMarble(size, seed);
    speculum::render::ImageMetadata metadata;
    metadata.attributes = {{"Software", "speculum-make-marble"},
                           {"ImageDescription", "procedural marble texture"},
                           {"speculum:seed", std::to_string(seed)}};
    // The marble is already sRGB-encoded bytes: this overload writes them unchanged.
    if (const auto status = speculum::render::writeImage(out, marble, metadata); !status) {
        std::fprintf(stderr, "speculum-make-marble: %s\n", status.error().c_str());
        return 1;
    }
    return 0;
}
