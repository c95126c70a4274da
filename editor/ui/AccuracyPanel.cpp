#include "editor/ui/AccuracyPanel.hpp"

#include "accuracy/Report.hpp"
#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "editor/document/Commands.hpp"
#include "editor/document/SweepResults.hpp"
#include "editor/ui/CompareView.hpp"
#include "editor/ui/SweepChart.hpp"
#include "editor/ui/SweepRunJob.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/model/Scene.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QUndoStack>
#include <QVBoxLayout>

namespace speculum::ui {

// The last error map laid over the viewport, half transparent, with a caption: it belongs to the view it
// was measured on, so after the view moves it is only a memory of that view.
class ErrorMapOverlay : public QWidget {
public:
    explicit ErrorMapOverlay(QWidget& viewport)
        : QWidget(&viewport) {
        setObjectName(QStringLiteral("errorMapOverlay"));
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_TranslucentBackground);
        viewport.installEventFilter(this);
        setGeometry(viewport.rect());
        hide();
    }
    // `caption` says what the image is (the error map's by default).
    void setImage(const QImage& image, const QString& caption = {}) {
        m_image = image;
        m_caption = caption;
        update();
    }
    const QImage& image() const { return m_image; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Resize) {
            setGeometry(static_cast<QWidget*>(watched)->rect());
        }
        return false;
    }
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        painter.setOpacity(0.85);
        // The compared image has the view's field of view over its height, in its own aspect: over the
        // viewport it spans the height, centred (cut at the sides of a narrower viewport).
        if (!m_image.isNull()) {
            const double w = double(height()) * m_image.width() / std::max(1, m_image.height());
            painter.drawImage(QRectF((width() - w) / 2.0, 0.0, w, height()), m_image);
        }
        painter.setOpacity(1.0);
        const QString caption =
            m_caption.isEmpty()
                ? tr("Error map of the compared view (brighter = worse; 64/255 or more = top)")
                : m_caption;
        const QRect box = painter.fontMetrics().boundingRect(caption).adjusted(-6, -3, 6, 3);
        const QRect at = box.translated(8 - box.left(), height() - box.height() - 8 - box.top());
        painter.fillRect(at, QColor(0, 0, 0, 170));
        painter.setPen(Qt::white);
        painter.drawText(at, Qt::AlignCenter, caption);
    }

private:
    QImage m_image;
    QString m_caption;
};

// An image scaled to fit the space it has, keeping its aspect (at most twice its own size); the pixmap
// it holds is the image at full size, so the layout is not forced as wide as the image.
ImageTile::ImageTile(QWidget* parent)
    : QLabel(parent) {
    setAlignment(Qt::AlignCenter);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

void ImageTile::setImage(const QImage& image) {
    m_image = image;
    if (image.isNull()) {
        QLabel::clear();
    } else {
        setPixmap(QPixmap::fromImage(image));
    }
    updateGeometry();
    update();
}

void ImageTile::setImageHeights(int minimum, int maximum) {
    m_minimumHeight = minimum;
    m_maximumHeight = maximum;
    updateGeometry();
}

QSize ImageTile::sizeHint() const {
    if (m_image.isNull()) {
        return minimumSizeHint();
    }
    // As wide as the image at its largest allowed height, no wider.
    const int width =
        std::min(m_image.width(), std::max(1, m_maximumHeight * m_image.width() / m_image.height()));
    return {width, heightForWidth(width)};
}

QSize ImageTile::minimumSizeHint() const {
    // Never shrunk to a thumbnail nobody can read: at least m_minimumHeight tall (or the image's height).
    return {48, m_image.isNull() ? 27 : std::min(m_image.height(), m_minimumHeight)};
}

bool ImageTile::hasHeightForWidth() const {
    return !m_image.isNull();
}

int ImageTile::heightForWidth(int width) const {
    if (m_image.isNull() || m_image.width() <= 0) {
        return minimumSizeHint().height();
    }
    const int shown = std::min(width, m_image.width());
    const int lowest = minimumSizeHint().height();
    return std::clamp(shown * m_image.height() / m_image.width(), lowest, std::max(lowest, m_maximumHeight));
}

QRect ImageTile::imageRect() const {
    if (m_image.isNull()) {
        return {};
    }
    const QSize fitted =
        m_image.size().scaled(contentsRect().size().boundedTo(m_image.size() * 2), Qt::KeepAspectRatio);
    QRect r(QPoint(0, 0), fitted);
    r.moveCenter(contentsRect().center());
    return r;
}

void ImageTile::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    if (m_image.isNull()) {
        return;
    }
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    painter.drawImage(imageRect(), m_image);
}

void ImageTile::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && !m_image.isNull()) {
        emit clicked();
    }
    QLabel::mousePressEvent(event);
}

namespace {

// "12 s", "2 min 5 s": a time the user waits.
QString duration(double seconds) {
    const int s = std::max(1, int(std::lround(seconds)));
    return s < 60 ? AccuracyPanel::tr("%1 s").arg(s)
                  : AccuracyPanel::tr("%1 min %2 s").arg(s / 60).arg(s % 60);
}

QString decibels(const std::optional<double>& db) {
    return db ? QStringLiteral("%1 dB").arg(*db, 0, 'f', 2) : QObject::tr("— (no such pixels)");
}

} // namespace

AccuracyPanel::AccuracyPanel(scene::Scene& scene, QUndoStack& undoStack, Viewport& viewport,
                             view::AnimationClock& clock, QWidget* parent)
    : QWidget(parent)
    , m_scene(scene)
    , m_undoStack(undoStack)
    , m_viewport(viewport)
    , m_clock(clock)
    , m_comparison(new ExactComparison(scene, viewport, this)) {
    // Built top to bottom, in the order the widgets sit (which is also the tab order).
    QGroupBox* compareBox = buildCompareBox();
    QGroupBox* sweepBox = buildSweepBox(); // AccuracyPanelSweep.cpp
    buildScrollArea(compareBox, sweepBox);
    connectComparison();
    connectSweep(); // AccuracyPanelSweep.cpp
    connect(&m_scene, &scene::Scene::changed, this, [this] {
        if (m_last && !m_comparison->running()) {
            m_status->setText(tr("The scene changed since these numbers: compare again."));
        }
        m_sceneChangedDuringSweep = m_sceneChangedDuringSweep || m_sweep->running();
    });
    // A measurement of the previous document says nothing about the new one.
    connect(&m_scene, &scene::Scene::sceneReset, this, &AccuracyPanel::clear);
}

// "This view against the exact tracer": the buttons, the numbers, the images and the overlay switch.
QGroupBox* AccuracyPanel::buildCompareBox() {
    auto* compareBox = new QGroupBox(tr("This view against the exact tracer"), this);
    QVBoxLayout* buttons = buildCompareButtons(compareBox);
    m_progress = new QProgressBar(compareBox);
    m_progress->setObjectName(QStringLiteral("accuracyProgress"));
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(false);
    m_progress->hide();
    m_status = new QLabel(tr("Renders the current view both ways and measures the difference."), compareBox);
    m_status->setObjectName(QStringLiteral("accuracyStatus"));
    m_status->setWordWrap(true);

    QFormLayout* numbers = buildNumbers(compareBox);
    buildImages(compareBox);
    m_overlay = new QCheckBox(tr("Show over the viewport:"), compareBox);
    m_overlay->setObjectName(QStringLiteral("accuracyOverlay"));
    m_overlay->setEnabled(false);
    m_overlayMap = new QComboBox(compareBox);
    m_overlayMap->setObjectName(QStringLiteral("accuracyOverlayMap"));
    m_overlayMap->addItem(tr("the error map"));
    m_overlayMap->addItem(tr("the FLIP map"));
    m_overlayMap->setToolTip(tr("The error map: each pixel's sRGB difference on a fixed scale. The FLIP map: "
                                "what a viewer flipping between the images would notice (0 black, 1 pale "
                                "yellow)."));
    m_overlayWidget = new ErrorMapOverlay(m_viewport);
    auto* overlayRow = new QHBoxLayout;
    overlayRow->addWidget(m_overlay);
    overlayRow->addWidget(m_overlayMap, 1);

    auto* compareLayout = new QVBoxLayout(compareBox);
    compareLayout->addLayout(buttons);
    compareLayout->addWidget(m_progress);
    compareLayout->addWidget(m_status);
    compareLayout->addLayout(numbers);
    compareLayout->addWidget(m_explanation);
    compareLayout->addWidget(m_images, 1);
    compareLayout->addLayout(overlayRow);
    return compareBox;
}

// The comparison's quality (width, paths per rough pixel), then Compare with exact and Cancel.
QVBoxLayout* AccuracyPanel::buildCompareButtons(QGroupBox* compareBox) {
    m_width = new QSpinBox(compareBox);
    m_width->setObjectName(QStringLiteral("accuracyWidth"));
    m_width->setRange(32, 4096);
    m_width->setValue(480); // interactive on a software rasterizer; the tracer's time grows with pixels
    m_width->setSuffix(tr(" px wide"));
    m_width->setToolTip(tr("Both images are rendered this wide, in the 16:9 aspect of a still (the view's "
                           "field of view, whatever the viewport's shape)"));
    m_paths = new QComboBox(compareBox);
    m_paths->setObjectName(QStringLiteral("accuracyPaths"));
    m_paths->addItem(tr("Auto (≤ 20 s)"), 0);
    for (int paths : kComparisonPathLevels) {
        m_paths->addItem(tr("%1 paths").arg(paths), paths);
    }
    m_paths->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_paths->setMinimumContentsLength(9);
    m_paths->setToolTip(
        tr("How exact the traced image is where it sees a rough mirror or reflector: it is traced with 4 "
           "paths a pixel first, then refined with four times as many at each step (its noise halves) up to "
           "this count. Auto refines while the estimate stays within about 20 seconds. Pixels that see no "
           "rough surface are exact with one path."));
    m_compare = new QPushButton(tr("Compare with exact"), compareBox);
    m_compare->setObjectName(QStringLiteral("compareExact"));
    m_cancel = new QPushButton(tr("Cancel"), compareBox);
    m_cancel->setObjectName(QStringLiteral("cancelCompare"));
    m_cancel->setEnabled(false);
    auto* quality = new QHBoxLayout;
    quality->addWidget(m_width);
    quality->addWidget(m_paths, 1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_compare, 1);
    buttons->addWidget(m_cancel);
    auto* rows = new QVBoxLayout;
    rows->addLayout(quality);
    rows->addLayout(buttons);
    return rows;
}

// RMSE, the PSNRs and the two times, and under them the sentence that says what the figures mean.
QFormLayout* AccuracyPanel::buildNumbers(QGroupBox* compareBox) {
    auto* numbers = new QFormLayout;
    auto label = [&](const char* name) {
        auto* l = new QLabel(QStringLiteral("—"), compareBox);
        l->setObjectName(QString::fromLatin1(name));
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
        return l;
    };
    m_rmse = label("accuracyRmse");
    m_psnr = label("accuracyPsnr");
    m_psnrMirrors = label("accuracyPsnrMirrors");
    m_psnrReflector = label("accuracyPsnrReflector");
    m_psnrInterval = label("accuracyPsnrInterval");
    m_psnrInterval->setToolTip(
        tr("Where the PSNR against a noiseless exact image lies (95 %), given the exact "
           "image's own noise (which also makes the PSNR shown a little pessimistic)"));
    m_mae = label("accuracyMae");
    m_ssim = label("accuracySsim");
    m_flip = label("accuracyFlip");
    m_rasterMs = label("accuracyRasterMs");
    m_traceMs = label("accuracyTraceMs");
    m_noise = label("accuracyNoise");
    m_noise->setToolTip(tr("The exact image's own Monte Carlo noise where it sees rough surfaces: the RMS "
                           "standard error of a pixel (linear radiance). It halves with each refinement; "
                           "differences smaller than it are noise, not error."));
    numbers->addRow(tr("RMSE (sRGB)"), m_rmse);
    numbers->addRow(tr("PSNR"), m_psnr);
    numbers->addRow(tr("PSNR mirrors"), m_psnrMirrors);
    numbers->addRow(tr("PSNR reflector"), m_psnrReflector);
    numbers->addRow(tr("PSNR 95 %"), m_psnrInterval);
    numbers->addRow(tr("MAE (sRGB)"), m_mae);
    numbers->addRow(tr("SSIM"), m_ssim);
    numbers->addRow(tr("FLIP (LDR · HDR)"), m_flip);
    numbers->addRow(tr("Raster frame"), m_rasterMs);
    numbers->addRow(tr("Exact tracer"), m_traceMs);
    numbers->addRow(tr("Tracer noise"), m_noise);

    m_explanation = new QLabel(
        tr("<b>RMSE</b> is the typical difference of a pixel's colour between the two images (sRGB, 0 = "
           "identical, 1 = black against white); <b>PSNR</b> says the same in decibels, 20·log10(1 / RMSE), "
           "so higher is better: above 40 dB the differences are invisible, 30–40 dB they show on a close "
           "look, below 30 dB they are obvious. <b>SSIM</b> compares local structure (1 = identical). "
           "<b>FLIP</b> is what a viewer flipping between the two images would notice, 0 to 1 (about 0.1 is "
           "one just-noticeable colour difference); its map shows where."),
        compareBox);
    m_explanation->setObjectName(QStringLiteral("accuracyExplanation"));
    m_explanation->setWordWrap(true);
    m_explanation->setTextFormat(Qt::RichText);
    return numbers;
}

// What the numbers measured, two ways: the exact image, the raster image and their difference side by
// side, or one larger view that flips between the exact and the raster image (differences jump out
// when the eye stays in one place).
void AccuracyPanel::buildImages(QGroupBox* compareBox) {
    m_imageMode = new QComboBox(compareBox);
    m_imageMode->setObjectName(QStringLiteral("accuracyImageMode"));
    m_imageMode->addItem(tr("Side by side"));
    m_imageMode->addItem(tr("Flip exact / raster"));
    m_imageMode->addItem(tr("Swipe exact / raster (zoom)"));
    m_imageMode->addItem(tr("Exact beside raster (zoom)"));
    m_imageMode->setToolTip(tr("Show the four images next to each other, one image that alternates "
                               "between the exact and the raster one, or a zoomable view that swipes "
                               "between them or shows them side by side"));
    m_flipButton = new QPushButton(tr("Flip"), compareBox);
    m_flipButton->setObjectName(QStringLiteral("accuracyFlipButton"));
    m_flipButton->setToolTip(tr("Alternate the view between the exact and the raster image (or click "
                                "the image)"));
    m_flipButton->hide();
    auto* modeRow = new QHBoxLayout;
    modeRow->addWidget(m_imageMode, 1);
    modeRow->addWidget(m_flipButton);

    m_images = new QWidget(compareBox);
    m_images->setObjectName(QStringLiteral("accuracyImages"));
    auto* imagesLayout = new QVBoxLayout(m_images);
    imagesLayout->setContentsMargins(0, 0, 0, 0);
    imagesLayout->addLayout(modeRow);
    buildSideBySide();
    buildFlipPage();
    m_compareView = new CompareView(m_images);
    m_compareView->setObjectName(QStringLiteral("accuracyCompareView"));
    m_compareView->setMinimumHeight(240);
    m_compareView->hide();
    imagesLayout->addWidget(m_sideBySide);
    imagesLayout->addWidget(m_flipPage);
    imagesLayout->addWidget(m_compareView, 1);
    m_images->hide();
}

// The exact image, the raster image and the error map, each over its caption.
void AccuracyPanel::buildSideBySide() {
    m_sideBySide = new QWidget(m_images);
    auto* imagesRow = new QHBoxLayout(m_sideBySide);
    imagesRow->setContentsMargins(0, 0, 0, 0);
    auto tile = [&](const char* name, const QString& caption, const QString& tooltip) {
        auto* column = new QVBoxLayout;
        auto* image = new ImageTile(m_sideBySide);
        image->setObjectName(QString::fromLatin1(name));
        image->setToolTip(tooltip);
        auto* text = new QLabel(caption, m_sideBySide);
        text->setAlignment(Qt::AlignCenter);
        text->setWordWrap(true);
        text->setToolTip(tooltip);
        column->addWidget(image, 1);
        column->addWidget(text);
        imagesRow->addLayout(column, 1);
        return image;
    };
    m_reference = tile("accuracyReference", tr("Exact (ray traced)"),
                       tr("The reference: the exact tracer's image of this view"));
    m_raster = tile("accuracyRaster", tr("Raster (what the editor draws)"),
                    tr("The rasterizer's image with the scene's settings"));
    m_errorMap = tile("accuracyErrorMap", tr("Error map"),
                      tr("Brighter = larger difference; 64/255 or more is the top of the ramp"));
    m_flipMap = tile("accuracyFlipMap", tr("FLIP map"),
                     tr("What a viewer flipping between the images would notice, in magma: black none, pale "
                        "yellow 1"));
}

// One larger image that flips between the exact and the raster image, with a caption saying which.
void AccuracyPanel::buildFlipPage() {
    m_flipPage = new QWidget(m_images);
    auto* flipLayout = new QVBoxLayout(m_flipPage);
    flipLayout->setContentsMargins(0, 0, 0, 0);
    m_flipView = new ImageTile(m_flipPage);
    m_flipView->setObjectName(QStringLiteral("accuracyFlipView"));
    m_flipView->setImageHeights(200, 320);
    m_flipView->setToolTip(tr("Click to flip between the exact and the raster image"));
    m_flipView->setCursor(Qt::PointingHandCursor);
    m_flipCaption = new QLabel(m_flipPage);
    m_flipCaption->setObjectName(QStringLiteral("accuracyFlipCaption"));
    m_flipCaption->setAlignment(Qt::AlignCenter);
    m_flipCaption->setWordWrap(true);
    flipLayout->addWidget(m_flipView, 1);
    flipLayout->addWidget(m_flipCaption);
    m_flipPage->hide();
}

void AccuracyPanel::buildScrollArea(QGroupBox* compareBox, QGroupBox* sweepBox) {
    // In a scroll area: the images and the chart keep a useful size in a short dock.
    auto* content = new QWidget;
    content->setObjectName(QStringLiteral("accuracyContent"));
    auto* contentLayout = new QVBoxLayout(content);
    contentLayout->addWidget(compareBox);
    contentLayout->addWidget(sweepBox, 1);
    auto* scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("accuracyScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(content);
    // As wide as the content needs (its buttons), so that nothing is cut off at the right.
    scroll->setMinimumWidth(content->minimumSizeHint().width() +
                            scroll->verticalScrollBar()->sizeHint().width());
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);
}

void AccuracyPanel::connectComparison() {
    connect(m_compare, &QPushButton::clicked, this, &AccuracyPanel::compareWithExact);
    connect(m_cancel, &QPushButton::clicked, this, &AccuracyPanel::cancelComparison);
    connect(m_comparison, &ExactComparison::estimated, this, [this](double seconds, int paths) {
        m_status->setText(tr("Tracing the exact image up to %1 paths per rough pixel: about %2 in all.")
                              .arg(paths)
                              .arg(duration(seconds)));
    });
    connect(m_comparison, &ExactComparison::progress, this, [this](double fraction, int paths, double left) {
        m_progress->setValue(int(std::clamp(fraction, 0.0, 1.0) * 1000));
        m_progress->setFormat(tr("%1 paths per rough pixel · about %2 left").arg(paths).arg(duration(left)));
    });
    connect(m_comparison, &ExactComparison::refined, this, [this](const ComparisonResult& result) {
        showResult(result);
        m_status->setText(
            tr("Refining the exact image (%1 paths per rough pixel so far)…").arg(result.paths));
    });
    connect(m_comparison, &ExactComparison::finished, this, &AccuracyPanel::showResult);
    connect(m_comparison, &ExactComparison::failed, this, &AccuracyPanel::comparisonFailed);
    connect(m_overlay, &QCheckBox::toggled, m_overlayWidget, &QWidget::setVisible);
    connect(m_overlayMap, &QComboBox::currentIndexChanged, this, &AccuracyPanel::showOverlayImage);
    connect(m_imageMode, &QComboBox::currentIndexChanged, this, &AccuracyPanel::showImageMode);
    connect(m_flipButton, &QPushButton::clicked, this, &AccuracyPanel::flip);
    connect(m_flipView, &ImageTile::clicked, this, &AccuracyPanel::flip);
}

QString AccuracyPanel::explanationText() const {
    return m_explanation->text();
}

void AccuracyPanel::clear() {
    m_comparison->cancel();
    if (m_sweep->running()) {
        cancelSweep();
    }
    m_last.reset();
    for (QLabel* l : {m_rmse, m_psnr, m_psnrMirrors, m_psnrReflector, m_psnrInterval, m_mae, m_ssim, m_flip,
                      m_rasterMs, m_traceMs, m_noise}) {
        l->setText(QStringLiteral("—"));
    }
    for (ImageTile* tile : {m_reference, m_raster, m_errorMap, m_flipMap, m_flipView}) {
        tile->setImage({});
    }
    m_compareView->setImages({}, {});
    m_flipCaption->clear();
    m_flipShowsReference = true;
    m_images->hide();
    m_status->setText(tr("Renders the current view both ways and measures the difference."));
    m_overlay->setChecked(false);
    m_overlay->setEnabled(false);
    m_overlayWidget->setImage({});
    m_overlayWidget->hide();
    m_chartBefore.reset();
    m_chart->setResults({});
    m_findings->clear();
    m_findingsScroll->hide();
    m_sweepMessage->setText(
        tr("Click a point to give the document that configuration's settings (one undo step)."));
}

bool AccuracyPanel::flipShowsReference() const {
    return m_flipShowsReference;
}

void AccuracyPanel::setImageMode(ImageMode mode) {
    m_imageMode->setCurrentIndex(static_cast<int>(mode));
}

void AccuracyPanel::showImageMode(int mode) {
    m_sideBySide->setVisible(mode == static_cast<int>(ImageMode::SideBySide));
    m_flipPage->setVisible(mode == static_cast<int>(ImageMode::Flip));
    m_flipButton->setVisible(mode == static_cast<int>(ImageMode::Flip));
    const bool zoomable =
        mode == static_cast<int>(ImageMode::Swipe) || mode == static_cast<int>(ImageMode::ZoomSideBySide);
    m_compareView->setLayoutMode(mode == static_cast<int>(ImageMode::Swipe)
                                     ? CompareView::Layout::Swipe
                                     : CompareView::Layout::SideBySide);
    m_compareView->setVisible(zoomable);
}

void AccuracyPanel::setOverlayMap(OverlayMap map) {
    m_overlayMap->setCurrentIndex(map == OverlayMap::Flip ? 1 : 0);
}

void AccuracyPanel::showOverlayImage() {
    if (!m_last) {
        m_overlayWidget->setImage({});
        return;
    }
    if (m_overlayMap->currentIndex() == 1) {
        m_overlayWidget->setImage(m_last->flipMap,
                                  tr("FLIP map of the compared view (what a viewer would notice: black none, "
                                     "pale yellow 1)"));
    } else {
        m_overlayWidget->setImage(m_last->errorMap);
    }
}

void AccuracyPanel::flip() {
    m_flipShowsReference = !m_flipShowsReference;
    showFlipImage();
}

void AccuracyPanel::showFlipImage() {
    if (!m_last) {
        m_flipView->setImage({});
        m_flipCaption->clear();
        return;
    }
    m_flipView->setImage(m_flipShowsReference ? m_last->reference : m_last->raster);
    m_flipCaption->setText(m_flipShowsReference
                               ? tr("Exact (ray traced) — Flip for the raster image")
                               : tr("Raster (what the editor draws) — Flip for the exact image"));
}

void AccuracyPanel::setPreviewWidth(int pixels) {
    m_width->setValue(pixels);
}

void AccuracyPanel::setPaths(int paths) {
    m_paths->setCurrentIndex(std::max(0, m_paths->findData(paths)));
}

void AccuracyPanel::setBusy(bool busy) {
    m_compare->setEnabled(!busy);
    m_cancel->setEnabled(busy);
    m_progress->setVisible(busy);
    m_progress->setValue(0);
    m_progress->setTextVisible(busy);
    m_progress->setFormat(tr("estimating…"));
}

void AccuracyPanel::compareWithExact() {
    setBusy(true);
    m_status->setText(tr("Estimating the exact image's time…"));
    if (!m_comparison->start({m_width->value(), m_paths->currentData().toInt()}, m_clock.time())) {
        setBusy(false);
    }
}

void AccuracyPanel::cancelComparison() {
    m_comparison->cancel();
}

void AccuracyPanel::showResult(const ComparisonResult& result) {
    if (result.final) {
        setBusy(false);
    }
    m_last = result;
    m_rmse->setText(QString::number(result.rmse, 'f', 4));
    m_psnr->setText(decibels(result.psnr));
    m_psnrMirrors->setText(decibels(result.psnrMirrors));
    m_psnrReflector->setText(decibels(result.psnrReflector));
    m_psnrInterval->setText(result.roughPixels == 0
                                ? tr("exact: the reference has no noise here")
                                : tr("%1 – %2").arg(decibels(result.psnrLow), decibels(result.psnrHigh)));
    m_mae->setText(QString::number(result.mae, 'f', 4));
    m_ssim->setText(QString::number(result.ssim, 'f', 4));
    m_flip->setText(tr("%1 · %2").arg(result.flip, 0, 'f', 4).arg(result.hdrFlip, 0, 'f', 4));
    m_rasterMs->setText(result.rasterGpuMs >= 0.0 ? tr("%1 ms GPU · %2 ms CPU")
                                                        .arg(result.rasterGpuMs, 0, 'f', 2)
                                                        .arg(result.rasterCpuMs, 0, 'f', 2)
                                                  : tr("%1 ms CPU").arg(result.rasterCpuMs, 0, 'f', 2));
    m_traceMs->setText(tr("%1 ms").arg(result.traceMs, 0, 'f', 0));
    m_noise->setText(
        result.roughPixels == 0
            ? tr("none: no rough surface in view, every pixel is exact")
            : tr("%1 at %2 paths per rough pixel").arg(result.noiseRms, 0, 'g', 2).arg(result.paths));
    m_status->setText(tr("%1×%2 px, the view at t = %3 s; shadows traced with each light's PCF footprint.")
                          .arg(result.width)
                          .arg(result.height)
                          .arg(m_clock.time(), 0, 'f', 2));
    m_reference->setImage(result.reference);
    m_raster->setImage(result.raster);
    m_errorMap->setImage(result.errorMap);
    m_flipMap->setImage(result.flipMap);
    m_compareView->setImages(result.reference, result.raster);
    showFlipImage();
    m_images->show();
    showOverlayImage();
    m_overlay->setEnabled(true);
    if (!result.final) {
        return; // the messages once, for the result that stands
    }
    for (const QString& w : result.warnings) {
        emit message(tr("Accuracy: %1").arg(w));
    }
    emit message(tr("Compared with exact: PSNR %1, raster %2 vs tracer %3")
                     .arg(decibels(result.psnr), m_rasterMs->text(), m_traceMs->text()));
}

void AccuracyPanel::comparisonFailed(const QString& text, bool cancelled) {
    setBusy(false);
    m_status->setText(cancelled ? tr("Cancelled.") : tr("Could not compare: %1").arg(text));
}

} // namespace speculum::ui
