#pragma once

#include "scene/export/AnimationExport.hpp"

#include <QDialog>
#include <QSize>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace speculum::ui {

// File ▸ Export Animation: output (a clip, .mp4 / .webm / .gif, or a PNG sequence "name_%04d.png"), the
// frames, fps, size, supersampling, raster or exact (the CPU tracer, with its paths), the camera, and a
// turntable. The frames default to one loop of the scene's animation at the fps; a turntable sets them to
// its turn (seconds × fps), so the clip loops. The choices other than the file and the frames are
// remembered for the next export (QSettings, the "exportAnimation/" keys). The drawing itself is
// MainWindow::startAnimationExport(), the same engine as `speculum render --frames`.
class ExportAnimationDialog : public QDialog {
    Q_OBJECT

public:
    // `suggestedBase`: the output's path without extension ("/scenes/teapot"); `loopSeconds`: one loop of
    // the scene's animation (scene::animationLoopSeconds); `viewSize`: the viewport's, the default size.
    ExportAnimationDialog(const QString& suggestedBase, double loopSeconds, QSize viewSize,
                          QWidget* parent = nullptr);

    QString outputPath() const;
    scene::AnimationSettings settings() const; // camera: the scene's (set by the caller for "view")
    bool useCurrentView() const;
    QString framesNote() const; // "48 frames, 2.000 s at 24 fps: one loop of the scene's animation"

    void accept() override; // refuses invalid settings with a message, remembers valid ones

private:
    void addFileRows(QFormLayout* form, const QString& suggestedBase);
    void addFrameRows(QFormLayout* form);
    void addTurntableRows(QFormLayout* form);
    void addSizeRows(QFormLayout* form, QSize viewSize);
    void addRendererRows(QFormLayout* form);
    void restoreChoices();
    void rememberChoices() const;
    void selectFormatOf(const QString& path);
    void formatChanged();
    void browse();
    void fpsChanged();
    void rangeEdited();
    void turntableChanged();
    void setFrameCount(int count);
    void updateFramesNote();
    void rendererChanged();

    QLineEdit* m_path = nullptr;
    QComboBox* m_format = nullptr;
    QSpinBox* m_first = nullptr;
    QSpinBox* m_last = nullptr;
    QSpinBox* m_fps = nullptr;
    QLabel* m_framesNote = nullptr;
    double m_loopSeconds = 0.0;
    bool m_rangeFollowsLoop = true; // until the user sets the frames: one loop at whatever fps
    bool m_settingRange = false;    // the dialog, not the user, is changing the frames
    QCheckBox* m_turntable = nullptr;
    QDoubleSpinBox* m_turnSeconds = nullptr;
    QSpinBox* m_width = nullptr;
    QSpinBox* m_height = nullptr;
    QSpinBox* m_ssaa = nullptr;
    QComboBox* m_renderer = nullptr;
    QSpinBox* m_samples = nullptr;
    QComboBox* m_camera = nullptr;
    QLabel* m_error = nullptr;
};

} // namespace speculum::ui
