#pragma once

#include "base/Result.hpp"

#include <QJsonObject>

namespace speculum::scene {

// The format version of project files: what this program writes and the newest it reads.
//
// Fields are added, never renamed. An added field is optional, so older files read as before,
// and a speculum that predates it keeps it as an unknown field and writes it back: it needs no new
// version (the top-level "editorView", the editor's own view, is such a field of version 1). A new version
// is for a change an older reader would get wrong.
inline constexpr int kProjectFormatVersion = 1;

// The header of a project file, checked before anything else is read: "format" must be
// "speculum-scene" and "version" a whole number from 1 to kProjectFormatVersion. Returns the version;
// errors name the field ("version: version 3 is newer than this speculum (reads up to 1)").
base::Result<int> readProjectHeader(const QJsonObject& root);

// Brings a file of an older format version (as readProjectHeader returned it) to the current layout,
// in place, so the readers only ever see the current one. This is the one place for such steps: a
// version N adds the step from N − 1 to N here, and the steps run in order. Version 1 is the first
// format, so there is nothing to convert yet.
void upgradeToCurrentVersion(QJsonObject& root, int version);

} // namespace speculum::scene
