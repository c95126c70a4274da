#include "editor/ui/AccuracyPanel.hpp"

#include "accuracy/Report.hpp"
#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "editor/document/Commands.hpp"
#include "editor/document/SweepResults.hpp"
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
    void setImage(const QImage& image) {
        m_image = image;
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
        painter.drawImage(rect(), m_image);
        painter.setOpacity(1.0);
        const QString caption = tr("Error map of the compared view (brighter = worse; 64/255 or more = top)");
        const QRect box = painter.fontMetrics().boundingRect(caption).adjusted(-6, -3, 6, 3);
        const QRect at = box.translated(8 - box.left(), height() - box.height() - 8 - box.top());
        painter.fillRect(at, QColor(0, 0, 0, 170));
        painter.setPen(Qt::white);
        painter.drawText(at, Qt::AlignCenter, caption);
    }

private:
    QImage m_image;
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

QString decibels(const std::optional<double>& db) {
    return db ? QStringLiteral("%1 dB").arg(*db, 0, 'f', 2) : QObject::tr("— (no such pixels)");
}

// The findings of accuracy::findings as Markdown for a label: a heading per family, a bullet per finding.
QString findingsMarkdown(const std::vector<accuracy::FamilyFindings>& findings) {
    QString md;
    for (const auto& family : findings) {
        md += QStringLiteral("**%1** (judged by %2)\n\n")
                  .arg(QString::fromStdString(family.title), QString::fromStdString(family.judgedBy));
        for (const std::string& line : family.lines) {
            md += QStringLiteral("- %1\n").arg(QString::fromStdString(line));
        }
        md += QLatin1Char('\n');
    }
    return md;
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
    auto* compareBox = new QGroupBox(tr("This view against the exact tracer"), this);
    m_width = new QSpinBox(compareBox);
    m_width->setObjectName(QStringLiteral("accuracyWidth"));
    m_width->setRange(32, 4096);
    m_width->setValue(480); // interactive on a software rasterizer; the tracer's time grows with pixels
    m_width->setSuffix(tr(" px wide"));
    m_width->setToolTip(tr("Both images are rendered this wide (at most the viewport's width), in the "
                           "viewport's aspect"));
    m_compare = new QPushButton(tr("Compare with exact"), compareBox);
    m_compare->setObjectName(QStringLiteral("compareExact"));
    m_cancel = new QPushButton(tr("Cancel"), compareBox);
    m_cancel->setObjectName(QStringLiteral("cancelCompare"));
    m_cancel->setEnabled(false);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_width);
    buttons->addWidget(m_compare, 1);
    buttons->addWidget(m_cancel);
    m_progress = new QProgressBar(compareBox);
    m_progress->setObjectName(QStringLiteral("accuracyProgress"));
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(false);
    m_progress->hide();
    m_status = new QLabel(tr("Renders the current view both ways and measures the difference."), compareBox);
    m_status->setObjectName(QStringLiteral("accuracyStatus"));
    m_status->setWordWrap(true);

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
    m_rasterMs = label("accuracyRasterMs");
    m_traceMs = label("accuracyTraceMs");
    numbers->addRow(tr("RMSE (sRGB)"), m_rmse);
    numbers->addRow(tr("PSNR"), m_psnr);
    numbers->addRow(tr("PSNR mirrors"), m_psnrMirrors);
    numbers->addRow(tr("PSNR reflector"), m_psnrReflector);
    numbers->addRow(tr("Raster frame"), m_rasterMs);
    numbers->addRow(tr("Exact tracer"), m_traceMs);

    m_explanation = new QLabel(
        tr("<b>RMSE</b> is the typical difference of a pixel's colour between the two images (sRGB, 0 = "
           "identical, 1 = black against white); <b>PSNR</b> says the same in decibels, 20·log10(1 / RMSE), "
           "so higher is better: above 40 dB the differences are invisible, 30–40 dB they show on a close "
           "look, below 30 dB they are obvious."),
        compareBox);
    m_explanation->setObjectName(QStringLiteral("accuracyExplanation"));
    m_explanation->setWordWrap(true);
    m_explanation->setTextFormat(Qt::RichText);

    // What the numbers measured, two ways: the exact image, the raster image and their difference side by
    // side, or one larger view that flips between the exact and the raster image (differences jump out
    // when the eye stays in one place).
    m_imageMode = new QComboBox(compareBox);
    m_imageMode->setObjectName(QStringLiteral("accuracyImageMode"));
    m_imageMode->addItem(tr("Side by side"));
    m_imageMode->addItem(tr("Flip exact / raster"));
    m_imageMode->setToolTip(tr("Show the three images next to each other, or one image that alternates "
                               "between the exact and the raster one"));
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
    imagesLayout->addWidget(m_sideBySide);
    imagesLayout->addWidget(m_flipPage);
    m_images->hide();
    m_overlay = new QCheckBox(tr("Show the error map over the viewport"), compareBox);
    m_overlay->setObjectName(QStringLiteral("accuracyOverlay"));
    m_overlay->setEnabled(false);
    m_overlayWidget = new ErrorMapOverlay(viewport);

    auto* compareLayout = new QVBoxLayout(compareBox);
    compareLayout->addLayout(buttons);
    compareLayout->addWidget(m_progress);
    compareLayout->addWidget(m_status);
    compareLayout->addLayout(numbers);
    compareLayout->addWidget(m_explanation);
    compareLayout->addWidget(m_images, 1);
    compareLayout->addWidget(m_overlay);

    auto* sweepBox = new QGroupBox(tr("Sweep of the settings (speculum bench)"), this);
    m_sweep = new SweepRunJob(this);
    m_runSweep = new QPushButton(tr("Run sweep…"), sweepBox);
    m_runSweep->setObjectName(QStringLiteral("runSweep"));
    m_runSweep->setToolTip(tr("Measure every setting the scene uses against the exact tracer, as "
                              "`speculum bench` does: the scene's camera at t = 0, in this process"));
    m_sweepSize = new QComboBox(sweepBox);
    m_sweepSize->setObjectName(QStringLiteral("sweepSize"));
    for (bool quick : {true, false}) {
        const accuracy::SweepSize size = accuracy::defaultSweepSize(quick);
        m_sweepSize->addItem(
            (quick ? tr("Quick, %1×%2") : tr("Full, %1×%2")).arg(size.width).arg(size.height), quick);
    }
    m_cancelSweep = new QPushButton(tr("Cancel"), sweepBox);
    m_cancelSweep->setObjectName(QStringLiteral("cancelSweep"));
    m_cancelSweep->setEnabled(false);
    m_loadSweep = new QPushButton(tr("Load sweep…"), sweepBox);
    m_loadSweep->setObjectName(QStringLiteral("loadSweep"));
    m_loadSweep->setToolTip(tr("Open the results.json that `speculum bench PROJECT --out DIR` wrote"));
    // Two rows, so that the panel fits a dock beside the Properties one.
    auto* sweepButtons = new QGridLayout;
    sweepButtons->addWidget(m_runSweep, 0, 0);
    sweepButtons->addWidget(m_sweepSize, 0, 1);
    sweepButtons->addWidget(m_cancelSweep, 1, 0);
    sweepButtons->addWidget(m_loadSweep, 1, 1);
    m_sweepProgress = new QProgressBar(sweepBox);
    m_sweepProgress->setObjectName(QStringLiteral("sweepProgress"));
    m_sweepProgress->setFormat(QStringLiteral("%v / %m"));
    m_sweepProgress->hide();
    m_sweepStatus = new QLabel(sweepBox);
    m_sweepStatus->setObjectName(QStringLiteral("sweepStatus"));
    m_sweepStatus->setWordWrap(true);
    m_sweepStatus->hide();
    m_chart = new SweepChart(sweepBox);
    m_sweepMessage = new QLabel(tr("Click a point to give the document that configuration's settings "
                                   "(one undo step)."),
                                sweepBox);
    m_sweepMessage->setObjectName(QStringLiteral("sweepMessage"));
    m_sweepMessage->setWordWrap(true);
    m_findings = new QLabel(sweepBox);
    m_findings->setObjectName(QStringLiteral("sweepFindings"));
    m_findings->setTextFormat(Qt::MarkdownText);
    m_findings->setWordWrap(true);
    m_findings->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_findings->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    auto* sweepLayout = new QVBoxLayout(sweepBox);
    sweepLayout->addLayout(sweepButtons);
    sweepLayout->addWidget(m_sweepProgress);
    sweepLayout->addWidget(m_sweepStatus);
    // The findings run to a few paragraphs per family: they scroll, under the chart.
    m_findingsScroll = new QScrollArea(sweepBox);
    m_findingsScroll->setObjectName(QStringLiteral("sweepFindingsScroll"));
    m_findingsScroll->setWidgetResizable(true);
    m_findingsScroll->setFrameShape(QFrame::NoFrame);
    m_findingsScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_findingsScroll->setWidget(m_findings);
    m_findingsScroll->setMinimumHeight(160);
    m_findingsScroll->hide();
    sweepLayout->addWidget(m_chart, 3);
    sweepLayout->addWidget(m_sweepMessage);
    sweepLayout->addWidget(m_findingsScroll, 2);

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

    connect(m_compare, &QPushButton::clicked, this, &AccuracyPanel::compareWithExact);
    connect(m_cancel, &QPushButton::clicked, this, &AccuracyPanel::cancelComparison);
    connect(m_comparison, &ExactComparison::progress, this,
            [this](double fraction) { m_progress->setValue(int(fraction * 1000)); });
    connect(m_comparison, &ExactComparison::finished, this, &AccuracyPanel::showResult);
    connect(m_comparison, &ExactComparison::failed, this, &AccuracyPanel::comparisonFailed);
    connect(m_overlay, &QCheckBox::toggled, m_overlayWidget, &QWidget::setVisible);
    connect(m_imageMode, &QComboBox::currentIndexChanged, this, [this](int mode) {
        m_sideBySide->setVisible(mode == 0);
        m_flipPage->setVisible(mode == 1);
        m_flipButton->setVisible(mode == 1);
    });
    connect(m_flipButton, &QPushButton::clicked, this, &AccuracyPanel::flip);
    connect(m_flipView, &ImageTile::clicked, this, &AccuracyPanel::flip);
    connect(m_loadSweep, &QPushButton::clicked, this, &AccuracyPanel::loadSweepDialog);
    connect(m_runSweep, &QPushButton::clicked, this,
            [this] { runSweep(m_sweepSize->currentData().toBool()); });
    connect(m_cancelSweep, &QPushButton::clicked, this, &AccuracyPanel::cancelSweep);
    connect(m_sweep, &SweepRunJob::progress, this, &AccuracyPanel::sweepProgress);
    connect(m_sweep, &SweepRunJob::recordsChanged, this,
            [this](const std::vector<accuracy::Record>& records) {
                accuracy::ResultsFile partial;
                partial.records = records;
                m_chart->setResults(partial);
            });
    connect(m_sweep, &SweepRunJob::finished, this, &AccuracyPanel::sweepFinished);
    connect(m_sweep, &SweepRunJob::failed, this, &AccuracyPanel::sweepFailed);
    connect(m_chart, &SweepChart::recordChosen, this, &AccuracyPanel::applyRecord);
    connect(&m_scene, &scene::Scene::changed, this, [this] {
        if (m_last && !m_comparison->running()) {
            m_status->setText(tr("The scene changed since these numbers: compare again."));
        }
        m_sceneChangedDuringSweep = m_sceneChangedDuringSweep || m_sweep->running();
    });
    // A measurement of the previous document says nothing about the new one.
    connect(&m_scene, &scene::Scene::sceneReset, this, &AccuracyPanel::clear);
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
    for (QLabel* l : {m_rmse, m_psnr, m_psnrMirrors, m_psnrReflector, m_rasterMs, m_traceMs}) {
        l->setText(QStringLiteral("—"));
    }
    for (ImageTile* tile : {m_reference, m_raster, m_errorMap, m_flipView}) {
        tile->setImage({});
    }
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
    m_imageMode->setCurrentIndex(mode == ImageMode::Flip ? 1 : 0);
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

void AccuracyPanel::setBusy(bool busy) {
    m_compare->setEnabled(!busy);
    m_cancel->setEnabled(busy);
    m_progress->setVisible(busy);
    m_progress->setValue(0);
}

void AccuracyPanel::compareWithExact() {
    setBusy(true);
    m_status->setText(tr("Tracing the exact image…"));
    if (!m_comparison->start(m_width->value(), m_clock.time())) {
        setBusy(false);
    }
}

void AccuracyPanel::cancelComparison() {
    m_comparison->cancel();
}

void AccuracyPanel::showResult(const ComparisonResult& result) {
    setBusy(false);
    m_last = result;
    m_rmse->setText(QString::number(result.rmse, 'f', 4));
    m_psnr->setText(decibels(result.psnr));
    m_psnrMirrors->setText(decibels(result.psnrMirrors));
    m_psnrReflector->setText(decibels(result.psnrReflector));
    m_rasterMs->setText(result.rasterGpuMs >= 0.0 ? tr("%1 ms GPU · %2 ms CPU")
                                                        .arg(result.rasterGpuMs, 0, 'f', 2)
                                                        .arg(result.rasterCpuMs, 0, 'f', 2)
                                                  : tr("%1 ms CPU").arg(result.rasterCpuMs, 0, 'f', 2));
    m_traceMs->setText(tr("%1 ms").arg(result.traceMs, 0, 'f', 0));
    m_status->setText(tr("%1×%2 px, the view at t = %3 s; shadows traced with each light's PCF footprint.")
                          .arg(result.width)
                          .arg(result.height)
                          .arg(m_clock.time(), 0, 'f', 2));
    m_reference->setImage(result.reference);
    m_raster->setImage(result.raster);
    m_errorMap->setImage(result.errorMap);
    showFlipImage();
    m_images->show();
    m_overlayWidget->setImage(result.errorMap);
    m_overlay->setEnabled(true);
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

base::Status AccuracyPanel::loadSweepFile(const QString& path) {
    // A FIFO or a device as results.json would block the GUI thread in open() or read() for good: only a
    // regular file is handed to the reader.
    if (auto regular = base::requireRegularFile(path.toStdString()); !regular) {
        const std::string error = base::printable(path.toStdString()) + ": " + regular.error();
        m_sweepMessage->setText(QString::fromStdString(error));
        return base::Error{error};
    }
    if (m_sweep->running()) {
        const std::string error = "a sweep is running: cancel it first";
        m_sweepMessage->setText(QString::fromStdString(error));
        return base::Error{error};
    }
    auto results = document::loadSweepResults(path);
    if (!results) {
        m_sweepMessage->setText(QString::fromStdString(results.error()));
        return base::Error{results.error()};
    }
    m_chart->setResults(*results);
    m_findingsScroll->hide();
    m_findings->clear();
    m_sweepMessage->setText(tr("%1 configurations of %2 at %3 (%4). Click a point to apply its settings.")
                                .arg(results->records.size())
                                .arg(QString::fromStdString(results->run.scene),
                                     QString::fromStdString(results->size()), QFileInfo(path).fileName()));
    return base::Done{};
}

void AccuracyPanel::loadSweepDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Load Sweep"), QString(),
                                                      tr("Bench results (results.json);;JSON (*.json)"));
    if (!path.isEmpty()) {
        loadSweepFile(path);
    }
}

QString AccuracyPanel::applyRecord(int index) {
    const auto& records = m_chart->results().records;
    if (index < 0 || std::size_t(index) >= records.size()) {
        return {};
    }
    if (m_sweep->running()) {
        // The document does not change while a sweep measures it.
        const QString busy = tr("A sweep is running: its points apply once it is done.");
        m_sweepMessage->setText(busy);
        return busy;
    }
    const auto& record = records[std::size_t(index)];
    std::optional<scene::ReflectorParallax> proxy;
    if (m_last) {
        proxy = document::sweepParallaxProxy(m_last->input);
    } else {
        std::vector<std::string> ignored;
        proxy = document::sweepParallaxProxy(
            scene::snapshot(m_scene, m_clock.time(), m_viewport.meshes(), ignored));
    }
    const QString family = QString::fromStdString(accuracy::familyName(record.config.family));
    const QString label = QString::fromStdString(record.config.label);
    const QString text = tr("Apply Sweep Setting %1 %2").arg(family, label);
    auto application = document::applySweepSettings(m_scene, record.settings, text, proxy);
    QString summary;
    // pushEdit: a record whose settings the document already has leaves no step, and keeps the redo steps
    // and the clean state.
    if (application.command && document::pushEdit(m_undoStack, application.command.release())) {
        summary = tr("Applied %1 %2 (%3 ms, PSNR %4 dB).")
                      .arg(family, label)
                      .arg(accuracy::frameMs(record), 0, 'f', 2)
                      .arg(record.psnr, 0, 'f', 2);
    } else {
        summary = tr("%1 %2: the document already has these settings.").arg(family, label);
    }
    if (!application.skipped.isEmpty()) {
        summary +=
            QLatin1Char(' ') + tr("Not applied: %1.").arg(application.skipped.join(QStringLiteral("; ")));
    }
    m_chart->highlight(index);
    m_sweepMessage->setText(summary);
    emit message(summary);
    return summary;
}

bool AccuracyPanel::sweeping() const {
    return m_sweep->running();
}

QString AccuracyPanel::findingsText() const {
    return m_findings->text();
}

void AccuracyPanel::setSweeping(bool sweeping) {
    m_runSweep->setEnabled(!sweeping);
    m_sweepSize->setEnabled(!sweeping);
    m_loadSweep->setEnabled(!sweeping);
    m_cancelSweep->setEnabled(sweeping);
    m_sweepProgress->setVisible(sweeping);
    m_sweepStatus->setVisible(sweeping);
    if (sweeping) {
        m_sweepProgress->setRange(0, 0); // busy until the first step is counted
        m_findingsScroll->hide();
    }
}

void AccuracyPanel::runSweep(bool quick) {
    if (m_sweep->running()) {
        return;
    }
    std::vector<std::string> warnings;
    const QString name =
        m_scene.projectPath().isEmpty() ? tr("untitled") : QFileInfo(m_scene.projectPath()).fileName();
    accuracy::SweepInput input = SweepRunJob::inputFor(m_scene, m_viewport.meshes(), name, quick, warnings);
    for (const std::string& w : warnings) {
        emit message(tr("Sweep: %1").arg(QString::fromStdString(w)));
    }
    m_chartBefore = m_chart->results();
    m_sceneChangedDuringSweep = false;
    m_chart->setResults({});
    m_sweepStatus->setText(tr("Starting the sweep…"));
    setSweeping(true);
    const accuracy::SweepSize size = accuracy::defaultSweepSize(quick);
    m_sweepMessage->setText(tr("Sweeping %1 at %2×%3: the scene's camera at t = 0, as `speculum bench` "
                               "measures it. Times are of one frame until the timing rounds are done.")
                                .arg(name)
                                .arg(size.width)
                                .arg(size.height));
    if (!m_sweep->start(std::move(input))) {
        setSweeping(false);
    }
}

void AccuracyPanel::cancelSweep() {
    m_sweep->cancel();
    m_sweepStatus->setText(tr("Cancelling…"));
}

void AccuracyPanel::sweepProgress(int done, int total, const QString& line) {
    m_sweepProgress->setRange(0, std::max(1, total));
    m_sweepProgress->setValue(std::min(done, total));
    m_sweepStatus->setText(line);
}

void AccuracyPanel::sweepFinished(const accuracy::ResultsFile& results) {
    setSweeping(false);
    m_chartBefore.reset();
    m_chart->setResults(results);
    const QString findings = findingsMarkdown(accuracy::findings(results.records));
    m_findings->setText(findings.isEmpty() ? tr("The scene has nothing to sweep: no curved reflector, no "
                                                "planar mirror, no shadowed light and no built-in teapot.")
                                           : findings);
    m_findingsScroll->show();
    QString text =
        tr("%1 configurations of %2 at %3. Click a point to apply its settings.")
            .arg(results.records.size())
            .arg(QString::fromStdString(results.run.sceneName), QString::fromStdString(results.size()));
    if (m_sceneChangedDuringSweep) {
        text += QLatin1Char(' ') + tr("The scene changed during the sweep: these figures are of the scene as "
                                      "it was when the sweep started.");
    }
    m_sweepMessage->setText(text);
    emit message(tr("Sweep done: %1 configurations").arg(results.records.size()));
}

void AccuracyPanel::sweepFailed(const QString& text, bool cancelled) {
    setSweeping(false);
    // Nothing half-done stays: the chart shows what it showed before the sweep.
    m_chart->setResults(m_chartBefore.value_or(accuracy::ResultsFile{}));
    m_chartBefore.reset();
    m_sweepMessage->setText(cancelled ? tr("Sweep cancelled; nothing changed.")
                                      : tr("The sweep failed: %1").arg(text));
    emit message(m_sweepMessage->text());
}

} // namespace speculum::ui
