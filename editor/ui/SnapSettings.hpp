#pragma once

#include "editor/ui/Gizmo.hpp"

#include <QDialog>
#include <optional>

class QCheckBox;
class QDoubleSpinBox;

namespace speculum::ui {

// How handle drags snap, remembered between sessions (QSettings, the "snap/" keys): the steps, and
// whether drags snap without Ctrl (Ctrl then drags freely, as Blender's snap toggle inverts it).
struct SnapSettings {
    bool always = false;
    SnapSteps steps;

    // Each step's range; a remembered value outside it (or not a number) reads as the default.
    static constexpr double kMaxMoveStep = 1e6;
    static constexpr double kMinRotateStep = 0.01, kMaxRotateStep = 180.0;
    static constexpr double kMinScaleStep = 0.001, kMaxScaleStep = 10.0;

    static SnapSettings load();
    void save() const;
    // The steps a drag snaps to with Ctrl held or not, or none.
    std::optional<SnapSteps> forDrag(bool ctrlHeld) const;
    bool operator==(const SnapSettings&) const = default;
};

// View ▸ Snap Steps…: the three steps and the snap-always choice, with Restore Defaults. Accepting saves
// them (SnapSettings::save); settings() is what the fields say.
class SnapSettingsDialog : public QDialog {
    Q_OBJECT
public:
    SnapSettingsDialog(const SnapSettings& initial, QWidget* parent = nullptr);
    SnapSettings settings() const;

private:
    void fill(const SnapSettings& settings);
    QCheckBox* m_always = nullptr;
    QDoubleSpinBox* m_move = nullptr;
    QDoubleSpinBox* m_rotate = nullptr;
    QDoubleSpinBox* m_scale = nullptr;
};

} // namespace speculum::ui
