#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace speculum::render::reference {

// What a primary ray hit first.
enum class HitKind : std::uint8_t {
    Background, // nothing: the background colour
    Object,     // FrameInput::items[index]
    Mirror,     // the reflective side of FrameInput::mirrors[index]
    MirrorBack, // the back of FrameInput::mirrors[index] (shows its material)
    Reflector,  // FrameInput::reflectors[index]
};

// "background", "object", "mirror", "mirror-back", "reflector" (explain --pixel's JSON).
std::string_view toString(HitKind kind);

struct PixelId {
    HitKind kind = HitKind::Background;
    int index = -1;

    bool operator==(const PixelId&) const = default;
};

// One PixelId per pixel, row 0 at the top, like Image.
struct IdBuffer {
    int width = 0;
    int height = 0;
    std::vector<PixelId> ids;

    const PixelId& at(int x, int y) const { return ids[static_cast<std::size_t>(y) * width + x]; }
};

// Pixel masks for metrics (one byte per pixel, 1 = in the mask), row 0 at the top.
std::vector<std::uint8_t> maskOf(const IdBuffer& ids, HitKind kind);
// Pixels whose primary ray hit the reflective side of any mirror.
inline std::vector<std::uint8_t> mirrorMask(const IdBuffer& ids) {
    return maskOf(ids, HitKind::Mirror);
}
inline std::vector<std::uint8_t> reflectorMask(const IdBuffer& ids) {
    return maskOf(ids, HitKind::Reflector);
}

} // namespace speculum::render::reference
