#pragma once

#include "base/Result.hpp"
#include "scene/model/Scene.hpp"
#include "scene/project/ProjectVersion.hpp"

#include <QByteArray>
#include <QDir>
#include <QString>
#include <string>
#include <vector>

namespace speculum::scene {

// Project files (*.speculum.json), format "speculum-scene" version 1, specified in docs/scene-format.md (the
// version check and the place for upgrading older versions: ProjectVersion.hpp). The fields are those the
// components declare (render/frame/Field.hpp); FieldReader.hpp and ProjectWriter.cpp walk the declarations.
//
// Reading validates everything; an error names the JSON path ("nodes[2].mirror.size: expected 2 numbers")
// or, for broken JSON, the line and column. Unknown fields are no error: each gives a warning
// ("nodes[0].transfrom: unknown field, ignored") and is kept in the model's `unknown` fields so that saving
// writes it back. Relative paths in the file are resolved against the project file's folder (the model
// holds them absolute); writing makes them relative to the folder of the file written.
//
// Writing is deterministic: the declarations' order, 2-space indentation, shortest round-trip numbers,
// integers without ".0", unknown fields after the known ones in alphabetical order. A field is written as
// its declaration says: always, unless it has its default value, or only where it applies (a spot angle of
// a spot light). Saving a loaded file twice gives identical bytes.

// Parses file contents. baseDir resolves relative paths. Warnings are appended only on success.
base::Result<SceneData> parseProject(const QByteArray& json, const QDir& baseDir,
                                     std::vector<std::string>& warnings);

// Reads and parses a file. Warnings are appended only on success.
base::Result<SceneData> loadProject(const QString& path, std::vector<std::string>& warnings);

// loadProject, then, only on success, scene.reset() and scene.setProjectPath(path). On failure the scene
// is untouched.
base::Status openProject(Scene& scene, const QString& path, std::vector<std::string>& warnings);

// The file contents for data, with paths made relative to baseDir.
QByteArray serializeProject(const SceneData& data, const QDir& baseDir);

// Writes atomically (base::writeFileAtomically): on failure the previous file is intact. The data is
// validated by reading the serialized bytes back first, so a file that saves always loads; a model the reader
// would reject is not written (the error names the JSON path). Does not change scene.projectPath(); the
// caller does that after a successful "Save As".
base::Status saveProject(const SceneData& data, const QString& path);
base::Status saveProject(const Scene& scene, const QString& path);

} // namespace speculum::scene
