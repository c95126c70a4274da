#pragma once

#include "accuracy/Results.hpp"
#include "base/Result.hpp"
#include "editor/ui/ExactComparison.hpp"

#include <QImage>
#include <QLabel>
#include <QWidget>
#include <optional>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QGridLayout;
class QGroupBox;
class QHBoxLayout;
class QVBoxLayout;
class QProgressBar;
class QScrollArea;
class QPushButton;
class QSpinBox;
class QUndoStack;

namespace speculum::scene {
class Scene;
} // namespace speculum::scene

namespace speculum::view {
class AnimationClock;
}

namespace speculum::ui {

class CompareView;
class ErrorMapOverlay;
class SweepChart;
class SweepRunJob;
class Viewport;

// One of the Accuracy panel's images: drawn scaled down to the space it has, keeping its aspect, so a
// 480-pixel comparison fits a narrow dock; pixmap() is the whole image. Emits clicked() on a left click.
class ImageTile : public QLabel {
    Q_OBJECT

public:
    explicit ImageTile(QWidget* parent = nullptr);
    void setImage(const QImage& image); // a null image empties it
    const QImage& image() const { return m_image; }
    // The height it takes: at least `minimum` (a short dock scrolls), at most `maximum`.
    void setImageHeights(int minimum, int maximum);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    bool hasHeightForWidth() const override;
    int heightForWidth(int width) const override;

signals:
    void clicked();

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

private:
    QRect imageRect() const;

    QImage m_image;
    int m_minimumHeight = 96;
    int m_maximumHeight = 160;
};

// The Accuracy dock: "Compare with exact" measures the current view's raster frame against the exact tracer
// (numbers explained in a sentence; the exact image, the raster image and the error map side by side, or a
// flip view that alternates the exact and the raster image in one place; the error map optionally over the
// viewport). A new or opened document clears it (Scene::sceneReset, or clear()). "Run sweep" runs the
// bench's sweep on the document's scene in-process (accuracy::runSweep on a worker thread, with progress and
// cancel), filling the chart as points arrive and showing the report's findings when done; "Load sweep…"
// charts a results.json that `speculum bench` wrote. Clicking a point applies that configuration's settings
// to the document, as one undoable step.
class AccuracyPanel : public QWidget {
    Q_OBJECT

public:
    AccuracyPanel(scene::Scene& scene, QUndoStack& undoStack, Viewport& viewport, view::AnimationClock& clock,
                  QWidget* parent = nullptr);

    const std::optional<ComparisonResult>& lastComparison() const { return m_last; }
    bool comparing() const { return m_comparison->running(); }
    void setPreviewWidth(int pixels);
    // The paths per rough pixel the comparison refines to (0: auto, within about 20 s).
    void setPaths(int paths);
    // Loads a bench results.json into the chart; the error names the file and the problem.
    base::Status loadSweepFile(const QString& path);
    SweepChart& chart() { return *m_chart; }
    bool sweeping() const;
    // The findings of the last finished sweep, as shown (Markdown); empty before one finished.
    QString findingsText() const;
    // The sentence under the numbers that says what RMSE and PSNR measure and what a good value is.
    QString explanationText() const;

    // How the compared images show: the four side by side (exact, raster, error map, FLIP map), one view
    // that flips exact / raster, or a zoomable view that swipes between them or shows them side by side.
    enum class ImageMode { SideBySide, Flip, Swipe, ZoomSideBySide };
    void setImageMode(ImageMode mode);
    // Whether the flip view shows the exact image (else the raster one).
    bool flipShowsReference() const;
    CompareView& compareView() { return *m_compareView; }
    // What the viewport overlay shows: the error map or the FLIP map.
    enum class OverlayMap { Error, Flip };
    void setOverlayMap(OverlayMap map);

public slots:
    // Forgets the comparison and the sweep of the previous document (New, Open, Restore): numbers, images,
    // the overlay and the chart; a running comparison or sweep is cancelled.
    void clear();
    // The flip view changes to the other image (exact ↔ raster).
    void flip();
    void compareWithExact();
    void cancelComparison();
    // Applies the settings of results record `index` (what clicking its point does). Returns the message
    // shown under the chart.
    QString applyRecord(int index);
    // Runs the bench's sweep on the document's scene at the bench's quick or full size.
    void runSweep(bool quick = true);
    void cancelSweep();

signals:
    void message(const QString& text); // for the status bar and the log

private:
    // Construction, one group of widgets each, called in the order the widgets sit. The sweep's are in
    // AccuracyPanelSweep.cpp.
    QGroupBox* buildCompareBox();
    QVBoxLayout* buildCompareButtons(QGroupBox* compareBox);
    QFormLayout* buildNumbers(QGroupBox* compareBox);
    void buildImages(QGroupBox* compareBox);
    void buildSideBySide();
    void buildFlipPage();
    QGroupBox* buildSweepBox();
    QGridLayout* buildSweepButtons(QGroupBox* sweepBox);
    void buildScrollArea(QGroupBox* compareBox, QGroupBox* sweepBox);
    void connectComparison();
    void connectSweep();

    void showResult(const ComparisonResult& result);
    void showFlipImage();
    void showImageMode(int mode);
    void showOverlayImage();
    void comparisonFailed(const QString& text, bool cancelled);
    void setBusy(bool busy);
    void loadSweepDialog();
    void setSweeping(bool sweeping);
    void sweepProgress(int done, int total, const QString& line);
    void sweepFinished(const accuracy::ResultsFile& results);
    void sweepFailed(const QString& text, bool cancelled);

    scene::Scene& m_scene;
    QUndoStack& m_undoStack;
    Viewport& m_viewport;
    view::AnimationClock& m_clock;
    ExactComparison* m_comparison = nullptr;
    std::optional<ComparisonResult> m_last;

    QSpinBox* m_width = nullptr;
    QComboBox* m_paths = nullptr;
    QPushButton* m_compare = nullptr;
    QPushButton* m_cancel = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QLabel* m_rmse = nullptr;
    QLabel* m_psnr = nullptr;
    QLabel* m_psnrMirrors = nullptr;
    QLabel* m_psnrReflector = nullptr;
    QLabel* m_psnrInterval = nullptr;
    QLabel* m_mae = nullptr;
    QLabel* m_ssim = nullptr;
    QLabel* m_flip = nullptr;
    QLabel* m_rasterMs = nullptr;
    QLabel* m_traceMs = nullptr;
    QLabel* m_noise = nullptr;
    QLabel* m_explanation = nullptr;
    QWidget* m_images = nullptr;
    QComboBox* m_imageMode = nullptr;
    QWidget* m_sideBySide = nullptr;
    ImageTile* m_reference = nullptr;
    ImageTile* m_raster = nullptr;
    ImageTile* m_errorMap = nullptr;
    ImageTile* m_flipMap = nullptr;
    CompareView* m_compareView = nullptr;
    QWidget* m_flipPage = nullptr;
    ImageTile* m_flipView = nullptr;
    QLabel* m_flipCaption = nullptr;
    QPushButton* m_flipButton = nullptr;
    bool m_flipShowsReference = true;
    QCheckBox* m_overlay = nullptr;
    QComboBox* m_overlayMap = nullptr;
    ErrorMapOverlay* m_overlayWidget = nullptr;
    SweepChart* m_chart = nullptr;
    QLabel* m_sweepMessage = nullptr;

    SweepRunJob* m_sweep = nullptr;
    QPushButton* m_runSweep = nullptr;
    QPushButton* m_cancelSweep = nullptr;
    QPushButton* m_loadSweep = nullptr;
    QComboBox* m_sweepSize = nullptr;
    QProgressBar* m_sweepProgress = nullptr;
    QLabel* m_sweepStatus = nullptr;
    QLabel* m_findings = nullptr;
    QScrollArea* m_findingsScroll = nullptr;
    // What the chart showed before the running sweep: shown again if it is cancelled or fails.
    std::optional<accuracy::ResultsFile> m_chartBefore;
    bool m_sceneChangedDuringSweep = false;
};

} // namespace speculum::ui
