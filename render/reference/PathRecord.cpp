#include "render/reference/PathRecord.hpp"

namespace speculum::render::reference {

std::string_view toString(PathEventKind kind) {
    switch (kind) {
    case PathEventKind::Mirror:
        return "mirror";
    case PathEventKind::Reflector:
        return "reflector";
    case PathEventKind::Surface:
        return "surface";
    case PathEventKind::Background:
        return "background";
    case PathEventKind::DepthLimit:
        return "depth-limit";
    case PathEventKind::LostBelow:
        return "lost-below";
    }
    return "surface";
}

} // namespace speculum::render::reference
