#include "editor/ui/RenderPassesPanel.hpp"

#include <QHeaderView>
#include <QLabel>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace speculum::ui {

namespace {

constexpr int kUpdateIntervalMs = 250;

QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

QString ms(double value) {
    return value < 0.0 ? QStringLiteral("–") : QString::number(value, 'f', 2);
}

// Whether the frame's environment-map passes are grouped by bounce: there are maps of several reflectors,
// or of more than one bounce. One reflector's one map stays a row of its own.
bool groupsMaps(const render::FrameReport& report) {
    std::string first;
    for (const render::PassRun& run : report.ran) {
        const render::PlannedPass& p = report.planned(run);
        if (p.kind != render::PassKind::Envmap)
            continue;
        if (p.details.bounces > 0 || (!first.empty() && p.target != first))
            return true;
        first = p.target;
    }
    return false;
}

} // namespace

RenderPassesPanel::RenderPassesPanel(QWidget* parent)
    : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    m_summary = new QLabel(tr("No frame yet"), this);
    m_summary->setObjectName(QStringLiteral("passesSummary"));
    layout->addWidget(m_summary);
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("passesTree"));
    m_tree->setColumnCount(4);
    m_tree->setHeaderLabels({tr("Pass"), tr("Target"), tr("GPU ms"), tr("Why")});
    m_tree->headerItem()->setToolTip(
        2, tr("Time each pass took on the GPU, from OpenGL timestamp queries. On a software renderer "
              "(Mesa llvmpipe, on machines without a graphics card) the \"GPU\" is the CPU's cores, so "
              "these times compete with the editor's own work and say little about a graphics card."));
    m_tree->setRootIsDecorated(true);
    m_tree->setUniformRowHeights(true);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_tree->header()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_tree->header()->setStretchLastSection(true);
    layout->addWidget(m_tree, 1);
}

void RenderPassesPanel::showReport(const render::FrameReport& report) {
    if (m_sinceUpdate.isValid() && m_sinceUpdate.elapsed() < kUpdateIntervalMs) {
        return;
    }
    showReportNow(report);
}

void RenderPassesPanel::showReportNow(const render::FrameReport& report) {
    m_sinceUpdate.start();
    m_summary->setText(tr("%1 passes, %2 skipped · CPU %3 ms · GPU %4 ms")
                           .arg(report.ran.size())
                           .arg(report.skipped.size())
                           .arg(ms(report.cpuMs), ms(report.gpuMs)));

    QString layout;
    for (const render::PassRun& run : report.ran) {
        const render::PlannedPass& p = report.planned(run);
        layout += text(render::toString(p.kind)) + QLatin1Char('/') + QString::fromStdString(p.target) +
                  QLatin1Char('/') + QString::fromStdString(report.reason(run)) + QLatin1Char('\n');
    }
    layout += QStringLiteral("--\n");
    for (const auto& s : report.skipped) {
        layout += QString::fromStdString(s.target) + QLatin1Char('/') + QString::fromStdString(s.reason()) +
                  QLatin1Char('\n');
    }
    if (layout == m_lastLayout && m_tree->topLevelItemCount() == 2 &&
        m_passItems.size() == report.ran.size()) {
        // Same passes: only the timings change.
        showTimings(report);
        return;
    }
    m_lastLayout = layout;
    m_tree->clear();
    m_passItems.clear();
    m_groups.clear();
    auto* passes =
        new QTreeWidgetItem(m_tree, {tr("Passes (%1)").arg(report.ran.size()), QString(), ms(report.gpuMs)});
    // With several reflectors or bounces, the maps of each bounce are a group: one row per reflector in it.
    const bool grouped = groupsMaps(report);
    Group* group = nullptr;
    for (std::size_t i = 0; i < report.ran.size(); ++i) {
        const render::PlannedPass& p = report.planned(report.ran[i]);
        QTreeWidgetItem* parent = passes;
        if (grouped && p.kind == render::PassKind::Envmap) {
            if (!group || group->bounce != p.details.bounce) {
                auto* row = new QTreeWidgetItem(passes, {tr("maps, bounce %1").arg(p.details.bounce)});
                row->setToolTip(
                    0, p.details.bounce == 0
                           ? tr("Each reflector's map, the other reflectors drawn with their material")
                           : tr("Each map again, the other reflectors drawn with their maps: of bounce %1 "
                                "where drawn this frame, else as kept")
                                 .arg(p.details.bounce - 1));
                m_groups.push_back({row, p.details.bounce, {}});
                group = &m_groups.back();
            }
            group->runs.push_back(i);
            parent = group->row;
        } else {
            group = nullptr;
        }
        const QString reason = QString::fromStdString(report.reason(report.ran[i]));
        auto* item =
            new QTreeWidgetItem(parent, {text(render::toString(p.kind)), QString::fromStdString(p.target),
                                         ms(report.ran[i].gpuMs), reason});
        item->setToolTip(3, reason);
        item->setTextAlignment(2, Qt::AlignRight | Qt::AlignVCenter);
        m_passItems.push_back(item);
    }
    showTimings(report);
    auto* skipped = new QTreeWidgetItem(m_tree, {tr("Skipped effects (%1)").arg(report.skipped.size())});
    for (const auto& s : report.skipped) {
        const QString reason = QString::fromStdString(s.reason());
        auto* item = new QTreeWidgetItem(
            skipped, {tr("skipped"), QString::fromStdString(s.target), QString(), reason});
        item->setToolTip(3, reason);
        item->setForeground(0, QColor(150, 90, 20));
    }
    m_tree->expandAll();
}

void RenderPassesPanel::showTimings(const render::FrameReport& report) {
    for (std::size_t i = 0; i < m_passItems.size() && i < report.ran.size(); ++i)
        m_passItems[i]->setText(2, ms(report.ran[i].gpuMs));
    for (const Group& group : m_groups) {
        double sum = 0.0;
        for (std::size_t i : group.runs)
            sum = i < report.ran.size() && report.ran[i].gpuMs >= 0.0 && sum >= 0.0
                      ? sum + report.ran[i].gpuMs
                      : -1.0;
        group.row->setText(2, ms(sum));
        group.row->setTextAlignment(2, Qt::AlignRight | Qt::AlignVCenter);
    }
    m_tree->topLevelItem(0)->setText(2, ms(report.gpuMs));
}

} // namespace speculum::ui
