#include "scene/project/ProjectVersion.hpp"

#include "base/Printable.hpp"

#include <QJsonDocument>
#include <QLocale>
#include <cassert>
#include <cmath>

namespace speculum::scene {

namespace {

// How a JSON value looks in the file, for messages: numbers as written, strings quoted.
std::string shown(const QJsonValue& v) {
    if (v.isDouble()) {
        return QString::number(v.toDouble(), 'g', QLocale::FloatingPointShortest).toStdString();
    }
    if (v.isString()) {
        return "\"" + base::printable(v.toString().toStdString(), 40) + "\""; // file text: escaped
    }
    if (v.isBool()) {
        return v.toBool() ? "true" : "false";
    }
    if (v.isNull()) {
        return "null";
    }
    return v.isArray() ? "an array" : "an object";
}

} // namespace

base::Result<int> readProjectHeader(const QJsonObject& root) {
    const QJsonValue format = root.value(QLatin1String("format"));
    if (format.isUndefined()) {
        return base::Error{"format: missing (this is not a speculum scene file)"};
    }
    if (format.toString() != QLatin1String("speculum-scene")) {
        return base::Error{"format: expected \"speculum-scene\"" +
                           (format.isString() ? ", got " + shown(format) : std::string()) +
                           " (this is not a speculum scene file)"};
    }

    const QJsonValue version = root.value(QLatin1String("version"));
    if (version.isUndefined()) {
        return base::Error{"version: missing"};
    }
    const double v = version.isDouble() ? version.toDouble() : NAN;
    if (!std::isfinite(v) || v != std::floor(v)) {
        return base::Error{"version: expected an integer format version such as 1, got " + shown(version)};
    }
    if (v > kProjectFormatVersion) {
        return base::Error{"version: version " + shown(version) +
                           " is newer than this speculum (reads up to " +
                           std::to_string(kProjectFormatVersion) + "); open it with a newer speculum"};
    }
    if (v < 1) {
        return base::Error{"version: must be at least 1 (the first speculum-scene format), got " +
                           shown(version)};
    }
    return static_cast<int>(v);
}

void upgradeToCurrentVersion(QJsonObject& root, int version) {
    assert(version >= 1 && version <= kProjectFormatVersion &&
           "upgradeToCurrentVersion(): the version was not checked by readProjectHeader");
    // Steps go here, oldest first: if (version < 2) { ...version 1 → 2...; } and so on.
    (void)root;
    (void)version;
}

} // namespace speculum::scene
