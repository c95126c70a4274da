#include "editor/document/FieldProperties.hpp"

#include "scene/import/ModelFormats.hpp"

#include <QFileInfo>
#include <algorithm>
#include <cctype>
#include <cmath>

namespace speculum::document::fieldprops {

namespace {

QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

PropertyKind kindOf(render::FieldType type) {
    switch (type) {
    case render::FieldType::Bool:
        return PropertyKind::Bool;
    case render::FieldType::Integer:
        return PropertyKind::Integer;
    case render::FieldType::Vector2:
        return PropertyKind::Vector2;
    case render::FieldType::Vector3:
        return PropertyKind::Vector3;
    case render::FieldType::Color:
        return PropertyKind::Color;
    case render::FieldType::Choice:
    case render::FieldType::WrapPair:
        return PropertyKind::Enum;
    case render::FieldType::Path:
        return PropertyKind::FilePath;
    case render::FieldType::Text:
        return PropertyKind::Text;
    case render::FieldType::Number:
    case render::FieldType::Object:
        break;
    }
    return PropertyKind::Number;
}

template <int N>
std::optional<glm::vec<N, double>> numbers(const QVariant& value) {
    const QVariantList list = value.toList();
    if (list.size() != N)
        return std::nullopt;
    glm::vec<N, double> out;
    for (int i = 0; i < N; ++i) {
        bool ok = false;
        out[i] = list[i].toDouble(&ok);
        if (!ok)
            return std::nullopt;
    }
    return out;
}

// A camera field's label by its name, for the camera's whole rules.
QString cameraLabel(const std::string& field) {
    const render::FieldSpec* spec = render::findField<render::Camera>(field);
    return spec ? text(spec->label) : QString::fromStdString(field);
}

} // namespace

std::optional<std::string> wholeProblem(const render::Camera& camera) {
    // The project reader's rule for the whole camera (SceneChecks.hpp), word for word.
    if (const std::optional<scene::FieldProblem> problem = scene::cameraProblem(camera))
        return "Camera " + cameraLabel(problem->field).toStdString() + " " + problem->what;
    return std::nullopt;
}

std::optional<std::string> wholeProblem(const render::ParallaxParams& proxy) {
    if (const auto problem = render::parallaxProblem(proxy))
        return "Parallax proxy: " + problem->second;
    return std::nullopt;
}

PropertyInfo infoOf(const render::FieldSpec& spec, const QString& key) {
    PropertyInfo info;
    info.key = key;
    info.label = text(spec.label);
    info.kind = kindOf(spec.type);
    info.tooltip = text(spec.meaning);
    info.unit = text(spec.unit);
    const bool magnitude = spec.rule == render::FieldRule::Magnitude;
    info.minimum = magnitude ? -spec.max : spec.type == render::FieldType::Color ? 0.0 : spec.min;
    info.maximum = spec.type == render::FieldType::Color ? 1.0 : spec.max;
    info.minimumExclusive = spec.minOpen && !magnitude;
    info.maximumExclusive = spec.maxOpen;
    info.softMinimum = std::isfinite(info.minimum) ? info.minimum : 0.0;
    info.softMaximum = std::isfinite(info.maximum) ? info.maximum : 1.0;
    if (spec.slider) {
        info.slider = true;
        info.softMinimum = spec.softMin;
        info.softMaximum = spec.softMax;
    }
    info.decimals = spec.type == render::FieldType::Integer ? 0 : spec.decimals;
    info.step = spec.type == render::FieldType::Integer ? std::max(1.0, spec.step) : spec.step;
    if (spec.type == render::FieldType::Color) {
        info.step = 0.05;
        info.tooltip += QStringLiteral(" (linear RGB, each component 0..1)");
    }
    info.options = choiceLabels(spec);
    if (spec.type == render::FieldType::Path)
        info.fileFilter =
            spec.name == "file"
                ? scene::modelFileFilter()
                : QStringLiteral("Images (*.png *.jpg *.jpeg *.tif *.tiff *.exr *.hdr);;All files (*)");
    return info;
}

QStringList choiceLabels(const render::FieldSpec& spec) {
    QStringList options;
    for (const render::names::Name& n : spec.choices)
        options << text(n.label);
    return options;
}

// "Reflectivity must be in 0..1, got 2". A problem that starts with the label's own word ("colour
// components must ...") continues the label instead of repeating it.
base::Status refuse(const render::FieldSpec& spec, const std::string& problem) {
    std::string label(spec.label);
    std::string lower = label;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (!lower.empty() && problem.rfind(lower + " ", 0) == 0)
        return base::Error{label + problem.substr(lower.size())};
    return base::Error{label + " " + problem};
}

std::optional<render::FieldValue> toFieldValue(const render::FieldSpec& spec, const QVariant& value) {
    bool ok = false;
    switch (spec.type) {
    case render::FieldType::Bool:
        return value.toBool();
    case render::FieldType::Integer:
    case render::FieldType::Choice: {
        const double d = value.toDouble(&ok);
        if (!ok || !std::isfinite(d) || d != std::floor(d) || std::abs(d) > 1e9)
            return std::nullopt;
        return static_cast<int>(d);
    }
    case render::FieldType::Number: {
        const double d = value.toDouble(&ok);
        return ok ? std::optional<render::FieldValue>(d) : std::nullopt;
    }
    case render::FieldType::Vector2:
        if (auto v = numbers<2>(value))
            return *v;
        return std::nullopt;
    case render::FieldType::Vector3:
    case render::FieldType::Color:
        if (auto v = numbers<3>(value))
            return *v;
        return std::nullopt;
    case render::FieldType::Path:
    case render::FieldType::Text:
        return value.toString().toStdString();
    case render::FieldType::WrapPair:
    case render::FieldType::Object:
        break;
    }
    return std::nullopt;
}

QVariant toVariant(const render::FieldValue& value) {
    if (const bool* b = std::get_if<bool>(&value))
        return *b;
    if (const int* i = std::get_if<int>(&value))
        return *i;
    if (const double* d = std::get_if<double>(&value))
        return *d;
    if (const auto* v2 = std::get_if<glm::dvec2>(&value))
        return QVariantList{v2->x, v2->y};
    if (const auto* v3 = std::get_if<glm::dvec3>(&value))
        return QVariantList{v3->x, v3->y, v3->z};
    return QString::fromStdString(std::get<std::string>(value));
}

base::Result<std::string> checkedPath(const render::FieldSpec& spec, const QString& entered,
                                      bool allowEmpty) {
    const QString path = entered.trimmed();
    const std::string label(spec.label);
    if (path.isEmpty()) {
        if (!allowEmpty)
            return base::Error{label + " needs a file"};
        return std::string();
    }
    const QFileInfo file(path);
    if (!file.isAbsolute())
        return base::Error{label + " needs an absolute path, got \"" + path.toStdString() + "\""};
    // A texture may also name an image embedded in a model file, "/abs/model.glb#*0", as import writes it.
    const qsizetype hash = path.lastIndexOf(QLatin1Char('#'));
    if (!file.isFile() && allowEmpty && hash > 0 && QFileInfo(path.left(hash)).isFile())
        return path.toStdString();
    if (!file.isFile())
        return base::Error{label + " file does not exist: " + path.toStdString()};
    return file.absoluteFilePath().toStdString();
}

} // namespace speculum::document::fieldprops
