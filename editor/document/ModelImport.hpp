#pragma once

#include "render/Result.hpp"
#include "render/mesh/MeshData.hpp"

#include <string>
#include <vector>

namespace speculum::document {

// Reads any format Assimp knows (OBJ, glTF 2, FBX, Collada, PLY, STL, ...) into one triangle mesh: the
// node hierarchy is flattened with its transforms, points and lines are dropped, the first uv channel is
// kept, and the result goes through render::repairMesh(). Non-fatal findings (repairs, ignored content)
// are appended to `warnings`, each prefixed with the file name. Errors name the file and the reason
// ("model.obj: file is empty"). Never throws.
render::Result<render::MeshData> importModel(const std::string& path, std::vector<std::string>& warnings);

} // namespace speculum::document
