#pragma once

#include <QString>

namespace speculum::scene {

// What Assimp can import, for file dialogs and drag-and-drop.

// True when the file's extension is one Assimp reads (case-insensitive).
bool isImportableModel(const QString& path);

// A file-dialog filter: "3D models (*.obj *.fbx ...);;All files (*)".
QString modelFileFilter();

} // namespace speculum::scene
