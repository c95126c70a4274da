#include "scene/import/ModelFormats.hpp"

#include <QFileInfo>
#include <QStringList>
#include <assimp/Importer.hpp>

namespace speculum::scene {

bool isImportableModel(const QString& path) {
    const QString suffix = QFileInfo(path).suffix();
    if (suffix.isEmpty()) {
        return false;
    }
    // Project files are JSON, which Assimp does not read; checked first so they never count as models.
    if (path.endsWith(QStringLiteral(".speculum.json"), Qt::CaseInsensitive)) {
        return false;
    }
    return Assimp::Importer().IsExtensionSupported(("." + suffix.toLower()).toStdString());
}

QString modelFileFilter() {
    std::string list;
    Assimp::Importer().GetExtensionList(list); // "*.3ds;*.obj;..."
    const QStringList patterns = QString::fromStdString(list).split(QLatin1Char(';'), Qt::SkipEmptyParts);
    return QStringLiteral("3D models (%1);;All files (*)").arg(patterns.join(QLatin1Char(' ')));
}

} // namespace speculum::scene
