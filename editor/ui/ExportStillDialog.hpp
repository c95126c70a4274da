#pragma once

#include "editor/document/StillExport.hpp"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace speculum::ui {

// File ▸ Export Still: output file, size, format, supersampling, animation time, camera, and the exact
// reference (disabled until the reference tracer exists). The rendering itself is MainWindow's
// exportStillFile(), the same code path as `speculum render`.
class ExportStillDialog : public QDialog {
    Q_OBJECT

public:
    ExportStillDialog(const QString& suggestedPath, double time, QWidget* parent = nullptr);

    QString outputPath() const;
    document::StillExportSettings settings() const; // camera: scene camera (set by the caller for "view")
    bool useCurrentView() const;

    void accept() override; // refuses invalid settings with a message

private:
    void formatChanged();
    void browse();

    QLineEdit* m_path = nullptr;
    QComboBox* m_format = nullptr;
    QSpinBox* m_width = nullptr;
    QSpinBox* m_height = nullptr;
    QSpinBox* m_ssaa = nullptr;
    QDoubleSpinBox* m_time = nullptr;
    QComboBox* m_camera = nullptr;
    QCheckBox* m_reference = nullptr;
    QLabel* m_error = nullptr;
};

} // namespace speculum::ui
