#pragma once

#include "scene/export/StillExport.hpp"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace speculum::ui {

// File ▸ Export Still: output file, size, format, supersampling, animation time, camera, and the exact
// reference (the CPU tracer, as `speculum render --reference`). The time defaults to the scene's start
// (t = 0, as the CLI); the time slider's (`time`, the animation clock's) is one choice away, and a note
// says which the still uses. The rendering itself is MainWindow's exportStillFile(), the same code path
// as `speculum render`.
class ExportStillDialog : public QDialog {
    Q_OBJECT

public:
    ExportStillDialog(const QString& suggestedPath, double time, QWidget* parent = nullptr);

    QString outputPath() const;
    scene::StillExportSettings settings() const; // camera: scene camera (set by the caller for "view")
    bool useCurrentView() const;
    QString timeNote() const; // "Renders the scene at t = 0.000 s, its start …"

    void accept() override; // refuses invalid settings with a message

private:
    void addFileRows(QFormLayout* form, const QString& suggestedPath);
    void addSizeRows(QFormLayout* form);
    void addTimeRows(QFormLayout* form, double time);
    void addCameraRows(QFormLayout* form);
    void addReferenceRows(QFormLayout* form);
    void selectFormatOf(const QString& path);
    void formatChanged();
    void referenceChanged();
    void browse();
    void timeChanged();

    QLineEdit* m_path = nullptr;
    QComboBox* m_format = nullptr;
    QSpinBox* m_width = nullptr;
    QSpinBox* m_height = nullptr;
    QSpinBox* m_ssaa = nullptr;
    QDoubleSpinBox* m_time = nullptr;
    QComboBox* m_timeSource = nullptr;
    QLabel* m_timeNote = nullptr;
    double m_clockTime = 0.0;
    QComboBox* m_camera = nullptr;
    QCheckBox* m_reference = nullptr;
    QSpinBox* m_samples = nullptr;
    QLabel* m_error = nullptr;
};

} // namespace speculum::ui
