#include "editor/ui/AccuracyPanel.hpp"

#include "editor/document/Scene.hpp"
#include "editor/document/Snapshot.hpp"
#include "editor/document/SweepResults.hpp"
#include "editor/ui/AnimationClock.hpp"
#include "editor/ui/SweepChart.hpp"
#include "editor/ui/Viewport.hpp"
#include "render/io/FileKind.hpp"
#include "render/io/Printable.hpp"
#include "render/math/Projection.hpp"
#include "render/mesh/MeshData.hpp"
#include "render/plan/Planner.hpp"

#include <QCheckBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QUndoStack>
#include <QVBoxLayout>
#include <glm/glm.hpp>

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

namespace {

QString decibels(const std::optional<double>& db) {
    return db ? QStringLiteral("%1 dB").arg(*db, 0, 'f', 2) : QObject::tr("— (no such pixels)");
}

// "Parallax on" of the bench for a reflector without a proxy of its own: a box around everything but the
// reflector, relative to the capture point, when that box encloses the reflector (app/bench/Sweep.cpp's
// sceneTraits; the same rule, so the applied setting is the one that was measured).
std::optional<document::ReflectorParallax> derivedProxy(const render::FrameInput& scene) {
    if (!scene.reflector || !scene.reflector->mesh) {
        return std::nullopt;
    }
    render::FrameInput environment = scene;
    environment.reflector.reset();
    const render::math::Box around = render::math::sceneBounds(environment);
    const render::math::Box own =
        render::math::worldBounds(render::computeBounds(*scene.reflector->mesh), scene.reflector->world);
    if (around.empty() || own.empty()) {
        return std::nullopt;
    }
    const double tolerance = 1e-6 * std::max(1.0, glm::length(around.max - around.min));
    if (!glm::all(glm::lessThanEqual(around.min, own.min + tolerance)) ||
        !glm::all(glm::greaterThanEqual(around.max, own.max - tolerance))) {
        return std::nullopt;
    }
    const glm::dvec3 centre = render::envmapCapture(scene).centre;
    document::ReflectorParallax proxy;
    proxy.shape = document::ParallaxShape::Box;
    proxy.min = around.min - centre;
    proxy.max = around.max - centre;
    return proxy;
}

} // namespace

AccuracyPanel::AccuracyPanel(document::Scene& scene, QUndoStack& undoStack, Viewport& viewport,
                             AnimationClock& clock, QWidget* parent)
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

    m_errorMap = new QLabel(compareBox);
    m_errorMap->setObjectName(QStringLiteral("accuracyErrorMap"));
    m_errorMap->setAlignment(Qt::AlignCenter);
    m_errorMap->setMinimumHeight(80);
    m_overlay = new QCheckBox(tr("Show the error map over the viewport"), compareBox);
    m_overlay->setObjectName(QStringLiteral("accuracyOverlay"));
    m_overlay->setEnabled(false);
    m_overlayWidget = new ErrorMapOverlay(viewport);

    auto* compareLayout = new QVBoxLayout(compareBox);
    compareLayout->addLayout(buttons);
    compareLayout->addWidget(m_progress);
    compareLayout->addWidget(m_status);
    compareLayout->addLayout(numbers);
    compareLayout->addWidget(m_errorMap);
    compareLayout->addWidget(m_overlay);

    auto* sweepBox = new QGroupBox(tr("Last sweep (speculum bench)"), this);
    auto* load = new QPushButton(tr("Load sweep…"), sweepBox);
    load->setObjectName(QStringLiteral("loadSweep"));
    load->setToolTip(tr("Open the results.json that `speculum bench PROJECT --out DIR` wrote"));
    m_chart = new SweepChart(sweepBox);
    m_sweepMessage = new QLabel(tr("Click a point to give the document that configuration's settings "
                                   "(one undo step)."),
                                sweepBox);
    m_sweepMessage->setObjectName(QStringLiteral("sweepMessage"));
    m_sweepMessage->setWordWrap(true);
    auto* sweepLayout = new QVBoxLayout(sweepBox);
    sweepLayout->addWidget(load);
    sweepLayout->addWidget(m_chart, 1);
    sweepLayout->addWidget(m_sweepMessage);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(compareBox);
    layout->addWidget(sweepBox, 1);

    connect(m_compare, &QPushButton::clicked, this, &AccuracyPanel::compareWithExact);
    connect(m_cancel, &QPushButton::clicked, this, &AccuracyPanel::cancelComparison);
    connect(m_comparison, &ExactComparison::progress, this,
            [this](double fraction) { m_progress->setValue(int(fraction * 1000)); });
    connect(m_comparison, &ExactComparison::finished, this, &AccuracyPanel::showResult);
    connect(m_comparison, &ExactComparison::failed, this, &AccuracyPanel::comparisonFailed);
    connect(m_overlay, &QCheckBox::toggled, m_overlayWidget, &QWidget::setVisible);
    connect(load, &QPushButton::clicked, this, &AccuracyPanel::loadSweepDialog);
    connect(m_chart, &SweepChart::recordChosen, this, &AccuracyPanel::applyRecord);
    connect(&m_scene, &document::Scene::changed, this, [this] {
        if (m_last && !m_comparison->running()) {
            m_status->setText(tr("The scene changed since these numbers: compare again."));
        }
    });
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
    m_errorMap->setPixmap(QPixmap::fromImage(
        result.errorMap.scaledToWidth(std::min(result.errorMap.width(), 320), Qt::SmoothTransformation)));
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

render::Status AccuracyPanel::loadSweepFile(const QString& path) {
    // A FIFO or a device as results.json would block the GUI thread in open() or read() for good: only a
    // regular file is handed to the reader.
    if (auto regular = render::requireRegularFile(path.toStdString()); !regular) {
        const std::string error = render::printable(path.toStdString()) + ": " + regular.error();
        m_sweepMessage->setText(QString::fromStdString(error));
        return render::Error{error};
    }
    auto results = document::loadSweepResults(path);
    if (!results) {
        m_sweepMessage->setText(QString::fromStdString(results.error()));
        return render::Error{results.error()};
    }
    m_chart->setResults(*results);
    m_sweepMessage->setText(tr("%1 configurations of %2 at %3 (%4). Click a point to apply its settings.")
                                .arg(results->records.size())
                                .arg(results->scene, results->size, QFileInfo(path).fileName()));
    return render::Done{};
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
    const auto& record = records[std::size_t(index)];
    std::optional<document::ReflectorParallax> proxy;
    if (m_last) {
        proxy = derivedProxy(m_last->input);
    } else {
        std::vector<std::string> ignored;
        proxy = derivedProxy(document::snapshot(m_scene, m_clock.time(), m_viewport.meshes(), ignored));
    }
    const QString text = tr("Apply Sweep Setting %1 %2").arg(record.family, record.label);
    auto application = document::applySweepSettings(m_scene, record.settings, text, proxy);
    QString summary;
    if (application.command) {
        m_undoStack.push(application.command.release());
        summary = tr("Applied %1 %2 (%3 ms, PSNR %4 dB).")
                      .arg(record.family, record.label)
                      .arg(record.ms(), 0, 'f', 2)
                      .arg(record.psnr, 0, 'f', 2);
    } else {
        summary = tr("%1 %2: the document already has these settings.").arg(record.family, record.label);
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

} // namespace speculum::ui
