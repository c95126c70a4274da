#pragma once

#include "base/Result.hpp"
#include "scene/model/SceneData.hpp"

#include <QString>
#include <QStringList>
#include <QVariant>
#include <functional>
#include <limits>
#include <vector>

namespace speculum::document {

// Descriptions of every editable property: what the inspector generates its editors from. Each property
// knows its type, its valid range and unit, how to read it from a value and how to write a new value into
// one. Writing validates: an invalid value is refused with a message for the user (the same rule the
// project reader applies, so an edit can never produce a file that does not load); it is never clamped.
//
// Values travel as QVariant: double (Number), int (Integer, Enum: the option index), bool, QString (Text,
// FilePath) and QVariantList of doubles (Vector2, Vector3, Color).

enum class PropertyKind { Text, Number, Integer, Bool, Enum, Vector2, Vector3, Color, FilePath };

struct PropertyInfo {
    QString key;   // "material.specular": unique, stable; editors are named after it
    QString label; // "Specular"
    PropertyKind kind = PropertyKind::Number;
    double minimum = -std::numeric_limits<double>::infinity();
    double maximum = std::numeric_limits<double>::infinity();
    bool minimumExclusive = false;
    bool maximumExclusive = false;
    // Slider range for numbers whose valid range is open-ended (0..∞): the slider covers this, the spin
    // box accepts anything valid.
    double softMinimum = 0.0;
    double softMaximum = 1.0;
    bool slider = false;
    QString unit; // shown as a suffix: "°", "s", "units", "px"
    int decimals = 3;
    double step = 0.1;
    QStringList options; // Enum: display names, in index order
    QString fileFilter;  // FilePath: for the file dialog
    QString tooltip;
};

template <typename T>
struct Property {
    PropertyInfo info;
    std::function<QVariant(const T&)> get;
    // Writes value into target after validating it; on error target is unchanged.
    std::function<base::Status(T&, const QVariant&)> set;
    // Hidden when it does not apply (a spot angle on a point light); empty = always shown.
    std::function<bool(const T&)> visible;
    // What the value does in this case when that is not what it says (a rough mirror set to the stencil
    // technique is drawn with the texture technique): shown under the editor; empty = nothing to add.
    std::function<QString(const T&)> note;
    QString noteFor(const T& value) const { return note ? note(value) : QString(); }

    bool isVisible(const T& value) const { return !visible || visible(value); }
};

// A group of node properties that is present or absent as a whole ("material", "mirror").
struct ComponentInfo {
    QString key;   // "material"; "node" and "transform" are always present
    QString title; // "Material"
    bool optional = true;
    std::function<bool(const scene::NodeData&)> present;
    // Adds the component with defaults / removes it. Fails with a message when the node would become
    // invalid (a reflector needs a mesh).
    std::function<base::Status(scene::NodeData&)> add;
    std::function<base::Status(scene::NodeData&)> remove;
    std::vector<Property<scene::NodeData>> properties;
};

const std::vector<ComponentInfo>& nodeComponents();
const ComponentInfo* findComponent(const QString& key);
const Property<scene::NodeData>* findNodeProperty(const QString& key);

const std::vector<Property<scene::SceneSettings>>& settingsProperties();
const std::vector<Property<scene::CameraData>>& cameraProperties();
const Property<scene::SceneSettings>* findSettingsProperty(const QString& key);
const Property<scene::CameraData>* findCameraProperty(const QString& key);

// The checks of a number against info's range; the message names the label ("Reflectivity must be in
// 0..1, got 2").
base::Status checkRange(const PropertyInfo& info, double value);

// Formats a number the way messages show it (shortest form, no trailing zeros).
QString formatNumber(double value);

} // namespace speculum::document
