// AccuracyPanel, its sweep half: the chart of a bench run, run in this process (accuracy::runSweep on a
// worker, SweepRunJob) or loaded from a results.json, and applying a point's settings to the document.
#include "accuracy/Report.hpp"
#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "editor/document/Commands.hpp"
#include "editor/document/SweepResults.hpp"
#include "editor/ui/AccuracyPanel.hpp"
#include "editor/ui/SweepChart.hpp"
#include "editor/ui/SweepRunJob.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/model/Scene.hpp"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QUndoStack>
#include <QVBoxLayout>

namespace speculum::ui {

namespace {

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

// "Sweep of the settings": the buttons, the progress, the chart, the message under it and the findings.
QGroupBox* AccuracyPanel::buildSweepBox() {
    auto* sweepBox = new QGroupBox(tr("Sweep of the settings (speculum bench)"), this);
    m_sweep = new SweepRunJob(this);
    QGridLayout* sweepButtons = buildSweepButtons(sweepBox);
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
    return sweepBox;
}

// Run sweep (it starts at once: no ellipsis), its size, Cancel and Load sweep… (a file dialog).
QGridLayout* AccuracyPanel::buildSweepButtons(QGroupBox* sweepBox) {
    m_runSweep = new QPushButton(tr("Run sweep"), sweepBox);
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
    return sweepButtons;
}

void AccuracyPanel::connectSweep() {
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
        std::vector<scene::Warning> ignored;
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
    } else if (application.skipped.isEmpty()) {
        summary = tr("%1 %2: the document already has these settings.").arg(family, label);
    } else {
        summary = tr("%1 %2: nothing applied.").arg(family, label);
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
    std::vector<scene::Warning> warnings;
    const QString name =
        m_scene.projectPath().isEmpty() ? tr("untitled") : QFileInfo(m_scene.projectPath()).fileName();
    accuracy::SweepInput input = SweepRunJob::inputFor(m_scene, m_viewport.meshes(), name, quick, warnings);
    for (const scene::Warning& w : warnings) {
        emit message(tr("Sweep: %1").arg(QString::fromStdString(w.message)));
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
    const QString findings = findingsMarkdown(accuracy::findings(results.records, results.run.furnace));
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
