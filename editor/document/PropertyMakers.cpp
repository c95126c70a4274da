#include "editor/document/PropertyMakers.hpp"

#include "render/frame/SceneLimits.hpp"
#include "scene/model/SceneChecks.hpp"

#include <QFileInfo>

namespace speculum::document::makers {

base::Status fail(const PropertyInfo& info, const QString& why) {
    return base::Error{QStringLiteral("%1 %2").arg(info.label, why).toStdString()};
}

std::optional<double> toNumber(const QVariant& v) {
    bool ok = false;
    const double d = v.toDouble(&ok);
    if (!ok) {
        return std::nullopt;
    }
    return d;
}

PropertyInfo numberInfo(QString key, QString label, PropertyKind kind, NumberRange range, QString unit,
                        QString tooltip) {
    PropertyInfo info;
    info.key = std::move(key);
    info.label = std::move(label);
    info.kind = kind;
    info.minimum = range.minimum;
    info.maximum = range.maximum;
    info.minimumExclusive = range.minimumExclusive;
    info.maximumExclusive = range.maximumExclusive;
    info.unit = std::move(unit);
    info.tooltip = std::move(tooltip);
    if (std::isfinite(range.minimum)) {
        info.softMinimum = range.minimum;
    }
    if (std::isfinite(range.maximum)) {
        info.softMaximum = range.maximum;
    }
    return info;
}

Property<scene::NodeData> filePath(QString key, QString label, Access<scene::NodeData, std::string> access,
                                   QString filter, bool allowEmpty) {
    Property<scene::NodeData> p;
    p.info.key = std::move(key);
    p.info.label = std::move(label);
    p.info.kind = PropertyKind::FilePath;
    p.info.fileFilter = std::move(filter);
    p.get = [access](const scene::NodeData& d) {
        const std::string* s = read(access, d);
        return s ? QVariant(QString::fromStdString(*s)) : QVariant();
    };
    p.set = [access, info = p.info, allowEmpty](scene::NodeData& d, const QVariant& value) -> base::Status {
        const QString path = value.toString().trimmed();
        std::string* field = access(d);
        if (!field) {
            return fail(info, QStringLiteral("does not apply to this node"));
        }
        if (path.isEmpty()) {
            if (!allowEmpty) {
                return fail(info, QStringLiteral("needs a file"));
            }
            field->clear();
            return base::Done{};
        }
        const QFileInfo file(path);
        if (!file.isAbsolute()) {
            return fail(info, QStringLiteral("needs an absolute path, got \"%1\"").arg(path));
        }
        // Texture fields (the ones that may be empty) may also name an image embedded in a model file,
        // "/abs/model.glb#*0", as import writes them.
        const qsizetype hash = path.lastIndexOf(QLatin1Char('#'));
        if (!file.isFile() && allowEmpty && hash > 0 && QFileInfo(path.left(hash)).isFile()) {
            *field = path.toStdString();
            return base::Done{};
        }
        if (!file.isFile()) {
            return fail(info, QStringLiteral("file does not exist: %1").arg(path));
        }
        *field = file.absoluteFilePath().toStdString();
        return base::Done{};
    };
    return p;
}

QString nonZeroScale(const glm::dvec3& s) {
    for (int i = 0; i < 3; ++i) {
        if (s[i] == 0.0) {
            return QStringLiteral("components must be non-zero (a zero scale flattens the node)");
        }
        // The project reader's limits (render/frame/SceneLimits.hpp): beyond them float maths overflows.
        if (std::abs(s[i]) < render::kMinScale || std::abs(s[i]) > render::kMaxScale) {
            return QStringLiteral("components must be in %1..%2 in size (negative mirrors), got %3")
                .arg(QString::fromStdString(scene::formatLimit(render::kMinScale)),
                     QString::fromStdString(scene::formatLimit(render::kMaxScale)),
                     QString::fromStdString(scene::formatLimit(s[i])));
        }
    }
    return {};
}

QString positiveExtents(const glm::dvec2& s) {
    if (!(s.x > 0.0 && s.y > 0.0)) {
        return QStringLiteral("extents must be greater than 0");
    }
    for (int i = 0; i < 2; ++i) {
        if (s[i] < render::kMinScale || s[i] > render::kMaxCoordinate) {
            return QStringLiteral("extents must be in %1..%2, got %3")
                .arg(QString::fromStdString(scene::formatLimit(render::kMinScale)),
                     QString::fromStdString(scene::formatLimit(render::kMaxCoordinate)),
                     QString::fromStdString(scene::formatLimit(s[i])));
        }
    }
    return {};
}

base::Status ok() {
    return base::Done{};
}

} // namespace speculum::document::makers
