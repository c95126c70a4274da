#include "editor/ui/SnapSettings.hpp"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>
#include <cmath>

namespace speculum::ui {

namespace {

const QString kAlwaysKey = QStringLiteral("snap/always");
const QString kMoveKey = QStringLiteral("snap/moveStep");
const QString kRotateKey = QStringLiteral("snap/rotateStep");
const QString kScaleKey = QStringLiteral("snap/scaleStep");

// A remembered number within [low, high], or `fallback` (a hand-edited or foreign value).
double remembered(const QSettings& settings, const QString& key, double low, double high, double fallback) {
    bool ok = false;
    const double value = settings.value(key, fallback).toDouble(&ok);
    return ok && std::isfinite(value) && value >= low && value <= high ? value : fallback;
}

QDoubleSpinBox* stepField(const char* name, double low, double high, int decimals, const QString& suffix) {
    auto* field = new QDoubleSpinBox;
    field->setObjectName(QLatin1String(name));
    field->setRange(low, high);
    field->setDecimals(decimals);
    field->setSuffix(suffix);
    field->setAccelerated(true);
    return field;
}

} // namespace

SnapSettings SnapSettings::load() {
    const QSettings settings;
    const SnapSteps defaults;
    SnapSettings s;
    s.always = settings.value(kAlwaysKey, false).toBool();
    s.steps.move = remembered(settings, kMoveKey, 0.0, kMaxMoveStep, defaults.move);
    s.steps.rotate = remembered(settings, kRotateKey, kMinRotateStep, kMaxRotateStep, defaults.rotate);
    s.steps.scale = remembered(settings, kScaleKey, kMinScaleStep, kMaxScaleStep, defaults.scale);
    return s;
}

void SnapSettings::save() const {
    QSettings settings;
    settings.setValue(kAlwaysKey, always);
    settings.setValue(kMoveKey, steps.move);
    settings.setValue(kRotateKey, steps.rotate);
    settings.setValue(kScaleKey, steps.scale);
}

std::optional<SnapSteps> SnapSettings::forDrag(bool ctrlHeld) const {
    if (always == ctrlHeld) {
        return std::nullopt;
    }
    return steps;
}

SnapSettingsDialog::SnapSettingsDialog(const SnapSettings& initial, QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("snapSettingsDialog"));
    setWindowTitle(tr("Snap Steps"));
    m_always = new QCheckBox(tr("Snap while dragging (Ctrl then drags freely)"));
    m_always->setObjectName(QStringLiteral("snap.always"));
    m_move = stepField("snap.move", 0.0, SnapSettings::kMaxMoveStep, 4, {});
    m_move->setSpecialValueText(tr("Grid spacing"));
    m_move->setToolTip(tr("Moves snap to multiples of this distance; at 0, to the ground grid's lines "
                          "(their spacing follows the zoom)"));
    m_rotate = stepField("snap.rotate", SnapSettings::kMinRotateStep, SnapSettings::kMaxRotateStep, 2,
                         QStringLiteral("°"));
    m_scale = stepField("snap.scale", SnapSettings::kMinScaleStep, SnapSettings::kMaxScaleStep, 3, {});
    m_scale->setToolTip(tr("Scaling snaps the factor the drag multiplies by to multiples of this step"));
    auto* form = new QFormLayout;
    form->addRow(m_always);
    form->addRow(tr("&Move step:"), m_move);
    form->addRow(tr("&Rotate step:"), m_rotate);
    form->addRow(tr("&Scale factor step:"), m_scale);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                         QDialogButtonBox::RestoreDefaults);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        settings().save();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            [this] { fill(SnapSettings{}); });
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
    fill(initial);
}

void SnapSettingsDialog::fill(const SnapSettings& settings) {
    m_always->setChecked(settings.always);
    m_move->setValue(settings.steps.move);
    m_rotate->setValue(settings.steps.rotate);
    m_scale->setValue(settings.steps.scale);
}

SnapSettings SnapSettingsDialog::settings() const {
    SnapSettings s;
    s.always = m_always->isChecked();
    s.steps.move = m_move->value();
    s.steps.rotate = m_rotate->value();
    s.steps.scale = m_scale->value();
    return s;
}

} // namespace speculum::ui
