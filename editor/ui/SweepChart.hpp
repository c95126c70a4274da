#pragma once

#include "editor/document/SweepResults.hpp"

#include <QChartView>
#include <vector>

class QScatterSeries;

namespace speculum::ui {

// PSNR against frame time of a bench run (loaded, or one running in the Accuracy panel), one scatter series
// per family, the Pareto front as a line and the scene's own setting ringed. Clicking a point emits
// recordChosen with its index in the results.
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

signals:
    void recordChosen(int index);

private:
    static QString placeholder();
    void pointClicked(const QString& family, const QPointF& point);
    int nearest(const QString& family, const QPointF& point) const; // record index, -1 if none

    document::SweepResults m_results;
    QScatterSeries* m_highlight = nullptr;
};

} // namespace speculum::ui
