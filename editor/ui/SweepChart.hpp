#pragma once

#include "editor/document/SweepResults.hpp"

#include <QChartView>
#include <vector>

class QGraphicsRectItem;
class QGraphicsTextItem;
class QScatterSeries;
class QValueAxis;

namespace speculum::ui {

// PSNR against frame time of a bench run (loaded, or one running in the Accuracy panel), one scatter series
// per family, the Pareto front as a line and the scene's own setting ringed. Clicking a point emits
// recordChosen with its index in the results; resting on one labels it with its settings.
class SweepChart : public QChartView {
    Q_OBJECT

public:
    explicit SweepChart(QWidget* parent = nullptr);

    void setResults(const document::SweepResults& results);
    const document::SweepResults& results() const { return m_results; }
    // Rings a record (the one last applied); -1 rings none.
    void highlight(int index);
    int seriesCount() const; // scatter series, one per family
    int pointCount() const;  // points in them

    // The label a point shows while the pointer rests on it: family and configuration, frame time, PSNR
    // and every setting of the record (plain text).
    QString pointLabel(int index) const;
    // Shows record `index`'s label next to its point (what hovering it does); -1 hides the label.
    void hoverRecord(int index);
    QString hoverText() const { return m_hoverText; } // empty while no point is hovered

signals:
    void recordChosen(int index);

private:
    static QString placeholder();
    void pointClicked(const QString& family, const QPointF& point);
    int nearest(const QString& family, const QPointF& point) const; // record index, -1 if none

    document::SweepResults m_results;
    QScatterSeries* m_highlight = nullptr;
    QValueAxis* m_axisX = nullptr;
    QValueAxis* m_axisY = nullptr;
    QGraphicsRectItem* m_callout = nullptr; // the hover label, drawn in the chart (tooltips may not show)
    QGraphicsTextItem* m_calloutText = nullptr;
    QString m_hoverText;
};

} // namespace speculum::ui
