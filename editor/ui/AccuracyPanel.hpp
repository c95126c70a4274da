#pragma once

#include "editor/ui/ExactComparison.hpp"
#include "render/Result.hpp"

#include <QWidget>
#include <optional>

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QUndoStack;

namespace speculum::document {
class Scene;
}

namespace speculum::ui {

class AnimationClock;
class ErrorMapOverlay;
class SweepChart;
class Viewport;

// The Accuracy dock: "Compare with exact" measures the current view's raster frame against the exact tracer
// (numbers, error map, optionally over the viewport), and the chart of a bench run (results.json) applies
// a configuration's settings to the document, as one undoable step, when a point is clicked.
class AccuracyPanel : public QWidget {
    Q_OBJECT

public:
    AccuracyPanel(document::Scene& scene, QUndoStack& undoStack, Viewport& viewport, AnimationClock& clock,
                  QWidget* parent = nullptr);

    const std::optional<ComparisonResult>& lastComparison() const { return m_last; }
    bool comparing() const { return m_comparison->running(); }
    void setPreviewWidth(int pixels);
    // Loads a bench results.json into the chart; the error names the file and the problem.
    render::Status loadSweepFile(const QString& path);
    SweepChart& chart() { return *m_chart; }

public slots:
    void compareWithExact();
    void cancelComparison();
    // Applies the settings of results record `index` (what clicking its point does). Returns the message
    // shown under the chart.
    QString applyRecord(int index);

signals:
    void message(const QString& text); // for the status bar and the log

private:
    void showResult(const ComparisonResult& result);
    void comparisonFailed(const QString& text, bool cancelled);
    void setBusy(bool busy);
    void loadSweepDialog();

    document::Scene& m_scene;
    QUndoStack& m_undoStack;
    Viewport& m_viewport;
    AnimationClock& m_clock;
    ExactComparison* m_comparison = nullptr;
    std::optional<ComparisonResult> m_last;

    QSpinBox* m_width = nullptr;
    QPushButton* m_compare = nullptr;
    QPushButton* m_cancel = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QLabel* m_rmse = nullptr;
    QLabel* m_psnr = nullptr;
    QLabel* m_psnrMirrors = nullptr;
    QLabel* m_psnrReflector = nullptr;
    QLabel* m_rasterMs = nullptr;
    QLabel* m_traceMs = nullptr;
    QLabel* m_errorMap = nullptr;
    QCheckBox* m_overlay = nullptr;
    ErrorMapOverlay* m_overlayWidget = nullptr;
    SweepChart* m_chart = nullptr;
    QLabel* m_sweepMessage = nullptr;
};

} // namespace speculum::ui
