#pragma once

#include "render/plan/FrameReport.hpp"

#include <QElapsedTimer>
#include <QWidget>

class QLabel;
class QTreeWidget;

namespace speculum::ui {

// The Render passes dock: the live frame — every pass that ran, in order, with its target, GPU time and
// the reason it ran (the plan's, then what running it found) — and the effects that got no pass, with
// the reason. Updated from the viewport's frame
// reports at most a few times per second so a playing animation does not spend its time on this list.
class RenderPassesPanel : public QWidget {
    Q_OBJECT

public:
    explicit RenderPassesPanel(QWidget* parent = nullptr);

    QTreeWidget& tree() { return *m_tree; }

public slots:
    void showReport(const speculum::render::FrameReport& report);
    // Shows a report now, ignoring the rate limit.
    void showReportNow(const speculum::render::FrameReport& report);

private:
    QLabel* m_summary = nullptr;
    QTreeWidget* m_tree = nullptr;
    QElapsedTimer m_sinceUpdate;
    QString m_lastLayout; // kinds/targets/reasons of the shown passes: only timings change most frames
};

} // namespace speculum::ui
