#include "editor/ui/SweepChart.hpp"

#include "accuracy/Analysis.hpp"

#include <QChart>
#include <QCursor>
#include <QFont>
#include <QLegendMarker>
#include <QLineSeries>
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

void SweepChart::setResults(const document::SweepResults& results) {
    m_results = results;
    QChart* c = chart();
    c->removeAllSeries();
    for (QAbstractAxis* axis : c->axes()) {
        c->removeAxis(axis);
        delete axis;
    }
    m_highlight = nullptr;
    const auto& records = m_results.records;

    auto* axisX = new QValueAxis;
    axisX->setTitleText(m_results.gpuTimes() ? tr("GPU ms per frame") : tr("CPU ms per frame"));
    auto* axisY = new QValueAxis;
    axisY->setTitleText(tr("PSNR (dB)"));
    c->addAxis(axisX, Qt::AlignBottom);
    c->addAxis(axisY, Qt::AlignLeft);
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
            const int index = nearest(family, p);
            if (entered && index >= 0) {
                const auto& r = m_results.records[std::size_t(index)];
                QStringList settings;
                for (const auto& [key, value] : r.settings) {
                    settings << QString::fromStdString(key + " " + value).toHtmlEscaped();
                }
                QToolTip::showText(QCursor::pos(),
                                   tr("<b>%1 %2</b><br>%3 ms · PSNR %4 dB<br>%5")
                                       .arg(family, QString::fromStdString(r.config.label).toHtmlEscaped())
                                       .arg(accuracy::frameMs(r), 0, 'f', 2)
                                       .arg(r.psnr, 0, 'f', 2)
                                       .arg(settings.join(QStringLiteral(", "))));
            } else {
                QToolTip::hideText();
            }
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
