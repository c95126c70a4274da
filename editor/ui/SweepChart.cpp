#include "editor/ui/SweepChart.hpp"

#include "accuracy/Analysis.hpp"

#include <QChart>
#include <QFont>
#include <QGraphicsRectItem>
#include <QGraphicsTextItem>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPen>
#include <QScatterSeries>
#include <QToolTip>
#include <QValueAxis>
#include <algorithm>
#include <limits>
#include <map>

namespace speculum::ui {

SweepChart::SweepChart(QWidget* parent)
    : QChartView(new QChart, parent) {
    setObjectName(QStringLiteral("sweepChart"));
    setRenderHint(QPainter::Antialiasing);
    chart()->setTitle(placeholder());
    chart()->legend()->setAlignment(Qt::AlignBottom);
    chart()->setMargins(QMargins(2, 2, 2, 2));
    setMinimumHeight(300);
    QFont small = chart()->legend()->font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    chart()->legend()->setFont(small);
}

int SweepChart::seriesCount() const {
    int n = 0;
    for (QAbstractSeries* s : chart()->series()) {
        n += s != m_highlight && qobject_cast<QScatterSeries*>(s) != nullptr;
    }
    return n;
}

QString SweepChart::placeholder() {
    return tr("Run a sweep, or load a bench results.json, to compare settings");
}

int SweepChart::pointCount() const {
    int n = 0;
    for (QAbstractSeries* s : chart()->series()) {
        if (auto* scatter = qobject_cast<QScatterSeries*>(s); scatter && s != m_highlight) {
            n += int(scatter->count());
        }
    }
    return n;
}

namespace {

// Each family's colour and marker, fixed by the family (not by the order series happen to be added), so a
// family looks the same in every run; colours from the Okabe–Ito set, told apart with colour blindness
// too, and a shape of their own besides.
struct FamilyStyle {
    QColor color;
    QScatterSeries::MarkerShape shape;
};

FamilyStyle familyStyle(accuracy::Family family) {
    static const QColor colors[] = {QColor(0, 0, 0),       QColor(230, 159, 0),  QColor(86, 180, 233),
                                    QColor(0, 158, 115),   QColor(213, 94, 0),   QColor(0, 114, 178),
                                    QColor(204, 121, 167), QColor(240, 228, 66), QColor(153, 153, 153),
                                    QColor(128, 64, 160)};
    // In the families' order: the scene (the anchor) a star; the families a chart usually shows together
    // (the reflector's, the mirrors', the shadows') shapes that differ.
    using S = QScatterSeries;
    static const S::MarkerShape shapes[] = {S::MarkerShapeStar,
                                            S::MarkerShapeCircle,
                                            S::MarkerShapeRectangle,
                                            S::MarkerShapeTriangle,
                                            S::MarkerShapeRotatedRectangle,
                                            S::MarkerShapePentagon,
                                            S::MarkerShapeCircle,
                                            S::MarkerShapeRectangle,
                                            S::MarkerShapeTriangle,
                                            S::MarkerShapeRotatedRectangle};
    const auto i = static_cast<std::size_t>(family);
    return {colors[i % std::size(colors)], shapes[i % std::size(shapes)]};
}

} // namespace

void SweepChart::setResults(const document::SweepResults& results) {
    m_results = results;
    QChart* c = chart();
    c->removeAllSeries();
    m_highlight = nullptr;
    hoverRecord(-1);
    const auto& records = m_results.records;

    // The same two axes for every run: a removed and deleted axis can stay drawn (Qt Charts 6.4), so a
    // cleared chart that then loads a run would show two sets of ticks over each other.
    if (!m_axisX) {
        m_axisX = new QValueAxis(this);
        m_axisY = new QValueAxis(this);
        m_axisY->setTitleText(tr("PSNR (dB)"));
        c->addAxis(m_axisX, Qt::AlignBottom);
        c->addAxis(m_axisY, Qt::AlignLeft);
    }
    QValueAxis* axisX = m_axisX;
    QValueAxis* axisY = m_axisY;
    // One title whatever the run: each point's callout says which clock timed it (the GPU's where it is
    // timed, else the CPU's), and an empty chart does not change its title when it fills.
    axisX->setTitleText(tr("ms per frame"));
    axisX->setRange(0.0, 1.0);
    axisY->setRange(0.0, 1.0);
    // The panel names the run under the chart; a title here would squeeze the plot in a narrow dock.
    c->setTitle(records.empty() ? placeholder() : QString());

    // Families in the order of the file, so colours follow the bench's own order.
    std::vector<QString> families;
    std::map<QString, QScatterSeries*> byFamily;
    auto familyOf = [](const accuracy::Record& r) {
        return QString::fromStdString(accuracy::familyName(r.config.family));
    };
    double lowMs = std::numeric_limits<double>::infinity(), highMs = 0.0;
    double lowDb = std::numeric_limits<double>::infinity(), highDb = 0.0;
    for (const auto& r : records) {
        const QString family = familyOf(r);
        if (!byFamily.count(family)) {
            auto* series = new QScatterSeries;
            series->setName(family);
            series->setMarkerSize(9);
            const FamilyStyle style = familyStyle(r.config.family);
            series->setColor(style.color);
            series->setBorderColor(style.color.darker(140));
            series->setMarkerShape(style.shape);
            byFamily[family] = series;
            families.push_back(family);
        }
        const double ms = accuracy::frameMs(r);
        byFamily[family]->append(ms, r.psnr);
        lowMs = std::min(lowMs, ms), highMs = std::max(highMs, ms);
        lowDb = std::min(lowDb, r.psnr), highDb = std::max(highDb, r.psnr);
    }
    auto* front = new QLineSeries;
    front->setName(tr("Pareto front"));
    front->setColor(QColor(110, 110, 110)); // not a family's colour
    for (std::size_t i : accuracy::paretoFront(records)) {
        front->append(accuracy::frameMs(records[i]), records[i].psnr);
    }
    c->addSeries(front);
    front->attachAxis(axisX);
    front->attachAxis(axisY);
    for (const QString& family : families) {
        QScatterSeries* series = byFamily[family];
        c->addSeries(series);
        series->attachAxis(axisX);
        series->attachAxis(axisY);
        connect(series, &QScatterSeries::clicked, this,
                [this, family](const QPointF& p) { pointClicked(family, p); });
        connect(series, &QScatterSeries::hovered, this, [this, family](const QPointF& p, bool entered) {
            hoverRecord(entered ? nearest(family, p) : -1);
        });
    }
    m_highlight = new QScatterSeries;
    m_highlight->setName(tr("applied"));
    m_highlight->setMarkerSize(16);
    m_highlight->setColor(Qt::transparent);
    m_highlight->setBorderColor(Qt::black);
    c->addSeries(m_highlight);
    m_highlight->attachAxis(axisX);
    m_highlight->attachAxis(axisY);
    for (QLegendMarker* marker : c->legend()->markers(m_highlight)) {
        marker->setVisible(false); // a ring, not a family
    }
    if (!records.empty()) {
        const double padMs = std::max(0.05, 0.08 * (highMs - lowMs));
        const double padDb = std::max(0.5, 0.08 * (highDb - lowDb));
        axisX->setRange(std::max(0.0, lowMs - padMs), highMs + padMs);
        axisY->setRange(lowDb - padDb, highDb + padDb);
    }
    for (std::size_t i = 0; i < records.size(); ++i) {
        if (records[i].sceneSetting) {
            highlight(int(i));
            break;
        }
    }
}

QString SweepChart::pointLabel(int index) const {
    if (index < 0 || std::size_t(index) >= m_results.records.size()) {
        return {};
    }
    const auto& r = m_results.records[std::size_t(index)];
    QStringList settings;
    for (const auto& [key, value] : r.settings) {
        settings << QString::fromStdString(key + " " + value);
    }
    const QString perceptual = r.perceptual ? tr(" · FLIP %1 · SSIM %2%3")
                                                  .arg(r.flip, 0, 'f', 4)
                                                  .arg(r.ssim, 0, 'f', 4)
                                                  .arg(r.tiedWith.empty() ? QString() : tr(" · tied (noise)"))
                                            : QString();
    return tr("%1 %2\n%3 ms %4 · PSNR %5 dB%6\n%7")
        .arg(QString::fromStdString(accuracy::familyName(r.config.family)),
             QString::fromStdString(r.config.label))
        .arg(accuracy::frameMs(r), 0, 'f', 2)
        .arg(r.gpuMs >= 0.0 ? tr("GPU") : tr("CPU"))
        .arg(r.psnr, 0, 'f', 2)
        .arg(perceptual, settings.join(QStringLiteral(", ")));
}

void SweepChart::hoverRecord(int index) {
    m_hoverText = pointLabel(index);
    if (!m_callout) {
        m_callout = new QGraphicsRectItem(chart());
        m_callout->setBrush(QColor(255, 255, 225, 235));
        m_callout->setPen(QPen(QColor(120, 120, 120)));
        m_callout->setZValue(100);
        m_calloutText = new QGraphicsTextItem(m_callout);
    }
    if (m_hoverText.isEmpty()) {
        m_callout->hide();
        QToolTip::hideText();
        return;
    }
    const auto& r = m_results.records[std::size_t(index)];
    m_calloutText->setTextWidth(-1);
    m_calloutText->setPlainText(m_hoverText);
    const QRectF plot = chart()->plotArea();
    m_calloutText->setTextWidth(std::min(m_calloutText->boundingRect().width(), plot.width() * 0.9));
    const QRectF box = m_calloutText->boundingRect();
    m_callout->setRect(box);
    // Beside the point, kept inside the plot: right of it and below where there is room, else mirrored.
    const QPointF at = chart()->mapToPosition(QPointF(accuracy::frameMs(r), r.psnr));
    double x = at.x() + 10, y = at.y() + 10;
    if (x + box.width() > plot.right()) {
        x = std::max(plot.left(), at.x() - 10 - box.width());
    }
    if (y + box.height() > plot.bottom()) {
        y = std::max(plot.top(), at.y() - 10 - box.height());
    }
    m_callout->setPos(x, y);
    m_callout->show();
}

void SweepChart::highlight(int index) {
    if (!m_highlight) {
        return;
    }
    m_highlight->clear();
    if (index >= 0 && std::size_t(index) < m_results.records.size()) {
        const auto& r = m_results.records[std::size_t(index)];
        m_highlight->append(accuracy::frameMs(r), r.psnr);
    }
}

void SweepChart::pointClicked(const QString& family, const QPointF& point) {
    if (const int index = nearest(family, point); index >= 0) {
        emit recordChosen(index);
    }
}

int SweepChart::nearest(const QString& family, const QPointF& point) const {
    // In screen distance: the axes have different units.
    const QPointF at = chart()->mapToPosition(point);
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m_results.records.size(); ++i) {
        const auto& r = m_results.records[i];
        if (QString::fromStdString(accuracy::familyName(r.config.family)) != family) {
            continue;
        }
        const QPointF p = chart()->mapToPosition(QPointF(accuracy::frameMs(r), r.psnr));
        const double d = QLineF(p, at).length();
        if (d < bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

} // namespace speculum::ui
