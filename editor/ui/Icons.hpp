#pragma once

#include "scene/model/SceneData.hpp"

#include <QIcon>
#include <QString>

namespace speculum::ui {

// What a node is, for icons and tooltips: the most specific of its components wins.
enum class NodeKind { Empty, Mesh, Mirror, Reflector, Light, Camera };

NodeKind nodeKind(const scene::NodeData& data);
QString kindName(NodeKind kind); // "Mesh", "Planar mirror", ...

// Icons drawn with QPainter (crisp at any size, no resource files to ship), cached per kind.
QIcon kindIcon(NodeKind kind);

} // namespace speculum::ui
