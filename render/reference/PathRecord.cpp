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

void weighPath(TracedPath& path) {
    glm::dvec3 weight(1.0);
    for (PathVertex& v : path.vertices) {
        v.weight = weight;
        if (v.kind == PathEventKind::Mirror || v.kind == PathEventKind::Reflector)
            weight *= v.reflectivity * v.tint * v.lobeWeight;
    }
}

} // namespace speculum::render::reference
