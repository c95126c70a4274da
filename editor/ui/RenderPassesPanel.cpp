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
    if (layout == m_lastLayout && m_tree->topLevelItemCount() == 2) {
        // Same passes: only the timings change.
        QTreeWidgetItem* passes = m_tree->topLevelItem(0);
        for (int i = 0; i < passes->childCount() && i < int(report.ran.size()); ++i) {
            passes->child(i)->setText(2, ms(report.ran[std::size_t(i)].gpuMs));
        }
        passes->setText(2, ms(report.gpuMs));
        return;
    }
    m_lastLayout = layout;
    m_tree->clear();
    auto* passes =
        new QTreeWidgetItem(m_tree, {tr("Passes (%1)").arg(report.ran.size()), QString(), ms(report.gpuMs)});
    for (const render::PassRun& run : report.ran) {
        const render::PlannedPass& p = report.planned(run);
        const QString reason = QString::fromStdString(report.reason(run));
        auto* item = new QTreeWidgetItem(passes, {text(render::toString(p.kind)),
                                                  QString::fromStdString(p.target), ms(run.gpuMs), reason});
        item->setToolTip(3, reason);
        item->setTextAlignment(2, Qt::AlignRight | Qt::AlignVCenter);
    }
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

} // namespace speculum::ui
