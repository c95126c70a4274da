#include "render/reference/IdBuffer.hpp"

namespace speculum::render::reference {

std::vector<std::uint8_t> maskOf(const IdBuffer& ids, HitKind kind) {
    std::vector<std::uint8_t> mask(ids.ids.size(), 0);
    for (std::size_t i = 0; i < ids.ids.size(); ++i)
        mask[i] = ids.ids[i].kind == kind ? 1 : 0;
    return mask;
}

std::string_view toString(HitKind kind) {
    switch (kind) {
    case HitKind::Background:
        return "background";
    case HitKind::Object:
        return "object";
    case HitKind::Mirror:
        return "mirror";
    case HitKind::MirrorBack:
        return "mirror-back";
    case HitKind::Reflector:
        return "reflector";
    }
    return "background";
}

} // namespace speculum::render::reference
