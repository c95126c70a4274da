#include "scene/model/SceneData.hpp"

#include <utility>

namespace speculum::scene {

static_assert(int(BuiltinMesh::Plane) + 1 == kBuiltinMeshNames.size(), "one name per built-in mesh");

int defaultTessellation(BuiltinMesh kind) {
    switch (kind) {
    case BuiltinMesh::Teapot:
        return 8; // per Bézier patch edge: smooth enough for a hero object
    case BuiltinMesh::Sphere:
        return 32; // rings; render::kSphereDefaultTessellation

    case BuiltinMesh::Box:
    case BuiltinMesh::Plane:
        return 1; // flat faces need no subdivision
    }
    return 1;
}

MeshComponent MeshComponent::fromBuiltin(BuiltinMesh kind, int tessellation) {
    MeshComponent mesh;
    mesh.builtin = kind;
    mesh.tessellation = tessellation > 0 ? tessellation : defaultTessellation(kind);
    return mesh;
}

MeshComponent MeshComponent::fromFile(std::string absolutePath) {
    MeshComponent mesh;
    mesh.builtin.reset();
    mesh.tessellation = 1; // unused for files; fixed so that equality stays meaningful
    mesh.file = std::move(absolutePath);
    return mesh;
}

} // namespace speculum::scene
