#pragma once

#include "render/plan/FrameReport.hpp"

#include <QElapsedTimer>
#include <QWidget>
#include <vector>

class QLabel;
class QTreeWidget;
class QTreeWidgetItem;

namespace speculum::ui {

// The Render passes dock: the live frame — every pass that ran, in order, with its target, GPU time and
// the reason it ran (the plan's, then what running it found) — and the effects that got no pass, with
// the reason. With several curved reflectors or bounces, the environment maps of each bounce are grouped
// under a row of their own with their total time. Updated from the viewport's frame
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
    // A bounce's maps: its row and the passes under it (indices into FrameReport::ran).
    struct Group {
        QTreeWidgetItem* row = nullptr;
        int bounce = 0;
        std::vector<std::size_t> runs;
    };
    // Sets every pass's and group's time from `report`, whose passes the rows show.
    void showTimings(const speculum::render::FrameReport& report);

    QLabel* m_summary = nullptr;
    QTreeWidget* m_tree = nullptr;
    QElapsedTimer m_sinceUpdate;
    QString m_lastLayout; // kinds/targets/reasons of the shown passes: only timings change most frames
    std::vector<QTreeWidgetItem*> m_passItems; // the row of each pass that ran, in order
    std::vector<Group> m_groups;
};

} // namespace speculum::ui
